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

/// Every pixel guarded (each channel clamped to ±PIXEL_GUARD, NaN to
/// −PIXEL_GUARD) and multiplied by `m`, in place: `count` pixels of
/// `stride` floats (at least 3).
void GuardedMatrix(const Matrix3f& m, float* pixels, size_t count, size_t stride) noexcept;
void GuardedMatrixReference(const Matrix3f& m, float* pixels, size_t count,
                            size_t stride) noexcept;

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

/// The instruction set the SIMD forms run on here ("AVX2", "SSE4", ...).
const char* PixelKernelTarget() noexcept;

}  // namespace bandlight
