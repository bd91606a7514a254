// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The defaults of what a job writes and how it runs, beside the library's own
// (transforms/Defaults.h, included): folders, file formats, the plates an
// accuracy run compares, threads. Read by the jobs' requests, the command's
// options and the Python module's keywords alike.

#include "transforms/Defaults.h"

namespace bandlight::defaults
{

/// How a config extending a base rewrites the base's relative search paths.
inline constexpr const char* BASE_PATHS = "relative";

/// The folder `package` writes into.
inline constexpr const char* PACKAGE_DIR = "bandlight-package";

/// The plate conventions `accuracy` measures: both lit and balanced.
inline constexpr const char* ACCURACY_PLATES = "both";
/// What a light group of a render is to `apply --light-group` when the
/// plates are not given: lit by its own light (a render's group carries its
/// light's cast; no single white balances a mix of lights).
inline constexpr const char* LIGHT_GROUP_PLATES = "lit";
/// Threads of a job: 0 is every core.
inline constexpr int THREADS = 0;
/// How messages name a scene or spectrum given as text rather than a file.
inline constexpr const char* SCENE_SOURCE = "<scene>";
inline constexpr const char* TEXT_SOURCE = "<string>";

}  // namespace bandlight::defaults
