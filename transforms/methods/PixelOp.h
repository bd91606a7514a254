// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The pixel work of a method that is not one 3×3, as an op: its method's
// registry entry makes one for a change of light (MethodEntry::makeOp), and
// Relighter applies it to whole buffers. Relighter guards every pixel
// (PIXEL_GUARD) and applies the op's input matrix; the op does the rest.
// Nothing outside an op's own file knows which method it belongs to.

#include <cstddef>
#include <memory>

#include "spectral/Colorimetry.h"

namespace bandlight
{

class RootPolynomial;

class PixelOp
{
public:
    virtual ~PixelOp() = default;

    /// The 3×3 applied to the guarded pixel before the op (balanced plates:
    /// the inverse balance for `from`; rootpoly-camera: the way back to the
    /// camera's record), when `hasInput`.
    bool hasInput = false;
    Mat3 input = Mat3::Identity();

    /// One pixel, guarded and through `input`, in double precision.
    virtual Vec3 apply(const Vec3& in) const = 0;
    /// `count` pixels, guarded and through `input`, in place: apply() for
    /// each, unless the op shares work among pixels (upsample: one fit per
    /// chromaticity).
    virtual void apply(Vec3* rgb, size_t count) const;
    /// `count` packed RGB float triples through `input` (not yet guarded:
    /// an op that needs the guard applies it) in place, on `threads`
    /// threads (0: all cores).
    virtual void applyAfterInput(float* rgb, size_t count, int threads) const = 0;
    /// Pixels of `stride` floats (R, G, B first), the guard and `input`
    /// included, in one pass, when the op has such a kernel (the root
    /// polynomial's SIMD kernel): true when done; false to let Relighter
    /// guard, apply `input` and call applyAfterInput.
    virtual bool applyWhole(float* pixels, size_t count, size_t stride, int threads) const;
    /// The 3×3 that stands for the op where a caller asks for one (upsample:
    /// the metamer matrix its pixels without a positive channel take);
    /// the identity when there is none.
    virtual Mat3 linearPart() const { return Mat3::Identity(); }
    /// The root polynomial of the root-polynomial methods (the cost table
    /// times it natively); nullptr for other ops.
    virtual const RootPolynomial* rootPolynomial() const { return nullptr; }
};

}  // namespace bandlight
