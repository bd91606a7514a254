// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace bandlight
{

/// A spectrum sampled on a regular wavelength grid: value i belongs to
/// wavelength start + i * step (nm). Between samples the spectrum is the
/// piecewise-linear interpolant; outside [start, end] it is zero unless a
/// caller asks for edge extension (see extended()).
///
/// The unit of the values is the caller's: relative spectral power for
/// illuminants, a factor in [0, 1] for remittances, a tristimulus weight
/// for matching functions.
class Spectrum
{
public:
    Spectrum() = default;
    /// Throws Exception when step <= 0 or values is empty.
    Spectrum(double startNm, double stepNm, std::vector<double> values);

    /// A constant spectrum over [startNm, startNm + (count-1)*stepNm].
    static Spectrum Constant(double startNm, double stepNm, size_t count, double value);

    double start() const noexcept { return m_start; }
    double step() const noexcept { return m_step; }
    double end() const noexcept { return m_start + m_step * double(m_values.size() - 1); }
    size_t size() const noexcept { return m_values.size(); }
    bool empty() const noexcept { return m_values.empty(); }
    double wavelength(size_t i) const noexcept { return m_start + m_step * double(i); }
    const std::vector<double>& values() const noexcept { return m_values; }
    std::vector<double>& values() noexcept { return m_values; }
    double operator[](size_t i) const noexcept { return m_values[i]; }

    /// Value at lambdaNm by linear interpolation; 0 outside [start, end].
    double operator()(double lambdaNm) const noexcept;

    /// Linear resampling onto a new grid; zero outside the data's range.
    Spectrum resampled(double startNm, double stepNm, size_t count) const;

    /// Resampling onto the grid of another spectrum.
    Spectrum resampledLike(const Spectrum& grid) const
    {
        return resampled(grid.start(), grid.step(), grid.size());
    }

    /// The same spectrum over [startNm, endNm] on this spectrum's step,
    /// holding the first and last value constant outside the data
    /// (CIE 15:2004 §7.2.1 recommends this for missing remittance data).
    Spectrum extended(double startNm, double endNm) const;

    /// True when other has the same start, step and count (to 1e-9 nm).
    bool sameGrid(const Spectrum& other) const noexcept;

    /// Rectangle-rule integral sum(v_i) * step, the CIE's summation
    /// convention (CIE 15:2004 §7.1); units: value·nm.
    double sum() const noexcept;

    /// Exact integral of the piecewise-linear interpolant over [aNm, bNm]
    /// (zero outside the data); units: value·nm.
    double integrateLinear(double aNm, double bNm) const noexcept;

    double maxValue() const noexcept;

    Spectrum& operator*=(double s) noexcept;
    Spectrum& operator+=(double s) noexcept;
    /// Pointwise arithmetic; a spectrum on another grid is first resampled
    /// onto this one's grid.
    Spectrum& operator*=(const Spectrum& other);
    Spectrum& operator+=(const Spectrum& other);
    Spectrum& operator-=(const Spectrum& other);

private:
    double m_start = 0.0;
    double m_step = 1.0;
    std::vector<double> m_values;
};

Spectrum operator*(Spectrum a, double s);
Spectrum operator*(double s, Spectrum a);
Spectrum operator*(Spectrum a, const Spectrum& b);
Spectrum operator+(Spectrum a, const Spectrum& b);
Spectrum operator-(Spectrum a, const Spectrum& b);

/// One emission line: all its power at one wavelength.
struct SpectralLine
{
    double wavelengthNm = 0.0;
    double power = 0.0;  ///< integrated power of the line, value·nm
};

/// A spectrum of emission lines at arbitrary wavelengths (a laser, the
/// mercury lines of a fluorescent lamp). Lines are never smeared: integrals
/// against a matching function use the function's value at each line, and
/// band means count each line in the one band that holds it.
class LineSpectrum
{
public:
    LineSpectrum() = default;
    /// Throws Exception on a non-finite wavelength or power.
    explicit LineSpectrum(std::vector<SpectralLine> lines);

    const std::vector<SpectralLine>& lines() const noexcept { return m_lines; }
    bool empty() const noexcept { return m_lines.empty(); }

    /// Sum of power_i * f(lambda_i), f linearly interpolated: the exact
    /// integral of this spectrum times f.
    double integrate(const Spectrum& f) const noexcept;

    /// Sum of the powers of the lines with aNm <= lambda < bNm.
    double powerIn(double aNm, double bNm) const noexcept;

    /// A sampled equivalent on the given grid: each line's power is split
    /// between its two neighbouring samples in proportion to proximity, so
    /// that summing against any function sampled on the same grid gives
    /// exactly the integral against that function's linear interpolant.
    Spectrum sampled(double startNm, double stepNm, size_t count) const;

private:
    std::vector<SpectralLine> m_lines;
};

}  // namespace bandlight
