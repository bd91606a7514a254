// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Academy Spectral Similarity Index (SSI): how closely a light's
// spectral power distribution follows a reference's over 375–675 nm, for
// cameras rather than eyes (Academy of Motion Picture Arts and Sciences,
// Specification S-2018-001; Holm et al., "A Cinematographic Spectral
// Similarity Index", SMPTE 2016 Annual Technical Conference; SMPTE ST
// 2122:2020).

#include <string>
#include <vector>

#include "spectral/Spectrum.h"

namespace bandlight
{

/// The SSI of a test light against a reference.
struct SpectralSimilarity
{
    /// SSI rounded to an integer, as the Academy's specification reports
    /// it: 100 for a spectrum proportional to the reference over 375–675 nm,
    /// lower the more they differ (it can fall below 0).
    double ssi = 0.0;
    /// The same before rounding (useful to optimise a spectrum against).
    double unrounded = 0.0;
    /// The test light's CCT (K) when the reference was derived from it, else 0.
    double cctK = 0.0;
    /// "Planckian 3200 K", "CIE daylight 5600 K", or the caller's name.
    std::string referenceName;
    /// Conditions under which the figure means less, one sentence each.
    std::vector<std::string> warnings;
};

/// The default SSI reference at `cctK` (Academy S-2018-001): a Planckian
/// radiator up to 4000 K, CIE daylight from 5000 K to 25000 K, and between
/// them the luminance-matched blend of the two in proportion to the CCT's
/// place, as CIE 224:2017 forms its reference (ColourFidelityReference,
/// its luminances over 375–780 nm), on 375–675 nm at 1 nm. Throws Exception
/// outside 1000–25000 K.
Spectrum SsiReference(double cctK);

/// The name of SsiReference(cctK).
std::string SsiReferenceName(double cctK);

/// SSI of `test` against `reference` (both relative spectral power, any
/// scale and grid; each is interpolated linearly to 1 nm over 375–675 nm,
/// zero outside its data). Throws Exception when either has no positive
/// power in 375–675 nm.
SpectralSimilarity ComputeSpectralSimilarity(const Spectrum& test, const Spectrum& reference,
                                             const std::string& referenceName = "reference");

/// SSI of `test` against the default reference at its own CCT, the CCT the
/// colour fidelity figures use (ColourFidelityCct: CIE 1931, 380–780 nm).
/// Throws Exception outside 1000–25000 K.
SpectralSimilarity ComputeSpectralSimilarity(const Spectrum& test);

/// The rounded SSI of `test` against `reference`.
double ComputeSsi(const Spectrum& test, const Spectrum& reference);

}  // namespace bandlight
