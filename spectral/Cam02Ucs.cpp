// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Cam02Ucs.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

// clang-format off
/// CAT02 (CIE 159:2004): XYZ to the sharpened RGB of the adaptation.
const Mat3& Cat02()
{
    static const Mat3 m = (Mat3() <<  0.7328, 0.4296, -0.1624,
                                     -0.7036, 1.6975,  0.0061,
                                      0.0030, 0.0136,  0.9834).finished();
    return m;
}

/// Adapted RGB to Hunt–Pointer–Estévez cone space (CIE 159:2004):
/// M_HPE · M_CAT02⁻¹, one matrix.
const Mat3& Cat02ToHpe()
{
    static const Mat3 m = (Mat3() <<  0.38971, 0.68898, -0.07868,
                                     -0.22981, 1.18340,  0.04641,
                                      0.0,     0.0,      1.0).finished() * Cat02().inverse();
    return m;
}
// clang-format on

/// Post-adaptation compression (CIE 159:2004), odd in its argument as
/// the model's notes extend it to negative responses.
double Compress(double x, double fl) noexcept
{
    const double p = std::pow(fl * std::abs(x) / 100.0, 0.42);
    return std::copysign(400.0 * p / (27.13 + p), x) + 0.1;
}

/// The compressed cone responses R'a, G'a, B'a of XYZ.
Vec3 Responses(const Vec3& xyz, const Vec3& dRgb, double fl) noexcept
{
    const Vec3 rgbc = dRgb.cwiseProduct(Cat02() * xyz);
    const Vec3 p = Cat02ToHpe() * rgbc;
    return {Compress(p.x(), fl), Compress(p.y(), fl), Compress(p.z(), fl)};
}

/// Achromatic signal A before the factor N_bb.
double Achromatic(const Vec3& ra) noexcept
{
    return 2.0 * ra.x() + ra.y() + ra.z() / 20.0 - 0.305;
}

}  // namespace

Cam02::Cam02(const Vec3& whiteXyz, const CamViewingConditions& v) : m_c(v.c), m_nc(v.nc)
{
    const double la = v.adaptingLuminance;
    if (!whiteXyz.allFinite() || !(whiteXyz.y() > 0.0) || !(la > 0.0) || !std::isfinite(la) ||
        !(v.backgroundY > 0.0) || !std::isfinite(v.backgroundY))
    {
        throw Exception("CIECAM02: the white must have Y > 0 and L_A, Y_b must be positive");
    }
    // CIE 159:2004: luminance adaptation F_L, background n, induction
    // factors N_bb = N_cb, base exponent z, degree of adaptation D.
    const double k = 1.0 / (5.0 * la + 1.0);
    const double k4 = k * k * k * k;
    m_fl = 0.2 * k4 * 5.0 * la + 0.1 * (1.0 - k4) * (1.0 - k4) * std::cbrt(5.0 * la);
    m_n = v.backgroundY / whiteXyz.y();
    m_nbb = 0.725 * std::pow(1.0 / m_n, 0.2);
    m_z = 1.48 + std::sqrt(m_n);
    m_d = v.discountIlluminant
              ? 1.0
              : std::clamp(v.f * (1.0 - std::exp((-la - 42.0) / 92.0) / 3.6), 0.0, 1.0);
    const Vec3 rgbw = Cat02() * whiteXyz;
    if (!(rgbw.minCoeff() > 0.0))
    {
        throw Exception("CIECAM02: the white has a non-positive CAT02 response");
    }
    m_dRgb = (m_d * whiteXyz.y() * rgbw.cwiseInverse()).array() + (1.0 - m_d);
    m_aw = Achromatic(Responses(whiteXyz, m_dRgb, m_fl)) * m_nbb;
}

CamCorrelates Cam02::correlates(const Vec3& xyz) const noexcept
{
    const Vec3 ra = Responses(xyz, m_dRgb, m_fl);
    // Opponent signals, hue angle and eccentricity factor.
    const double a = ra.x() - 12.0 * ra.y() / 11.0 + ra.z() / 11.0;
    const double b = (ra.x() + ra.y() - 2.0 * ra.z()) / 9.0;
    double h = std::atan2(b, a) * 180.0 / kPi;
    if (h < 0.0)
    {
        h += 360.0;
    }
    const double et = 0.25 * (std::cos(h * kPi / 180.0 + 2.0) + 3.8);

    CamCorrelates out;
    out.h = h;
    const double achromatic = Achromatic(ra) * m_nbb;
    out.j = achromatic > 0.0 ? 100.0 * std::pow(achromatic / m_aw, m_c * m_z) : 0.0;
    const double fl4 = std::pow(m_fl, 0.25);
    out.q = 4.0 / m_c * std::sqrt(out.j / 100.0) * (m_aw + 4.0) * fl4;
    // Chroma from the temporary quantity t; N_cb = N_bb.
    const double denominator = ra.x() + ra.y() + 21.0 / 20.0 * ra.z();
    const double t = denominator > 0.0 ? 50000.0 / 13.0 * m_nc * m_nbb * et *
                                             std::sqrt(a * a + b * b) / denominator
                                       : 0.0;
    out.c =
        std::pow(t, 0.9) * std::sqrt(out.j / 100.0) * std::pow(1.64 - std::pow(0.29, m_n), 0.73);
    out.m = out.c * fl4;
    out.s = out.q > 0.0 ? 100.0 * std::sqrt(out.m / out.q) : 0.0;
    return out;
}

Vec3 Cam02::ucs(const Vec3& xyz) const noexcept
{
    const CamCorrelates c = correlates(xyz);
    return JmhToCam02Ucs(c.j, c.m, c.h);
}

Vec3 JmhToCam02Ucs(double j, double m, double hDegrees) noexcept
{
    // Luo, Cui & Li 2006, CAM02-UCS: K_L = 1, c1 = 0.007, c2 = 0.0228.
    constexpr double c1 = 0.007, c2 = 0.0228;
    const double jp = (1.0 + 100.0 * c1) * j / (1.0 + c1 * j);
    const double mp = std::log1p(c2 * m) / c2;
    const double h = hDegrees * kPi / 180.0;
    return {jp, mp * std::cos(h), mp * std::sin(h)};
}

double DeltaECam02Ucs(const Vec3& a, const Vec3& b) noexcept
{
    return (a - b).norm();
}

}  // namespace bandlight
