// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>

#include <Eigen/Core>

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// Correlated colour temperature and the signed distance from the
/// Planckian locus in the CIE 1960 (u, v) diagram (positive above it,
/// towards green).
struct CctDuv
{
    double cctK = 0.0;
    double duv = 0.0;
};

/// (u, v) of a Planckian radiator at `kelvin` for the CIE 1931 observer,
/// integrated exactly from Planck's law on the matching functions' grid.
Eigen::Vector2d PlanckianUv(double kelvin);

/// CCT (CIE 15:2004 §9.5: the temperature of the Planckian radiator nearest
/// in CIE 1960 UCS) and Duv of a stimulus's XYZ (CIE 1931 observer),
/// searched between 1000 K and 100000 K to better than 0.01 K for
/// |Duv| < 0.05. Throws Exception for XYZ with no chromaticity (all zero).
CctDuv ComputeCct(const Vec3& xyz);

/// CIE 13.3-1995 colour rendering: Ra and the special indices R1–R14, and
/// R15 (JIS Z 8726's Japanese skin sample TCS15, computed by CIE 13.3's
/// own formula, as spectrometers and lighting data sheets report it).
struct ColourRendering
{
    double cctK = 0.0;
    double duv = 0.0;
    double ra = 0.0;
    std::array<double, 15> r{};  ///< R1–R15
    /// True when |Duv| > 5.4e-3: CIE 13.3 says the source is then too far
    /// from the Planckian locus for Ra to be meaningful.
    bool outsideTolerance = false;
};

/// Colour rendering index of a light source (CIE 13.3-1995): the reference
/// is a Planckian radiator below 5000 K and CIE daylight from 5000 K on,
/// both at the source's CCT; TCS01–TCS14 are compared after a von Kries
/// adaptation in CIE 1960 (u, v), in CIE 1964 U*V*W* (TCS15 likewise, for
/// R15; Ra stays the mean of R1–R8). Throws Exception when
/// the CCT lies outside 1000–25000 K.
ColourRendering ComputeColourRendering(const Spectrum& illuminant);

}  // namespace bandlight
