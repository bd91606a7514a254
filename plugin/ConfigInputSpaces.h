// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Input colour spaces: camera IDTs a config carries beside its looks. How a
// config holds them is plugin/ConfigInputSpaces.cpp; BuildConfig and
// ExtendConfig (plugin/ConfigBuilder.h) add them.

#include <string>

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// An input colour space: camera RGB → a linear RGB space by a 3×3 (a
/// camera's IDT, white-balance gains folded in). In a config it is an
/// "Input" family, scene-linear colour space whose to-reference transform
/// is the matrix followed by the way from `space` to the config's
/// reference; its matrix is also written as a CLF file of its own
/// (luts/<name>.clf, through OCIO's writer).
struct InputSpace
{
    std::string name;
    std::string description;
    Mat3 toSpace = Mat3::Identity();
    std::string space = "aces2065-1";  ///< the built-in RGB space the matrix lands in
};

}  // namespace bandlight
