// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `idt`: the verb. Its request and result are in requests/Idt.h, the fits
// in camera/IdtFit.h, the JSON and text report in report/IdtReport.h.


#include "report/IdtReport.h"
#include "requests/Idt.h"

namespace bandlight::jobs
{

/// Checks every input and output first (one line each: dead channels,
/// lights a channel does not see, chart files, options that do not go
/// together, output paths), then fits, measures and writes (the JSON and the
/// config commit together).
IdtResult MakeIdt(const IdtRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
