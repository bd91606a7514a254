// SPDX-License-Identifier: BSD-3-Clause
// The SIMD pixel kernels against their scalar references: bit for bit, on
// every target this CPU runs (AVX-512, AVX2, SSE4, ... down to the portable
// one), so every machine writes the same image; on RGB and RGBA, with NaN,
// Inf, signed zeros and HDR values, at every buffer length around the vector
// width; and against the double-precision forms.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <hwy/targets.h>
#include <catch2/catch.hpp>

#include "spectral/Illuminants.h"
#include "transforms/IlluminantChange.h"
#include "transforms/LitMethod.h"
#include "transforms/PixelKernels.h"

using namespace bandlight;

namespace
{
std::vector<float> HardPixels(size_t count, size_t stride, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> stops(-12.0f, 12.0f);
    const float special[] = {std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::infinity(),
                             -std::numeric_limits<float>::infinity(),
                             0.0f,
                             -0.0f,
                             1e30f,
                             -1e30f,
                             std::numeric_limits<float>::denorm_min(),
                             -0.18f};
    std::vector<float> px(count * stride);
    for (size_t i = 0; i < px.size(); ++i)
    {
        px[i] = (rng() % 7 == 0) ? special[rng() % 9] : std::exp2(stops(rng));
    }
    return px;
}

bool SameBits(const std::vector<float>& a, const std::vector<float>& b)
{
    // (memcmp takes no null pointer, which an empty vector's data() may be.)
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

Light L(const char* n)
{
    return {n, BuiltinIlluminant(n)};
}

/// Runs `f` once on each target Highway compiled the kernels for and this
/// CPU supports, then returns dispatch to the best.
template <class F>
void OnEveryTarget(F&& f)
{
    const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
    REQUIRE(!targets.empty());
    struct Restore
    {
        ~Restore() { hwy::SetSupportedTargetsForTest(0); }
    } restore;
    for (const int64_t target : targets)
    {
        hwy::SetSupportedTargetsForTest(target);
        const std::string name = PixelKernelTarget();
        INFO("kernel target " << name);
        REQUIRE(name == hwy::TargetName(target));
        f();
    }
}
}  // namespace

TEST_CASE("The guarded 3x3 kernel equals its scalar reference bit for bit", "[transforms][simd]")
{
    OnEveryTarget(
        []
        {
            const Matrix3f m{{0.9f, 0.2f, -0.1f, 0.05f, 1.1f, -0.15f, -0.02f, 0.1f, 1.3f}};
            for (const size_t stride : {3u, 4u, 5u})
            {
                for (size_t count = 0; count < 70; count += 1)
                {
                    std::vector<float> simd =
                        HardPixels(count, stride, unsigned(count + 7 * stride));
                    std::vector<float> ref = simd;
                    GuardedMatrix(m, simd.data(), count, stride);
                    GuardedMatrixReference(m, ref.data(), count, stride);
                    INFO("stride " << stride << ", " << count << " pixels");
                    REQUIRE(SameBits(simd, ref));
                    for (size_t i = 0; i < count; ++i)
                    {
                        for (size_t c = 0; c < 3; ++c)
                        {
                            REQUIRE(std::isfinite(simd[i * stride + c]));
                        }
                    }
                }
            }
            // Alpha and other channels pass through untouched.
            std::vector<float> rgba = {1.0f, 2.0f, 3.0f, 0.25f};
            GuardedMatrix(m, rgba.data(), 1, 4);
            CHECK(rgba[3] == 0.25f);
        });
}

TEST_CASE("The root polynomial kernels equal their scalar references bit for bit",
          "[transforms][simd]")
{
    OnEveryTarget(
        []
        {
            const RgbSpace& ws = FindRgbSpace("acescg");
            for (const char* method : {"rootpoly", "rootpoly3"})
            {
                for (const bool balanced : {false, true})
                {
                    MethodSpec spec = test::LitMethod(method);
                    spec.plates.convention =
                        balanced ? PlateConvention::BALANCED : PlateConvention::LIT;
                    const Relighter r(L("F11"), L("D65"), spec, ws);
                    RootPolyKernelData k;
                    k.degree = r.rootPolynomial()->degree();
                    std::memcpy(k.coefficients, r.rootPolynomial()->floats(),
                                sizeof k.coefficients);
                    if (const Mat3* pre = r.inputMatrix())
                    {
                        k.hasInput = true;
                        for (int i = 0; i < 9; ++i)
                        {
                            k.input.m[i] = float((*pre)(i / 3, i % 3));
                        }
                    }
                    for (const size_t stride : {3u, 4u})
                    {
                        for (const size_t count : {0u, 1u, 7u, 8u, 9u, 16u, 17u, 33u, 1000u})
                        {
                            std::vector<float> simd =
                                HardPixels(count, stride, unsigned(count + stride));
                            std::vector<float> ref = simd;
                            RootPolyPixels(k, simd.data(), count, stride);
                            RootPolyPixelsReference(k, ref.data(), count, stride);
                            INFO(method << (balanced ? " balanced" : " lit") << ", stride "
                                        << stride << ", " << count << " pixels");
                            REQUIRE(SameBits(simd, ref));
                            for (size_t i = 0; i < count; ++i)
                            {
                                for (size_t c = 0; c < 3; ++c)
                                {
                                    REQUIRE(std::isfinite(simd[i * stride + c]));
                                }
                            }
                        }
                    }
                }
            }
        });
}

TEST_CASE("The float kernels agree with the double-precision forms", "[transforms][simd]")
{
    // Stated bound: 4e-6 of the pixel's largest channel (about 32 float ulp:
    // 6 or 13 terms of either sign summed in float; degree 3's cube roots
    // are within 2 ulp). Measured: 3x3 and degree 2 below 1e-6, degree 3 2.1e-6.
    const RgbSpace& ws = FindRgbSpace("acescg");
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-8.0, 6.0);
    for (const char* method : {"bradford", "band3", "rootpoly", "rootpoly3"})
    {
        const Relighter r(L("A"), L("D65"), ParseMethod(method), ws);
        std::vector<float> px(3 * 4096);
        for (float& v : px)
        {
            v = float(std::exp2(u(rng)));
        }
        std::vector<float> fast = px;
        r.apply(fast.data(), px.size() / 3, 1);
        double worst = 0.0;
        for (size_t i = 0; i < px.size(); i += 3)
        {
            const Vec3 exact = r.apply(Vec3(px[i], px[i + 1], px[i + 2]));
            const double scale = std::max(exact.cwiseAbs().maxCoeff(), 1e-30);
            for (int c = 0; c < 3; ++c)
            {
                worst = std::max(worst, std::abs(fast[i + size_t(c)] - exact[c]) / scale);
            }
        }
        INFO(method << ": worst relative difference " << worst);
        CHECK(worst < 4e-6);
    }
}

TEST_CASE("cube roots in float are within 2 ulp of std::cbrt", "[transforms][simd]")
{
    RootPolyKernelData k;
    k.degree = 3;
    k.coefficients[0][6] = 1.0f;  // out R = cbrt(r) · cbrt(g)² with g = 1: cbrt(r)
    for (float x = 1e-30f; x < 1e16f; x *= 1.37f)  // the guard bounds pixels at 1e16
    {
        float p[3] = {x, 1.0f, 1.0f};
        RootPolyPixelsReference(k, p, 1, 3);
        const float want = std::cbrt(x);
        CHECK(std::abs(p[0] - want) <= 2.0f * (std::nextafter(want, 1e38f) - want));
    }
}

TEST_CASE("The spectral dot product equals its reference bit for bit, within the stated bound",
          "[transforms][simd]")
{
    // Bit for bit on every target: an image integrated on an AVX-512 machine
    // is the one an AVX2 machine writes. |result − exact| ≤ 2·n·2⁻²⁴·Σ|w·v|
    // (PixelKernels.h).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const size_t n : {1u, 2u, 7u, 15u, 16u, 17u, 31u, 32u, 33u, 48u, 63u, 64u, 81u, 100u, 120u, 143u, 144u, 471u, 1100u})
    {
        const size_t stride = n + 4;  // R, G, B, A beside the spectrum
        const size_t count = 37;
        std::vector<float> w(3 * n);
        for (float& x : w)
        {
            x = u(rng) - 0.3f;
        }
        std::vector<float> px(count * stride);
        for (float& x : px)
        {
            x = std::exp2(24.0f * u(rng) - 12.0f);
        }
        std::vector<float> ref(3 * count);
        SpectralDotReference(w.data(), n, px.data() + 4, count, stride, ref.data(), 3);
        OnEveryTarget(
            [&]
            {
                INFO(n << " samples");
                std::vector<float> fast(3 * count);
                SpectralDot(w.data(), n, px.data() + 4, count, stride, fast.data(), 3);
                REQUIRE(SameBits(fast, ref));
            });
        for (size_t p = 0; p < count; ++p)
        {
            for (size_t c = 0; c < 3; ++c)
            {
                double bound = 0.0, exact = 0.0;
                for (size_t j = 0; j < n; ++j)
                {
                    const double t = double(w[c * n + j]) * double(px[p * stride + 4 + j]);
                    bound += std::abs(t);
                    exact += t;
                }
                bound *= 2.0 * double(n) * std::ldexp(1.0, -24);
                CHECK(std::abs(double(ref[3 * p + c]) - exact) <= bound);
            }
        }
    }
    // The order is the documented one: 16 partial sums folded in halves.
    // With 1 at j = 0 and 2⁻²⁴ at j = 1 and 9, a sequential sum rounds each
    // 2⁻²⁴ away (1 + 2⁻²⁴ ties to 1); the fold adds them first, in partial
    // 1, and 1 + 2⁻²³ is exact.
    {
        std::vector<float> w(3 * 16, 1.0f), v(16, 0.0f), ref(3);
        v[0] = 1.0f;
        v[1] = v[9] = std::ldexp(1.0f, -24);
        SpectralDotReference(w.data(), 16, v.data(), 1, 16, ref.data(), 3);
        CHECK(ref[0] == 1.0f + std::ldexp(1.0f, -23));
        OnEveryTarget(
            [&]
            {
                std::vector<float> out(3);
                SpectralDot(w.data(), 16, v.data(), 1, 16, out.data(), 3);
                REQUIRE(SameBits(out, ref));
            });
    }
    // What follows a spectrum (the next pixel's R, G, B, A) never reaches its
    // sums, NaN included; the buffer ends where the last spectrum does, so
    // the sanitised suite sees any read past it.
    for (const size_t n : {5u, 17u, 81u})
    {
        const size_t stride = n + 4, count = 9;
        std::vector<float> w(3 * n, 0.25f);
        std::vector<float> px((count - 1) * stride + n, std::nanf(""));
        for (size_t p = 0; p < count; ++p)
        {
            std::fill_n(px.begin() + long(p * stride), n, float(p + 1));
        }
        std::vector<float> out(3 * count);
        SpectralDot(w.data(), n, px.data(), count, stride, out.data(), 3);
        for (size_t p = 0; p < count; ++p)
        {
            CHECK(out[3 * p + 2] == Approx(0.25 * double(n) * double(p + 1)).epsilon(1e-6));
        }
    }
    // NaN and Inf in the spectrum propagate.
    std::vector<float> w(3 * 20, 0.5f), px(20, 1.0f), out(3);
    px[13] = std::numeric_limits<float>::quiet_NaN();
    SpectralDot(w.data(), 20, px.data(), 1, 20, out.data(), 3);
    CHECK(std::isnan(out[0]));
    px[13] = std::numeric_limits<float>::infinity();
    SpectralDot(w.data(), 20, px.data(), 1, 20, out.data(), 3);
    CHECK(std::isinf(out[1]));
}
