// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Spectrum.h"
#include "spectral/Surface.h"

namespace bandlight
{

/// Remittance → working RGB under one illuminant, as a 3 × N matrix on the
/// grid 380–780 nm at 5 nm (N = 81): the exact spectral answer for a
/// surface, with the white reflector at Y = 1. Every method is judged
/// against it and the spectral methods are built from it.
class SurfaceRenderer
{
public:
    static constexpr double kStartNm = 380.0;
    static constexpr double kStepNm = 5.0;
    static constexpr int kSamples = 81;

    using Matrix = Eigen::Matrix<double, 3, kSamples>;
    using Samples = Eigen::Matrix<double, kSamples, 1>;

    SurfaceRenderer(const Spectrum& illuminant, const RgbSpace& working,
                    Observer observer = Observer::CIE1931_2DEG);

    /// A remittance on the renderer's grid (edge-extended where it ends early).
    static Samples Sample(const Spectrum& remittance);
    /// The grid's wavelength i in nm.
    static double Wavelength(int i) noexcept { return kStartNm + kStepNm * i; }

    Vec3 render(const Samples& remittance) const { return m_a * remittance; }
    Vec3 render(const Spectrum& remittance) const { return m_a * Sample(remittance); }
    /// Any surface (spectral/Surface.h: a remittance, a bi-spectral
    /// fluorescent one): the light it sends back under the illuminant,
    /// integrated on the grid (zero where it sends nothing), the white
    /// reflector still at Y = 1. For a RemittanceSurface it equals
    /// render(remittance) to rounding.
    Vec3 render(const Surface& surface) const;

    const Matrix& matrix() const noexcept { return m_a; }
    /// The perfect white reflector's RGB (Y = 1).
    const Vec3& white() const noexcept { return m_white; }
    const Mat3& rgbToXyz() const noexcept { return m_rgbToXyz; }

private:
    Matrix m_a;
    Vec3 m_white;
    Mat3 m_rgbToXyz;
    /// The illuminant, and light on the grid → working RGB (the matching
    /// functions with the renderer's normalisation): what render(Surface)
    /// needs apart, since a surface may move light between wavelengths.
    Spectrum m_illuminant;
    Matrix m_light;
};

/// A named set of remittances.
struct ReflectanceSet
{
    std::string name;
    std::vector<NamedSpectrum> samples;
};

/// TCS01–TCS08 (CIE 13.3's Ra set) and 100 smooth random remittances
/// (seed 1): what fitted methods are fitted on.
const ReflectanceSet& TrainingSet();
/// TCS09–TCS15: the held-out test colours (saturated red, yellow, green,
/// blue, skin, leaf, skin) that no method is fitted on.
const ReflectanceSet& HeldOutTcs();
/// All fifteen TCS.
const ReflectanceSet& AllTcs();
/// `count` smooth random remittances in (0, 1): 0.5 + 0.5·tanh of a
/// random Fourier series of four terms over 380–780 nm.
ReflectanceSet RandomSmoothSet(int count, unsigned seed, const std::string& name);

}  // namespace bandlight
