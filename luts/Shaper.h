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
/// `minLinear` (a negative value) maps to 0 and `maxLinear` to 1. The LUT's
/// nodes then sit about a stop apart in the highlights and evenly in linear
/// near zero and below it, where any linear transform is reproduced exactly.
/// Values outside [minLinear, maxLinear] are clamped by the LUT: that is the
/// stated range.
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
    double minLinear = -0.01;
    double breakLinear = 1.0 / 64.0;
    double maxLinear = 131072.0;  // 2^17: covers half-float's 65504 with a stop to spare

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
