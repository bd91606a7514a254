// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/BandModel.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"

namespace bandlight
{

BandRule ParseBandRule(const std::string& text)
{
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    if (t == "lecture" || t == "sample-mean" || t == "samples")
    {
        return BandRule::SAMPLE_MEAN;
    }
    if (t == "exact" || t == "integral")
    {
        return BandRule::EXACT;
    }
    throw Exception("unknown band rule '" + text + "' (lecture or exact)");
}

std::vector<double> BandMeans(const Spectrum& f, const BandSet& bands, BandRule rule)
{
    bands.validateRange(f.start(), f.end() + (rule == BandRule::SAMPLE_MEAN ? f.step() : 0.0),
                        "the spectrum");
    std::vector<double> out;
    out.reserve(bands.size());
    for (const Band& b : bands)
    {
        if (rule == BandRule::EXACT)
        {
            out.push_back(f.integrateLinear(b.minNm, b.maxNm) / b.width());
            continue;
        }
        // Samples with a ≤ λ < b; the small tolerance keeps grid points that
        // sit on an edge up to rounding on the side the rule puts them.
        const double eps = 1e-9 * f.step();
        const double first = std::ceil((b.minNm - f.start()) / f.step() - eps);
        const double last = std::ceil((b.maxNm - f.start()) / f.step() - eps) - 1.0;
        const double i0 = std::max(first, 0.0);
        const double i1 = std::min(last, double(f.size() - 1));
        if (i1 < i0)
        {
            throw Exception("band " + b.name + " holds no sample of a spectrum sampled every " +
                            std::to_string(f.step()) + " nm");
        }
        double s = 0.0;
        for (size_t i = size_t(i0); i <= size_t(i1); ++i)
        {
            s += f[i];
        }
        out.push_back(s / (i1 - i0 + 1.0));
    }
    return out;
}

std::vector<double> BandMeans(const LineSpectrum& lines, const BandSet& bands)
{
    std::vector<double> out;
    for (const Band& b : bands)
    {
        out.push_back(lines.powerIn(b.minNm, b.maxNm) / b.width());
    }
    return out;
}

std::vector<Spectrum> MatchingFunctionsOf(MatchingSet set, Observer observer)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    if (set == MatchingSet::XYZ)
    {
        return {cmf.x, cmf.y, cmf.z};
    }
    // r̄ḡb̄ = M_XYZ→RGB · x̄ȳz̄ (docs/science.md §1.2): the EBU RGB matching functions.
    const Mat3 m = RgbToXyzMatrix(Ebu3213Space().chromaticities).inverse();
    std::vector<Spectrum> rgb = {cmf.x * m(0, 0), cmf.x * m(1, 0), cmf.x * m(2, 0)};
    for (int k = 0; k < 3; ++k)
    {
        rgb[k] += cmf.y * m(k, 1);
        rgb[k] += cmf.z * m(k, 2);
    }
    return rgb;
}

Eigen::MatrixXd MatchingBandMatrix(const BandSet& bands, MatchingSet set, Observer observer,
                                   BandRule rule)
{
    const std::vector<Spectrum> fns = MatchingFunctionsOf(set, observer);
    Eigen::MatrixXd m(3, bands.size());
    for (int k = 0; k < 3; ++k)
    {
        const std::vector<double> means = BandMeans(fns[size_t(k)], bands, rule);
        double sum = 0.0;
        for (double v : means)
        {
            sum += v;
        }
        if (!(std::abs(sum) > 0.0))
        {
            throw Exception("matching function " + std::to_string(k + 1) +
                            " has zero band sum over bands " + bands.describe() +
                            ": it cannot be row-normalised");
        }
        for (size_t b = 0; b < means.size(); ++b)
        {
            m(k, Eigen::Index(b)) = means[b] / sum;
        }
    }
    return m;
}

std::vector<double> RemittanceBands(const Spectrum& remittance, const BandSet& bands, BandRule rule)
{
    return BandMeans(remittance, bands, rule);
}

std::vector<double> IlluminantBands(const Spectrum& illuminant, const BandSet& bands, BandRule rule)
{
    std::vector<double> means = BandMeans(illuminant, bands, rule);
    const double peak = *std::max_element(means.begin(), means.end());
    if (!(peak > 0.0) || !std::isfinite(peak))
    {
        throw Exception("illuminant has no power in bands " + bands.describe() +
                        ": it cannot be normalised to its largest band");
    }
    for (double& v : means)
    {
        v /= peak;
    }
    return means;
}

double ConditionNumber(const Eigen::MatrixXd& m)
{
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
    const auto& s = svd.singularValues();
    const double smin = s(s.size() - 1);
    return smin > 0.0 ? s(0) / smin : std::numeric_limits<double>::infinity();
}

void CheckBandCondition(const BandSet& bands, double condition)
{
    if (!std::isfinite(condition))
    {
        throw Exception("band matrix for bands " + bands.describe() + " nm is singular");
    }
    if (condition > MAX_BAND_CONDITION)
    {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3g", condition);
        throw Exception("band matrix for bands " + bands.describe() +
                        " nm is ill-conditioned: " + "condition number " + buf +
                        " exceeds the limit " + std::to_string(int(MAX_BAND_CONDITION)) +
                        " (band values would amplify pixel errors that much); widen the bands "
                        "the matching functions barely see");
    }
}

BandMatrix3 BandToColourMatrix(const BandSet& bands, MatchingSet set, Observer observer,
                               BandRule rule)
{
    if (bands.size() != 3)
    {
        throw Exception("a band → colour 3×3 needs three bands, got " +
                        std::to_string(bands.size()));
    }
    BandMatrix3 out;
    out.toColour = MatchingBandMatrix(bands, set, observer, rule);
    out.conditionNumber = ConditionNumber(out.toColour);
    CheckBandCondition(bands, out.conditionNumber);
    out.fromColour = out.toColour.inverse();
    return out;
}

}  // namespace bandlight
