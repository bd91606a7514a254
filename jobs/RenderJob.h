// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `render`: the verb. Its request is in requests/Render.h, its files are
// written by imaging/RenderFiles.h.

#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "render/SceneRenderer.h"
#include "report/DeltaEMap.h"
#include "imaging/RenderFiles.h"
#include "requests/Render.h"

namespace bandlight::jobs
{

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
