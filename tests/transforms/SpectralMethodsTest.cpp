// SPDX-License-Identifier: BSD-3-Clause
// Covers, through the entry points it calls: transforms/Upsampler.cpp,
// transforms/methods/Upsample.cpp.
#include <catch2/catch.hpp>

#include "transforms/LitMethod.h"

#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/IlluminantChange.h"
#include "transforms/SpectralMethods.h"
#include "transforms/Upsampler.h"

using namespace bandlight;
using Catch::Matchers::Contains;

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

Vec3 Lab(const SurfaceRenderer& r, const Vec3& rgb)
{
    return XyzToLab(r.rgbToXyz() * rgb, r.rgbToXyz() * r.white());
}
}  // namespace

TEST_CASE("fit3x3, prefilter and metamer map S1's white to S2's", "[transforms][methods]")
{
    for (const auto& [from, to] :
         {std::pair{"A", "D65"}, std::pair{"F11", "D65"}, std::pair{"F2", "A"}})
    {
        const SurfaceRenderer r1(BuiltinIlluminant(from), Working());
        const SurfaceRenderer r2(BuiltinIlluminant(to), Working());
        for (const char* method : {"fit3x3", "prefilter", "metamer"})
        {
            INFO(method << " " << from << " → " << to);
            const Mat3 m =
                IlluminantChangeMatrix(L(from), L(to), test::LitMethod(method), Working());
            CHECK((m * r1.white() - r2.white()).norm() < 1e-6);
        }
    }
}

TEST_CASE("fit3x3 beats Bradford on the colours it was fitted on", "[transforms][methods]")
{
    const SurfaceRenderer r1(BuiltinIlluminant("F11"), Working());
    const SurfaceRenderer r2(BuiltinIlluminant("D65"), Working());
    const Mat3 fit =
        IlluminantChangeMatrix(L("F11"), L("D65"), test::LitMethod("fit3x3"), Working());
    const Mat3 brad =
        IlluminantChangeMatrix(L("F11"), L("D65"), test::LitMethod("bradford"), Working());
    double eFit = 0.0, eBrad = 0.0;
    for (const NamedSpectrum& s : TrainingSet().samples)
    {
        const Vec3 c1 = r1.render(s.spectrum), c2 = r2.render(s.spectrum);
        eFit += (fit * c1 - c2).squaredNorm();
        eBrad += (brad * c1 - c2).squaredNorm();
    }
    CHECK(eFit < eBrad);
    CHECK_THROWS_WITH(FitMatrix(r1, r2, {TestColourSamples()[0]}), Contains("at least three"));
}

TEST_CASE("metamer reproduces the input under S1 exactly, with a smooth remittance",
          "[transforms][methods]")
{
    const SurfaceRenderer r1(BuiltinIlluminant("A"), Working());
    for (const Vec3& c : {Vec3(0.2, 0.3, 0.1), Vec3(0.05, 0.02, 0.4), Vec3(1.0, 1.0, 1.0)})
    {
        const SurfaceRenderer::Samples r = SmoothestMetamer(r1, c);
        CHECK((r1.render(r) - c).norm() < 1e-9 * c.norm());
    }
    // The white's smoothest metamer is the flat remittance 1.
    const SurfaceRenderer::Samples w = SmoothestMetamer(r1, r1.white());
    CHECK((w.array() - 1.0).abs().maxCoeff() < 1e-6);
}

TEST_CASE("upsample: remittances in [0, 1], RGB round trip within 0.02 ΔE76 in gamut",
          "[transforms][methods]")
{
    for (const char* ill : {"D65", "A", "F11"})
    {
        const SurfaceRenderer r(BuiltinIlluminant(ill), Working());
        const Upsampler up(r);
        for (const NamedSpectrum& s : TestColourSamples())
        {
            // A real surface's colour is inside the reflectance gamut.
            const Vec3 c = r.render(s.spectrum);
            const Upsampler::Fit f = up.fit(c / up.gamutScale(c));
            const SurfaceRenderer::Samples rem = Upsampler::Remittance(f.coeffs);
            INFO(ill << " " << s.name << ": residual " << f.residual << " after " << f.iterations);
            CHECK(rem.minCoeff() >= 0.0);
            CHECK(rem.maxCoeff() <= 1.0);
            CHECK(DeltaE76(Lab(r, r.render(rem) * up.gamutScale(c)), Lab(r, c)) < 0.02);
        }
    }
}

TEST_CASE("upsample keeps white, scales HDR and never makes NaN", "[transforms][methods]")
{
    const Relighter relight(L("A"), L("D65"), test::LitMethod("upsample"), Working());
    CHECK_FALSE(relight.isLinear());
    const SurfaceRenderer r1(BuiltinIlluminant("A"), Working());
    const SurfaceRenderer r2(BuiltinIlluminant("D65"), Working());
    CHECK((relight.apply(r1.white()) - r2.white()).norm() < 1e-5);
    // Scale, not clip: above the white, 100× the light gives 100× the result.
    const Vec3 c(2.0, 1.5, 0.5);
    CHECK((relight.apply(c * 100.0) - relight.apply(c) * 100.0).norm() <
          1e-6 * relight.apply(c * 100.0).norm());
    for (const Vec3& odd : {Vec3(0, 0, 0), Vec3(-0.01, 0.2, 0.1), Vec3(-1, -1, -1),
                            Vec3(1e-6, 0, 0), Vec3(5.0, 0.0, 0.0)})
    {
        CHECK(relight.apply(odd).allFinite());
    }
}

TEST_CASE("upsample fits a chromaticity once per source light, whoever asks",
          "[transforms][methods]")
{
    // Colours at several exposures, in and out of gamut.
    const int n = 4000;
    std::vector<float> pixels;
    for (int i = 0; i < n; ++i)
    {
        const float k = std::ldexp(1.0f, i % 9 - 6);
        pixels.insert(pixels.end(), {k * float(1 + i % 7) / 7.0f, k * float(1 + i % 11) / 11.0f,
                                     k * float(1 + i % 13) / 13.0f});
    }
    const SurfaceRenderer underA(BuiltinIlluminant("A"), Working());
    std::vector<float> one = pixels;
    {
        const Relighter toD65(L("A"), L("D65"), ParseMethod("upsample"), Working());
        const std::shared_ptr<UpsampleFits> fits = UpsampleFits::ForSource(underA);
        CHECK(fits->size() == 0);
        toD65.apply(one.data(), size_t(n), 1);
        const size_t fitted = fits->size();
        CHECK(fitted > 100);
        CHECK(fitted < size_t(n) / 4);  // the exposures of one colour share a fit
        // On two threads, through the filled store: bit for bit the same.
        std::vector<float> two = pixels;
        toD65.apply(two.data(), size_t(n), 2);
        CHECK(one == two);
        // Another target from A fits nothing new; another source has its own.
        const Relighter toF2(L("A"), L("F2"), ParseMethod("upsample"), Working());
        std::vector<float> f2 = pixels;
        toF2.apply(f2.data(), size_t(n), 1);
        CHECK(fits->size() == fitted);
        const Relighter fromD65(L("D65"), L("A"), ParseMethod("upsample"), Working());
        CHECK(UpsampleFits::ForSource(SurfaceRenderer(BuiltinIlluminant("D65"), Working())) !=
              fits);
    }
    // With every user gone the store is freed; a new one fitted in the
    // reverse order gives the same pixels.
    const Relighter again(L("A"), L("D65"), ParseMethod("upsample"), Working());
    CHECK(UpsampleFits::ForSource(underA)->size() == 0);
    std::vector<float> reversed;
    for (int i = n - 1; i >= 0; --i)
    {
        reversed.insert(reversed.end(), pixels.begin() + 3 * i, pixels.begin() + 3 * i + 3);
    }
    again.apply(reversed.data(), size_t(n), 1);
    for (int i = 0; i < n; ++i)
    {
        for (int c = 0; c < 3; ++c)
        {
            CHECK(reversed[size_t(3 * (n - 1 - i) + c)] == one[size_t(3 * i + c)]);
        }
    }
}

TEST_CASE("spectral is the reference, not an image transform", "[transforms][methods]")
{
    CHECK_THROWS_WITH(Relighter(L("A"), L("D65"), test::LitMethod("spectral"), Working()),
                      Contains("needs the spectra of the surfaces"));
    CHECK_THROWS_WITH(
        IlluminantChangeMatrix(L("A"), L("D65"), test::LitMethod("upsample"), Working()),
        Contains("is not one 3x3"));
    CHECK(AllMethodNames().size() == 15);
}
