// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `config`: an OCIO config of bandlight's looks (and input spaces), new or
// extending a studio's. The request, its result and the building are in
// requests/Config.h; the verb is that step, as every face calls it.

#include "requests/Config.h"

namespace bandlight::jobs
{

/// Builds the config of `request` and, with `out`, writes it. The returned
/// config's working folder is `out`, so its LUT-file looks resolve. With
/// `outputs`, the files join that set of outputs and the caller commits it.
ConfigResult MakeConfig(const ConfigRequest& request, Reporter& reporter = SilentReporter(),
                        OutputSet* outputs = nullptr);

}  // namespace bandlight::jobs
