// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/ColourRendering.h"

#include <cmath>
#include <vector>

#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/GoldenSection.h"
#include "spectral/Illuminants.h"

namespace bandlight
{

Eigen::Vector2d PlanckianUv(double kelvin)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
    Vec3 xyz = Vec3::Zero();
    for (size_t i = 0; i < cmf.x.size(); ++i)
    {
        const double l = cmf.x.wavelength(i);
        xyz += PlanckRadiance(l, kelvin) * Vec3(cmf.x[i], cmf.y[i], cmf.z[i]);
    }
    return XyzToUv1960(xyz);
}

namespace
{

constexpr double kMinKelvin = 1000.0;
constexpr double kMaxKelvin = 100000.0;

/// The locus tabulated every 1 mired (1e6 / T) from kMaxKelvin to kMinKelvin,
/// computed once: the coarse stage of the search.
const std::vector<Eigen::Vector2d>& LocusTable()
{
    static const std::vector<Eigen::Vector2d> table = []
    {
        std::vector<Eigen::Vector2d> t;
        for (double mired = 1e6 / kMaxKelvin; mired <= 1e6 / kMinKelvin + 1e-9; mired += 1.0)
        {
            t.push_back(PlanckianUv(1e6 / mired));
        }
        return t;
    }();
    return table;
}

}  // namespace

CctDuv ComputeCct(const Vec3& xyz)
{
    if (!xyz.allFinite() || xyz.x() + 15.0 * xyz.y() + 3.0 * xyz.z() <= 0.0)
    {
        throw Exception("CCT: the stimulus has no chromaticity (XYZ is zero or not finite)");
    }
    const Eigen::Vector2d uv = XyzToUv1960(xyz);
    const std::vector<Eigen::Vector2d>& table = LocusTable();
    const double mired0 = 1e6 / kMaxKelvin;
    size_t best = 0;
    for (size_t i = 1; i < table.size(); ++i)
    {
        if ((table[i] - uv).squaredNorm() < (table[best] - uv).squaredNorm())
        {
            best = i;
        }
    }
    // Golden-section refinement on the exact locus within ±1 mired of the best node.
    double lo = std::max(mired0, mired0 + double(best) - 1.0);
    double hi = std::min(1e6 / kMinKelvin, mired0 + double(best) + 1.0);
    auto dist2 = [&](double mired) { return (PlanckianUv(1e6 / mired) - uv).squaredNorm(); };
    const GoldenSectionResult r = GoldenSectionMinimum(dist2, lo, hi, 1e-7);
    const double mired = 0.5 * (r.lo + r.hi);
    const Eigen::Vector2d p = PlanckianUv(1e6 / mired);
    const double d = (uv - p).norm();
    return {1e6 / mired, uv.y() >= p.y() ? d : -d};
}

namespace
{

/// c and d of CIE 13.3 eq. (6) for a (u, v) chromaticity.
Eigen::Vector2d CieCd(const Eigen::Vector2d& uv)
{
    const double u = uv.x(), v = uv.y();
    return {(4.0 - u - 10.0 * v) / v, (1.708 * v + 0.404 - 1.481 * u) / v};
}

Vec3 Uvw(const Vec3& xyz, const Eigen::Vector2d& uv, const Eigen::Vector2d& whiteUv)
{
    const double w = 25.0 * std::cbrt(xyz.y()) - 17.0;
    return {13.0 * w * (uv.x() - whiteUv.x()), 13.0 * w * (uv.y() - whiteUv.y()), w};
}

}  // namespace

ColourRendering ComputeColourRendering(const Spectrum& illuminant)
{
    const Observer obs = Observer::CIE1931_2DEG;
    const CctDuv cct = ComputeCct(IntegrateXyz(illuminant, obs));
    if (cct.cctK < kMinKelvin || cct.cctK > 25000.0)
    {
        throw Exception("colour rendering index: CCT " + std::to_string(cct.cctK) +
                        " K is outside 1000–25000 K, where CIE 13.3 defines a reference");
    }
    const Spectrum reference = cct.cctK < 5000.0 ? Planckian(cct.cctK, illuminant.start(),
                                                             illuminant.step(), illuminant.size())
                                                 : Daylight(cct.cctK).resampledLike(illuminant);

    const XyzIntegrator test(illuminant, obs);
    const XyzIntegrator ref(reference, obs);
    const Vec3 testWhite = IlluminantWhiteXyz(illuminant, obs);
    const Vec3 refWhite = IlluminantWhiteXyz(reference, obs);
    const Eigen::Vector2d uvk = XyzToUv1960(testWhite);
    const Eigen::Vector2d uvr = XyzToUv1960(refWhite);
    const Eigen::Vector2d cdk = CieCd(uvk);
    const Eigen::Vector2d cdr = CieCd(uvr);

    ColourRendering out;
    out.cctK = cct.cctK;
    out.duv = cct.duv;
    out.outsideTolerance = std::abs(cct.duv) > 5.4e-3;
    const std::vector<NamedSpectrum>& tcs = TestColourSamples();
    double sum8 = 0.0;
    for (size_t i = 0; i < out.r.size(); ++i)
    {
        const Vec3 xyzR = ref(tcs[i].spectrum);
        const Vec3 xyzK = test(tcs[i].spectrum);
        // Von Kries adaptation of the sample under the test source to the
        // reference (CIE 13.3 eq. 7).
        const Eigen::Vector2d cdki = CieCd(XyzToUv1960(xyzK));
        const double c = cdr.x() / cdk.x() * cdki.x();
        const double d = cdr.y() / cdk.y() * cdki.y();
        const double den = 16.518 + 1.481 * c - d;
        const Eigen::Vector2d uvAdapted((10.872 + 0.404 * c - 4.0 * d) / den, 5.520 / den);
        const Vec3 uvwK = Uvw(xyzK, uvAdapted, uvr);
        const Vec3 uvwR = Uvw(xyzR, XyzToUv1960(xyzR), uvr);
        out.r[i] = 100.0 - 4.6 * (uvwK - uvwR).norm();
        if (i < 8)
        {
            sum8 += out.r[i];
        }
    }
    out.ra = sum8 / 8.0;
    return out;
}

}  // namespace bandlight
