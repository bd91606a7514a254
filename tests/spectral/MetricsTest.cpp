// SPDX-License-Identifier: BSD-3-Clause
// The metric registry (spectral/Metrics.h) against published values.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/Metrics.h"

using namespace bandlight;

namespace
{
/// D65's white point, Y = 1 (CIE 15:2018).
const Vec3 kD65(0.95047, 1.0, 1.08883);
}  // namespace

TEST_CASE("Every metric has one key, a name, units and a definition", "[metrics]")
{
    std::set<std::string> keys;
    for (const MetricEntry& m : Metrics())
    {
        CHECK(keys.insert(m.key).second);
        CHECK(std::string(m.name).size() > 2);
        CHECK(std::string(m.units).size() > 2);
        CHECK(std::string(m.definition).size() > 40);
    }
    CHECK(keys == std::set<std::string>{"de00", "de76", "deitp", "rgbrel"});
    CHECK(std::string(Metrics().front().key) == "de00");  // the default, listed first
    CHECK_THROWS_AS(FindMetric("de2000"), ParameterError);
    CHECK_THROWS_WITH(FindMetric("de2000"), Catch::Contains("de00, de76, deitp, rgbrel"));
}

TEST_CASE("ΔE00 and ΔE76 of Sharma, Wu and Dalal's first pair", "[metrics]")
{
    // Sharma, Wu & Dalal (2005), "The CIEDE2000 color-difference formula",
    // Table 1, pair 1: ΔE00 = 2.0425. ΔE76 is the pair's Euclidean distance.
    MetricContext c;
    c.whiteXyz = kD65;
    const Vec3 a = LabToXyz(Vec3(50.0, 2.6772, -79.7751), kD65);
    const Vec3 b = LabToXyz(Vec3(50.0, 0.0, -82.7485), kD65);
    CHECK(FindMetric("de00").compute(a, b, c) == Approx(2.0425).margin(1e-4));
    CHECK(FindMetric("de76").compute(a, b, c) ==
          Approx(std::hypot(2.6772, 82.7485 - 79.7751)).margin(1e-9));
    // Through a working space's matrix: the same pair as RGB.
    MetricContext rgb = c;
    rgb.rgbToXyz << 0.4124, 0.3576, 0.1805, 0.2126, 0.7152, 0.0722, 0.0193, 0.1192, 0.9505;
    const Mat3 toRgb = rgb.rgbToXyz.inverse();
    CHECK(FindMetric("de00").compute(toRgb * a, toRgb * b, rgb) == Approx(2.0425).margin(1e-4));
}

TEST_CASE("ΔE ITP works on BT.2100 ICtCp of absolute light", "[metrics]")
{
    // A D65 grey has L = M = S in BT.2100's LMS, so Ct = Cp = 0 and I is the
    // PQ of its luminance: PQ(100 cd/m²) = 0.5081, PQ(10000) = 1 (SMPTE ST
    // 2084; BT.2100 Table 4's 10-bit code 520 for 100 cd/m²).
    const Vec3 white = XyzToICtCp(100.0 * kD65);
    CHECK(white[0] == Approx(0.50808).margin(5e-5));
    CHECK(std::abs(white[1]) < 1e-4);
    CHECK(std::abs(white[2]) < 1e-4);
    CHECK(XyzToICtCp(10000.0 * kD65)[0] == Approx(1.0).margin(1e-4));
    CHECK(std::round(1023.0 * white[0]) == 520.0);

    MetricContext c;
    c.whiteXyz = kD65;
    const MetricEntry& itp = FindMetric("deitp");
    CHECK(itp.compute(kD65, kD65, c) == 0.0);
    // Two greys differ in I alone: 720 |ΔI|.
    const double d = itp.compute(1.1 * kD65, kD65, c);
    CHECK(d == Approx(720.0 * (XyzToICtCp(110.0 * kD65)[0] - white[0])).epsilon(1e-9));
    // The white's luminance matters: the same relative step is a different
    // absolute one.
    MetricContext bright = c;
    bright.whiteLuminance = 1000.0;
    CHECK(itp.compute(1.1 * kD65, kD65, bright) != Approx(d).epsilon(1e-3));
}

TEST_CASE("RGB relative error", "[metrics]")
{
    const MetricContext c;
    const MetricEntry& rel = FindMetric("rgbrel");
    CHECK(rel.compute(Vec3(1.1, 1.0, 1.0), Vec3::Ones(), c) == Approx(0.1 / std::sqrt(3.0)));
    CHECK(rel.compute(Vec3::Zero(), Vec3::Zero(), c) == 0.0);
    const std::vector<double> v =
        MetricValues(rel, {Vec3(2, 2, 2), Vec3(1, 1, 1)}, {Vec3(1, 1, 1), Vec3(1, 1, 1)}, c);
    REQUIRE(v.size() == 2);
    CHECK(v[0] == Approx(1.0));
    CHECK(v[1] == 0.0);
    CHECK_THROWS_AS(MetricValues(rel, {Vec3::Ones()}, {}, c), Exception);
}
