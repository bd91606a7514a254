// SPDX-License-Identifier: BSD-3-Clause
// hueplane (transforms/methods/HuePlane.cpp): the properties Andersen &
// Hardeberg 2005 build it to have — white exact, exposure invariant,
// continuous, each hue plane kept a plane — checked on the op itself, and
// its accuracy against the spectral answer on colours it was not fitted on.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "spectral/Colorimetry.h"
#include "spectral/Illuminants.h"
#include "transforms/IlluminantChange.h"
#include "transforms/LitMethod.h"
#include "transforms/SurfaceRenderer.h"

using namespace bandlight;

namespace
{
Light L(const char* name)
{
    return {name, BuiltinIlluminant(name)};
}
const RgbSpace& Working()
{
    return FindRgbSpace("acescg");
}

/// Mean ΔE00 of a relighter on `set` against the spectral answer (lit plates).
double MeanError(const Relighter& r, const char* from, const char* to,
                 const std::vector<NamedSpectrum>& set)
{
    const SurfaceRenderer r1(BuiltinIlluminant(from), Working());
    const SurfaceRenderer r2(BuiltinIlluminant(to), Working());
    const Vec3 white = r2.rgbToXyz() * r2.white();
    double sum = 0.0;
    for (const NamedSpectrum& s : set)
    {
        const Vec3 out = r.apply(r1.render(s.spectrum));
        sum += DeltaE2000(XyzToLab(r2.rgbToXyz() * out, white),
                          XyzToLab(r2.rgbToXyz() * r2.render(s.spectrum), white));
    }
    return sum / double(set.size());
}
}  // namespace

TEST_CASE("hueplane maps white exactly and is exposure invariant", "[transforms][methods]")
{
    for (const auto& [from, to] : {std::pair{"A", "D65"}, {"F11", "D50"}, {"D65", "F2"}})
    {
        INFO(from << " -> " << to);
        const Relighter lit(L(from), L(to), test::LitMethod("hueplane"), Working());
        const SurfaceRenderer r1(BuiltinIlluminant(from), Working());
        const SurfaceRenderer r2(BuiltinIlluminant(to), Working());
        CHECK((lit.apply(r1.white()) - r2.white()).norm() < 1e-12);
        // Balanced plates: white stays white.
        const Relighter balanced(L(from), L(to), ParseMethod("hueplane"), Working());
        CHECK((balanced.apply(Vec3::Ones()) - Vec3::Ones()).norm() < 1e-12);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.01, 1.0);
        for (int i = 0; i < 200; ++i)
        {
            const Vec3 x(u(rng), u(rng), u(rng));
            const Vec3 y = lit.apply(x);
            for (double k : {1.0 / 256, 1.0 / 16, 3.0, 16.0})
            {
                CHECK((lit.apply(k * x) - k * y).norm() <= 1e-12 * k * y.norm());
            }
        }
    }
}

TEST_CASE("hueplane is continuous and keeps each hue plane a plane", "[transforms][methods]")
{
    const Relighter r(L("A"), L("D65"), test::LitMethod("hueplane"), Working());
    const SurfaceRenderer r1(BuiltinIlluminant("A"), Working());
    const Vec3 w = r1.white();
    const Vec3 n = w.normalized();
    const Vec3 a = (Vec3::UnitX() - n.x() * n).normalized();
    const Vec3 b = n.cross(a);
    // Round the neutral axis in 0.01° steps: no jump between neighbours
    // larger than the map's largest gain allows (a discontinuity at a plane
    // would be a jump of the size of the colour).
    double worst = 0.0;
    Vec3 previous = r.apply(w + 0.3 * a);
    for (int step = 1; step <= 36000; ++step)
    {
        const double t = step * 2.0 * 3.14159265358979323846 / 36000.0;
        const Vec3 x = w + 0.3 * (std::cos(t) * a + std::sin(t) * b);
        const Vec3 y = r.apply(x);
        worst = std::max(worst, (y - previous).norm());
        previous = y;
    }
    CHECK(worst < 1e-3);
    // Colours of one hue plane (a·w + c·d, c > 0) stay on one plane through
    // black and the target white.
    for (double t : {0.1, 1.3, 2.9, 4.4, 5.8})
    {
        const Vec3 d = std::cos(t) * a + std::sin(t) * b;
        Mat3 m;
        m.col(0) = r.apply(w);
        m.col(1) = r.apply(0.5 * w + 0.2 * d);
        m.col(2) = r.apply(1.5 * w + 0.05 * d);
        CHECK(std::abs(m.determinant()) < 1e-12);
    }
}

TEST_CASE("hueplane beats Bradford on smooth colours it was not fitted on", "[transforms][methods]")
{
    // 100 smooth random remittances (not in its 205 training remittances).
    const std::vector<NamedSpectrum> held = RandomSmoothSet(100, 2, "random").samples;
    for (const auto& [from, to] : {std::pair{"A", "D65"}, {"F11", "D65"}, {"F2", "D65"}})
    {
        INFO(from << " -> " << to);
        const double hueplane = MeanError(
            Relighter(L(from), L(to), test::LitMethod("hueplane"), Working()), from, to, held);
        const double bradford = MeanError(
            Relighter(L(from), L(to), test::LitMethod("bradford"), Working()), from, to, held);
        CHECK(hueplane < bradford);
    }
}
