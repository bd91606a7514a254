// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The fits of the linear methods (transforms/IlluminantChange.cpp), which
// the method registry (transforms/Methods.cpp) points to. Not installed.

#include "transforms/IlluminantChange.h"

namespace bandlight::detail
{

/// none: the identity.
Mat3 IdentityFit(const Light&, const Light&, const MethodSpec&, const RgbSpace&, Observer);
/// vonkries, bradford, cat02, prefilter: a chromatic adaptation of the whites.
Mat3 AdaptationFit(const Light& from, const Light& to, const MethodSpec& method,
                   const RgbSpace& working, Observer observer);
/// band, band-wp: a diagonal in band space.
Mat3 BandFit(const Light& from, const Light& to, const MethodSpec& method, const RgbSpace& working,
             Observer observer);
/// fit3x3: least squares on the training remittances.
Mat3 LeastSquaresFit(const Light& from, const Light& to, const MethodSpec& method,
                     const RgbSpace& working, Observer observer);
/// metamer: the smoothest remittance of each pixel, re-lit.
Mat3 MetamerFit(const Light& from, const Light& to, const MethodSpec& method,
                const RgbSpace& working, Observer observer);

}  // namespace bandlight::detail
