// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/Scene.h"
#include "render/ScenePlan.h"

namespace bandlight
{

/// Work the renderer did, counted (summed over threads).
struct RenderCounters
{
    uint64_t pixels = 0;
    uint64_t hits = 0;
    uint64_t lightTerms = 0;        ///< (pixel, light) geometry evaluations
    uint64_t specularTerms = 0;     ///< cosⁿψ evaluations
    uint64_t attenuationTerms = 0;  ///< f_att evaluations
    uint64_t spectralSamples = 0;   ///< per-pixel spectral samples (the unplanned path)
};

/// A rendered image: interleaved float channels, row-major, top row first.
struct RenderedImage
{
    int width = 0;
    int height = 0;
    int channels = 3;
    std::vector<std::string> channelNames;
    std::vector<float> pixels;
};

/// Renders with a plan: primary rays (pinhole or orthographic) against
/// spheres and planes (no shadows: the band model's local Phong model), per pixel
/// Σ_terms geometry × precomputed colour; rows split over `threads` threads
/// (0: all cores).
RenderedImage RenderScene(const Scene& scene, const ScenePlan& plan, int threads = 0,
                          RenderCounters* counters = nullptr);

/// The same image computed the slow, literal way: per pixel, per light, per
/// band or wavelength sample, then converted — the reference the planned
/// path is tested against.
RenderedImage RenderSceneUnplanned(const Scene& scene, int threads = 0,
                                   RenderCounters* counters = nullptr);

/// What RenderSceneUnplanned does for this scene, as text, for `bandlight
/// render --unplanned`: every light its own term, every effect evaluated,
/// per pixel and per band or wavelength sample.
std::string ExplainUnplanned(const Scene& scene);

}  // namespace bandlight
