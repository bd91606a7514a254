// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/RgbSpaces.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <Eigen/LU>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/TextFile.h"

namespace bandlight
{

namespace
{

/// The prefixes that say a name means the linear space ("lin-rec709").
constexpr const char* kLinearPrefixes[] = {"lin-", "linear-", "lin_"};

}  // namespace

const std::vector<RgbSpace>& BuiltinRgbSpaces()
{
    // Chromaticities: SMPTE ST 2065-1 (AP0), Academy S-2014-004 (AP1),
    // ITU-R BT.709, ITU-R BT.2020, SMPTE EG 432-1 (P3), EBU Tech 3213.
    // Interop IDs: the Color Interop Forum's recommendation (2024).
    // clang-format off
    static const std::vector<RgbSpace> spaces = {
        {"acescg", "ACEScg", "ACES AP1 primaries, ACES white (x 0.32168, y 0.33767); SMPTE ST 2065-1 / S-2014-004",
         {0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767},
         {"ap1"}, "ACEScg", "ACEScg",
         {{"lin_ap1_scene", false}},
         {"acescg", "ap1"}},
        {"aces2065-1", "ACES2065-1", "ACES AP0 primaries, ACES white; SMPTE ST 2065-1",
         {0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.0770, 0.32168, 0.33767},
         {"ap0", "aces"}, "ACES2065-1", "ACES2065-1",
         {{"lin_ap0_scene", false}},
         {"aces2065", "ap0", "aces"}},
        {"rec709", "Linear Rec.709 (sRGB)", "ITU-R BT.709 / IEC 61966-2-1 primaries, D65 white",
         {0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290},
         {"bt709", "rec.709", "lin-srgb", "linear-srgb", "lin_srgb"}, "Linear Rec.709 (sRGB)", "Rec.709",
         {{"lin_rec709_scene", false}, {"srgb_rec709_scene", true}, {"srgb_rec709_display", true}},
         {"709", "srgb", "bt.709", "rec709"}},
        {"rec2020", "Linear Rec.2020", "ITU-R BT.2020 primaries, D65 white",
         {0.708, 0.292, 0.170, 0.797, 0.131, 0.046, 0.3127, 0.3290},
         {"bt2020", "rec.2020"}, "Linear Rec.2020", "Rec.2020",
         {{"lin_rec2020_scene", false}},
         {"2020", "2100"}},
        {"p3-d65", "Linear P3-D65", "SMPTE EG 432-1 P3 primaries, D65 white",
         {0.680, 0.320, 0.265, 0.690, 0.150, 0.060, 0.3127, 0.3290},
         {"p3", "p3d65"}, "Linear P3-D65", "P3-D65",
         {{"lin_p3d65_scene", false}},
         {"p3"}},
        {"ebu3213", "Linear EBU Tech 3213", "EBU Tech 3213 primaries, D65 white",
         {0.64, 0.33, 0.29, 0.60, 0.15, 0.06, 0.3127, 0.3290},
         {"ebu", "ebu-3213"}, "Linear EBU Tech 3213", "EBU Tech 3213",
         {},
         {"ebu", "3213"}},
    };
    // clang-format on
    return spaces;
}

const RgbSpace& Rec709Space()
{
    static const RgbSpace& s = FindRgbSpace("rec709");
    return s;
}

const RgbSpace& Rec2020Space()
{
    static const RgbSpace& s = FindRgbSpace("rec2020");
    return s;
}

const RgbSpace& AcesCgSpace()
{
    static const RgbSpace& s = FindRgbSpace("acescg");
    return s;
}

const RgbSpace& Aces2065Space()
{
    static const RgbSpace& s = FindRgbSpace("aces2065-1");
    return s;
}

const RgbSpace& Ebu3213Space()
{
    static const RgbSpace& s = FindRgbSpace("ebu3213");
    return s;
}

std::string RgbSpaceChoices()
{
    std::string choices;
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        choices += (choices.empty() ? "" : ", ") + s.name;
    }
    return choices;
}

const RgbSpace& FindRgbSpace(const std::string& name)
{
    const std::string given = ToLower(name);
    const auto find = [](const std::string& k) -> const RgbSpace*
    {
        for (const RgbSpace& s : BuiltinRgbSpaces())
        {
            if (s.name == k || std::find(s.aliases.begin(), s.aliases.end(), k) != s.aliases.end())
            {
                return &s;
            }
        }
        return nullptr;
    };
    if (const RgbSpace* s = find(given))
    {
        return *s;
    }
    for (const char* prefix : kLinearPrefixes)
    {
        if (given.rfind(prefix, 0) == 0)
        {
            if (const RgbSpace* s = find(given.substr(std::string(prefix).size())))
            {
                return *s;
            }
        }
    }
    if (given == "srgb")
    {
        throw ParameterError("'" + name +
                             "' is the sRGB-encoded image encoding, not a linear working space: "
                             "the linear space of sRGB's primaries is rec709 (also lin-srgb); "
                             "for sRGB-encoded images say {colorspace=}srgb");
    }
    throw Exception("unknown working space '" + name + "' (choices: " + RgbSpaceChoices() + ")");
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

Mat3 SpaceToSpace(const RgbSpace& src, const RgbSpace& dst)
{
    const Mat3 ms = RgbToXyzMatrix(src.chromaticities);
    const Mat3 md = RgbToXyzMatrix(dst.chromaticities);
    const Vec3 ws = WhiteXyz(src.chromaticities.wx, src.chromaticities.wy);
    const Vec3 wd = WhiteXyz(dst.chromaticities.wx, dst.chromaticities.wy);
    const Mat3 cat = (ws - wd).norm() < 1e-9 ? Mat3::Identity()
                                             : AdaptationMatrix(ws, wd, AdaptationMethod::BRADFORD);
    return md.inverse() * cat * ms;
}

}  // namespace bandlight
