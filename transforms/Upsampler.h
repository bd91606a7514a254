// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <unordered_map>

#include <Eigen/Core>

#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

/// Spectral upsampling after W. Jakob and J. Hanika, "A Low-Dimensional
/// Function Space for Efficient Spectral Upsampling", Computer Graphics
/// Forum 38(2), 2019: a remittance r(λ) = S(c0 t² + c1 t + c2), t = (λ −
/// 380 nm) / 400 nm, with the sigmoid S(x) = ½ + x / (2 √(1 + x²)), so r is
/// smooth and strictly inside (0, 1). The three coefficients are fitted by
/// Levenberg–Marquardt so that r reproduces a pixel under illuminant S1.
class Upsampler
{
public:
    using Coeffs = Eigen::Vector3d;

    explicit Upsampler(const SurfaceRenderer& from);

    struct Fit
    {
        Coeffs coeffs = Coeffs::Zero();
        double residual = 0.0;  ///< |A1·r − c| / |w1| at the end
        int iterations = 0;
    };

    /// Fits c (working RGB under S1, at most the white in each channel)
    /// starting from `start` (the flat grey 0.5 by default).
    Fit fit(const Vec3& rgb, const Coeffs& start = Coeffs::Zero()) const;

    /// The remittance of a fit on the renderer's grid.
    static SurfaceRenderer::Samples Remittance(const Coeffs& c);

    /// The scale every pixel is fitted at: it is divided by
    /// k = max_i(c_i / w1_i) / kCanonicalLevel before fitting and its
    /// result multiplied by k after. A pixel's level is irradiance ×
    /// remittance and says nothing about the surface, so fitting its
    /// chromaticity at one level makes upsample exactly exposure invariant
    /// (f(k·c) = k·f(c)); HDR values and greys keep their ratios.
    double gamutScale(const Vec3& rgb) const noexcept;
    /// The level (largest channel relative to the white) pixels are fitted
    /// at. Chosen on training data, never on a test set: over rawtoaces'
    /// 190 reflectances, A/F2/F11/D50/D65 pairs, mean ΔE00 1.92 at 0.2,
    /// 1.68 at 0.35, 1.60 at 0.5, 1.73 at 0.7, 2.69 at 0.9 (too bright:
    /// saturated colours leave the smooth remittances' gamut).
    static constexpr double kCanonicalLevel = 0.5;

    const SurfaceRenderer& renderer() const noexcept { return m_from; }

private:
    const SurfaceRenderer& m_from;
};

/// Fits already made for colours at the canonical level (see gamutScale),
/// keyed by the scaled colour quantised to 2^-20 of the white: all pixels
/// of one chromaticity share a fit. One per thread.
using UpsampleCache = std::unordered_map<uint64_t, Upsampler::Coeffs>;

/// `upsample` for one pixel: scale into the gamut, fit under S1, render
/// the remittance under S2, scale back. Pixels with no positive channel go
/// through `fallback` (a linear 3×3: black and negative noise have no
/// remittance). `warm` carries coefficients between neighbouring pixels.
Vec3 UpsampleRelight(const Upsampler& up, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb, Upsampler::Coeffs* warm = nullptr,
                     UpsampleCache* cache = nullptr);

}  // namespace bandlight
