// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CIECAM02 (CIE 159:2004) forward model and CAM02-UCS (Luo, Cui & Li, Color
// Res. Appl. 31(4), 2006): the space CIE 224:2017 and ANSI/IES TM-30 measure
// colour fidelity in.

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// CIECAM02 viewing conditions (CIE 159:2004). The defaults are
/// those CIE 224:2017 and TM-30 prescribe: L_A = 100 cd/m², Y_b = 20, an
/// average surround, the illuminant fully discounted (D = 1).
struct CamViewingConditions
{
    double adaptingLuminance = 100.0;  ///< L_A, cd/m²
    double backgroundY = 20.0;         ///< Y_b, relative to the white's Y_w
    double f = 1.0;                    ///< surround factor F (average 1.0, dim 0.9, dark 0.8)
    double c = 0.69;                   ///< surround impact c (average 0.69, dim 0.59, dark 0.525)
    double nc = 1.0;                   ///< chromatic induction N_c (average 1.0, dim 0.9, dark 0.8)
    /// True: D = 1 (the observer adapts fully to the white). False: D from
    /// F and L_A, D = F (1 − e^((−L_A − 42)/92) / 3.6).
    bool discountIlluminant = true;
};

/// CIECAM02 correlates of one colour.
struct CamCorrelates
{
    double j = 0.0;  ///< lightness J
    double c = 0.0;  ///< chroma C
    double h = 0.0;  ///< hue angle h, degrees in [0, 360)
    double m = 0.0;  ///< colourfulness M
    double q = 0.0;  ///< brightness Q
    double s = 0.0;  ///< saturation s
};

/// CIECAM02 for one white and one set of viewing conditions: everything
/// that depends only on them (F_L, n, N_bb, z, the white's adapted
/// responses and achromatic signal A_w) is computed once, so converting a
/// colour is a few matrix products and powers.
class Cam02
{
public:
    /// `whiteXyz` is the adopted white on the colours' scale (Y_w, usually
    /// 100). Throws Exception for a white with a non-positive cone response
    /// or non-finite conditions.
    Cam02(const Vec3& whiteXyz, const CamViewingConditions& conditions = {});

    /// The correlates of a colour of tristimulus values `xyz` (same scale as
    /// the white). Never NaN for finite input: a post-adaptation response
    /// below the model's range (an achromatic signal A < 0, which only
    /// stimuli outside the spectrum locus reach) is treated as black.
    CamCorrelates correlates(const Vec3& xyz) const noexcept;

    /// CAM02-UCS (J', a', b') of a colour (Luo et al. 2006, K_L = 1,
    /// c1 = 0.007, c2 = 0.0228).
    Vec3 ucs(const Vec3& xyz) const noexcept;

    /// The degree of adaptation D in use.
    double degreeOfAdaptation() const noexcept { return m_d; }

private:
    Vec3 m_dRgb;  ///< per-channel von Kries factors D·Y_w/RGB_w + 1 − D
    double m_fl = 0.0, m_n = 0.0, m_nbb = 0.0, m_z = 0.0, m_aw = 0.0, m_d = 1.0;
    double m_c = 0.69, m_nc = 1.0;
};

/// CAM02-UCS (J', a', b') of CIECAM02 lightness J, colourfulness M and hue
/// angle h (degrees).
Vec3 JmhToCam02Ucs(double j, double m, double hDegrees) noexcept;

/// ΔE' in CAM02-UCS: the Euclidean distance of two (J', a', b').
double DeltaECam02Ucs(const Vec3& a, const Vec3& b) noexcept;

}  // namespace bandlight
