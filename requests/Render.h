// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `render`'s request: the scene read (a file or text), planned, and every
// output path checked before the render.

#include <optional>
#include <string>
#include <vector>

#include "render/Scene.h"
#include "render/ScenePlan.h"
#include "requests/Defaults.h"

namespace bandlight::jobs
{

/// A scene read from a file (`path`) or from YAML text (`text`, named
/// `source` in messages), with its mode overridden by `mode` when given
/// ("band3", "bandN", "spectral"). Throws ParameterError when band values
/// (output: bands) are asked for in spectral mode: they exist only in band
/// mode, and switching the output behind the user's back would hide that.
Scene LoadScene(const std::string& path, const std::optional<std::string>& text,
                const std::string& source, const std::optional<std::string>& mode);

/// `render`: a YAML scene (docs/scenes.md) rendered in band or spectral
/// mode, planned so only the effects the scene calls for are simulated.
struct RenderRequest
{
    /// The scene: a file, or the YAML itself (`text`, named `source` in
    /// messages and anchoring its relative file names); one of the two.
    std::string scene;
    std::optional<std::string> text;
    std::string source = defaults::SCENE_SOURCE;
    /// Overrides the scene's mode: "band3", "bandN" or "spectral".
    std::optional<std::string> mode;
    /// The EXR to write (linear RGB in the scene's output space, or band
    /// values); empty: nothing is written and the result holds the image.
    std::string out;
    /// An sRGB PNG of an RGB render beside `out` (its stem + .png), or at
    /// `previewPath` when given.
    bool preview = true;
    std::string previewPath;
    /// Spectral mode: the spectral radiance goes into the EXR too, as
    /// S0.<nm> channels beside R, G, B (Fichet 2021 layout).
    bool spectra = false;
    /// One layer per light group of the scene (a light's `group:`, else its
    /// name) beside the beauty: "<group>.R/G/B" (and "<group>.S0.<λ>nm" with
    /// `spectra`), the groups listed in bandlight:lightGroups; the beauty is
    /// their sum, each group rendered and planned on its own.
    bool lightGroups = false;
    /// Also render the spectral reference and write the ΔE00 map of the
    /// render against it beside `out` (stem + _dE00.exr and _dE00.png).
    bool compare = false;
    /// Only plan: the result holds the explanation, nothing is rendered.
    bool explain = false;
    /// Evaluate every term per pixel and sample (the planner's reference).
    bool unplanned = false;
    int threads = defaults::THREADS;  ///< 0: all cores
};

/// The EXR a render writes when no output is named: the scene file's stem
/// + ".exr", beside it.
std::string DefaultRenderOutput(const std::string& scenePath);

/// A request with its scene read and planned: what MakeRender renders.
/// The command prints the explanation before the work.
struct PreparedRender
{
    RenderRequest request;
    Scene scene;
    ScenePlan plan;  ///< empty with `unplanned`
    /// What --explain prints: the plan and why (with `unplanned`: what the
    /// literal path evaluates).
    std::string explanation;
};

/// Reads and plans the scene of `request`. Throws Exception naming the
/// scene file and line, ParameterError for a mode it cannot take.
PreparedRender PrepareRender(const RenderRequest& request);

/// Throws ParameterError when the outputs asked for do not go together:
/// spectra need spectral mode and an RGB output, a comparison an RGB
/// output, files an `out`. Nothing with `explain`.
void CheckRenderOutputs(const PreparedRender& prepared);

/// Every file of the set, before the work: a folder that is not there
/// fails now, not after the render, and the scene is never overwritten.
void CheckRenderFiles(const RenderRequest& request, const Scene& scene);

/// The files a render's outputs go beside it: its preview (stem + ".png")
/// and the comparison's map (stem + "_dE00" + `extension`).
std::string PreviewPath(const std::string& out);
std::string MapPath(const std::string& out, const std::string& extension);

/// Whether the scene writes band values rather than RGB.
bool BandOutput(const Scene& scene);

/// "band3", "band6" or "spectral": the mode as --mode names it.
std::string ModeName(const RenderSettings& settings);

}  // namespace bandlight::jobs
