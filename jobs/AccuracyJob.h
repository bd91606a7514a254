// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `accuracy`: the verb. Its request, result and tables are in
// measure/AccuracyRun.h.

#include "farm/Reporter.h"
#include "measure/AccuracyRun.h"

namespace bandlight::jobs
{

/// Measures `request` and writes its JSON document and plot, as one set.
AccuracyResult MeasureAccuracyJob(const AccuracyRequest& request,
                                  Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
