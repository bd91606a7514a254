// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>

#include "render/Scene.h"

namespace bandlight::jobs
{

/// A scene read from a file (`path`) or from YAML text (`text`, named
/// `source` in messages), with its mode overridden by `mode` when given
/// ("band3", "bandN", "spectral"). Throws ParameterError when band values
/// (output: bands) are asked for in spectral mode: they exist only in band
/// mode, and switching the output behind the user's back would hide that.
Scene LoadScene(const std::string& path, const std::optional<std::string>& text,
                const std::string& source, const std::optional<std::string>& mode);

}  // namespace bandlight::jobs
