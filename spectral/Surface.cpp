// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Surface.h"

#include <utility>

#include "spectral/Exception.h"

namespace bandlight
{

RemittanceSurface::RemittanceSurface(Spectrum remittance) : m_remittance(std::move(remittance))
{
    if (m_remittance.empty())
    {
        throw Exception("a remittance surface needs a remittance");
    }
}

Spectrum RemittanceSurface::reflect(const Spectrum& incident) const
{
    const Spectrum beta = m_remittance.extended(incident.start(), incident.end());
    Spectrum out = incident;
    for (size_t i = 0; i < out.size(); ++i)
    {
        out.values()[i] = beta(out.wavelength(i)) * incident[i];
    }
    return out;
}

BispectralSurface::BispectralSurface(double startNm, double stepNm, Eigen::MatrixXd donaldson)
    : m_start(startNm), m_step(stepNm), m_d(std::move(donaldson))
{
    if (!(stepNm > 0.0) || m_d.rows() == 0 || m_d.rows() != m_d.cols())
    {
        throw Exception("a bi-spectral surface needs a square Donaldson matrix on a grid with a "
                        "positive step, got " +
                        std::to_string(m_d.rows()) + " x " + std::to_string(m_d.cols()));
    }
    if (!m_d.allFinite() || m_d.minCoeff() < 0.0)
    {
        throw Exception("a bi-spectral surface's Donaldson matrix must be finite and "
                        "non-negative");
    }
}

BispectralSurface BispectralSurface::FromRemittance(const Spectrum& remittance, double startNm,
                                                    double stepNm, size_t count)
{
    const Spectrum beta = remittance.extended(startNm, startNm + stepNm * double(count - 1));
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(Eigen::Index(count), Eigen::Index(count));
    for (size_t i = 0; i < count; ++i)
    {
        d(Eigen::Index(i), Eigen::Index(i)) = beta(startNm + stepNm * double(i));
    }
    return BispectralSurface(startNm, stepNm, std::move(d));
}

Spectrum BispectralSurface::reflect(const Spectrum& incident) const
{
    const size_t n = size_t(m_d.rows());
    Eigen::VectorXd e(Eigen::Index(n), 1);
    for (size_t i = 0; i < n; ++i)
    {
        e(Eigen::Index(i)) = incident(m_start + m_step * double(i));
    }
    const Eigen::VectorXd out = m_d * e;
    return Spectrum(m_start, m_step, std::vector<double>(out.data(), out.data() + out.size()));
}

}  // namespace bandlight
