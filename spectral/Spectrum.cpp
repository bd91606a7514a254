// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Spectrum.h"

#include <algorithm>
#include <cmath>

#include "spectral/Exception.h"

namespace bandlight
{

Spectrum::Spectrum(double startNm, double stepNm, std::vector<double> values)
    : m_start(startNm), m_step(stepNm), m_values(std::move(values))
{
    if (!(stepNm > 0.0) || !std::isfinite(stepNm) || !std::isfinite(startNm))
    {
        throw Exception("spectrum grid: step must be a positive number of nm, got " +
                        std::to_string(stepNm));
    }
    if (m_values.empty())
    {
        throw Exception("spectrum: no samples");
    }
}

Spectrum Spectrum::Constant(double startNm, double stepNm, size_t count, double value)
{
    return Spectrum(startNm, stepNm, std::vector<double>(count, value));
}

double Spectrum::operator()(double lambdaNm) const noexcept
{
    if (m_values.empty())
    {
        return 0.0;
    }
    const double t = (lambdaNm - m_start) / m_step;
    const double last = double(m_values.size() - 1);
    // Tolerate rounding at the ends so that end() itself is inside.
    if (t < -1e-9 || t > last + 1e-9)
    {
        return 0.0;
    }
    const double tc = std::clamp(t, 0.0, last);
    const size_t i = std::min(size_t(tc), m_values.size() - 1);
    if (i + 1 >= m_values.size())
    {
        return m_values[i];
    }
    const double f = tc - double(i);
    return m_values[i] + f * (m_values[i + 1] - m_values[i]);
}

Spectrum Spectrum::resampled(double startNm, double stepNm, size_t count) const
{
    std::vector<double> v(count);
    for (size_t i = 0; i < count; ++i)
    {
        v[i] = (*this)(startNm + stepNm * double(i));
    }
    return Spectrum(startNm, stepNm, std::move(v));
}

Spectrum Spectrum::extended(double startNm, double endNm) const
{
    // Keep this spectrum's samples exactly: the new grid is aligned with it.
    const double k0 = std::floor((startNm - m_start) / m_step + 1e-9);
    const double k1 = std::ceil((endNm - m_start) / m_step - 1e-9);
    const double lo = std::min(k0, 0.0);
    const double hi = std::max(k1, double(m_values.size() - 1));
    if (!(hi - lo < 1e8))
    {
        throw Exception("extending a spectrum on a " + std::to_string(m_step) + " nm grid to " +
                        std::to_string(startNm) + "–" + std::to_string(endNm) +
                        " nm needs more than 1e8 samples");
    }
    const size_t count = size_t(hi - lo) + 1;
    std::vector<double> v(count);
    for (size_t i = 0; i < count; ++i)
    {
        const double k = lo + double(i);
        if (k < 0)
        {
            v[i] = m_values.front();
        }
        else if (k > double(m_values.size() - 1))
        {
            v[i] = m_values.back();
        }
        else
        {
            v[i] = m_values[size_t(k)];
        }
    }
    return Spectrum(m_start + lo * m_step, m_step, std::move(v));
}

bool Spectrum::sameGrid(const Spectrum& other) const noexcept
{
    return m_values.size() == other.m_values.size() && std::abs(m_start - other.m_start) < 1e-9 &&
           std::abs(m_step - other.m_step) < 1e-9;
}

double Spectrum::sum() const noexcept
{
    double s = 0.0;
    for (double v : m_values)
    {
        s += v;
    }
    return s * m_step;
}

double Spectrum::integrateLinear(double aNm, double bNm) const noexcept
{
    if (m_values.empty() || !(bNm > aNm))
    {
        return 0.0;
    }
    const double a = std::max(aNm, m_start);
    const double b = std::min(bNm, end());
    if (!(b > a))
    {
        return 0.0;
    }
    // Trapezoids over each grid interval clipped to [a, b]; the interpolant is
    // linear inside an interval, so the trapezoid is exact.
    double total = 0.0;
    const size_t i0 = size_t(std::floor((a - m_start) / m_step));
    for (size_t i = i0; i + 1 < m_values.size(); ++i)
    {
        const double x0 = std::max(wavelength(i), a);
        const double x1 = std::min(wavelength(i + 1), b);
        if (x0 >= b)
        {
            break;
        }
        if (x1 > x0)
        {
            total += 0.5 * ((*this)(x0) + (*this)(x1)) * (x1 - x0);
        }
    }
    return total;
}

double Spectrum::maxValue() const noexcept
{
    return m_values.empty() ? 0.0 : *std::max_element(m_values.begin(), m_values.end());
}

Spectrum& Spectrum::operator*=(double s) noexcept
{
    for (double& v : m_values)
    {
        v *= s;
    }
    return *this;
}

Spectrum& Spectrum::operator+=(double s) noexcept
{
    for (double& v : m_values)
    {
        v += s;
    }
    return *this;
}

namespace
{
template <typename Op>
void Combine(Spectrum& a, const Spectrum& b, Op op)
{
    std::vector<double>& va = a.values();
    if (a.sameGrid(b))
    {
        for (size_t i = 0; i < va.size(); ++i)
        {
            va[i] = op(va[i], b[i]);
        }
        return;
    }
    for (size_t i = 0; i < va.size(); ++i)
    {
        va[i] = op(va[i], b(a.wavelength(i)));
    }
}
}  // namespace

Spectrum& Spectrum::operator*=(const Spectrum& other)
{
    Combine(*this, other, [](double x, double y) { return x * y; });
    return *this;
}

Spectrum& Spectrum::operator+=(const Spectrum& other)
{
    Combine(*this, other, [](double x, double y) { return x + y; });
    return *this;
}

Spectrum& Spectrum::operator-=(const Spectrum& other)
{
    Combine(*this, other, [](double x, double y) { return x - y; });
    return *this;
}

Spectrum operator*(Spectrum a, double s)
{
    return a *= s;
}
Spectrum operator*(double s, Spectrum a)
{
    return a *= s;
}
Spectrum operator*(Spectrum a, const Spectrum& b)
{
    return a *= b;
}
Spectrum operator+(Spectrum a, const Spectrum& b)
{
    return a += b;
}
Spectrum operator-(Spectrum a, const Spectrum& b)
{
    return a -= b;
}

LineSpectrum::LineSpectrum(std::vector<SpectralLine> lines) : m_lines(std::move(lines))
{
    for (const SpectralLine& l : m_lines)
    {
        if (!std::isfinite(l.wavelengthNm) || !std::isfinite(l.power) || l.wavelengthNm <= 0.0)
        {
            throw Exception("line spectrum: invalid line at " + std::to_string(l.wavelengthNm) +
                            " nm with power " + std::to_string(l.power));
        }
    }
    std::sort(m_lines.begin(), m_lines.end(),
              [](const SpectralLine& a, const SpectralLine& b)
              { return a.wavelengthNm < b.wavelengthNm; });
}

double LineSpectrum::integrate(const Spectrum& f) const noexcept
{
    double s = 0.0;
    for (const SpectralLine& l : m_lines)
    {
        s += l.power * f(l.wavelengthNm);
    }
    return s;
}

double LineSpectrum::powerIn(double aNm, double bNm) const noexcept
{
    double s = 0.0;
    for (const SpectralLine& l : m_lines)
    {
        if (l.wavelengthNm >= aNm && l.wavelengthNm < bNm)
        {
            s += l.power;
        }
    }
    return s;
}

Spectrum LineSpectrum::sampled(double startNm, double stepNm, size_t count) const
{
    Spectrum out = Spectrum::Constant(startNm, stepNm, count, 0.0);
    std::vector<double>& v = out.values();
    for (const SpectralLine& l : m_lines)
    {
        const double t = (l.wavelengthNm - startNm) / stepNm;
        if (t < -1e-9 || t > double(count - 1) + 1e-9)
        {
            continue;  // outside the grid: nothing of it is seen there
        }
        const double tc = std::clamp(t, 0.0, double(count - 1));
        const size_t i = std::min(size_t(tc), count - 1);
        const double f = tc - double(i);
        // Density such that sum(v) * step == power, split by tent weights.
        v[i] += (1.0 - f) * l.power / stepNm;
        if (f > 0.0 && i + 1 < count)
        {
            v[i + 1] += f * l.power / stepNm;
        }
    }
    return out;
}

}  // namespace bandlight
