// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Colour fidelity of a light source: CIE 224:2017 (the CIE 2017 colour
// fidelity index Rf) and ANSI/IES TM-30-18/-20 (Rf, the gamut index Rg and
// the 16 hue-bin figures), which share one computation: the 99 colour
// evaluation samples (CES) under the test light and under a reference
// illuminant of the same CCT, compared in CAM02-UCS for the CIE 1964 10°
// observer over 380–780 nm.

#include <array>
#include <string>
#include <vector>

#include "spectral/ColourRendering.h"
#include "spectral/Spectrum.h"

namespace bandlight
{

/// Number of colour evaluation samples (CIE 224:2017, TM-30-18).
constexpr size_t CES_COUNT = 99;
/// Number of TM-30 hue bins, each 22.5° of reference hue wide.
constexpr size_t HUE_BIN_COUNT = 16;

/// The two standards define one computation, but their reference
/// calculators treat a light given at 5 nm differently, as their published
/// figures for CIE FL2 show: the CIE's spreadsheet for CIE 224:2017 gives
/// those of an evaluation at 5 nm (the CES and the observer at 5 nm), the
/// IES's TM-30-18 calculator those of the light interpolated linearly to
/// 1 nm (Rf 70.12 against 70.21, Rf,i up to 0.2 apart). For data at 1 nm
/// both agree; data on any other grid both interpolate linearly to 1 nm.
enum class FidelityMethod
{
    CIE_224,  ///< as the CIE 224:2017 calculator: 5 nm data evaluated at 5 nm
    TM_30,    ///< as the ANSI/IES TM-30-18 calculator: every grid brought to 1 nm
};

/// Colour fidelity and gamut figures of a light source.
struct ColourFidelity
{
    /// How the figures were computed (see FidelityMethod).
    FidelityMethod method = FidelityMethod::CIE_224;
    /// CCT (K) and Duv of the test light over 380–780 nm, CIE 1931 2°
    /// observer in CIE 1960 (u, v): ColourFidelityCct, by ComputeCct (to
    /// better than 0.01 K) where CIE 224:2017 names Ohno's 2013 method.
    double cctK = 0.0;
    double duv = 0.0;
    /// General colour fidelity index Rf (CIE 224:2017; TM-30 Rf),
    /// 0–100, from the mean ΔE' of the 99 samples.
    double rf = 0.0;
    /// TM-30 gamut index Rg: 100 × the area of the polygon of the 16 bins'
    /// mean (a', b') under the test light over that under the reference.
    double rg = 0.0;
    /// Special colour fidelity index Rf,i of each CES, in CES order.
    std::array<double, CES_COUNT> rfSample{};
    /// TM-30 local colour fidelity Rf,hj of each hue bin j (bin 0 holds
    /// reference hues 0–22.5°, bin 15 337.5–360°). This and the other
    /// per-bin figures are NaN for a bin that holds no sample, which happens
    /// only below about 1150 K (a warning says so).
    std::array<double, HUE_BIN_COUNT> rfHue{};
    /// TM-30 local chroma shift Rcs,hj as a fraction (−0.25 where TM-30
    /// prints −25 %): the shift of the bin's mean along the bin's middle
    /// direction, over the reference mean's chroma.
    std::array<double, HUE_BIN_COUNT> chromaShift{};
    /// TM-30 local hue shift Rhs,hj, dimensionless as TM-30 prints it: the
    /// shift across the bin's middle direction over the reference mean's
    /// chroma (for small shifts the hue angle change in radians).
    std::array<double, HUE_BIN_COUNT> hueShift{};
    /// Mean CAM02-UCS (a', b') of each bin's samples under the test light and
    /// under the reference, unnormalised: the colour vector graphic of TM-30
    /// divides both by the reference mean's chroma.
    std::array<std::array<double, 2>, HUE_BIN_COUNT> testBinAb{};
    std::array<std::array<double, 2>, HUE_BIN_COUNT> referenceBinAb{};
    /// Which reference was used: "Planckian 3288 K", "CIE daylight 6504 K"
    /// or "blend at 4225 K: 77 % Planckian, 23 % CIE daylight".
    std::string referenceName;
    /// True when |Duv| > 0.02: the light is far enough from the Planckian
    /// locus that a reference of the same CCT, and so Rf and Rg, says little.
    bool outsideTolerance = false;
    /// Each condition under which the figures are less meaningful or were
    /// computed from data the standards do not ask for, one sentence each.
    std::vector<std::string> warnings;
};

/// The reference illuminant of CIE 224:2017 and TM-30-18 at `cctK`: a
/// Planckian radiator (Planckian()) up to 4000 K, CIE daylight (Daylight(),
/// interpolated linearly from its 5 nm basis) from 5000 K, and
/// between them the mix (5000 − T)/1000 · P + (T − 4000)/1000 · D of the two,
/// each first normalised to the same luminance (CIE 1931 Y). Returned on the
/// given grid (by default 380–780 nm at 1 nm), normalised to Y = 100 (CIE
/// 1931) on that grid. Throws Exception outside 1000–25000 K, where the
/// standards define no reference (CIE daylight ends at 25000 K).
Spectrum ColourFidelityReference(double cctK, double startNm = 380.0, double stepNm = 1.0,
                                 size_t count = 401);

/// Names the reference of ColourFidelityReference at `cctK`.
std::string ColourFidelityReferenceName(double cctK);

/// The CCT and Duv the fidelity figures use: CIE 1931 2° (CIE 15:2004
/// §9.5, ComputeCct) of the light over 380–780 nm on the grid `method`
/// evaluates it on (see ComputeColourFidelity), from the 1 nm tables. Throws
/// Exception for a light with no power there.
CctDuv ColourFidelityCct(const Spectrum& light, FidelityMethod method = FidelityMethod::CIE_224);

/// CIE 224:2017 / TM-30-18 colour fidelity of a light of relative spectral
/// power `light` (any scale, any grid). With FidelityMethod::CIE_224 a light
/// on a 5 nm grid aligned to 380 nm is evaluated at 5 nm as given; every
/// other case is interpolated linearly to 1 nm (see FidelityMethod). Data
/// missing from 380–780 nm count as zero (and add a warning). Throws
/// Exception when the light has no chromaticity or its CCT lies outside
/// 1000–25000 K.
ColourFidelity ComputeColourFidelity(const Spectrum& light,
                                     FidelityMethod method = FidelityMethod::CIE_224);

}  // namespace bandlight
