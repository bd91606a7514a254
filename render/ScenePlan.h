// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "render/Scene.h"

namespace bandlight
{

/// What the renderer will evaluate, decided from the scene before any pixel
/// (the planner's rule: simulate only the effects a scene calls for). The plan
/// changes the cost, never the picture: RenderScene with a plan gives
/// RenderSceneUnplanned's image (tested to 1e-6 on generated scenes).
struct ScenePlan
{
    bool specular = false;       ///< some material has a non-zero R_spek
    bool attenuation = false;    ///< some point light attenuates
    bool ambient = false;        ///< some ambient light and some non-zero R_amb
    bool ambientFolded = false;  ///< one direct light: the ambient is a per-material constant
    /// Direct lights grouped by their spectrum's values (never by name):
    /// each group is one spectral term.
    std::vector<std::vector<int>> groups;
    double stepNm = 5.0;               ///< spectral grid (spectral mode)
    int samples = 0;                   ///< spectral samples (or bands) per product
    int lineCount = 0;                 ///< emission lines integrated exactly
    int channels = 3;                  ///< output channels
    std::vector<std::string> reasons;  ///< why, one line each

    /// Per material m and group g, the output colour of one unit of the
    /// group's light on the diffuse / specular remittance, and per material
    /// the summed ambient colour: the spectral products, computed once.
    std::vector<std::vector<std::vector<double>>> diffuseColour;   // [g][m][channel]
    std::vector<std::vector<std::vector<double>>> specularColour;  // [g][m][channel]
    std::vector<std::vector<double>> ambientColour;                // [m][channel]
};

struct PlanOptions
{
    /// false: every term is evaluated (each light its own term, specular
    /// and attenuation always) — the full pipeline the planner is checked
    /// against.
    bool optimise = true;
};

/// Analyses the scene and precomputes its spectral products. Throws
/// Exception for an inconsistent scene (a material index out of range, a
/// band set outside the data, "bands" output in spectral mode).
ScenePlan PlanScene(const Scene& scene, const PlanOptions& options = {});

/// The plan as text, for `bandlight render --explain`.
std::string ExplainPlan(const Scene& scene, const ScenePlan& plan);

}  // namespace bandlight
