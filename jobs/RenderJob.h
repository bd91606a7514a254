// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "jobs/Defaults.h"
#include "farm/Reporter.h"
#include "render/Scene.h"
#include "render/ScenePlan.h"
#include "render/SceneRenderer.h"
#include "report/DeltaEMap.h"

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

/// A file the render wrote, and what it holds ("960x360, 3 channels, ACEScg").
struct RenderFile
{
    std::string path;
    std::string what;
};

/// The render against its spectral reference (`compare`).
struct RenderComparison
{
    DeltaESummary summary;  ///< over the pixels where something was hit
    std::string exr;        ///< the ΔE00 map, one float channel "dE00"
    std::string png;        ///< the map in colour, with its scale
};

struct RenderResult
{
    std::string explanation;  ///< as PreparedRender::explanation
    RenderedImage image;      ///< the render (empty with `explain`)
    RenderCounters counters;  ///< what the renderer evaluated
    double seconds = 0.0;     ///< wall time of the render itself
    /// The render and its preview, as written.
    std::vector<RenderFile> files;
    std::optional<RenderComparison> comparison;

    /// Every file written: the render, its preview and the comparison's maps.
    std::vector<std::string> written() const;
};

/// Throws ParameterError when the outputs asked for do not go together:
/// spectra need spectral mode and an RGB output, a comparison an RGB
/// output, files an `out`. Nothing with `explain`.
void CheckRenderOutputs(const PreparedRender& prepared);

/// Renders a prepared request and writes its outputs as one set. First,
/// before anything is rendered, CheckRenderOutputs, and every file to be
/// written is checked (OutputPlan: its folder exists and can be written,
/// it is not the scene file). Then renders and writes the render, its
/// preview and, with `compare`, the ΔE00 map against the spectral render
/// (L*a*b* relative to the equal-energy white at the lights' summed
/// intensity; the background is left out). Either every file is replaced
/// or none is.
RenderResult MakeRender(const PreparedRender& prepared, Reporter& reporter = SilentReporter());

/// PrepareRender, then MakeRender.
RenderResult MakeRender(const RenderRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
