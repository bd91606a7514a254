// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Camera.h"

#include <cmath>

#include <Eigen/LU>

#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "transforms/Plates.h"
#include "transforms/RootPolynomial.h"

namespace bandlight
{

SpectralCamera::SpectralCamera(const CameraSensitivities& s)
    : m_name(s.name), m_source(s.source.empty() ? s.name : s.source)
{
    for (int c = 0; c < 3; ++c)
    {
        const Spectrum& ch = s.channel(c);
        for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
        {
            const double l = SurfaceRenderer::Wavelength(i);
            // Zero outside the measured range: a sensitivity is not extended.
            m_s(c, i) = (l < ch.start() - 1e-9 || l > ch.end() + 1e-9) ? 0.0 : ch(l);
        }
    }
    const double peak = m_s.cwiseAbs().maxCoeff();
    if (!(peak > 0.0) || !std::isfinite(peak))
    {
        throw Exception(label() + ": no finite response over 380-780 nm");
    }
    int exponent = 0;
    std::frexp(peak, &exponent);
    m_s = m_s.unaryExpr([exponent](double v) { return std::ldexp(v, -exponent); });
}

std::string SpectralCamera::label() const
{
    return m_source == m_name ? m_source + ": camera" : m_source + ": camera " + m_name;
}

CameraShot::CameraShot(const SpectralCamera& camera, const Spectrum& light)
{
    Eigen::Matrix<double, 1, SurfaceRenderer::kSamples> s;
    for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
    {
        s(i) = light(SurfaceRenderer::Wavelength(i));
    }
    m_a = camera.sensitivities().array().rowwise() * s.array();
    const Vec3 white = m_a.rowwise().sum();
    // A channel that records less than 1e-12 of the strongest one records
    // nothing: its gain would be past 1e12 (past double's range for a
    // channel of denormal sensitivities), balancing noise, not light.
    const double strongest = white.cwiseAbs().maxCoeff();
    for (int c = 0; c < 3; ++c)
    {
        if (!(white[c] > 1e-12 * strongest) || !std::isfinite(white[c]))
        {
            throw Exception(camera.label() + ": its " +
                            (c == 0   ? "red"
                             : c == 1 ? "green"
                                      : "blue") +
                            " channel records nothing under this light: no white balance exists");
        }
        m_gains[c] = 1.0 / white[c];
    }
    m_a = m_gains.asDiagonal() * m_a;
}

Mat3 FitIdt(const SpectralCamera& camera, const Spectrum& light, const RgbSpace& working,
            AdaptationMethod adaptation, Observer observer,
            const std::vector<NamedSpectrum>& training)
{
    const CameraShot shot(camera, light);
    const SurfaceRenderer eye(light, working, observer);
    const Mat3 balance = BalanceMatrix(light, working, adaptation, observer);
    ColourFit fit;
    for (const NamedSpectrum& t : training.empty() ? Rawtoaces190() : training)
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        fit.input.push_back(shot.record(r));
        fit.target.push_back(balance * eye.render(r));
    }
    fit.whiteIn = Vec3::Ones();
    fit.whiteOut = Vec3::Ones();
    fit.rgbToXyz = eye.rgbToXyz();
    fit.labWhite = WorkingWhiteXyz(working);
    Mat3 idt = Mat3::Zero();
    try
    {
        idt = FitLabMatrix(fit);
    }
    catch (const Exception&)
    {
        idt = Mat3::Zero();  // refused below, naming the camera
    }
    if (!idt.allFinite() || std::abs(idt.determinant()) < 1e-12)
    {
        throw Exception(camera.label() +
                        ": its channels do not separate colours (the fitted input transform is "
                        "singular)");
    }
    return idt;
}

}  // namespace bandlight
