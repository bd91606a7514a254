// SPDX-License-Identifier: BSD-3-Clause
#include "requests/Render.h"

#include <cerrno>

#include "farm/OutputPaths.h"
#include "imageio/ImageColour.h"
#include "render/SceneFile.h"
#include "render/SceneRenderer.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{

namespace
{

/// `path` without its extension ("shots/a.exr" → "shots/a").
std::string Stem(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    return dot != std::string::npos && (slash == std::string::npos || dot > slash)
               ? path.substr(0, dot)
               : path;
}

}  // namespace

/// The preview beside the render: its stem + ".png".
std::string PreviewPath(const std::string& out)
{
    return Stem(out) + ".png";
}

/// The comparison's map beside the render: its stem + "_dE00" + `extension`.
std::string MapPath(const std::string& out, const std::string& extension)
{
    return Stem(out) + "_dE00" + extension;
}

bool BandOutput(const Scene& scene)
{
    return scene.settings.output == "bands";
}

/// "band3", "band6" or "spectral": the mode as --mode names it.
std::string ModeName(const RenderSettings& s)
{
    return s.mode == RenderSettings::Mode::SPECTRAL ? "spectral"
                                                    : "band" + std::to_string(s.bands.size());
}

Scene LoadScene(const std::string& path, const std::optional<std::string>& text,
                const std::string& source, const std::optional<std::string>& mode)
{
    if (!path.empty() && text.has_value())
    {
        throw ParameterError("give a scene file or {text=}YAML, not both");
    }
    if (path.empty() && !text.has_value())
    {
        // The command has no text option: an empty SCENE is a missing file.
        throw FileError(path, ENOENT, "no scene file to render");
    }
    const std::string name = text ? source : path;
    Scene scene = text ? ReadSceneText(*text, source) : ReadSceneFile(path);
    if (mode)
    {
        if (ModeBandCount(*mode) == 0 && scene.settings.output == "bands")
        {
            throw ParameterError("{mode} " + OneLine(*mode, 80) + ": " + name +
                                 " asks for output 'bands' (band values), which only band mode "
                                 "writes; set render: {output: acescg} (or another working "
                                 "space) to render it spectrally");
        }
        SetRenderMode(scene.settings, *mode);
    }
    return scene;
}

std::string DefaultRenderOutput(const std::string& scenePath)
{
    return Stem(scenePath) + ".exr";
}

PreparedRender PrepareRender(const RenderRequest& request)
{
    PreparedRender p;
    p.request = request;
    p.scene = LoadScene(request.scene, request.text, request.source, request.mode);
    // Unplanned, the explanation says what the literal path does, not what
    // a plan would.
    if (!request.unplanned)
    {
        p.plan = PlanScene(p.scene);
    }
    p.explanation = request.unplanned ? ExplainUnplanned(p.scene) : ExplainPlan(p.scene, p.plan);
    return p;
}

void CheckRenderFiles(const RenderRequest& r, const Scene& scene)
{
    OutputPlan plan;
    if (!r.text)
    {
        plan.input(r.scene);
    }
    plan.file("{out}", r.out);
    if (r.preview && !BandOutput(scene))
    {
        plan.file(r.previewPath.empty() ? "{out}" : "{preview}",
                  r.previewPath.empty() ? PreviewPath(r.out) : r.previewPath);
    }
    if (r.compare)
    {
        plan.file("{out}", MapPath(r.out, ".exr")).file("{out}", MapPath(r.out, ".png"));
    }
    plan.check();
}
void CheckRenderOutputs(const PreparedRender& prepared)
{
    const RenderRequest& r = prepared.request;
    const Scene& scene = prepared.scene;
    if (r.explain)
    {
        return;  // nothing is written
    }
    if (!r.out.empty() && (r.lightGroups || r.spectra))
    {
        RequireNamedChannels(r.out, r.lightGroups ? "light groups" : "spectral channels");
    }
    if (r.spectra)
    {
        if (scene.settings.mode != RenderSettings::Mode::SPECTRAL)
        {
            throw ParameterError(
                "{spectra} needs spectral mode ({mode=}spectral): band mode has no spectrum to "
                "write");
        }
        if (BandOutput(scene))
        {
            throw ParameterError(
                "{spectra} writes R, G, B beside the spectrum: give an RGB output");
        }
    }
    if (r.compare && BandOutput(scene))
    {
        throw ParameterError("{compare} needs an RGB output: the spectral reference has no bands");
    }
    if (r.compare && scene.settings.mode == RenderSettings::Mode::SPECTRAL)
    {
        throw ParameterError(
            "{compare} measures a band render against the spectral one, and this render is "
            "spectral already (its map would be 0 everywhere): give {mode=}band3 or bandN");
    }
    if (!r.previewPath.empty() && r.preview && BandOutput(scene))
    {
        throw ParameterError("{preview} shows RGB: band values (output: bands) have no preview");
    }
    if (r.out.empty())
    {
        if (r.lightGroups)
        {
            throw ParameterError(
                "{light_groups} writes one layer per light group into the render's EXR: give "
                "{out}");
        }
        if (r.spectra)
        {
            throw ParameterError("{spectra} writes the spectrum into the render's EXR: give {out}");
        }
        if (r.compare)
        {
            throw ParameterError("{compare} writes its ΔE00 map beside the render: give {out}");
        }
        if (!r.previewPath.empty() && r.preview)
        {
            throw ParameterError("{preview} is the picture of a render written: give {out}");
        }
    }
}

}  // namespace bandlight::jobs
