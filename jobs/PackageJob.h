// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "requests/Defaults.h"
#include "requests/Defaults.h"

namespace bandlight::jobs
{

/// `package`, the main job: the default config (ACEScg; A, C, D65, F2, F11;
/// every linear method) for white-balanced plates in `out`, the same for lit
/// plates in `out`/lit, and an example chart re-lit from A to D65 (EXR, and
/// an sRGB PNG preview of each). Everything is replaced as one set.
struct PackageRequest
{
    std::string out = defaults::PACKAGE_DIR;
};

struct PackageResult
{
    int looks = 0;                    ///< looks in each config
    size_t lights = 0;                ///< illuminants
    size_t methods = 0;               ///< methods
    std::string workingSpace;         ///< the config's name for it
    std::vector<std::string> charts;  ///< the chart images written, as <out>/<name>.exr and .png
};

PackageResult MakePackage(const PackageRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
