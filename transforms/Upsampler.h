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

    /// The scale of the out-of-gamut rule: a pixel whose largest channel
    /// exceeds kGamutFraction of the white's is divided by
    /// k = max_i(c_i / w1_i) / kGamutFraction before fitting and its result
    /// multiplied by k after (scale, not clip: HDR values and bright
    /// colours keep their ratios; greys stay exact).
    double gamutScale(const Vec3& rgb) const noexcept;
    static constexpr double kGamutFraction = 0.9;

    const SurfaceRenderer& renderer() const noexcept { return m_from; }

private:
    const SurfaceRenderer& m_from;
};

/// Fits already made for colours on the gamut's shell (see gamutScale),
/// keyed by the scaled colour quantised to 2^-20 of the white: all HDR
/// pixels of one chromaticity share a fit. One per thread.
using UpsampleCache = std::unordered_map<uint64_t, Upsampler::Coeffs>;

/// `upsample` for one pixel: scale into the gamut, fit under S1, render
/// the remittance under S2, scale back. Pixels with no positive channel go
/// through `fallback` (a linear 3×3: black and negative noise have no
/// remittance). `warm` carries coefficients between neighbouring pixels.
Vec3 UpsampleRelight(const Upsampler& up, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb, Upsampler::Coeffs* warm = nullptr,
                     UpsampleCache* cache = nullptr);

}  // namespace bandlight
