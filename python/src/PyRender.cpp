// SPDX-License-Identifier: BSD-3-Clause
// Scenes: a YAML scene (a file or text) rendered to a numpy image or to the
// files `bandlight render` writes (the render job, jobs/RenderJob.h), and
// the planner's account of it.
#include "PyBandlight.h"
#include "requests/Defaults.h"
#include "jobs/RenderJob.h"

namespace bandlight::python
{

namespace
{
/// The request's scene: a file or text, the mode override as `bandlight
/// render --mode` applies it.
jobs::RenderRequest SceneRequest(const std::optional<Path>& scene,
                                 const std::optional<std::string>& text, const std::string& source,
                                 const std::optional<std::string>& mode, bool unplanned)
{
    if (!scene && !text)
    {
        throw py::type_error("render() takes a scene file or text=YAML, one of the two");
    }
    jobs::RenderRequest r;
    r.scene = scene ? scene->string() : "";
    r.text = text;
    r.source = source;
    r.mode = mode;
    r.unplanned = unplanned;
    return r;
}

/// The image as (height, width, channels) float32, owning the renderer's
/// buffer (no copy).
py::array_t<float> ToImage(RenderedImage&& img)
{
    auto* pixels = new std::vector<float>(std::move(img.pixels));
    py::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<float>*>(p); });
    return py::array_t<float>(
        {py::ssize_t(img.height), py::ssize_t(img.width), py::ssize_t(img.channels)},
        pixels->data(), owner);
}

/// What the render wrote, as a dict (the image too).
py::dict ResultDict(jobs::RenderResult&& result)
{
    py::dict d;
    d["files"] = result.written();
    d["width"] = result.image.width;
    d["height"] = result.image.height;
    d["channels"] = result.image.channels;
    const RenderCounters& c = result.counters;
    py::dict counters;
    counters["pixels"] = c.pixels;
    counters["hits"] = c.hits;
    counters["light_terms"] = c.lightTerms;
    counters["specular_terms"] = c.specularTerms;
    counters["attenuation_terms"] = c.attenuationTerms;
    counters["spectral_samples"] = c.spectralSamples;
    d["counters"] = counters;
    d["seconds"] = result.seconds;
    d["explanation"] = result.explanation;
    py::object comparison = py::none();
    if (result.comparison)
    {
        const DeltaESummary& s = result.comparison->summary;
        py::dict cd;
        cd["pixels"] = s.pixels;
        cd["mean"] = s.mean;
        cd["p95"] = s.p95;
        cd["max"] = s.max;
        cd["exr"] = result.comparison->exr;
        cd["png"] = result.comparison->png;
        comparison = cd;
    }
    d["comparison"] = comparison;
    d["image"] = ToImage(std::move(result.image));
    return d;
}

py::object Render(const std::optional<Path>& scene, const std::optional<std::string>& text,
                  const std::string& source, const std::optional<std::string>& mode, int threads,
                  bool unplanned, const std::optional<Path>& out, bool spectra, bool compare,
                  const py::object& preview, bool lightGroups)
{
    jobs::RenderRequest r = SceneRequest(scene, text, source, mode, unplanned);
    r.threads = ToThreads(threads);
    r.out = out ? out->string() : "";
    r.spectra = spectra;
    r.compare = compare;
    r.lightGroups = lightGroups;
    if (py::isinstance<py::bool_>(preview))
    {
        r.preview = preview.cast<bool>();
    }
    else
    {
        r.previewPath = PathText(preview, "preview");
    }
    const jobs::PreparedRender prepared = jobs::PrepareRender(r);
    // Refused outputs are a ValueError, even when `out`'s folder is missing too.
    jobs::CheckRenderOutputs(prepared);
    PythonReporter reporter;
    jobs::RenderResult result;
    {
        py::gil_scoped_release release;
        result = jobs::MakeRender(prepared, reporter);
    }
    reporter.raiseIfFailed();
    if (r.out.empty())
    {
        return ToImage(std::move(result.image));
    }
    return ResultDict(std::move(result));
}
}  // namespace

void AddRender(py::module_& m)
{
    m.def("render", &Render, py::arg("scene") = py::none(), py::kw_only(),
          py::arg("text") = py::none(), py::arg("source") = defaults::SCENE_SOURCE,
          py::arg("mode") = py::none(), py::arg("threads") = defaults::THREADS,
          py::arg("unplanned") = false, py::arg("out") = py::none(), py::arg("spectra") = false,
          py::arg("compare") = false, py::arg("preview") = jobs::RenderRequest{}.preview,
          py::arg("light_groups") = false, R"doc(
Renders a YAML scene (docs/scenes.md) as ``bandlight render`` does.

Without out: returns the image, float32 (height, width, channels), top row
first: linear RGB in the scene's output space, or band values for
``output: bands``; nothing is written.

With out: writes what ``bandlight render SCENE -o OUT`` writes, the same
bytes: the EXR, its sRGB preview (an RGB render; preview: True beside out
as OUT.png, a path: there, False: none), with spectra=True the spectral
radiance as S0.<nm> channels beside R, G, B (spectral mode), with
compare=True the spectral reference's ΔE00 map OUT_dE00.exr and
OUT_dE00.png, with light_groups=True one layer per light group beside the
beauty (<group>.R/G/B, and <group>.S0.<nm> with spectra; docs/lightgroups.md);
all replaced together or none. Returns a dict: "files" (every
file written), "width", "height", "channels", "counters" (what the renderer
evaluated: pixels, hits, light_terms, specular_terms, attenuation_terms,
spectral_samples), "seconds" (the render itself), "explanation" (the plan),
"comparison" (None, or pixels, mean, p95, max, exr, png) and "image".

scene: a scene file; or text: the YAML itself, with source naming it in
error messages and anchoring its relative file names. mode: override the
scene's mode ("band3", "bandN" or "spectral"). unplanned: render the literal
way (every light, every effect, per pixel and sample), the planner's
reference; the planned image is the same to 1e-6. Runs with the GIL released
on threads threads (0: all cores). Raises ValueError "FILE:LINE: what" for
any error in the scene, ValueError for outputs that do not go together
(spectra in band mode, compare with band values), before rendering; OSError
when a file cannot be read or written.
)doc");
    m.def(
        "explain_scene",
        [](const std::optional<Path>& scene, const std::optional<std::string>& text,
           const std::string& source, const std::optional<std::string>& mode, bool unplanned)
        {
            jobs::RenderRequest r = SceneRequest(scene, text, source, mode, unplanned);
            r.explain = true;
            return jobs::PrepareRender(r).explanation;
        },
        py::arg("scene") = py::none(), py::kw_only(), py::arg("text") = py::none(),
        py::arg("source") = defaults::SCENE_SOURCE, py::arg("mode") = py::none(),
        py::arg("unplanned") = false,
        "What the planner evaluates for a scene, and why (``bandlight render --explain``).");
}

}  // namespace bandlight::python
