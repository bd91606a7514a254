// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The pixel kernels of the fast paths: the guarded 3×3 and the root
// polynomial of degree 2 and 3, on interleaved float pixels of any stride
// (R, G, B first: RGB is stride 3, RGBA stride 4, other channels pass
// through). Each has a SIMD form, compiled for every instruction set
// Google Highway targets and chosen once at run time for the CPU it runs
// on (HWY_DYNAMIC_DISPATCH), and a scalar reference with the same maths:
// the SIMD forms equal it bit for bit (no fused multiply-adds, the same
// order of operations), NaN and Inf included (tests/transforms/
// PixelKernelsTest.cpp).

#include <cstddef>

namespace bandlight
{

/// A 3×3 in float, row-major.
struct Matrix3f
{
    float m[9];
};

/// A clamp and an affine 3×3, as OpenColorIO's RangeTransform (clamp) and
/// MatrixTransform (with offset) compute them.
struct ClampMatrixKernel
{
    bool clamp = true;  ///< clamp each channel to [lo, hi] first, NaN to lo
    float lo = 0.0f;
    float hi = 0.0f;
    Matrix3f m{};
    bool hasOffset = false;
    float offset[3] = {};
};

/// Every pixel clamped (when k.clamp) and through the affine 3×3, in place:
/// `count` pixels of `stride` floats (at least 3).
void ClampMatrix(const ClampMatrixKernel& k, float* pixels, size_t count, size_t stride) noexcept;
void ClampMatrixReference(const ClampMatrixKernel& k, float* pixels, size_t count,
                          size_t stride) noexcept;

/// The guarded 3×3 of every linear method: ClampMatrix with the pixel guard
/// (each channel clamped to ±PIXEL_GUARD, NaN to −PIXEL_GUARD) and no offset.
ClampMatrixKernel GuardedMatrixKernel(const Matrix3f& m) noexcept;
void GuardedMatrix(const Matrix3f& m, float* pixels, size_t count, size_t stride) noexcept;
void GuardedMatrixReference(const Matrix3f& m, float* pixels, size_t count, size_t stride) noexcept;

/// A root polynomial as the kernel takes it: degree 2 (6 terms) or 3 (13),
/// its 3 × terms coefficients, and an optional 3×3 applied to the guarded
/// pixel first.
struct RootPolyKernelData
{
    int degree = 2;
    float coefficients[3][13] = {};
    bool hasInput = false;
    Matrix3f input{};
};

/// Every pixel guarded, through the input matrix (when set), then the root
/// polynomial, in place. Degree 3's cube roots are a Newton iteration in
/// float, within 2 ulp of std::cbrt.
void RootPolyPixels(const RootPolyKernelData& k, float* pixels, size_t count,
                    size_t stride) noexcept;
void RootPolyPixelsReference(const RootPolyKernelData& k, float* pixels, size_t count,
                             size_t stride) noexcept;

/// Spectral integration folded into weights: for each pixel, out[c] =
/// Σ_j weights[c·n + j] · pixel[j] for c = 0, 1, 2, over `n` consecutive
/// channels of each pixel (`stride` floats apart), written to `out` (3
/// floats a pixel, `outStride` apart). Both forms sum in the same order (16
/// partial sums, folded in halves, then the last n mod 16 samples; no fused
/// multiply-adds), so they agree bit for bit on every target and every
/// machine gives the same image; the result is within 2·n·2⁻²⁴ · Σ_j |w_j ·
/// v_j| of the exact sum (tested). NaN and Inf propagate.
void SpectralDot(const float* weights, size_t n, const float* pixels, size_t count, size_t stride,
                 float* out, size_t outStride) noexcept;
void SpectralDotReference(const float* weights, size_t n, const float* pixels, size_t count,
                          size_t stride, float* out, size_t outStride) noexcept;

/// The instruction set the SIMD forms run on here ("AVX2", "SSE4", ...).
const char* PixelKernelTarget() noexcept;

}  // namespace bandlight
