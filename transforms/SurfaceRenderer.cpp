// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/SurfaceRenderer.h"

#include <cmath>
#include <random>

#include <Eigen/LU>

#include "spectral/Colorimetry.h"

namespace bandlight
{

SurfaceRenderer::SurfaceRenderer(const Spectrum& illuminant, const RgbSpace& working,
                                 Observer observer)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    Eigen::Matrix<double, 3, kSamples> xyz;
    Eigen::Matrix<double, 3, kSamples> observerXyz;
    for (int i = 0; i < kSamples; ++i)
    {
        const double l = Wavelength(i);
        const double s = illuminant(l);
        observerXyz.col(i) = Vec3(cmf.x(l), cmf.y(l), cmf.z(l));
        xyz.col(i) = s * Vec3(cmf.x(l), cmf.y(l), cmf.z(l));
    }
    const double k = 1.0 / xyz.row(1).sum();  // white reflector: Y = 1
    m_rgbToXyz = RgbToXyzMatrix(working.chromaticities);
    m_a = m_rgbToXyz.inverse() * (xyz * k);
    m_white = m_a.rowwise().sum();
    m_illuminant = illuminant;
    m_light = m_rgbToXyz.inverse() * (observerXyz * k);
}

Vec3 SurfaceRenderer::render(const Surface& surface) const
{
    const Spectrum out = surface.reflect(m_illuminant);
    Samples s;
    for (int i = 0; i < kSamples; ++i)
    {
        s(i) = out(Wavelength(i));
    }
    return m_light * s;
}

SurfaceRenderer::Samples SurfaceRenderer::Sample(const Spectrum& remittance)
{
    Samples s;
    const Spectrum e = remittance.extended(kStartNm, kStartNm + kStepNm * (kSamples - 1));
    for (int i = 0; i < kSamples; ++i)
    {
        s(i) = e(Wavelength(i));
    }
    return s;
}

ReflectanceSet RandomSmoothSet(int count, unsigned seed, const std::string& name)
{
    ReflectanceSet set{name, {}};
    std::mt19937 rng(seed);
    std::normal_distribution<double> coeff(0.0, 1.0);
    for (int k = 0; k < count; ++k)
    {
        double a[4], b[4];
        for (int j = 0; j < 4; ++j)
        {
            a[j] = coeff(rng) / (1.0 + j);
            b[j] = coeff(rng) / (1.0 + j);
        }
        std::vector<double> v(SurfaceRenderer::kSamples);
        for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
        {
            const double t = double(i) / (SurfaceRenderer::kSamples - 1);
            double x = a[0];
            for (int j = 1; j < 4; ++j)
            {
                x += a[j] * std::cos(j * kPi * t) + b[j] * std::sin(j * kPi * t);
            }
            v[size_t(i)] = 0.5 + 0.5 * std::tanh(x);
        }
        char id[32];
        std::snprintf(id, sizeof id, "R%03d", k + 1);
        set.samples.push_back(
            {id, Spectrum(SurfaceRenderer::kStartNm, SurfaceRenderer::kStepNm, std::move(v))});
    }
    return set;
}

const ReflectanceSet& TrainingSet()
{
    static const ReflectanceSet set = []
    {
        ReflectanceSet s = RandomSmoothSet(100, 1, "training");
        for (size_t i = 0; i < 8; ++i)
        {
            s.samples.push_back(TestColourSamples()[i]);
        }
        return s;
    }();
    return set;
}

const ReflectanceSet& HeldOutTcs()
{
    static const ReflectanceSet set = []
    {
        ReflectanceSet s{"tcs09-15", {}};
        for (size_t i = 8; i < TestColourSamples().size(); ++i)
        {
            s.samples.push_back(TestColourSamples()[i]);
        }
        return s;
    }();
    return set;
}

const ReflectanceSet& AllTcs()
{
    static const ReflectanceSet set{"tcs", TestColourSamples()};
    return set;
}

}  // namespace bandlight
