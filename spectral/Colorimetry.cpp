// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Colorimetry.h"

#include <cmath>

namespace bandlight
{

namespace
{

// A stimulus coarser than the matching functions' tables, brought onto
// their grid. Summed at its own samples, a lamp given every 100 nm would be
// weighed at five wavelengths of the matching functions (equal energy came
// out at x 0.365), and one given at steps wider than the visible range at
// none. It is integrated through its linear interpolant on the tables' grid
// instead, the one resampler every spectrum goes through
// (Spectrum::resampled), as remittances are: exact for a spectrum that is
// linear between its samples, equal energy included. A stimulus as fine as
// the tables or finer is returned as it is.
Spectrum OnTableGrid(const Spectrum& stimulus, const MatchingFunctions& cmf)
{
    const double table = cmf.x.step();
    if (!(stimulus.step() > table * (1.0 + 1e-9)) || stimulus.size() < 2)
    {
        return stimulus;
    }
    const double first =
        cmf.x.start() + std::ceil((stimulus.start() - cmf.x.start()) / table - 1e-9) * table;
    const size_t count = size_t(std::floor((stimulus.end() - first) / table + 1e-9)) + 1;
    return stimulus.resampled(first, table, count);
}

}  // namespace

Vec3 IntegrateXyz(const Spectrum& stimulus, Observer observer)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    if (stimulus.step() > cmf.x.step() * (1.0 + 1e-9) && stimulus.size() > 1)
    {
        return IntegrateXyz(OnTableGrid(stimulus, cmf), observer);
    }
    Vec3 xyz = Vec3::Zero();
    const double offset = (stimulus.start() - cmf.x.start()) / cmf.x.step();
    const bool aligned = std::abs(stimulus.step() - cmf.x.step()) < 1e-9 &&
                         std::abs(offset - std::round(offset)) < 1e-9;
    if (aligned)
    {
        // Same grid up to an offset: the tabulated values, no interpolation.
        const long shift = std::lround(offset);
        for (size_t i = 0; i < stimulus.size(); ++i)
        {
            const long j = long(i) + shift;
            if (j >= 0 && size_t(j) < cmf.x.size())
            {
                xyz += stimulus[i] * Vec3(cmf.x[size_t(j)], cmf.y[size_t(j)], cmf.z[size_t(j)]);
            }
        }
        return xyz * stimulus.step();
    }
    for (size_t i = 0; i < stimulus.size(); ++i)
    {
        const double l = stimulus.wavelength(i);
        xyz += stimulus[i] * Vec3(cmf.x(l), cmf.y(l), cmf.z(l));
    }
    return xyz * stimulus.step();
}

Vec3 IntegrateXyz(const LineSpectrum& lines, Observer observer)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    return Vec3(lines.integrate(cmf.x), lines.integrate(cmf.y), lines.integrate(cmf.z));
}

Vec3 SurfaceXyz(const Spectrum& reflectance, const Spectrum& illuminant, Observer observer)
{
    // A light coarser than the tables is brought onto their grid before the
    // surface multiplies it, so that light and surface are weighed where the
    // matching functions are, as the light's own white is.
    const Spectrum light = OnTableGrid(illuminant, GetMatchingFunctions(observer));
    const Spectrum r = reflectance.extended(light.start(), light.end());
    Spectrum product = light;
    product *= r;
    const Vec3 white = IntegrateXyz(light, observer);
    return IntegrateXyz(product, observer) * (100.0 / white.y());
}

Vec3 IlluminantWhiteXyz(const Spectrum& illuminant, Observer observer)
{
    const Vec3 white = IntegrateXyz(illuminant, observer);
    return white * (100.0 / white.y());
}

Vec3 EqualEnergyNormalisedXyz(const Spectrum& stimulus, Observer observer)
{
    // Divide by the equal-energy stimulus on the same grid, so that φ = 1
    // gives exactly (1, 1, 1) whatever range the data cover.
    const Spectrum one =
        Spectrum::Constant(stimulus.start(), stimulus.step(), stimulus.size(), 1.0);
    return IntegrateXyz(stimulus, observer).cwiseQuotient(IntegrateXyz(one, observer));
}

XyzIntegrator::XyzIntegrator(const Spectrum& illuminant, Observer observer)
    : XyzIntegrator(OnTableGrid(illuminant, GetMatchingFunctions(observer)),
                    GetMatchingFunctions(observer))
{
}

XyzIntegrator::XyzIntegrator(const Spectrum& light, const MatchingFunctions& cmf)
    : m_wx(light), m_wy(light), m_wz(light)
{
    m_wx *= cmf.x;
    m_wy *= cmf.y;
    m_wz *= cmf.z;
    const double k = 100.0 / m_wy.sum();
    m_wx *= k * light.step();
    m_wy *= k * light.step();
    m_wz *= k * light.step();
}

Vec3 XyzIntegrator::integrate(const double* values) const noexcept
{
    // Eigen's dot products use packet (SIMD) partial sums.
    using Map = Eigen::Map<const Eigen::VectorXd>;
    const Eigen::Index n = Eigen::Index(m_wx.size());
    const Map v(values, n);
    return Vec3(Map(m_wx.values().data(), n).dot(v), Map(m_wy.values().data(), n).dot(v),
                Map(m_wz.values().data(), n).dot(v));
}

Vec3 XyzIntegrator::operator()(const Spectrum& reflectance) const
{
    if (reflectance.sameGrid(m_wx))
    {
        return integrate(reflectance.values().data());
    }
    const Spectrum r = reflectance.extended(m_wx.start(), m_wx.end()).resampledLike(m_wx);
    return integrate(r.values().data());
}

Vec3 XyzToxyY(const Vec3& xyz) noexcept
{
    const double s = xyz.sum();
    if (s == 0.0)
    {
        return Vec3::Zero();
    }
    return Vec3(xyz.x() / s, xyz.y() / s, xyz.y());
}

Vec3 xyYToXyz(const Vec3& xyY) noexcept
{
    if (xyY.y() == 0.0)
    {
        return Vec3::Zero();
    }
    const double Y = xyY.z();
    return Vec3(xyY.x() * Y / xyY.y(), Y, (1.0 - xyY.x() - xyY.y()) * Y / xyY.y());
}

Eigen::Vector2d XyzToUv1960(const Vec3& xyz) noexcept
{
    const double d = xyz.x() + 15.0 * xyz.y() + 3.0 * xyz.z();
    if (d == 0.0)
    {
        return Eigen::Vector2d::Zero();
    }
    return Eigen::Vector2d(4.0 * xyz.x() / d, 6.0 * xyz.y() / d);
}

namespace
{
// CIE 15:2004 §8.2.1: f(t) = t^(1/3) above (24/116)^3, linear below.
constexpr double kEpsilon = 216.0 / 24389.0;
constexpr double kKappa = 24389.0 / 27.0;

double LabF(double t) noexcept
{
    return t > kEpsilon ? std::cbrt(t) : (kKappa * t + 16.0) / 116.0;
}

double LabFInverse(double f) noexcept
{
    const double t = f * f * f;
    return t > kEpsilon ? t : (116.0 * f - 16.0) / kKappa;
}
}  // namespace

Vec3 XyzToLab(const Vec3& xyz, const Vec3& whiteXyz) noexcept
{
    const double fx = LabF(xyz.x() / whiteXyz.x());
    const double fy = LabF(xyz.y() / whiteXyz.y());
    const double fz = LabF(xyz.z() / whiteXyz.z());
    return Vec3(116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz));
}

Vec3 LabToXyz(const Vec3& lab, const Vec3& whiteXyz) noexcept
{
    const double fy = (lab.x() + 16.0) / 116.0;
    const double fx = fy + lab.y() / 500.0;
    const double fz = fy - lab.z() / 200.0;
    return Vec3(LabFInverse(fx) * whiteXyz.x(), LabFInverse(fy) * whiteXyz.y(),
                LabFInverse(fz) * whiteXyz.z());
}

double DeltaE76(const Vec3& lab1, const Vec3& lab2) noexcept
{
    return (lab1 - lab2).norm();
}

double DeltaE2000(const Vec3& lab1, const Vec3& lab2, double kL, double kC, double kH) noexcept
{
    // Step numbers follow Sharma, Wu & Dalal (2005), equations (1)–(22).
    const double deg = kPi / 180.0;
    const double L1 = lab1.x(), a1 = lab1.y(), b1 = lab1.z();
    const double L2 = lab2.x(), a2 = lab2.y(), b2 = lab2.z();

    const double C1 = std::hypot(a1, b1);
    const double C2 = std::hypot(a2, b2);
    const double Cbar = 0.5 * (C1 + C2);
    const double Cbar7 = std::pow(Cbar, 7.0);
    const double G = 0.5 * (1.0 - std::sqrt(Cbar7 / (Cbar7 + std::pow(25.0, 7.0))));
    const double a1p = (1.0 + G) * a1;
    const double a2p = (1.0 + G) * a2;
    const double C1p = std::hypot(a1p, b1);
    const double C2p = std::hypot(a2p, b2);
    // Hue angles in degrees in [0, 360); zero when the chroma is zero (eq. 7).
    auto hue = [&](double b, double ap)
    {
        if (b == 0.0 && ap == 0.0)
        {
            return 0.0;
        }
        double h = std::atan2(b, ap) / deg;
        return h < 0.0 ? h + 360.0 : h;
    };
    const double h1p = hue(b1, a1p);
    const double h2p = hue(b2, a2p);

    const double dLp = L2 - L1;
    const double dCp = C2p - C1p;
    double dhp = 0.0;
    if (C1p * C2p != 0.0)
    {
        dhp = h2p - h1p;
        if (dhp > 180.0)
        {
            dhp -= 360.0;
        }
        else if (dhp < -180.0)
        {
            dhp += 360.0;
        }
    }
    const double dHp = 2.0 * std::sqrt(C1p * C2p) * std::sin(0.5 * dhp * deg);

    const double Lbarp = 0.5 * (L1 + L2);
    const double Cbarp = 0.5 * (C1p + C2p);
    double hbarp = h1p + h2p;
    if (C1p * C2p != 0.0)
    {
        if (std::abs(h1p - h2p) <= 180.0)
        {
            hbarp *= 0.5;
        }
        else if (h1p + h2p < 360.0)
        {
            hbarp = 0.5 * (h1p + h2p + 360.0);
        }
        else
        {
            hbarp = 0.5 * (h1p + h2p - 360.0);
        }
    }
    const double T =
        1.0 - 0.17 * std::cos((hbarp - 30.0) * deg) + 0.24 * std::cos(2.0 * hbarp * deg) +
        0.32 * std::cos((3.0 * hbarp + 6.0) * deg) - 0.20 * std::cos((4.0 * hbarp - 63.0) * deg);
    const double dTheta = 30.0 * std::exp(-std::pow((hbarp - 275.0) / 25.0, 2.0));
    const double Cbarp7 = std::pow(Cbarp, 7.0);
    const double RC = 2.0 * std::sqrt(Cbarp7 / (Cbarp7 + std::pow(25.0, 7.0)));
    const double L50 = (Lbarp - 50.0) * (Lbarp - 50.0);
    const double SL = 1.0 + 0.015 * L50 / std::sqrt(20.0 + L50);
    const double SC = 1.0 + 0.045 * Cbarp;
    const double SH = 1.0 + 0.015 * Cbarp * T;
    const double RT = -std::sin(2.0 * dTheta * deg) * RC;

    const double tL = dLp / (kL * SL);
    const double tC = dCp / (kC * SC);
    const double tH = dHp / (kH * SH);
    return std::sqrt(tL * tL + tC * tC + tH * tH + RT * tC * tH);
}

}  // namespace bandlight
