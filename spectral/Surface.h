// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A surface as light sees it: what it sends back of an incident spectrum.
// A plain remittance multiplies wavelength by wavelength; a bi-spectral
// (fluorescent) surface also re-radiates light it absorbs at one wavelength
// at longer ones, which no remittance can state. The reference renderer
// (transforms/SurfaceRenderer) takes any surface through this interface, so
// a fluorescent surface is rendered exactly without touching the methods.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/Spectrum.h"

namespace bandlight
{

class Surface
{
public:
    virtual ~Surface() = default;
    /// The spectral radiance the surface sends back for the spectral
    /// irradiance `incident` (same units, on a grid of the surface's
    /// choosing; zero outside it).
    virtual Spectrum reflect(const Spectrum& incident) const = 0;
};

/// A plain remittance β(λ) in [0, 1]: reflected(λ) = β(λ) · incident(λ), on
/// the incident's grid; β is extended flat beyond its own range (as
/// measured remittances are, SurfaceRenderer::Sample).
class RemittanceSurface final : public Surface
{
public:
    explicit RemittanceSurface(Spectrum remittance);
    Spectrum reflect(const Spectrum& incident) const override;
    const Spectrum& remittance() const noexcept { return m_remittance; }

private:
    Spectrum m_remittance;
};

/// A bi-spectral surface: its Donaldson matrix D on one grid (start, step,
/// n samples), reflected(λo) = Σi D(o, i) · incident(λi). The diagonal is
/// the surface's plain remittance; D(o, i) for λo > λi is the light
/// re-radiated at λo per unit of incident light in the grid step at λi
/// (fluorescence: the step folded into the entry). The incident light is
/// resampled onto the grid first.
class BispectralSurface final : public Surface
{
public:
    /// Throws Exception when `donaldson` is not n × n for the grid, is not
    /// finite or is negative.
    BispectralSurface(double startNm, double stepNm, Eigen::MatrixXd donaldson);
    /// The diagonal matrix of a remittance on a grid: the same surface as
    /// RemittanceSurface, as a matrix.
    static BispectralSurface FromRemittance(const Spectrum& remittance, double startNm,
                                            double stepNm, size_t count);

    Spectrum reflect(const Spectrum& incident) const override;
    const Eigen::MatrixXd& donaldson() const noexcept { return m_d; }

private:
    double m_start;
    double m_step;
    Eigen::MatrixXd m_d;
};

}  // namespace bandlight
