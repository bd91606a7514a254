// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// The 1D curve that maps scene-linear values into a 3D LUT's [0, 1] domain.
///
/// `LOG2`: linear below `breakLinear`, log2 above, continuous with a
/// continuous slope (OCIO's LogCameraTransform, base 2), scaled so that
/// `minLinear` (a small negative value) maps to 0 and `maxLinear` to 1.
/// The 3D LUT is shaper-encoded in and out. Along any grey ray the exact
/// transform is then linear in the LUT's coordinates wherever input and
/// output are both above the break (log2) or both below it (linear), which
/// tetrahedral interpolation reproduces exactly: greys from 1e-4 to 65504
/// come out to float precision. Chromatic colours carry the interpolation
/// error of a matrix seen in log space (measured in docs/luts.md). The break
/// sits at 2^-15 so that the kink stays below 1e-4; the negative range it
/// leaves is small: values below `minLinear` are clamped by the LUT, and
/// that is the stated range.
///
/// `NONE`: the identity; the LUT covers linear [0, 1] (display-referred data).
struct ShaperSpec
{
    enum class Kind
    {
        NONE,
        LOG2,
    };
    Kind kind = Kind::LOG2;
    double minLinear = -0.0005;
    double breakLinear = 1.0 / 32768.0;  // 2^-15 ≈ 3.05e-5
    double maxLinear = 131072.0;         // 2^17: covers half-float's 65504 with a stop to spare

    /// The shaper for LUTs of non-linear transforms (upsample, rootpoly):
    /// the same log2 shaper, break at 2^-15. Both methods are exposure
    /// invariant (f(k·x) = k·f(x)), and in log2 coordinates scaling the
    /// pixel shifts input and output by the same amount: the LUT then errs
    /// alike at every exposure whose channels lie above the break (a 20 %
    /// grey's shadows 8 stops down are at 7e-4, far above 3e-5). An
    /// earlier break at 2^-8 made shadows the worst case.
    static ShaperSpec ForNonLinear() { return ShaperSpec(); }

    /// This shaper with minLinear moved (by a few per cent, never above
    /// zero) so that linear 0 falls exactly on a node of a size-point
    /// lattice: black then maps to exactly the exact transform's black
    /// rather than to an interpolation between its neighbours. Every lattice
    /// bandlight bakes uses the aligned shaper, and describe() reports it.
    ShaperSpec alignedTo(int size) const;

    /// "log2" or "none"; throws Exception otherwise.
    static ShaperSpec Parse(const std::string& text);

    /// "log2: linear -0.01 … 131072, linear below 0.015625, log2 above".
    std::string describe() const;

    /// The shaper as an OCIO transform, linear → [0, 1] (nullptr for NONE).
    OCIO::TransformRcPtr transform() const;

    /// The same curve evaluated directly (for tests and documentation).
    double encode(double linear) const noexcept;
    double decode(double encoded) const noexcept;
};

}  // namespace bandlight
