// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "plugin/Names.h"
#include "spectral/Colorimetry.h"
#include "transforms/Defaults.h"
#include "transforms/IlluminantChange.h"

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// The bound of the clamp in front of every matrix bandlight emits: finite
/// values up to ±1e16 pass unchanged; ±Inf become ±1e16, so a matrix never
/// computes Inf − Inf or 0 · Inf and never turns an infinite pixel into NaN.
/// A NaN channel cannot pass an OpenColorIO clamp: OCIO maps it to the
/// lower bound, so it enters the matrix as −1e16 (the pixel comes out hugely
/// negative and displays black). docs/robustness.md tabulates every case.
constexpr double INFINITY_GUARD = PIXEL_GUARD;

/// The guard alone: a RangeTransform clamping to ±INFINITY_GUARD.
OCIO::RangeTransformRcPtr InfinityGuard();

/// guard, matrix, guard: the form of the 3×3s that are used in both
/// directions (config colour spaces): each direction meets a guard first.
/// The relight, band and tint transforms are guard, matrix: they run
/// forward, and one clamp less is a third faster (bench_apply).
OCIO::GroupTransformRcPtr GuardedMatrixTransform(const Mat3& m);

/// A MatrixTransform holding a 3×3 (as OCIO's 4×4 with no offset).
OCIO::MatrixTransformRcPtr MakeMatrixTransform(const Mat3& m);

/// The illuminant change from `from` to `to` by `method`, for images in the
/// linear RGB space `working`, with the method's description as metadata: a
/// group holding the guard and one MatrixTransform for the linear methods;
/// for upsample, the log2 shaper, a `lutSize`³ 3D LUT baked from the
/// per-pixel spectral fit, and the inverse shaper. Throws Exception for
/// `spectral`.
OCIO::GroupTransformRcPtr IlluminantChangeTransform(const Light& from, const Light& to,
                                                    const MethodSpec& method,
                                                    const RgbSpace& working,
                                                    Observer observer = Observer::CIE1931_2DEG,
                                                    int lutSize = defaults::TRANSFORM_LUT_SIZE);

/// Working RGB → the band space of a three-band set (radiometric band
/// values, VB/VG/VR for the band model's bands). Throws Exception for other
/// than three bands (an N-band space has N channels, which OCIO images have not).
OCIO::GroupTransformRcPtr BandSpaceTransform(const BandSet& bands, const RgbSpace& working,
                                             Observer observer = Observer::CIE1931_2DEG);

/// The band model's material tint (R_diff as a diagonal in band space), in the
/// working space.
OCIO::GroupTransformRcPtr MaterialTintTransform(const std::vector<double>& remittance,
                                                const BandSet& bands, const RgbSpace& working,
                                                Observer observer = Observer::CIE1931_2DEG);

/// The 3×3 an OCIO processor applies, measured by running the basis vectors
/// through it (used to check configs against the library's matrices).
Mat3 MeasureMatrix(const OCIO::ConstProcessorRcPtr& processor);

}  // namespace bandlight
