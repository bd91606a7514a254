// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Spectrum.h"
#include "transforms/BandSet.h"

namespace bandlight
{

/// How a band mean m_b(f) = (1/Δλ_b) ∫_b f(λ) dλ is evaluated.
enum class BandRule
{
    /// The band model's rule (docs/science.md §1.2): the average of the samples with
    /// a ≤ λ < b. The default; reproduces the band model's tables.
    SAMPLE_MEAN,
    /// Exact integral of the piecewise-linear spectrum over [a, b] / (b - a).
    EXACT,
};

/// "lecture"/"sample-mean" or "exact"; throws Exception otherwise.
BandRule ParseBandRule(const std::string& text);

/// Band means of a sampled spectrum, one per band. Throws Exception when a
/// band lies outside the spectrum's range, or (SAMPLE_MEAN) holds no sample.
std::vector<double> BandMeans(const Spectrum& f, const BandSet& bands,
                              BandRule rule = BandRule::SAMPLE_MEAN);

/// Band means of emission lines: each line's power divided by the width of
/// the one band that holds it (exact; lines outside every band are dropped).
std::vector<double> BandMeans(const LineSpectrum& lines, const BandSet& bands);

/// The matching functions the band matrix is built from.
enum class MatchingSet
{
    XYZ,      ///< x̄ ȳ z̄ of the chosen observer
    EBU_RGB,  ///< r̄ ḡ b̄: x̄ȳz̄ converted to EBU Tech 3213 primaries, D65 white
};

/// The three matching functions of a set, as sampled spectra.
std::vector<Spectrum> MatchingFunctionsOf(MatchingSet set, Observer observer);

/// The row-normalised matching-function band matrix (3 × bands): entry
/// (k, b) is the band mean of matching function k in band b divided by the
/// sum of its row, so that an equal-energy source on an ideal white surface
/// (band values all 1) gives the valence (1, 1, 1) (docs/science.md §1.2).
Eigen::MatrixXd MatchingBandMatrix(const BandSet& bands, MatchingSet set, Observer observer,
                                   BandRule rule = BandRule::SAMPLE_MEAN);

/// Remittance band means (O_B, O_G, O_R, ...): raw, not normalised.
std::vector<double> RemittanceBands(const Spectrum& remittance, const BandSet& bands,
                                    BandRule rule = BandRule::SAMPLE_MEAN);

/// Illuminant band means (I_B, I_G, I_R, ...): normalised to the largest band = 1.
/// Throws Exception when every band mean is zero or any is not finite.
std::vector<double> IlluminantBands(const Spectrum& illuminant, const BandSet& bands,
                                    BandRule rule = BandRule::SAMPLE_MEAN);

/// A 3-band → colour (XYZ or RGB) matrix with its inverse and its 2-norm
/// condition number σ_max / σ_min.
struct BandMatrix3
{
    Mat3 toColour;
    Mat3 fromColour;
    double conditionNumber = 0.0;
};

/// The band → XYZ (MatchingSet::XYZ) or band → EBU RGB matrix of a
/// three-band set, i.e. MatchingBandMatrix as a 3×3, inverted. Throws
/// Exception when the set has not three bands or the matrix is singular.
BandMatrix3 BandToColourMatrix(const BandSet& bands, MatchingSet set, Observer observer,
                               BandRule rule = BandRule::SAMPLE_MEAN);

/// 2-norm condition number σ_max / σ_min of any matrix (infinite if singular).
double ConditionNumber(const Eigen::MatrixXd& m);

/// The largest condition number of a band matrix the band methods accept.
/// A band value solved from a pixel carries up to this many times the
/// pixel's relative error; the band model's bands give 4.3, ten equal bands
/// over 400–700 nm 5.2, and sets with a band the matching functions barely
/// see (380–390–400–780 nm: 1.4e5) are refused.
constexpr double MAX_BAND_CONDITION = 1000.0;

/// Throws Exception naming the band set, its condition number and the limit
/// when `condition` exceeds MAX_BAND_CONDITION (or is not finite).
void CheckBandCondition(const BandSet& bands, double condition);

}  // namespace bandlight
