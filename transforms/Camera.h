// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "spectral/CameraFile.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/SpectrumIO.h"
#include "transforms/SurfaceRenderer.h"
#include "transforms/Defaults.h"

namespace bandlight
{

/// A camera as the pipeline sees it: its sensitivities on SurfaceRenderer's
/// grid (380–780 nm at 5 nm; zero where the file has no data), scaled by a
/// power of two so that the largest is in [0.5, 1) (white balance removes
/// any common scale; this keeps 1e300 and 1e-300 files finite).
class SpectralCamera
{
public:
    using Matrix = Eigen::Matrix<double, 3, SurfaceRenderer::kSamples>;

    explicit SpectralCamera(const CameraSensitivities& sensitivities);

    const std::string& name() const noexcept { return m_name; }
    /// "SOURCE: camera NAME": how messages about this camera begin.
    std::string label() const;
    const Matrix& sensitivities() const noexcept { return m_s; }

private:
    std::string m_name;
    std::string m_source;
    Matrix m_s;
};

/// A camera shooting under one light, white-balanced by per-channel gains so
/// that the perfect white reflector records as RGB (1, 1, 1) — what a raw
/// developer's "as shot" balance for that light does.
class CameraShot
{
public:
    /// Throws Exception when a channel records nothing of the light.
    CameraShot(const SpectralCamera& camera, const Spectrum& light);

    /// White-balanced camera RGB of a remittance.
    Vec3 record(const SurfaceRenderer::Samples& remittance) const { return m_a * remittance; }
    /// The white-balance gains (raw × gains = balanced).
    const Vec3& gains() const noexcept { return m_gains; }

private:
    Eigen::Matrix<double, 3, SurfaceRenderer::kSamples> m_a;
    Vec3 m_gains;
};

/// The input transform a camera gets for one light, fitted the way the
/// Academy's rawtoaces fits IDTs: a 3×3 from the white-balanced camera RGB
/// of the training remittances (rawtoaces' 190 by default) shot under
/// `light` to their colours under that light balanced to the working
/// space's white by `adaptation` (working RGB), white (1, 1, 1) mapped
/// exactly onto (1, 1, 1), minimising the CIELAB error relative to the
/// working white (to first order: each residual weighted by the L*a*b*
/// Jacobian at its target). A camera whose sensitivities are the observer's
/// matching functions gets the exact answer, M⁻¹·CAT·M·diag(white).
Mat3 FitIdt(const SpectralCamera& camera, const Spectrum& light, const RgbSpace& working,
            AdaptationMethod adaptation, Observer observer = Observer::CIE1931_2DEG,
            const std::vector<NamedSpectrum>& training = {});

/// The light a camera's fixed daylight IDT is fitted for when none is
/// named: CIE D55, the "daylight" of camera vendors' IDTs.
const char* const DEFAULT_IDT_LIGHT = defaults::IDT_LIGHT;

}  // namespace bandlight
