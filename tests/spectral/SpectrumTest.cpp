// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Spectrum.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("Spectrum interpolates linearly and is zero outside its range", "[spectral]")
{
    const Spectrum s(400.0, 10.0, {1.0, 3.0, 2.0});
    CHECK(s.end() == Approx(420.0));
    CHECK(s(400.0) == 1.0);
    CHECK(s(405.0) == Approx(2.0));
    CHECK(s(417.5) == Approx(2.25));
    CHECK(s(420.0) == 2.0);
    CHECK(s(399.0) == 0.0);
    CHECK(s(421.0) == 0.0);
}

TEST_CASE("Resampling keeps a linear spectrum exact", "[spectral]")
{
    std::vector<double> v;
    for (int i = 0; i <= 80; ++i)
    {
        v.push_back(0.5 + 0.01 * i);
    }
    const Spectrum s(380.0, 5.0, v);
    const Spectrum r = s.resampled(380.0, 1.0, 401);
    for (size_t i = 0; i < r.size(); ++i)
    {
        CHECK(r[i] == Approx(0.5 + 0.002 * double(i)).margin(1e-12));
    }
    // Back onto the coarse grid: the original samples.
    const Spectrum back = r.resampledLike(s);
    for (size_t i = 0; i < s.size(); ++i)
    {
        CHECK(back[i] == Approx(s[i]).margin(1e-12));
    }
}

TEST_CASE("Arithmetic on spectra of different grids resamples the right operand", "[spectral]")
{
    const Spectrum a = Spectrum::Constant(400.0, 10.0, 11, 2.0);
    const Spectrum b(400.0, 50.0, {1.0, 2.0, 3.0});
    const Spectrum p = a * b;
    REQUIRE(p.sameGrid(a));
    CHECK(p[0] == Approx(2.0));
    CHECK(p[5] == Approx(4.0));
    CHECK(p[10] == Approx(6.0));
    CHECK((a + b)[5] == Approx(4.0));
    CHECK((a - b)[10] == Approx(-1.0));
}

TEST_CASE("Exact integration of the piecewise-linear interpolant", "[spectral]")
{
    const Spectrum s(400.0, 10.0, {0.0, 10.0, 0.0});
    CHECK(s.integrateLinear(400.0, 420.0) == Approx(100.0));
    CHECK(s.integrateLinear(405.0, 410.0) == Approx(0.5 * (5.0 + 10.0) * 5.0));
    CHECK(s.integrateLinear(300.0, 405.0) == Approx(12.5));
    CHECK(s.integrateLinear(420.0, 500.0) == 0.0);
    CHECK(s.sum() == Approx(100.0));  // rectangle rule: (0 + 10 + 0) * 10
}

TEST_CASE("Edge extension holds the end values and keeps the samples", "[spectral]")
{
    const Spectrum s(400.0, 5.0, {0.2, 0.4, 0.6});
    const Spectrum e = s.extended(380.0, 420.0);
    CHECK(e.start() == Approx(380.0));
    CHECK(e.end() == Approx(420.0));
    CHECK(e(380.0) == Approx(0.2));
    CHECK(e(405.0) == Approx(0.4));
    CHECK(e(420.0) == Approx(0.6));
}

TEST_CASE("A spectrum needs a positive step and samples", "[spectral]")
{
    CHECK_THROWS_AS(Spectrum(400.0, 0.0, {1.0}), Exception);
    CHECK_THROWS_WITH(Spectrum(400.0, -5.0, {1.0}), Contains("step must be a positive"));
    CHECK_THROWS_WITH(Spectrum(400.0, 5.0, {}), Contains("no samples"));
}

TEST_CASE("Line spectra integrate exactly at any grid, never smeared or lost", "[spectral]")
{
    // Mercury lines as in fluorescent lamps, and a 632.8 nm He-Ne laser.
    const LineSpectrum lines({{404.66, 1.0}, {435.83, 2.0}, {546.07, 3.0}, {632.8, 0.5}});
    const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
    const double exactY =
        1.0 * cmf.y(404.66) + 2.0 * cmf.y(435.83) + 3.0 * cmf.y(546.07) + 0.5 * cmf.y(632.8);
    CHECK(IntegrateXyz(lines, Observer::CIE1931_2DEG).y() == Approx(exactY).epsilon(1e-12));

    for (double step : {1.0, 2.0, 5.0, 10.0})
    {
        const size_t n = size_t((830.0 - 360.0) / step) + 1;
        const Spectrum sampled = lines.sampled(360.0, step, n);
        // Total power is kept at every grid.
        CHECK(sampled.sum() == Approx(6.5).epsilon(1e-12));
        // Summing against the matching function's interpolant on the same grid
        // gives the exact line integral.
        const Spectrum ybar = cmf.y.resampled(360.0, step, n);
        double y = 0.0;
        for (size_t i = 0; i < n; ++i)
        {
            y += sampled[i] * ybar[i] * step;
        }
        const LineSpectrum onGrid(lines.lines());
        CHECK(y == Approx(onGrid.integrate(ybar)).epsilon(1e-12));
    }
    CHECK(lines.powerIn(400.0, 500.0) == Approx(3.0));
    CHECK(lines.powerIn(500.0, 600.0) == Approx(3.0));
    CHECK(lines.powerIn(600.0, 700.0) == Approx(0.5));
    CHECK_THROWS_AS(LineSpectrum({{std::nan(""), 1.0}}), Exception);
}
