// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "spectral/CieData.h"
#include "spectral/Spectrum.h"

namespace bandlight
{

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// π, for the hue angles and the geometry bandlight computes.
inline constexpr double kPi = 3.14159265358979323846;

/// Tristimulus values of a stimulus phi(λ), unnormalised:
/// (Σ φ x̄ Δλ, Σ φ ȳ Δλ, Σ φ z̄ Δλ) on the stimulus's own grid, the matching
/// functions interpolated there (zero outside 360–830 nm).
Vec3 IntegrateXyz(const Spectrum& stimulus, Observer observer);

/// The same for emission lines: Σ P_i · cmf(λ_i), exact at any grid.
Vec3 IntegrateXyz(const LineSpectrum& lines, Observer observer);

/// Colorimetric XYZ of a surface of remittance `reflectance` lit by
/// `illuminant`, normalised so that the perfect white reflector has Y = 100
/// (CIE 15:2004 §7.1, k = 100 / Σ S ȳ Δλ). The sum runs over the
/// illuminant's grid; the remittance is extended at its ends as CIE 15
/// recommends when it does not cover the illuminant's range.
Vec3 SurfaceXyz(const Spectrum& reflectance, const Spectrum& illuminant, Observer observer);

/// XYZ of the illuminant itself on the same scale (its white point, Y = 100).
Vec3 IlluminantWhiteXyz(const Spectrum& illuminant, Observer observer);

/// The band model's normalisation: each tristimulus value divided by the
/// integral of its own matching function, so that the equal-energy
/// stimulus φ = 1 gives (1, 1, 1).
Vec3 EqualEnergyNormalisedXyz(const Spectrum& stimulus, Observer observer);

/// Precomputed weights w_k(λ) = k · S(λ) · cmf_k(λ) · Δλ for one illuminant
/// and observer, so a surface's XYZ is three dot products: the fast path of
/// SurfaceXyz (same result to rounding) for many remittances on one grid.
/// An illuminant coarser than the matching functions' tables is brought onto
/// their grid first, as IntegrateXyz does, so grid() is then the tables'.
class XyzIntegrator
{
public:
    XyzIntegrator(const Spectrum& illuminant, Observer observer);

    /// XYZ (white reflector Y = 100) of a remittance on grid(); a remittance
    /// on another grid is resampled (with edge extension) first.
    Vec3 operator()(const Spectrum& reflectance) const;

    /// Dot products over raw samples on grid(); `values` has grid().size() entries.
    Vec3 integrate(const double* values) const noexcept;

    const Spectrum& grid() const noexcept { return m_wx; }

private:
    /// `light` already on a grid no coarser than the tables.
    XyzIntegrator(const Spectrum& light, const MatchingFunctions& cmf);

    Spectrum m_wx, m_wy, m_wz;
};

/// xyY from XYZ; for XYZ = 0 the chromaticity is undefined and (0, 0, 0) is returned.
Vec3 XyzToxyY(const Vec3& xyz) noexcept;
Vec3 xyYToXyz(const Vec3& xyY) noexcept;

/// CIE 1960 UCS (u, v) chromaticity (CIE 15:2004 §8.1; v' = 1.5 v).
Eigen::Vector2d XyzToUv1960(const Vec3& xyz) noexcept;

/// CIELAB (CIE 15:2004 §8.2.1) relative to the white `whiteXyz` (same scale as xyz).
Vec3 XyzToLab(const Vec3& xyz, const Vec3& whiteXyz) noexcept;
Vec3 LabToXyz(const Vec3& lab, const Vec3& whiteXyz) noexcept;

/// ΔE*ab (CIE 1976): Euclidean distance in CIELAB.
double DeltaE76(const Vec3& lab1, const Vec3& lab2) noexcept;

/// CIEDE2000 colour difference (CIE 142-2001), with the implementation
/// notes of Sharma, Wu & Dalal, Color Res. Appl. 30(1), 2005; kL = kC = kH = 1
/// by default.
double DeltaE2000(const Vec3& lab1, const Vec3& lab2, double kL = 1.0, double kC = 1.0,
                  double kH = 1.0) noexcept;

}  // namespace bandlight
