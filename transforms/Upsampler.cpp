// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Upsampler.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include <Eigen/Cholesky>

namespace bandlight
{

namespace
{
constexpr int kN = SurfaceRenderer::kSamples;

double Sigmoid(double x) noexcept
{
    return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
}
double T(int i) noexcept
{
    return double(i) / double(kN - 1);
}

/// t of every sample of the grid.
const Eigen::Array<double, kN, 1>& Ts()
{
    static const Eigen::Array<double, kN, 1> ts = []
    {
        Eigen::Array<double, kN, 1> out;
        for (int i = 0; i < kN; ++i)
        {
            out(i) = T(i);
        }
        return out;
    }();
    return ts;
}
}  // namespace

Upsampler::Upsampler(const SurfaceRenderer& from) : m_from(from), m_rows(from.matrix().transpose())
{
}

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
    const double scale = 1.0 / m_from.white().norm();
    Fit f;
    f.coeffs = start;
    double mu = 1e-3;
    // The residual and its Jacobian from whole-spectrum array expressions
    // (vectorised) and twelve dot products with the rows of the renderer's
    // matrix, one square root a sample: this is upsample's inner loop
    // (every fit, every step).
    using Array = Eigen::Array<double, kN, 1>;
    const Array& t = Ts();
    auto evaluate = [&](const Coeffs& c, Vec3& residual, Mat3& jac)
    {
        const Array x = (c(0) * t + c(1)) * t + c(2);
        const Array q = 1.0 + x.square();
        const Array root = q.sqrt();
        const Array r = 0.5 + x / (2.0 * root);  // Sigmoid(x)
        const Array slope = 0.5 / (q * root);    // its derivative
        const Array slopeT = slope * t;
        const Array slopeTT = slopeT * t;
        for (int k = 0; k < 3; ++k)
        {
            const auto row = m_rows.col(k).array();
            residual(k) = ((row * r).sum() - rgb(k)) * scale;
            jac(k, 0) = (row * slopeTT).sum() * scale;
            jac(k, 1) = (row * slopeT).sum() * scale;
            jac(k, 2) = (row * slope).sum() * scale;
        }
        return residual.squaredNorm();
    };
    Vec3 res;
    Mat3 jac;
    double err = evaluate(f.coeffs, res, jac);
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
        const Coeffs step = -lhs.ldlt().solve(g);  // symmetric, positive definite
        const Coeffs trial = f.coeffs + step;
        Vec3 trialRes;
        Mat3 trialJac;
        const double trialErr = evaluate(trial, trialRes, trialJac);
        if (trialErr < err)
        {
            stalls = trialErr > 0.99 * err ? stalls + 1 : 0;
            f.coeffs = trial;
            err = trialErr;
            res = trialRes;
            jac = trialJac;
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
constexpr double kKeySteps = double(1 << 19);  // key steps per white, each side of zero
}  // namespace

UpsampleFits::UpsampleFits(const SurfaceRenderer& from) : m_from(from), m_up(m_from) {}

std::shared_ptr<UpsampleFits> UpsampleFits::ForSource(const SurfaceRenderer& from)
{
    // Weak references: a store is freed with its last user, and a light
    // seen again later starts a new one.
    static std::mutex mutex;
    static std::vector<std::weak_ptr<UpsampleFits>> live;
    const std::lock_guard<std::mutex> lock(mutex);
    std::shared_ptr<UpsampleFits> found;
    for (auto it = live.begin(); it != live.end();)
    {
        std::shared_ptr<UpsampleFits> s = it->lock();
        if (!s)
        {
            it = live.erase(it);
            continue;
        }
        if (!found && s->sameSource(from))
        {
            found = s;
        }
        ++it;
    }
    if (!found)
    {
        found = std::make_shared<UpsampleFits>(from);
        live.push_back(found);
    }
    return found;
}

bool UpsampleFits::sameSource(const SurfaceRenderer& from) const noexcept
{
    return m_from.matrix() == from.matrix() && m_from.white() == from.white();
}

size_t UpsampleFits::size() const
{
    const std::shared_lock<std::shared_mutex> lock(m_mutex);
    return m_fits.size();
}

bool UpsampleFits::key(const Vec3& scaled, uint64_t& key) const noexcept
{
    // Each channel relative to the white, in 2^-19 steps, packed into 21 bits.
    key = 0;
    for (int c = 0; c < 3; ++c)
    {
        const double q = scaled(c) / m_from.white()(c);
        if (!(std::abs(q) <= 1.0))
        {
            return false;
        }
        key = (key << 21) | (uint64_t(std::llround((q + 1.0) * kKeySteps)) & 0x1fffff);
    }
    return true;
}

Upsampler::Coeffs UpsampleFits::coeffs(uint64_t key)
{
    {
        const std::shared_lock<std::shared_mutex> lock(m_mutex);
        const auto it = m_fits.find(key);
        if (it != m_fits.end())
        {
            return it->second;
        }
    }
    // The key's own colour, so the fit is the same whoever asks first.
    Vec3 centre;
    for (int c = 0; c < 3; ++c)
    {
        const uint64_t bits = (key >> (21 * (2 - c))) & 0x1fffff;
        centre(c) = (double(bits) / kKeySteps - 1.0) * m_from.white()(c);
    }
    const Upsampler::Coeffs fit = m_up.fit(centre).coeffs;
    const std::unique_lock<std::shared_mutex> lock(m_mutex);
    if (m_fits.size() < kMaxEntries)
    {
        m_fits.emplace(key, fit);
    }
    return fit;
}

size_t UpsampleRendered::slot(uint64_t key) const noexcept
{
    // Fibonacci hashing, then linear probing to the key or an empty slot.
    size_t i = size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - m_bits));
    while (m_keys[i] != 0 && m_keys[i] != key)
    {
        i = (i + 1) & (m_keys.size() - 1);
    }
    return i;
}

const Vec3* UpsampleRendered::find(uint64_t key) const noexcept
{
    if (m_size == 0)
    {
        return nullptr;
    }
    const size_t i = slot(key);
    return m_keys[i] == key ? &m_values[i] : nullptr;
}

void UpsampleRendered::insert(uint64_t key, const Vec3& value)
{
    if (2 * (m_size + 1) > m_keys.size())
    {
        // Kept at most half full: double and re-insert.
        std::vector<uint64_t> keys = std::move(m_keys);
        std::vector<Vec3> values = std::move(m_values);
        m_bits = std::max(m_bits + 1, 10);
        m_keys.assign(size_t(1) << m_bits, 0);
        m_values.resize(m_keys.size());
        for (size_t k = 0; k < keys.size(); ++k)
        {
            if (keys[k] != 0)
            {
                const size_t i = slot(keys[k]);
                m_keys[i] = keys[k];
                m_values[i] = values[k];
            }
        }
    }
    const size_t i = slot(key);
    if (m_keys[i] == 0)
    {
        m_keys[i] = key;
        m_values[i] = value;
        ++m_size;
    }
}

Vec3 UpsampleRelight(const Upsampler& up, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb)
{
    if (!rgb.allFinite() || !(rgb.maxCoeff() > 0.0))
    {
        return fallback * rgb;
    }
    const double k = up.gamutScale(rgb);
    return to.render(Upsampler::Remittance(up.fit(rgb / k).coeffs)) * k;
}

Vec3 UpsampleRelight(UpsampleFits& fits, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb, UpsampleRendered& rendered)
{
    if (!rgb.allFinite() || !(rgb.maxCoeff() > 0.0))
    {
        return fallback * rgb;
    }
    const double k = fits.upsampler().gamutScale(rgb);
    const Vec3 scaled = rgb / k;
    uint64_t key = 0;
    if (!fits.key(scaled, key))
    {
        return UpsampleRelight(fits.upsampler(), to, fallback, rgb);
    }
    if (const Vec3* known = rendered.find(key))
    {
        return *known * k;
    }
    const Vec3 out = to.render(Upsampler::Remittance(fits.coeffs(key)));
    rendered.insert(key, out);
    return out * k;
}

}  // namespace bandlight
