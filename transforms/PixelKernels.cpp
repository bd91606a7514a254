// SPDX-License-Identifier: BSD-3-Clause
// The pixel kernels: SIMD forms compiled once per target by Highway's
// foreach_target, the best one chosen at run time; scalar references with
// the same operations in the same order.
#include "transforms/PixelKernels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "transforms/PixelKernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "transforms/IlluminantChange.h"

// ---------------------------------------------------------------------------
// The scalar maths, once (outside the per-target part): what every SIMD
// lane computes, operation for operation.
#ifndef BANDLIGHT_PIXEL_KERNELS_SCALAR
#define BANDLIGHT_PIXEL_KERNELS_SCALAR
namespace bandlight::kernel
{

constexpr float kGuard = float(PIXEL_GUARD);
constexpr float kThird = 1.0f / 3.0f;
/// The cube-root guess's offset: (127 − 127/3) · 2^23, the bias of the
/// float exponent divided by three (Kahan's bit trick).
constexpr int32_t kCbrtBias = 0x2a514067;

/// NaN goes to the lower bound: (lo < NaN) is false.
inline float Guard(float v) noexcept
{
    const float a = -kGuard < v ? v : -kGuard;
    return kGuard < a ? kGuard : a;
}

/// Cube root of x ≥ 0 (finite): a bit-trick guess, three Newton steps.
inline float Cbrt(float x) noexcept
{
    int32_t i;
    std::memcpy(&i, &x, 4);
    i = int32_t(float(i) * kThird) + kCbrtBias;
    float y;
    std::memcpy(&y, &i, 4);
    for (int k = 0; k < 3; ++k)
    {
        const float t = y * y;
        y = ((y + y) + x / t) * kThird;
    }
    return x > 0.0f ? y : 0.0f;
}

}  // namespace bandlight::kernel
#endif

HWY_BEFORE_NAMESPACE();
namespace bandlight::HWY_NAMESPACE
{
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;

HWY_INLINE V Clamp(V lo, V hi, V v)
{
    const V a = hn::IfThenElse(hn::Lt(lo, v), v, lo);
    return hn::IfThenElse(hn::Lt(hi, a), hi, a);
}

HWY_INLINE V Guard(D d, V v)
{
    return Clamp(hn::Set(d, -kernel::kGuard), hn::Set(d, kernel::kGuard), v);
}

HWY_INLINE void Multiply(D d, const float* m, V& r, V& g, V& b)
{
    const V r0 = r, g0 = g, b0 = b;
    r = hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0]), r0), hn::Mul(hn::Set(d, m[1]), g0)),
                hn::Mul(hn::Set(d, m[2]), b0));
    g = hn::Add(hn::Add(hn::Mul(hn::Set(d, m[3]), r0), hn::Mul(hn::Set(d, m[4]), g0)),
                hn::Mul(hn::Set(d, m[5]), b0));
    b = hn::Add(hn::Add(hn::Mul(hn::Set(d, m[6]), r0), hn::Mul(hn::Set(d, m[7]), g0)),
                hn::Mul(hn::Set(d, m[8]), b0));
}

HWY_INLINE V Cbrt(D d, V x)
{
    const hn::RebindToSigned<D> di;
    auto i = hn::BitCast(di, x);
    i = hn::Add(hn::ConvertTo(di, hn::Mul(hn::ConvertTo(d, i), hn::Set(d, kernel::kThird))),
                hn::Set(di, kernel::kCbrtBias));
    V y = hn::BitCast(d, i);
    const V third = hn::Set(d, kernel::kThird);
    for (int k = 0; k < 3; ++k)
    {
        const V t = hn::Mul(y, y);
        y = hn::Mul(hn::Add(hn::Add(y, y), hn::Div(x, t)), third);
    }
    return hn::IfThenElseZero(hn::Gt(x, hn::Zero(d)), y);
}

/// Loads N pixels of `stride` floats as R, G, B planes (and the 4th channel
/// for RGBA, written back unchanged).
template <class F>
HWY_INLINE void ForEachBlock(float* HWY_RESTRICT px, size_t count, size_t stride, F&& f,
                             size_t& done)
{
    const D d;
    const size_t n = hn::Lanes(d);
    done = 0;
    if (stride == 3)
    {
        for (; done + n <= count; done += n)
        {
            V r, g, b;
            hn::LoadInterleaved3(d, px + 3 * done, r, g, b);
            f(d, r, g, b);
            hn::StoreInterleaved3(r, g, b, d, px + 3 * done);
        }
    }
    else if (stride == 4)
    {
        for (; done + n <= count; done += n)
        {
            V r, g, b, a;
            hn::LoadInterleaved4(d, px + 4 * done, r, g, b, a);
            f(d, r, g, b);
            hn::StoreInterleaved4(r, g, b, a, d, px + 4 * done);
        }
    }
}

void ClampMatrixSimd(const ClampMatrixKernel* k, float* HWY_RESTRICT px, size_t count,
                     size_t stride, size_t* done)
{
    ForEachBlock(
        px, count, stride,
        [k](D d, V& r, V& g, V& b)
        {
            if (k->clamp)
            {
                const V lo = hn::Set(d, k->lo), hi = hn::Set(d, k->hi);
                r = Clamp(lo, hi, r);
                g = Clamp(lo, hi, g);
                b = Clamp(lo, hi, b);
            }
            Multiply(d, k->m.m, r, g, b);
            if (k->hasOffset)
            {
                r = hn::Add(r, hn::Set(d, k->offset[0]));
                g = hn::Add(g, hn::Set(d, k->offset[1]));
                b = hn::Add(b, hn::Set(d, k->offset[2]));
            }
        },
        *done);
}

void RootPolySimd(const RootPolyKernelData* k, float* HWY_RESTRICT px, size_t count, size_t stride,
                  size_t* done)
{
    const float(*c)[13] = k->coefficients;
    ForEachBlock(
        px, count, stride,
        [k, c](D d, V& r, V& g, V& b)
        {
            r = Guard(d, r);
            g = Guard(d, g);
            b = Guard(d, b);
            if (k->hasInput)
            {
                Multiply(d, k->input.m, r, g, b);
            }
            // max(x, 0) as (0 < x ? x : 0) on every target: -0 becomes +0.
            const V z = hn::Zero(d);
            const V rp = hn::IfThenElse(hn::Lt(z, r), r, z),
                    gp = hn::IfThenElse(hn::Lt(z, g), g, z),
                    bp = hn::IfThenElse(hn::Lt(z, b), b, z);
            V t[13] = {r,
                       g,
                       b,
                       hn::Sqrt(hn::Mul(rp, gp)),
                       hn::Sqrt(hn::Mul(gp, bp)),
                       hn::Sqrt(hn::Mul(rp, bp))};
            const int terms = k->degree == 3 ? 13 : 6;
            if (terms == 13)
            {
                const V cr = Cbrt(d, rp), cg = Cbrt(d, gp), cb = Cbrt(d, bp);
                t[6] = hn::Mul(hn::Mul(cr, cg), cg);
                t[7] = hn::Mul(hn::Mul(cg, cb), cb);
                t[8] = hn::Mul(hn::Mul(cr, cb), cb);
                t[9] = hn::Mul(hn::Mul(cg, cr), cr);
                t[10] = hn::Mul(hn::Mul(cb, cg), cg);
                t[11] = hn::Mul(hn::Mul(cb, cr), cr);
                t[12] = hn::Mul(hn::Mul(cr, cg), cb);
            }
            V out[3];
            for (int o = 0; o < 3; ++o)
            {
                V s = hn::Mul(hn::Set(d, c[o][0]), t[0]);
                for (int j = 1; j < terms; ++j)
                {
                    s = hn::Add(s, hn::Mul(hn::Set(d, c[o][j]), t[j]));
                }
                out[o] = s;
            }
            r = out[0];
            g = out[1];
            b = out[2];
        },
        *done);
}

// The dot product sums in 16 running partial sums (partial k takes the
// samples j ≡ k mod 16, with a multiply and an add, never fused), folds them
// in halves (k + 8, then + 4, + 2, + 1) and adds the last n mod 16 samples in
// order: the same operations in the same order on every target, whatever
// its vector width, so SpectralDotReference's bits. A 16-lane vector holds
// the partial sums in one register, an 8-lane one in two, a 4-lane one in
// four, the scalar target in sixteen.
constexpr size_t kDotPartials = 16;

#if HWY_TARGET != HWY_SCALAR
template <class DV>
HWY_INLINE auto FoldToFour(DV dv, hn::Vec<DV> v)
{
    if constexpr (hn::MaxLanes(DV()) <= 4)
    {
        (void)dv;
        return v;
    }
    else
    {
        const hn::Half<DV> dh;
        return FoldToFour(dh, hn::Add(hn::LowerHalf(dh, v), hn::UpperHalf(dh, v)));
    }
}
#endif

template <class DV>
HWY_INLINE float FoldPartials(DV dv, hn::Vec<DV>* acc, size_t k)
{
    for (; k > 1; k /= 2)
    {
        for (size_t i = 0; i < k / 2; ++i)
        {
            acc[i] = hn::Add(acc[i], acc[i + k / 2]);
        }
    }
#if HWY_TARGET == HWY_SCALAR
    (void)dv;
    return hn::GetLane(acc[0]);  // one lane: the 16 vectors were the partials
#else
    static_assert(hn::MaxLanes(DV()) >= 4, "vector targets have 4 lanes or more");
    HWY_ALIGN float q[4];
    hn::StoreU(FoldToFour(dv, acc[0]), hn::FixedTag<float, 4>(), q);
    return (q[0] + q[2]) + (q[1] + q[3]);
#endif
}

/// The dot products of `count` pixels. `Blocks` > 0 is n / 16 known at
/// compile time (0: read from n): the block loop then unrolls and the
/// pixel's loads interleave, which on an AVX-512 machine took 81 samples a
/// pixel from about 1.4 to 1.15–1.3 times the time of reading the same bytes
/// (docs/speed.md).
template <size_t Blocks>
void SpectralDotPixels(const float* HWY_RESTRICT w, size_t n, const float* HWY_RESTRICT px,
                       size_t count, size_t stride, float* HWY_RESTRICT out, size_t outStride)
{
    // Highway's targets have 1 (HWY_SCALAR), 4, 8 or 16 float lanes: each
    // divides the 16 partial sums.
    using DV = hn::CappedTag<float, kDotPartials>;
    const DV d;
    static_assert(kDotPartials % hn::MaxLanes(DV()) == 0,
                  "the vector width divides the partial sums");
    constexpr size_t lanes = hn::MaxLanes(DV());
    constexpr size_t k = kDotPartials / lanes;
    const size_t blocks = Blocks > 0 ? Blocks : n / kDotPartials;
    const size_t body = blocks * kDotPartials;
    const float* HWY_RESTRICT w1 = w + n;
    const float* HWY_RESTRICT w2 = w + 2 * n;
    for (size_t p = 0; p < count; ++p)
    {
        const float* v = px + p * stride;
        hn::Vec<DV> a0[k], a1[k], a2[k];
        for (size_t i = 0; i < k; ++i)
        {
            a0[i] = a1[i] = a2[i] = hn::Zero(d);
        }
        for (size_t blk = 0; blk < blocks; ++blk)
        {
            for (size_t i = 0; i < k; ++i)
            {
                const size_t o = blk * kDotPartials + i * lanes;
                const hn::Vec<DV> x = hn::LoadU(d, v + o);
                a0[i] = hn::Add(a0[i], hn::Mul(hn::LoadU(d, w + o), x));
                a1[i] = hn::Add(a1[i], hn::Mul(hn::LoadU(d, w1 + o), x));
                a2[i] = hn::Add(a2[i], hn::Mul(hn::LoadU(d, w2 + o), x));
            }
        }
        float s0 = FoldPartials(d, a0, k), s1 = FoldPartials(d, a1, k), s2 = FoldPartials(d, a2, k);
        for (size_t j = body; j < n; ++j)
        {
            s0 = s0 + w[j] * v[j];
            s1 = s1 + w1[j] * v[j];
            s2 = s2 + w2[j] * v[j];
        }
        float* o = out + p * outStride;
        o[0] = s0;
        o[1] = s1;
        o[2] = s2;
    }
}

/// SpectralDotPixels<0> (any length) and <1> … <8>, by the number of blocks.
template <size_t... B>
HWY_INLINE void SpectralDotByBlocks(std::index_sequence<B...>, const float* HWY_RESTRICT w,
                                    size_t n, const float* HWY_RESTRICT px, size_t count,
                                    size_t stride, float* HWY_RESTRICT out, size_t outStride)
{
    using Fn = void (*)(const float*, size_t, const float*, size_t, size_t, float*, size_t);
    static constexpr Fn kByBlocks[] = {&SpectralDotPixels<B>...};
    const size_t blocks = n / kDotPartials;
    kByBlocks[blocks < sizeof...(B) ? blocks : 0](w, n, px, count, stride, out, outStride);
}

void SpectralDotSimd(const float* HWY_RESTRICT w, size_t n, const float* HWY_RESTRICT px,
                     size_t count, size_t stride, float* HWY_RESTRICT out, size_t outStride)
{
    // Spectra of up to 143 samples (pbrt's 16 buckets, 5 nm over the
    // visible's 81) get a loop of known length; longer ones, whose block
    // loop costs little beside their loads, the general one.
    SpectralDotByBlocks(std::make_index_sequence<9>(), w, n, px, count, stride, out, outStride);
}

const char* TargetName()
{
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace bandlight::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace bandlight
{
HWY_EXPORT(ClampMatrixSimd);
HWY_EXPORT(RootPolySimd);
HWY_EXPORT(SpectralDotSimd);
HWY_EXPORT(TargetName);

void SpectralDot(const float* weights, size_t n, const float* pixels, size_t count, size_t stride,
                 float* out, size_t outStride) noexcept
{
    HWY_DYNAMIC_DISPATCH(SpectralDotSimd)(weights, n, pixels, count, stride, out, outStride);
}

void SpectralDotReference(const float* weights, size_t n, const float* pixels, size_t count,
                          size_t stride, float* out, size_t outStride) noexcept
{
    constexpr size_t kPartials = 16;  // the SIMD form's order (SpectralDotSimd)
    const size_t body = n - n % kPartials;
    for (size_t p = 0; p < count; ++p)
    {
        const float* v = pixels + p * stride;
        float* o = out + p * outStride;
        for (size_t c = 0; c < 3; ++c)
        {
            const float* w = weights + c * n;
            float part[kPartials] = {};
            for (size_t j = 0; j < body; ++j)
            {
                part[j % kPartials] = part[j % kPartials] + w[j] * v[j];
            }
            for (size_t half = kPartials / 2; half > 0; half /= 2)
            {
                for (size_t i = 0; i < half; ++i)
                {
                    part[i] = part[i] + part[i + half];
                }
            }
            float s = part[0];
            for (size_t j = body; j < n; ++j)
            {
                s = s + w[j] * v[j];
            }
            o[c] = s;
        }
    }
}

void ClampMatrixReference(const ClampMatrixKernel& k, float* px, size_t count,
                          size_t stride) noexcept
{
    const float* m = k.m.m;
    const auto clamp = [&k](float v)
    {
        if (!k.clamp)
        {
            return v;
        }
        const float a = k.lo < v ? v : k.lo;
        return k.hi < a ? k.hi : a;
    };
    for (size_t i = 0; i < count; ++i)
    {
        float* p = px + i * stride;
        const float r = clamp(p[0]), g = clamp(p[1]), b = clamp(p[2]);
        p[0] = (m[0] * r + m[1] * g) + m[2] * b;
        p[1] = (m[3] * r + m[4] * g) + m[5] * b;
        p[2] = (m[6] * r + m[7] * g) + m[8] * b;
        if (k.hasOffset)
        {
            p[0] = p[0] + k.offset[0];
            p[1] = p[1] + k.offset[1];
            p[2] = p[2] + k.offset[2];
        }
    }
}

ClampMatrixKernel GuardedMatrixKernel(const Matrix3f& m) noexcept
{
    ClampMatrixKernel k;
    k.lo = -kernel::kGuard;
    k.hi = kernel::kGuard;
    k.m = m;
    return k;
}

void GuardedMatrixReference(const Matrix3f& m, float* px, size_t count, size_t stride) noexcept
{
    ClampMatrixReference(GuardedMatrixKernel(m), px, count, stride);
}

void ClampMatrix(const ClampMatrixKernel& k, float* px, size_t count, size_t stride) noexcept
{
    size_t done = 0;
    HWY_DYNAMIC_DISPATCH(ClampMatrixSimd)(&k, px, count, stride, &done);
    // The tail (and strides the SIMD form does not take): the same maths.
    ClampMatrixReference(k, px + done * stride, count - done, stride);
}

void RootPolyPixelsReference(const RootPolyKernelData& k, float* px, size_t count,
                             size_t stride) noexcept
{
    const int terms = k.degree == 3 ? 13 : 6;
    for (size_t i = 0; i < count; ++i)
    {
        float* p = px + i * stride;
        float r = kernel::Guard(p[0]), g = kernel::Guard(p[1]), b = kernel::Guard(p[2]);
        if (k.hasInput)
        {
            const float* m = k.input.m;
            const float r0 = r, g0 = g, b0 = b;
            r = (m[0] * r0 + m[1] * g0) + m[2] * b0;
            g = (m[3] * r0 + m[4] * g0) + m[5] * b0;
            b = (m[6] * r0 + m[7] * g0) + m[8] * b0;
        }
        const float rp = 0.0f < r ? r : 0.0f, gp = 0.0f < g ? g : 0.0f, bp = 0.0f < b ? b : 0.0f;
        float t[13] = {r, g, b, std::sqrt(rp * gp), std::sqrt(gp * bp), std::sqrt(rp * bp)};
        if (terms == 13)
        {
            const float cr = kernel::Cbrt(rp), cg = kernel::Cbrt(gp), cb = kernel::Cbrt(bp);
            t[6] = (cr * cg) * cg;
            t[7] = (cg * cb) * cb;
            t[8] = (cr * cb) * cb;
            t[9] = (cg * cr) * cr;
            t[10] = (cb * cg) * cg;
            t[11] = (cb * cr) * cr;
            t[12] = (cr * cg) * cb;
        }
        for (int o = 0; o < 3; ++o)
        {
            float s = k.coefficients[o][0] * t[0];
            for (int j = 1; j < terms; ++j)
            {
                s = s + k.coefficients[o][j] * t[j];
            }
            p[o] = s;
        }
    }
}

void GuardedMatrix(const Matrix3f& m, float* px, size_t count, size_t stride) noexcept
{
    ClampMatrix(GuardedMatrixKernel(m), px, count, stride);
}

void RootPolyPixels(const RootPolyKernelData& k, float* px, size_t count, size_t stride) noexcept
{
    size_t done = 0;
    HWY_DYNAMIC_DISPATCH(RootPolySimd)(&k, px, count, stride, &done);
    RootPolyPixelsReference(k, px + done * stride, count - done, stride);
}

const char* PixelKernelTarget() noexcept
{
    return HWY_DYNAMIC_DISPATCH(TargetName)();
}

}  // namespace bandlight
#endif
