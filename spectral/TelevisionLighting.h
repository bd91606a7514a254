// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// EBU TLCI-2012 (Television Lighting Consistency Index) and TLMF-2013
// (Television Luminaire Matching Factor), as EBU Tech 3355 (March 2017)
// defines them and EBU R 137 recommends them: how far a light moves the
// colours of a chart, seen by a standard television camera and shown on a
// standard display, from those under a reference light.
//
// The model, shared by both (Tech 3355 §1.2–1.5), on 380–760 nm at 5 nm:
//  - the chart: the 24 ColorChecker reflectances of Tech 3355 Appendix 4
//    (TLCI scores the 18 coloured patches, TLMF all 24);
//  - the EBU standard camera: the Appendix 5 sensitivities, white-balanced
//    so that a flat 90 % reflector gives R = G = B = 1, then the linear
//    matrix of Appendix 5, a saturation matrix at S = 90 % (diagonal 14/15,
//    elsewhere 1/30), and the BT.709 OETF. Signals may rise above nominal
//    white up to code 255 of 8-bit studio swing, 239/219 (Tech 3355 §2, eq.
//    [61]); a patch whose matrixed signal goes negative under either light is
//    left out of the score (§1.5.1);
//  - the display: BT.709 primaries and D65 white, gamma 2.4; CIELAB
//    relative to that white, CIEDE2000 per patch (kL = kC = kH = 1);
//  - ΔEa = (Σ ΔE⁴ / n)^(1/4), Qa = 100 / (1 + (ΔEa / 3.16)^2.4).
//
// TLCI's reference (§1.1): the light's CCT is found against Tech 3355's own
// tabulated Planckian and daylight loci (Appendix 2); below 3400 K the
// reference is Planck's law (eq. [9], c2 = 1.435e7 nm·K), on the daylight
// locus (5000 K and up) Tech 3355's daylight (Appendix 3 vectors, its M1/M2
// coefficients), and from 3400 K to 5000 K a blend of Planckian 3400 K and
// daylight 5000 K in proportion to the CCT (§1.1.2.3). The camera is
// white-balanced on each light separately.
//
// TLMF's convention (§1.3.1): the camera is white-balanced on the reference
// light the user names, and the test light is seen through that same
// balance — a fixture matching the key light on camera without re-balancing.
// Only its exposure is matched: the test light is scaled so that the 90 %
// reflector under it gives luma Y = 1, the BT.709 luma of the camera signal
// after the linear matrix and before the saturation matrix (as
// colour-science reads §1.3.1; the place matters only when the test light is
// not neutral on camera).
//
// Light spectra may be on any grid and at any scale (results do not depend on
// the scale). Tech 3355 computes at 5 nm; a light on another grid is brought
// onto it as a spectroradiometer reporting every 5 nm would have measured it,
// through a triangular bandpass 5 nm wide at half height (the bandwidth equal
// to the interval, as CIE practice asks), which is also the exact integral of
// the light against the linear interpolants of the 5 nm tables. A narrow line
// therefore keeps its power wherever it falls. For narrow-band LEDs this
// differs from taking every fifth sample of a 1 nm file (by 0.7 in Qa for
// 14 nm-wide lobes, under 0.1 for phosphor whites); to take the samples at
// the 5 nm wavelengths instead, resample the light onto 380–760 nm at 5 nm
// first (Spectrum::resampled), whose samples are then used as they are.

#include <string>
#include <vector>

#include "spectral/Spectrum.h"

namespace bandlight
{

/// A TLCI-2012 or TLMF-2013 result.
struct TelevisionLightingScore
{
    /// Qa, 0–100: 100 when every patch looks as under the reference; 50 at
    /// ΔEa = 3.16, below which the EBU warns that colour correction may not
    /// make the pictures acceptable.
    double qa = 0.0;
    /// The test light's correlated colour temperature, K, found against Tech
    /// 3355's Appendix 2 loci (TLCI's reference is chosen by it; for TLMF it
    /// is given for information only).
    double cctK = 0.0;
    /// The test light's distance from that locus in Tech 3355's units
    /// (1 = 0.0054 in CIE 1960 u, v, CIE 13.3's limit), negative on the green
    /// side of the locus and positive towards magenta, as Tech 3355 §1.1.1
    /// and eqs. [16]–[17] print it (EBU's TLCI application shows the opposite
    /// sign). Above 1 in magnitude the CCT, and TLCI's reference, are uncertain.
    double d = 0.0;
    /// (Σ ΔE⁴ / n)^(1/4) over the patches scored.
    double deltaEa = 0.0;
    /// CIEDE2000 of each patch, in chart order (18 for TLCI, 24 for TLMF);
    /// NaN where the patch was excluded (a negative camera signal).
    std::vector<double> deltaE;
    /// The reference light: TLCI's, described ("Planckian 2856 K ..."), or
    /// the name TLMF was given.
    std::string referenceName;
    /// What makes the score less reliable, one sentence each: |d| > 1, a CCT
    /// beyond the loci's tables, excluded patches, data not covering
    /// 380–760 nm or coarser than 5 nm.
    std::vector<std::string> warnings;
};

/// TLCI-2012 of a light (relative spectral power, any grid and scale).
/// Throws Exception for a spectrum with values that are not finite, with no
/// light the standard camera sees in one of its channels (no white balance is
/// possible), or with every patch excluded.
TelevisionLightingScore ComputeTlci(const Spectrum& light);

/// TLMF-2013 of `test` against `reference` (both relative spectral power, any
/// grid and scale), `referenceName` naming the reference in the result. The
/// camera is balanced on the reference and the test light's exposure matched
/// (see the convention above). Throws Exception as ComputeTlci does.
TelevisionLightingScore ComputeTlmf(const Spectrum& test, const Spectrum& reference,
                                    const std::string& referenceName = "reference light");

/// The 24 patches of Tech 3355's chart, in order ("dark skin" … "black 2");
/// TLCI scores the first 18.
const std::vector<std::string>& TelevisionChartPatchNames();

}  // namespace bandlight
