// SPDX-License-Identifier: BSD-3-Clause
// What an OpenColorIO processor is, when bandlight's own SIMD kernels can
// run it instead: the processor taken apart into the ops it optimises to.
#pragma once

#include <optional>

#include <OpenColorIO/OpenColorIO.h>

#include "transforms/PixelKernels.h"

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// The clamp and affine 3×3 an optimised OCIO processor consists of, when
/// it is nothing else: a RangeTransform that only clamps (both bounds
/// finite, in = out) followed by a MatrixTransform that leaves alpha alone.
/// Any other op, a matrix without a clamp (NaN would reach OCIO's 4×4 and
/// its alpha), and any look that optimises to more, gives nullopt: it goes
/// through OCIO.
std::optional<ClampMatrixKernel> NativeClampMatrix(const OCIO::ConstProcessorRcPtr& processor);

}  // namespace bandlight
