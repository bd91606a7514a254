// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <catch2/catch.hpp>

#include "spectral/Colorimetry.h"
#include "spectral/Illuminants.h"

using namespace bandlight;

TEST_CASE("CIEDE2000 reproduces all 34 pairs of Sharma, Wu & Dalal (2005)", "[spectral][published]")
{
    // Table 1 of G. Sharma, W. Wu, E. N. Dalal, Color Res. Appl. 30(1):21-30, 2005.
    std::ifstream in(std::string(BANDLIGHT_TEST_DATA) + "/ciede2000_sharma2005.csv");
    REQUIRE(in);
    std::string line;
    int pairs = 0;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#' || line[0] == 'p')
        {
            continue;
        }
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream row(line);
        int id = 0;
        Vec3 lab1, lab2;
        double expected = 0.0;
        row >> id >> lab1.x() >> lab1.y() >> lab1.z() >> lab2.x() >> lab2.y() >> lab2.z() >>
            expected;
        REQUIRE(row);
        INFO("pair " << id);
        CHECK(DeltaE2000(lab1, lab2) == Approx(expected).margin(0.5e-4));
        CHECK(DeltaE2000(lab2, lab1) == Approx(expected).margin(0.5e-4));
        ++pairs;
    }
    CHECK(pairs == 34);
}

TEST_CASE("CIEDE2000 is zero for identical colours", "[spectral]")
{
    const Vec3 lab(50.0, 10.0, -20.0);
    CHECK(DeltaE2000(lab, lab) == 0.0);
    CHECK(DeltaE2000(Vec3(50, 0, 0), Vec3(50, 0, 0)) == 0.0);
}

TEST_CASE("CIELAB round-trips and puts the white at L* = 100", "[spectral]")
{
    const Vec3 white = IlluminantWhiteXyz(BuiltinIlluminant("D65"), Observer::CIE1931_2DEG);
    const Vec3 labWhite = XyzToLab(white, white);
    CHECK(labWhite.x() == Approx(100.0));
    CHECK(labWhite.y() == Approx(0.0).margin(1e-12));
    for (const Vec3& xyz : {Vec3(20.0, 30.0, 40.0), Vec3(0.1, 0.2, 0.05), Vec3(90, 95, 100)})
    {
        const Vec3 back = LabToXyz(XyzToLab(xyz, white), white);
        CHECK((back - xyz).norm() < 1e-10);
    }
    CHECK(DeltaE76(Vec3(50, 3, 4), Vec3(50, 0, 0)) == Approx(5.0));
}

TEST_CASE("xyY and CIE 1960 uv of the equal-energy white", "[spectral]")
{
    const Vec3 e(1.0, 1.0, 1.0);
    CHECK(XyzToxyY(e).x() == Approx(1.0 / 3.0));
    CHECK((xyYToXyz(XyzToxyY(e)) - e).norm() < 1e-12);
    CHECK(XyzToUv1960(e).x() == Approx(4.0 / 19.0));
    CHECK(XyzToUv1960(e).y() == Approx(6.0 / 19.0));
    CHECK(XyzToxyY(Vec3::Zero()) == Vec3::Zero());
}

TEST_CASE("Surface XYZ: the perfect white reflector has Y = 100", "[spectral]")
{
    for (const char* name : {"A", "D65", "F11"})
    {
        const Spectrum s = BuiltinIlluminant(name);
        const Spectrum white = Spectrum::Constant(360.0, 5.0, 95, 1.0);
        CHECK(SurfaceXyz(white, s, Observer::CIE1931_2DEG).y() == Approx(100.0));
        CHECK(SurfaceXyz(white, s, Observer::CIE1964_10DEG).y() == Approx(100.0));
        CHECK((SurfaceXyz(white, s, Observer::CIE1931_2DEG) -
               IlluminantWhiteXyz(s, Observer::CIE1931_2DEG))
                  .norm() < 1e-10);
    }
}

TEST_CASE("The precomputed integrator agrees with the reference path", "[spectral]")
{
    const Spectrum f11 = BuiltinIlluminant("F11");
    const XyzIntegrator fast(f11, Observer::CIE1931_2DEG);
    for (const NamedSpectrum& tcs : TestColourSamples())
    {
        const Vec3 ref = SurfaceXyz(tcs.spectrum, f11, Observer::CIE1931_2DEG);
        CHECK((fast(tcs.spectrum) - ref).norm() < 1e-10);
    }
}

TEST_CASE("Equal-energy normalisation maps E to (1, 1, 1)", "[spectral]")
{
    const Spectrum e = Spectrum::Constant(380.0, 5.0, 81, 1.0);
    const Vec3 v = EqualEnergyNormalisedXyz(e, Observer::CIE1931_2DEG);
    CHECK(v.x() == Approx(1.0));
    CHECK(v.y() == Approx(1.0));
    CHECK(v.z() == Approx(1.0));
    const Vec3 half = EqualEnergyNormalisedXyz(e * 0.5, Observer::CIE1964_10DEG);
    CHECK(half.y() == Approx(0.5));
}

TEST_CASE("A light on any regular grid is integrated through its linear interpolant",
          "[spectral][coarse]")
{
    // A flat light gives E's chromaticity (1/3, 1/3) on every grid from 1 to
    // 100 nm: summed at its own samples, five rows 100 nm apart gave
    // (0.3647, 0.3529).
    for (const double step : {1.0, 2.0, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0})
    {
        INFO(step);
        const size_t count = size_t(400.0 / step) + 1;
        const Vec3 xyY = XyzToxyY(IntegrateXyz(Spectrum::Constant(380.0, step, count, 1.0),
                                               Observer::CIE1931_2DEG));
        CHECK(std::abs(xyY.x() - 1.0 / 3.0) < 0.0005);
        CHECK(std::abs(xyY.y() - 1.0 / 3.0) < 0.0005);
    }
    // D65 on 10 nm: the CIE's 5 nm D65 is the linear interpolant of its
    // 10 nm table (CIE 15:2004 §3.1), so its 10 nm samples give the same
    // white to rounding.
    const Spectrum d65 = BuiltinIlluminant("D65");
    const Vec3 full = XyzToxyY(IntegrateXyz(d65, Observer::CIE1931_2DEG));
    std::vector<double> every10;
    for (double l = d65.start(); l <= d65.end() + 1e-9; l += 10.0)
    {
        every10.push_back(d65(l));
    }
    const Vec3 coarse =
        XyzToxyY(IntegrateXyz(Spectrum(d65.start(), 10.0, every10), Observer::CIE1931_2DEG));
    CHECK(std::abs(coarse.x() - full.x()) < 1e-4);
    CHECK(std::abs(coarse.y() - full.y()) < 1e-4);
}

TEST_CASE("A light of fewer than five samples is refused, not integrated", "[spectral][coarse]")
{
    CHECK_THROWS_WITH(UsableIlluminant(Spectrum(380.0, 400.0, {1.0, 1.0}), "two.csv"),
                      Catch::Matchers::Contains("two.csv: an illuminant of 2 samples"));
    // Five rows 100 nm apart are enough (and integrate to E, above).
    CHECK(UsableIlluminant(Spectrum::Constant(380.0, 100.0, 5, 1.0), "five.csv").size() == 5);
    // Samples 5580 nm apart (a fuzzed file: 5, 5585 and 59560 nm) are many
    // rows and no light: none of them falls where the eye sees.
    CHECK_THROWS_WITH(UsableIlluminant(Spectrum(5.0, 5580.0, {0.0, 6.0, 0.0, 0.0, 0.0, 0.0}),
                                       "wide.csv"),
                      Catch::Contains("wide.csv") && Catch::Contains("every 5580 nm"));
}

TEST_CASE("Surfaces under a coarse light are integrated on the tables' grid, as its white is",
          "[spectral][coarse]")
{
    // The fast path (XyzIntegrator) must weigh a light given every 100 nm as
    // IntegrateXyz does: through its linear interpolant on the 5 nm grid.
    // Summed at its own samples the white would be wrong (equal energy at
    // x 0.365), and a light wider apart than the visible range has no sample
    // where the eye sees at all.
    const Spectrum coarse = Spectrum::Constant(380.0, 100.0, 5, 1.0);
    const XyzIntegrator integrate(coarse, Observer::CIE1931_2DEG);
    CHECK(integrate.grid().step() == Approx(5.0));
    const Vec3 white = integrate(Spectrum::Constant(380.0, 5.0, 81, 1.0));
    const Vec3 expected = IlluminantWhiteXyz(coarse, Observer::CIE1931_2DEG);
    CHECK(white.x() == Approx(expected.x()).epsilon(1e-12));
    CHECK(white.y() == Approx(100.0).epsilon(1e-12));
    CHECK(white.z() == Approx(expected.z()).epsilon(1e-12));
    // Equal energy over 380-780 nm is linear between its samples: the white
    // is that of equal energy on the 5 nm grid.
    const Vec3 flat = IlluminantWhiteXyz(Spectrum::Constant(380.0, 5.0, 81, 1.0),
                                         Observer::CIE1931_2DEG);
    CHECK(white.x() == Approx(flat.x()).epsilon(1e-9));
    CHECK(white.z() == Approx(flat.z()).epsilon(1e-9));
    // A surface on any grid agrees with SurfaceXyz under the same light.
    const Spectrum ramp(400.0, 10.0, std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7,
                                                          0.8, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4,
                                                          0.3, 0.2, 0.1, 0.2, 0.3, 0.4, 0.5,
                                                          0.6, 0.7, 0.8, 0.9, 0.8, 0.7, 0.6,
                                                          0.5, 0.4, 0.3});
    const Vec3 fast = integrate(ramp);
    const Vec3 exact = SurfaceXyz(ramp, coarse, Observer::CIE1931_2DEG);
    CHECK((fast - exact).norm() < 1e-9 * exact.norm());
}
