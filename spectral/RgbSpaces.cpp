// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/RgbSpaces.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <Eigen/LU>

#include "spectral/Exception.h"

namespace bandlight
{

const std::vector<RgbSpace>& BuiltinRgbSpaces()
{
    // clang-format off
    static const std::vector<RgbSpace> spaces = {
        {"acescg", "ACEScg", "ACES AP1 primaries, ACES white (x 0.32168, y 0.33767); SMPTE ST 2065-1 / S-2014-004",
         {0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767}},
        {"aces2065-1", "ACES2065-1", "ACES AP0 primaries, ACES white; SMPTE ST 2065-1",
         {0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.0770, 0.32168, 0.33767}},
        {"rec709", "Linear Rec.709 (sRGB)", "ITU-R BT.709 / IEC 61966-2-1 primaries, D65 white",
         {0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290}},
        {"rec2020", "Linear Rec.2020", "ITU-R BT.2020 primaries, D65 white",
         {0.708, 0.292, 0.170, 0.797, 0.131, 0.046, 0.3127, 0.3290}},
        {"p3-d65", "Linear P3-D65", "SMPTE EG 432-1 P3 primaries, D65 white",
         {0.680, 0.320, 0.265, 0.690, 0.150, 0.060, 0.3127, 0.3290}},
        {"ebu3213", "Linear EBU Tech 3213", "EBU Tech 3213 primaries, D65 white",
         {0.64, 0.33, 0.29, 0.60, 0.15, 0.06, 0.3127, 0.3290}},
    };
    // clang-format on
    return spaces;
}

const RgbSpace& FindRgbSpace(const std::string& name)
{
    std::string k = name;
    std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
    for (const char* prefix : {"lin-", "linear-", "lin_"})
    {
        if (k.rfind(prefix, 0) == 0)
        {
            k = k.substr(std::string(prefix).size());
        }
    }
    if (k == "srgb" || k == "bt709" || k == "rec.709")
    {
        k = "rec709";
    }
    else if (k == "ap1")
    {
        k = "acescg";
    }
    else if (k == "ap0" || k == "aces")
    {
        k = "aces2065-1";
    }
    else if (k == "ebu" || k == "ebu-3213")
    {
        k = "ebu3213";
    }
    else if (k == "bt2020" || k == "rec.2020")
    {
        k = "rec2020";
    }
    else if (k == "p3" || k == "p3d65")
    {
        k = "p3-d65";
    }
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        if (s.name == k)
        {
            return s;
        }
    }
    std::string choices;
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        choices += (choices.empty() ? "" : ", ") + s.name;
    }
    throw Exception("unknown working space '" + name + "' (choices: " + choices + ")");
}

Vec3 WhiteXyz(double x, double y)
{
    return Vec3(x / y, 1.0, (1.0 - x - y) / y);
}

Mat3 RgbToXyzMatrix(const Chromaticities& c)
{
    Mat3 p;
    // clang-format off
    p << c.rx / c.ry,                 c.gx / c.gy,                 c.bx / c.by,
         1.0,                         1.0,                         1.0,
         (1 - c.rx - c.ry) / c.ry,    (1 - c.gx - c.gy) / c.gy,    (1 - c.bx - c.by) / c.by;
    // clang-format on
    if (!p.allFinite() || std::abs(p.determinant()) < 1e-12)
    {
        throw Exception("degenerate primaries: their chromaticities do not span a colour space");
    }
    const Vec3 s = p.inverse() * WhiteXyz(c.wx, c.wy);
    return p * s.asDiagonal();
}

}  // namespace bandlight
