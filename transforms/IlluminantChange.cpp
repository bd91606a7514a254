// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/IlluminantChange.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "transforms/BandModel.h"

namespace bandlight
{

namespace
{

std::string Lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

/// Band model matrix B (3 × N, rows normalised) and its Moore–Penrose
/// pseudo-inverse (the ordinary inverse for three bands).
struct BandBasis
{
    Eigen::MatrixXd b;
    Eigen::MatrixXd pinv;
};

BandBasis MakeBandBasis(const BandSet& bands, Observer observer)
{
    BandBasis out;
    out.b = MatchingBandMatrix(bands, MatchingSet::XYZ, observer);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(out.b, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const auto& s = svd.singularValues();
    if (s(s.size() - 1) <= 1e-12 * s(0))
    {
        throw Exception("band matrix for bands " + bands.describe() + " is singular");
    }
    out.pinv = svd.matrixV() * s.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
    return out;
}

Vec3 WhiteOf(const Light& light, Observer observer)
{
    const Vec3 w = IntegrateXyz(light.spectrum, observer);
    if (!(w.y() > 0.0) || !w.allFinite())
    {
        throw Exception("illuminant " + light.name + " has no luminance: no white to adapt from");
    }
    return w / w.y();
}

}  // namespace

MethodSpec ParseMethod(const std::string& name)
{
    const std::string n = Lower(name);
    MethodSpec m;
    m.name = n;
    if (n == "none")
    {
        m.method = ChangeMethod::NONE;
    }
    else if (n == "vonkries")
    {
        m.method = ChangeMethod::VON_KRIES;
    }
    else if (n == "bradford")
    {
        m.method = ChangeMethod::BRADFORD;
    }
    else if (n == "cat02")
    {
        m.method = ChangeMethod::CAT02;
    }
    else if (n.rfind("band", 0) == 0)
    {
        std::string rest = n.substr(4);
        m.method = ChangeMethod::BAND;
        const size_t dash = rest.find("-wp");
        if (dash != std::string::npos && dash + 3 == rest.size())
        {
            m.method = ChangeMethod::BAND_WP;
            rest = rest.substr(0, dash);
        }
        const bool digits =
            !rest.empty() && rest.size() <= 3 && std::all_of(rest.begin(), rest.end(), ::isdigit);
        const int count = digits ? std::stoi(rest) : 0;
        if (count < 3 || count > 300)
        {
            throw Exception("unknown method '" + name +
                            "': band methods are bandN or bandN-wp with 3 <= N <= 300");
        }
        m.bands = count == 3 ? BandSet::Lecture() : BandSet::Equal(size_t(count), 400.0, 700.0);
    }
    else
    {
        throw Exception("unknown method '" + name +
                        "' (none, vonkries, bradford, cat02, band3, band3-wp, bandN, bandN-wp)");
    }
    return m;
}

const std::vector<std::string>& LinearMethodNames()
{
    static const std::vector<std::string> names = {"none",  "vonkries", "bradford",
                                                   "cat02", "band3",    "band3-wp"};
    return names;
}

std::string DescribeMethod(const MethodSpec& m)
{
    switch (m.method)
    {
        case ChangeMethod::NONE:
            return "Identity: the image is left as it is (the baseline every method is "
                   "compared with).";
        case ChangeMethod::VON_KRIES:
            return "von Kries scaling of XYZ by the ratio of the two white points: exact on "
                   "white, the crudest chromatic adaptation for colours.";
        case ChangeMethod::BRADFORD:
            return "Bradford chromatic adaptation (linearised): exact on white; the usual "
                   "white-balance matrix, good for broadband lights.";
        case ChangeMethod::CAT02:
            return "CAT02 chromatic adaptation (CIECAM02): exact on white; similar to Bradford.";
        case ChangeMethod::BAND:
        {
            std::ostringstream s;
            s << "The lecture's " << m.bands.size() << "-band model: each band ("
              << m.bands.describe()
              << " nm) scaled by the ratio of the lights' band means, white luminance kept; "
                 "not exact on white, wrong where lights and surfaces are spiky.";
            return s.str();
        }
        case ChangeMethod::BAND_WP:
        {
            std::ostringstream s;
            s << m.bands.size() << "-band model (" << m.bands.describe()
              << " nm) with ratios from the band coordinates of the two whites: exact on white, "
                 "a diagonal in band space for colours.";
            return s.str();
        }
    }
    return {};
}

Eigen::MatrixXd WorkingToBandMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer)
{
    return MakeBandBasis(bands, observer).pinv * RgbToXyzMatrix(working.chromaticities);
}

Eigen::MatrixXd BandToWorkingMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer)
{
    return RgbToXyzMatrix(working.chromaticities).inverse() *
           MatchingBandMatrix(bands, MatchingSet::XYZ, observer);
}

Mat3 MaterialTintMatrix(const std::vector<double>& remittance, const BandSet& bands,
                        const RgbSpace& working, Observer observer)
{
    if (remittance.size() != bands.size())
    {
        throw Exception("material tint: " + std::to_string(remittance.size()) +
                        " remittance values for " + std::to_string(bands.size()) + " bands");
    }
    const Eigen::VectorXd r =
        Eigen::Map<const Eigen::VectorXd>(remittance.data(), Eigen::Index(remittance.size()));
    return BandToWorkingMatrix(bands, working, observer) * r.asDiagonal() *
           WorkingToBandMatrix(bands, working, observer);
}

Mat3 IlluminantChangeMatrix(const Light& from, const Light& to, const MethodSpec& method,
                            const RgbSpace& working, Observer observer)
{
    const Mat3 m = RgbToXyzMatrix(working.chromaticities);
    const Mat3 mInv = m.inverse();
    switch (method.method)
    {
        case ChangeMethod::NONE:
            return Mat3::Identity();
        case ChangeMethod::VON_KRIES:
        case ChangeMethod::BRADFORD:
        case ChangeMethod::CAT02:
        {
            const AdaptationMethod cat =
                method.method == ChangeMethod::VON_KRIES  ? AdaptationMethod::XYZ_SCALING
                : method.method == ChangeMethod::BRADFORD ? AdaptationMethod::BRADFORD
                                                          : AdaptationMethod::CAT02;
            return mInv * AdaptationMatrix(WhiteOf(from, observer), WhiteOf(to, observer), cat) * m;
        }
        case ChangeMethod::BAND:
        case ChangeMethod::BAND_WP:
            break;
    }
    const BandSet& bands = method.bands;
    const BandBasis basis = MakeBandBasis(bands, observer);
    Eigen::VectorXd ratio(Eigen::Index(bands.size()));
    if (method.method == ChangeMethod::BAND)
    {
        const std::vector<double> i1 = IlluminantBands(from.spectrum, bands);
        const std::vector<double> i2 = IlluminantBands(to.spectrum, bands);
        Eigen::VectorXd e1(ratio.size()), e2(ratio.size());
        for (size_t b = 0; b < bands.size(); ++b)
        {
            if (!(i1[b] > 0.0))
            {
                throw Exception("illuminant " + from.name + " has no power in band " +
                                bands[b].name + ": the band ratio " + to.name + "/" + from.name +
                                " is undefined");
            }
            ratio(Eigen::Index(b)) = i2[b] / i1[b];
            e1(Eigen::Index(b)) = i1[b];
            e2(Eigen::Index(b)) = i2[b];
        }
        // Keep the exposure: the band model's white under `from` keeps its Y.
        const double y1 = (basis.b * e1)(1);
        const double y2 = (basis.b * e2)(1);
        ratio *= y1 / y2;
    }
    else
    {
        const Eigen::VectorXd c1 = basis.pinv * WhiteOf(from, observer);
        const Eigen::VectorXd c2 = basis.pinv * WhiteOf(to, observer);
        for (Eigen::Index b = 0; b < ratio.size(); ++b)
        {
            if (!(c1(b) > 0.0) || !(c2(b) > 0.0))
            {
                throw Exception("band-wp: a white has a non-positive band coordinate in band " +
                                bands[size_t(b)].name + " (" + from.name + " → " + to.name +
                                "): no white-preserving band ratio exists");
            }
            ratio(b) = c2(b) / c1(b);
        }
    }
    return mInv * basis.b * ratio.asDiagonal() * basis.pinv * m;
}

}  // namespace bandlight
