// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/NativeKernels.h"

#include <cmath>

namespace bandlight
{

std::optional<ClampMatrixKernel> NativeClampMatrix(const OCIO::ConstProcessorRcPtr& processor)
{
    const OCIO::GroupTransformRcPtr group =
        processor
            ->getOptimizedProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                    OCIO::OPTIMIZATION_DEFAULT)
            ->createGroupTransform();
    ClampMatrixKernel k;
    k.clamp = false;
    const int n = group->getNumTransforms();
    int at = 0;
    if (n == 2)
    {
        const auto range = OCIO::DynamicPtrCast<const OCIO::RangeTransform>(group->getTransform(0));
        if (!range || range->getStyle() != OCIO::RANGE_CLAMP || !range->hasMinInValue() ||
            !range->hasMaxInValue() || !range->hasMinOutValue() || !range->hasMaxOutValue() ||
            range->getMinInValue() != range->getMinOutValue() ||
            range->getMaxInValue() != range->getMaxOutValue() ||
            range->getDirection() != OCIO::TRANSFORM_DIR_FORWARD)
        {
            return std::nullopt;
        }
        k.clamp = true;
        k.lo = float(range->getMinInValue());
        k.hi = float(range->getMaxInValue());
        if (!std::isfinite(k.lo) || !std::isfinite(k.hi) || !(k.lo <= k.hi))
        {
            return std::nullopt;
        }
        at = 1;
    }
    else
    {
        // A matrix without a clamp lets NaN and Inf into OCIO's 4×4, which
        // then writes NaN into alpha: OCIO's own processor keeps that.
        return std::nullopt;
    }
    const auto matrix = OCIO::DynamicPtrCast<const OCIO::MatrixTransform>(group->getTransform(at));
    if (!matrix || matrix->getDirection() != OCIO::TRANSFORM_DIR_FORWARD)
    {
        return std::nullopt;
    }
    double m44[16], offset[4];
    matrix->getMatrix(m44);
    matrix->getOffset(offset);
    // Alpha must pass through: the fourth row and column are the identity's.
    if (m44[3] != 0.0 || m44[7] != 0.0 || m44[11] != 0.0 || m44[12] != 0.0 || m44[13] != 0.0 ||
        m44[14] != 0.0 || m44[15] != 1.0 || offset[3] != 0.0)
    {
        return std::nullopt;
    }
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
        {
            k.m.m[3 * r + c] = float(m44[4 * r + c]);
        }
        k.offset[r] = float(offset[r]);
        k.hasOffset = k.hasOffset || offset[r] != 0.0;
    }
    return k;
}

}  // namespace bandlight
