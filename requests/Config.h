// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "requests/Inputs.h"
#include "plugin/ConfigBuilder.h"
#include "requests/Defaults.h"

namespace bandlight::jobs
{

/// `config`: an OCIO v2 config with one look per ordered pair of lights and
/// method, or the same looks added into an existing config.
struct ConfigRequest
{
    /// The folder config.ocio and its LUT files are written into (created
    /// if needed, all files replaced together or none; checked before any
    /// work, an empty path refused); not given: nothing is written, which is
    /// refused when the config needs LUT files.
    std::optional<std::string> out;
    /// A base config to extend, as a file (`base`) or already read
    /// (`baseConfig`, which wins); neither: a new config.
    std::string base;
    OCIO_NAMESPACE::ConstConfigRcPtr baseConfig;
    /// The base is `out`'s own config.ocio, replaced by the extended one
    /// (`idt --config` into a folder that holds a config: its spaces added).
    bool extendInPlace = false;
    /// The linear working space; empty: acescg, or with a base its
    /// scene_linear primaries as identified from the base.
    std::string workingSpace;
    std::vector<Light> lights;         ///< empty: defaults::CONFIG_ILLUMINANTS
    std::vector<std::string> methods;  ///< empty: LinearMethodNames()
    std::string observer = defaults::OBSERVER;
    int lutSize = defaults::CONFIG_LUT_SIZE;
    std::string basePaths = defaults::BASE_PATHS;  ///< "relative" or "absolute"
    PlatesRequest plates;
    /// false: no looks (lights and methods left empty), as for a config of
    /// input colour spaces alone (`idt --config`).
    bool looks = true;
    /// Input colour spaces (camera IDTs) to add.
    std::vector<InputSpace> inputSpaces;
};

struct ConfigResult
{
    ConfigPackage package;
    ConfigOptions options;   ///< what the config was built from
    std::string identified;  ///< the working space's built-in name (identified with a base)
};

/// The config of `request` built and, with `out`, written: its lights,
/// methods and plates resolved and checked (the output folder before any
/// work). The returned config's working folder is `out`, so its LUT-file
/// looks resolve. With `outputs`, the files join that set of outputs and the
/// caller commits it. The verb `config` and `idt --config` both end here.
ConfigResult BuildRequestedConfig(const ConfigRequest& request,
                                  Reporter& reporter = SilentReporter(),
                                  OutputSet* outputs = nullptr);

}  // namespace bandlight::jobs
