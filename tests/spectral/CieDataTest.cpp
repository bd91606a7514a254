// SPDX-License-Identifier: BSD-3-Clause
#include <fstream>

#include <catch2/catch.hpp>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Illuminants.h"
#include "spectral/SpectrumIO.h"

using namespace bandlight;

namespace
{
bool Exists(const std::string& path)
{
    return bool(std::ifstream(path));
}

/// Every sample of `embedded` equals the package's value at that wavelength.
void CheckSameSamples(const Spectrum& embedded, const Spectrum& package)
{
    for (size_t i = 0; i < embedded.size(); ++i)
    {
        const double l = embedded.wavelength(i);
        INFO("at " << l << " nm");
        CHECK(embedded[i] == Approx(package(l)).epsilon(1e-9).margin(1e-12));
    }
}
}  // namespace

TEST_CASE("Embedded CIE tables equal colord-data's files", "[spectral][data]")
{
    const std::string root = COLORD_DATA_DIR;
    if (!Exists(root + "/cmf/CIE1931-2deg-XYZ.cmf"))
    {
        WARN("colord-data is not installed (" << root << "): comparison skipped");
        return;
    }
    const auto cmf1931 = ReadSpectraFile(root + "/cmf/CIE1931-2deg-XYZ.cmf");
    const MatchingFunctions& m = GetMatchingFunctions(Observer::CIE1931_2DEG);
    CheckSameSamples(m.x, cmf1931.at(0).spectrum);
    CheckSameSamples(m.y, cmf1931.at(1).spectrum);
    CheckSameSamples(m.z, cmf1931.at(2).spectrum);
    const auto cmf1964 = ReadSpectraFile(root + "/cmf/CIE1964-10deg-XYZ.cmf");
    const MatchingFunctions& m10 = GetMatchingFunctions(Observer::CIE1964_10DEG);
    CheckSameSamples(m10.x, cmf1964.at(0).spectrum);
    CheckSameSamples(m10.z, cmf1964.at(2).spectrum);

    for (const NamedSpectrum& ill : TabulatedIlluminants())
    {
        INFO("illuminant " << ill.name);
        CheckSameSamples(
            ill.spectrum,
            ReadSpectraFile(root + "/illuminant/CIE-" + ill.name + ".sp").at(0).spectrum);
    }
    const auto tcs = ReadSpectraFile(root + "/ref/CIE-TCS.sp");
    REQUIRE(tcs.size() == TestColourSamples().size());
    for (size_t i = 0; i < tcs.size(); ++i)
    {
        CHECK(tcs[i].name == TestColourSamples()[i].name);
        CheckSameSamples(TestColourSamples()[i].spectrum, tcs[i].spectrum);
    }
    const auto basis = ReadSpectraFile(root + "/ref/CIE-1986-daylight-SPD.cmf");
    CheckSameSamples(GetDaylightBasis().s0, basis.at(0).spectrum);
    CheckSameSamples(GetDaylightBasis().s1, basis.at(1).spectrum);
    CheckSameSamples(GetDaylightBasis().s2, basis.at(2).spectrum);
}

TEST_CASE("Embedded tables have the expected grids", "[spectral][data]")
{
    const MatchingFunctions& m = GetMatchingFunctions(Observer::CIE1931_2DEG);
    CHECK(m.y.start() == 360.0);
    CHECK(m.y.end() == Approx(830.0));
    CHECK(m.y.step() == Approx(5.0));
    CHECK(m.y(555.0) == 1.0);  // ȳ is normalised to 1 at 555 nm
    CHECK(TabulatedIlluminants().size() == 18);
    CHECK(TestColourSamples().size() == 15);
    CHECK(TestColourSamples().front().name == "TCS01");
    // ∫ȳ dλ over 360–830 nm: 106.857 for the 1 nm table (CIE 15:2004); the
    // 5 nm table summed with Δλ = 5 nm gives the same to 6 digits.
    CHECK(m.y.sum() == Approx(106.857).epsilon(1e-5));
}

TEST_CASE("White points of A, D50 and D65 match CIE 15:2004", "[spectral][published]")
{
    // CIE 15:2004 Table T.3, CIE 1931 2° observer, 5 decimals.
    struct Case
    {
        const char* name;
        double x, y;
    };
    for (const Case c :
         {Case{"A", 0.44758, 0.40745}, Case{"D50", 0.34567, 0.35851}, Case{"D65", 0.31272, 0.32903},
          Case{"C", 0.31006, 0.31616}, Case{"D55", 0.33243, 0.34744}})
    {
        INFO(c.name);
        const Vec3 xyY =
            XyzToxyY(IlluminantWhiteXyz(BuiltinIlluminant(c.name), Observer::CIE1931_2DEG));
        CHECK(xyY.x() == Approx(c.x).margin(6e-5));
        CHECK(xyY.y() == Approx(c.y).margin(6e-5));
    }
}
