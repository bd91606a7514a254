// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Upsampler.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace bandlight
{

namespace
{
constexpr int kN = SurfaceRenderer::kSamples;

double Sigmoid(double x) noexcept
{
    return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
}
double SigmoidSlope(double x) noexcept
{
    const double q = 1.0 + x * x;
    return 0.5 / (q * std::sqrt(q));
}
double T(int i) noexcept
{
    return double(i) / double(kN - 1);
}
}  // namespace

Upsampler::Upsampler(const SurfaceRenderer& from) : m_from(from) {}

SurfaceRenderer::Samples Upsampler::Remittance(const Coeffs& c)
{
    SurfaceRenderer::Samples r;
    for (int i = 0; i < kN; ++i)
    {
        const double t = T(i);
        r(i) = Sigmoid((c(0) * t + c(1)) * t + c(2));
    }
    return r;
}

double Upsampler::gamutScale(const Vec3& rgb) const noexcept
{
    const Vec3& w = m_from.white();
    const double m = std::max({rgb.x() / w.x(), rgb.y() / w.y(), rgb.z() / w.z()});
    // Every pixel is fitted at the canonical level: its level says nothing
    // about the surface (it is irradiance × remittance), so the fit must not
    // depend on it — which makes upsample exposure invariant.
    return m > 0.0 ? m / kCanonicalLevel : 1.0;
}

Upsampler::Fit Upsampler::fit(const Vec3& rgb, const Coeffs& start) const
{
    const SurfaceRenderer::Matrix& a = m_from.matrix();
    const double scale = 1.0 / m_from.white().norm();
    Fit f;
    f.coeffs = start;
    double mu = 1e-3;
    auto evaluate = [&](const Coeffs& c, Vec3& residual, Mat3* jac)
    {
        SurfaceRenderer::Samples r;
        Eigen::Matrix<double, kN, 3> dr;
        for (int i = 0; i < kN; ++i)
        {
            const double t = T(i);
            const double x = (c(0) * t + c(1)) * t + c(2);
            r(i) = Sigmoid(x);
            if (jac)
            {
                const double s = SigmoidSlope(x);
                dr(i, 0) = s * t * t;
                dr(i, 1) = s * t;
                dr(i, 2) = s;
            }
        }
        residual = (a * r - rgb) * scale;
        if (jac)
        {
            *jac = a * dr * scale;
        }
        return residual.squaredNorm();
    };
    Vec3 res;
    Mat3 jac;
    double err = evaluate(f.coeffs, res, &jac);
    // 1e-11 on the squared residual relative to the white is ΔE76 ~ 1e-3.
    // A colour outside the gamut cannot get there: stop when three accepted
    // steps in a row gain less than 1 % each, or no step gains at all.
    int stalls = 0;
    for (f.iterations = 0; f.iterations < 60 && err > 1e-11 && stalls < 3; ++f.iterations)
    {
        const Mat3 jtj = jac.transpose() * jac;
        const Vec3 g = jac.transpose() * res;
        Mat3 lhs = jtj;
        lhs.diagonal() += mu * jtj.diagonal() + Vec3::Constant(1e-12);
        const Coeffs step = -lhs.fullPivLu().solve(g);
        const Coeffs trial = f.coeffs + step;
        Vec3 trialRes;
        const double trialErr = evaluate(trial, trialRes, nullptr);
        if (trialErr < err)
        {
            stalls = trialErr > 0.99 * err ? stalls + 1 : 0;
            f.coeffs = trial;
            err = evaluate(f.coeffs, res, &jac);
            mu = std::max(mu * 0.3, 1e-9);
        }
        else
        {
            mu *= 10.0;
            if (mu > 1e6)
            {
                break;  // no step lowers the residual: the nearest reachable remittance
            }
        }
    }
    f.residual = std::sqrt(err);
    return f;
}

namespace
{
/// The cache key of a colour scaled onto the gamut's shell: each channel
/// relative to the white, quantised to 2^-20 and packed into 21 bits.
uint64_t ShellKey(const Vec3& scaled, const Vec3& white)
{
    uint64_t key = 0;
    for (int c = 0; c < 3; ++c)
    {
        const double q = std::clamp(scaled(c) / white(c), -1.0, 1.0);
        key = (key << 21) | uint64_t(std::llround((q + 1.0) * double(1 << 19)) & 0x1fffff);
    }
    return key;
}
}  // namespace

Vec3 UpsampleRelight(const Upsampler& up, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb, Upsampler::Coeffs* warm, UpsampleCache* cache)
{
    if (!rgb.allFinite() || !(rgb.maxCoeff() > 0.0))
    {
        return fallback * rgb;
    }
    const double k = up.gamutScale(rgb);
    const Vec3 scaled = rgb / k;
    uint64_t key = 0;
    if (cache)
    {
        key = ShellKey(scaled, up.renderer().white());
        const auto it = cache->find(key);
        if (it != cache->end())
        {
            return to.render(Upsampler::Remittance(it->second)) * k;
        }
    }
    Upsampler::Fit f = up.fit(scaled, warm ? *warm : Upsampler::Coeffs::Zero());
    if (warm && f.residual > 1e-4)
    {
        // A neighbour's coefficients can sit on a far slope of the sigmoid:
        // start again from the flat grey and keep the better fit.
        const Upsampler::Fit cold = up.fit(scaled);
        if (cold.residual < f.residual)
        {
            f = cold;
        }
    }
    if (warm)
    {
        *warm = f.coeffs;
    }
    if (cache)
    {
        cache->emplace(key, f.coeffs);
    }
    return to.render(Upsampler::Remittance(f.coeffs)) * k;
}

}  // namespace bandlight
