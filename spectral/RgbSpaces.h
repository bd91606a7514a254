// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// Chromaticities (CIE 1931 x, y) of three primaries and a white point.
struct Chromaticities
{
    double rx, ry, gx, gy, bx, by, wx, wy;
};

/// A linear RGB colour space defined by its chromaticities.
struct RgbSpace
{
    std::string name;         ///< canonical key: "acescg", "rec709", ...
    std::string displayName;  ///< "ACEScg (AP1)", ...
    std::string description;  ///< standard and white point
    Chromaticities chromaticities;
};

/// The built-in spaces: ebu3213, rec709 (= linear sRGB), rec2020, p3-d65,
/// acescg (AP1), aces2065-1 (AP0).
const std::vector<RgbSpace>& BuiltinRgbSpaces();

/// Looks a space up by case-insensitive name or alias ("srgb", "lin-rec709",
/// "ap1", "ap0", "ebu"); throws Exception listing the choices otherwise.
const RgbSpace& FindRgbSpace(const std::string& name);

/// The RGB → XYZ matrix of a space, derived from its chromaticities
/// (SMPTE RP 177): columns are the primaries scaled so that RGB (1, 1, 1)
/// is the white point with Y = 1. Throws Exception for degenerate primaries.
Mat3 RgbToXyzMatrix(const Chromaticities& c);

/// XYZ (Y = 1) of a chromaticity.
Vec3 WhiteXyz(double x, double y);

}  // namespace bandlight
