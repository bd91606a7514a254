// SPDX-License-Identifier: BSD-3-Clause
#include <set>

#include <catch2/catch.hpp>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
void CheckMatrix(const Mat3& m, const Mat3& expected, double tol)
{
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
        {
            INFO("row " << r << " column " << c);
            CHECK(m(r, c) == Approx(expected(r, c)).margin(tol));
        }
    }
}
}  // namespace

TEST_CASE("ACEScg and ACES2065-1 matrices match the ACES specification", "[spectral][published]")
{
    Mat3 ap1, ap0;
    // clang-format off
    // Academy S-2014-004 (ACEScg) §4.1: AP1 → XYZ.
    ap1 <<  0.6624541811, 0.1340042065, 0.1561876870,
            0.2722287168, 0.6740817658, 0.0536895174,
           -0.0055746495, 0.0040607335, 1.0103391003;
    // SMPTE ST 2065-1 / Academy S-2008-001 §4.1.2: AP0 → XYZ.
    ap0 <<  0.9525523959, 0.0000000000,  0.0000936786,
            0.3439664498, 0.7281660966, -0.0721325464,
            0.0000000000, 0.0000000000,  1.0088251844;
    // clang-format on
    CheckMatrix(RgbToXyzMatrix(FindRgbSpace("ACEScg").chromaticities), ap1, 1e-9);
    CheckMatrix(RgbToXyzMatrix(FindRgbSpace("ap0").chromaticities), ap0, 1e-9);
}

TEST_CASE("sRGB / Rec.709 matrix matches IEC 61966-2-1", "[spectral][published]")
{
    Mat3 srgb;
    // clang-format off
    // IEC 61966-2-1:1999 §5.2, to four decimals.
    srgb << 0.4124, 0.3576, 0.1805,
            0.2126, 0.7152, 0.0722,
            0.0193, 0.1192, 0.9505;
    // clang-format on
    CheckMatrix(RgbToXyzMatrix(FindRgbSpace("lin-srgb").chromaticities), srgb, 0.6e-4);
}

TEST_CASE("Every built-in space maps RGB white to its white point, Y = 1", "[spectral]")
{
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        INFO(s.name);
        const Mat3 m = RgbToXyzMatrix(s.chromaticities);
        const Vec3 w = m * Vec3::Ones();
        const Vec3 expected = WhiteXyz(s.chromaticities.wx, s.chromaticities.wy);
        CHECK((w - expected).norm() < 1e-12);
        // RGB → XYZ → RGB round trip.
        const Vec3 rgb(0.18, 2.5, -0.01);
        CHECK((m.inverse() * (m * rgb) - rgb).norm() < 1e-12);
    }
}

TEST_CASE("RGB space names and aliases", "[spectral]")
{
    CHECK(FindRgbSpace("lin-rec709").name == "rec709");
    CHECK(FindRgbSpace("Linear-sRGB").name == "rec709");
    CHECK(FindRgbSpace("LIN_AP1").name == "acescg");
    CHECK(FindRgbSpace("EBU").name == "ebu3213");
    CHECK(FindRgbSpace("Rec2020").name == "rec2020");
    CHECK(FindRgbSpace("P3-D65").name == "p3-d65");
    CHECK_THROWS_WITH(FindRgbSpace("prophoto"), Contains("unknown working space 'prophoto'"));
    CHECK_THROWS_AS(RgbToXyzMatrix({0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3127, 0.329}), Exception);
}

TEST_CASE("A space is linear: 'srgb' alone names the encoding and is refused", "[spectral]")
{
    // "srgb" means the sRGB-encoded image encoding where an image's colour
    // space is named; a working space is linear, so the name is not taken
    // to mean linear Rec.709 in one place and encoded sRGB in another.
    CHECK_THROWS_AS(FindRgbSpace("sRGB"), ParameterError);
    try
    {
        FindRgbSpace("srgb");
    }
    catch (const ParameterError& e)
    {
        CHECK_THAT(e.spelled(Face::COMMAND), Contains("rec709") && Contains("--colorspace srgb"));
        CHECK_THAT(e.spelled(Face::PYTHON), Contains("colorspace=srgb"));
    }
}

TEST_CASE("The space table: each name once, every alias found, choices in one spelling",
          "[spectral]")
{
    std::set<std::string> names;
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        CHECK(names.insert(s.name).second);
        CHECK(&FindRgbSpace(s.name) == &s);
        CHECK(!s.configName.empty());
        CHECK(!s.label.empty());
        CHECK(!s.keywords.empty());
        for (const std::string& alias : s.aliases)
        {
            INFO(alias);
            CHECK(names.insert(alias).second);  // no alias names two spaces
            CHECK(&FindRgbSpace(alias) == &s);
            CHECK(&FindRgbSpace("lin-" + alias) == &s);
        }
        for (const InteropId& id : s.interopIds)
        {
            CHECK(names.insert(id.id).second);
        }
        CHECK_THAT(RgbSpaceChoices(), Contains(s.name));
    }
    CHECK(RgbSpaceChoices() == "acescg, aces2065-1, rec709, rec2020, p3-d65, ebu3213");
}

TEST_CASE("The spaces code names are the registry's entries of those keys", "[spectral]")
{
    CHECK(&bandlight::Rec709Space() == &bandlight::FindRgbSpace("rec709"));
    CHECK(&bandlight::Rec2020Space() == &bandlight::FindRgbSpace("rec2020"));
    CHECK(&bandlight::AcesCgSpace() == &bandlight::FindRgbSpace("ap1"));
    CHECK(&bandlight::Aces2065Space() == &bandlight::FindRgbSpace("ap0"));
    CHECK(&bandlight::Ebu3213Space() == &bandlight::FindRgbSpace("ebu"));
    // Rec.709's red primary (ITU-R BT.709-6, table 1): x 0.640, y 0.330.
    CHECK(bandlight::Rec709Space().chromaticities.rx == Approx(0.640));
    CHECK(bandlight::Rec709Space().chromaticities.ry == Approx(0.330));
}
