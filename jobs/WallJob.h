// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `wall`: the verb. Its request and result are in requests/Wall.h, the
// science in camera/Wall.h, the config in plugin/WallConfig.h, report.json
// and the text in report/WallReport.h.

#include "report/WallReport.h"
#include "requests/Wall.h"

namespace bandlight::jobs
{

/// Checks every input and output first (one line each: too few emitters,
/// names given twice, a negative sample or an emitter with no visible power,
/// an output folder that is empty or an input), then solves each white
/// balance and writes {out}/config.ocio, its CLF files and report.json,
/// committed together.
WallResult MakeWall(const WallRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
