// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `apply`: the verb. Its request and result are in requests/Apply.h; the
// pixels' forms of a change or a look in imaging/RelightForms.h, mattes in
// imaging/Mattes.h, light groups in imaging/ImageApply.h.

#include "farm/Reporter.h"
#include "requests/Apply.h"

namespace bandlight::jobs
{

/// Applies `request`: every output is complete or absent (written to a
/// temporary file, then renamed); alpha and other channels pass through.
/// Progress is reported per frame. Without keepGoing the first failing
/// frame throws (the frames before it are written).
ApplyResult ApplyImages(const ApplyRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
