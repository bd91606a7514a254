// SPDX-License-Identifier: BSD-3-Clause
// Covers, through the entry points it calls: transforms/methods/RootPoly.cpp.
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "spectral/Illuminants.h"
#include "transforms/IlluminantChange.h"
#include "transforms/RootPolynomial.h"

using namespace bandlight;

namespace
{
Light L(const char* name)
{
    return {name, BuiltinIlluminant(name)};
}

/// Mean CIEDE2000 of a map over remittances, against their colour under `to`.
template <typename Map>
double MeanDe(const SurfaceRenderer& from, const SurfaceRenderer& to,
              const std::vector<NamedSpectrum>& set, Map&& map)
{
    const Vec3 white = to.rgbToXyz() * to.white();
    double sum = 0.0;
    for (const NamedSpectrum& s : set)
    {
        const auto r = SurfaceRenderer::Sample(s.spectrum);
        sum += DeltaE2000(XyzToLab(to.rgbToXyz() * map(from.render(r)), white),
                          XyzToLab(to.rgbToXyz() * to.render(r), white));
    }
    return sum / double(set.size());
}
}  // namespace

TEST_CASE("Root polynomial: homogeneous of degree 1, so exposure invariant", "[transforms]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    for (const char* method : {"rootpoly", "rootpoly3"})
    {
        const Relighter r(L("F11"), L("D65"), ParseMethod(method), ws);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.001, 1.0);
        for (int i = 0; i < 50; ++i)
        {
            const Vec3 c(u(rng), u(rng), u(rng));
            const Vec3 base = r.apply(c);
            for (double k : {1.0 / 256, 1.0 / 16, 0.5, 4.0, 16.0, 1000.0})
            {
                INFO(method << " k " << k);
                CHECK((r.apply(k * c) / k - base).norm() <= 1e-12 * base.norm());
            }
        }
    }
}

TEST_CASE("Root polynomial: the white maps exactly to the white", "[transforms]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    for (const char* from : {"A", "F2", "F11"})
    {
        const SurfaceRenderer r1(BuiltinIlluminant(from), ws);
        const SurfaceRenderer r2(BuiltinIlluminant("D65"), ws);
        for (int degree : {2, 3})
        {
            const RootPolynomial rp = FitRootPolynomial(r1, r2, RootPolynomialTraining(), degree);
            CHECK((rp.apply(r1.white()) - r2.white()).cwiseAbs().maxCoeff() < 1e-9);
        }
    }
}

TEST_CASE("Root polynomial: the fast float path equals the scalar reference", "[transforms]")
{
    const Relighter r(L("A"), L("D65"), ParseMethod("rootpoly"), FindRgbSpace("acescg"));
    std::vector<float> px;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-0.05f, 4.0f);
    for (int i = 0; i < 3 * 1003; ++i)  // not a multiple of the 8-pixel block
    {
        px.push_back(u(rng));
    }
    std::vector<float> fast = px;
    r.apply(fast.data(), fast.size() / 3, 1);
    for (size_t i = 0; i < px.size() / 3; ++i)
    {
        const Vec3 e = r.apply(Vec3(px[3 * i], px[3 * i + 1], px[3 * i + 2]));
        for (int c = 0; c < 3; ++c)
        {
            CHECK(fast[3 * i + size_t(c)] == Approx(e[c]).epsilon(1e-5).margin(1e-6));
        }
    }
    // Hard pixels: finite out.
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> hard = {std::nanf(""), 0.2f, 0.2f, inf, inf, inf, -inf, 1.0f, 0.0f};
    r.apply(hard.data(), 3, 1);
    for (float v : hard)
    {
        CHECK(std::isfinite(v));
    }
}

TEST_CASE("Root polynomial: nested models fit at least as well in sample", "[transforms]")
{
    // The degree-2 terms contain R, G, B: fitted in CIELAB on one set, it
    // cannot do worse on that set than the 3x3 fitted the same way; degree 3
    // contains degree 2. Published behaviour (Finlayson et al. 2015, Table 2:
    // root-polynomial error falls with degree on training data).
    const RgbSpace& ws = FindRgbSpace("acescg");
    const SurfaceRenderer r1(BuiltinIlluminant("F2"), ws);
    const SurfaceRenderer r2(BuiltinIlluminant("D65"), ws);
    const auto& set = RootPolynomialTraining();
    const Mat3 m = FitLabMatrix(r1, r2, set);
    const RootPolynomial p2 = FitRootPolynomial(r1, r2, set, 2);
    const RootPolynomial p3 = FitRootPolynomial(r1, r2, set, 3);
    const double e1 = MeanDe(r1, r2, set, [&](const Vec3& c) { return Vec3(m * c); });
    const double e2 = MeanDe(r1, r2, set, [&](const Vec3& c) { return p2.apply(c); });
    const double e3 = MeanDe(r1, r2, set, [&](const Vec3& c) { return p3.apply(c); });
    INFO("3x3 " << e1 << ", degree 2 " << e2 << ", degree 3 " << e3);
    CHECK(e2 < e1);
    CHECK(e3 < e2 * 1.02);
    // And the bundled training data are the 190 rawtoaces patches plus TCS01-15.
    CHECK(set.size() == 205);
    CHECK(Rawtoaces190().front().name == "patch1");
}

TEST_CASE("Every method is exposure invariant in its ideal form", "[transforms]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    const std::vector<Vec3> colours = {Vec3(0.18, 0.18, 0.18), Vec3(0.5, 0.2, 0.05),
                                       Vec3(0.05, 0.3, 0.6), Vec3(0.02, 0.01, 0.015)};
    for (const std::string& name : AllMethodNames())
    {
        const Relighter r(L("F11"), L("D65"), ParseMethod(name), ws);
        for (const Vec3& c : colours)
        {
            const Vec3 base = r.apply(c);
            for (double k : {1.0 / 256, 1.0 / 16, 4.0, 16.0})
            {
                INFO(name << " k " << k);
                // Linear methods and rootpoly exactly; upsample to its fit's
                // convergence (every pixel is fitted at one level).
                CHECK((r.apply(k * c) / k - base).norm() <= 1e-6 * base.norm());
            }
        }
    }
}
