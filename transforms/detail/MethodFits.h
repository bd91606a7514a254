// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The fits of the illuminant-change methods (transforms/IlluminantChange.cpp),
// which the method registry (transforms/Methods.cpp) points to. Each reads
// what distinguishes its methods from the spec or its registry entry, never
// by comparing method values. Not installed.

#include "transforms/IlluminantChange.h"
#include "transforms/methods/PixelOp.h"

namespace bandlight::detail
{

/// none: the identity.
Mat3 IdentityFit(const Light&, const Light&, const MethodSpec&, const RgbSpace&, Observer);
/// vonkries, bradford, cat02, prefilter: a chromatic adaptation of the
/// whites by the entry's `adaptation`.
Mat3 AdaptationFit(const Light& from, const Light& to, const MethodSpec& method,
                   const RgbSpace& working, Observer observer);
/// band, band-wp: a diagonal in band space (ratios of the lights' band
/// means, or of the whites' band coordinates when `whitePreserving`).
Mat3 BandFit(const Light& from, const Light& to, const MethodSpec& method, const RgbSpace& working,
             Observer observer);
/// fit3x3: least squares on the training remittances (TrainingOf).
Mat3 LeastSquaresFit(const Light& from, const Light& to, const MethodSpec& method,
                     const RgbSpace& working, Observer observer);
/// metamer: the smoothest remittance of each pixel, re-lit.
Mat3 MetamerFit(const Light& from, const Light& to, const MethodSpec& method,
                const RgbSpace& working, Observer observer);

/// The balances of balanced plates around a non-linear method: the inverse
/// balance for `from` before it, the balance for `to` after it (identities
/// for lit plates).
struct PlateBalance
{
    bool balanced;
    Mat3 from = Mat3::Identity();
    Mat3 to = Mat3::Identity();
};

PlateBalance BalanceOf(const Light& from, const Light& to, const MethodSpec& method,
                       const RgbSpace& working, Observer observer);

/// upsample: the per-pixel sigmoid-polynomial fit, re-lit spectrally
/// (transforms/methods/Upsample.cpp).
std::unique_ptr<PixelOp> UpsampleOp(const Light& from, const Light& to, const MethodSpec& method,
                                    const RgbSpace& working, Observer observer);
/// upsample's fits under `from`, which every op from that light shares.
std::shared_ptr<void> UpsampleShared(const Light& from, const RgbSpace& working,
                                     Observer observer);
/// The op of a root polynomial M · φ(x) of `degree` (the SIMD kernel's),
/// after the 3×3 `input` when given: the root-polynomial methods' op, for
/// the files of transforms/methods/ that fit one their own way.
std::unique_ptr<PixelOp> RootPolynomialOp(int degree, Eigen::MatrixXd matrix,
                                          const Mat3* input = nullptr);
/// rootpoly, rootpoly3: the root polynomial fitted on the training set
/// (transforms/methods/RootPolynomial.cpp).
std::unique_ptr<PixelOp> RootPolyOp(const Light& from, const Light& to, const MethodSpec& method,
                                    const RgbSpace& working, Observer observer);
/// rootpoly-camera, rootpoly3-camera: the camera's daylight IDT undone,
/// then the root polynomial fitted from the camera's record.
std::unique_ptr<PixelOp> RootPolyCameraOp(const Light& from, const Light& to,
                                          const MethodSpec& method, const RgbSpace& working,
                                          Observer observer);

}  // namespace bandlight::detail
