// SPDX-License-Identifier: BSD-3-Clause
// Scenes: a YAML scene (a file or text) rendered to a numpy image, as
// `bandlight render` renders it, and the planner's account of it.
#include "PyBandlight.h"
#include "jobs/RenderJob.h"
#include "render/ScenePlan.h"
#include "render/SceneRenderer.h"
#include "jobs/Defaults.h"

namespace bandlight::python
{

namespace
{
/// The scene from a file or from text, with the mode override applied as
/// `bandlight render --mode` applies it (jobs::LoadScene).
Scene LoadScene(const std::optional<Path>& path, const std::optional<std::string>& text,
                const std::string& source, const std::optional<std::string>& mode)
{
    const std::string file = path ? path->string() : "";
    return path ? ReadingFile(file, [&] { return jobs::LoadScene(file, text, source, mode); })
                : jobs::LoadScene(file, text, source, mode);
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
}  // namespace

void AddRender(py::module_& m)
{
    m.def(
        "render",
        [](const std::optional<Path>& scene, const std::optional<std::string>& text,
           const std::string& source, const std::optional<std::string>& mode, int threadsArg,
           bool unplanned)
        {
            const int threads = ToThreads(threadsArg);
            const Scene s = LoadScene(scene, text, source, mode);
            RenderedImage img;
            {
                py::gil_scoped_release release;
                img = unplanned ? RenderSceneUnplanned(s, threads)
                                : RenderScene(s, PlanScene(s), threads);
            }
            return ToImage(std::move(img));
        },
        py::arg("scene") = py::none(), py::kw_only(), py::arg("text") = py::none(),
        py::arg("source") = defaults::SCENE_SOURCE, py::arg("mode") = py::none(), py::arg("threads") = defaults::THREADS,
        py::arg("unplanned") = false, R"doc(
Renders a YAML scene (docs/scenes.md) as ``bandlight render`` does and
returns the image, float32 (height, width, channels), top row first: linear
RGB in the scene's output space, or band values for ``output: bands``.

scene: a scene file; or text: the YAML itself, with source naming it in
error messages and anchoring its relative file names. mode: override the
scene's mode ("band3", "bandN" or "spectral"). unplanned: render the literal
way (every light, every effect, per pixel and sample), the planner's
reference; the planned image is the same to 1e-6. Runs with the GIL released
on threads threads (0: all cores). Raises ValueError "FILE:LINE: what" for
any error in the scene.
)doc");
    m.def(
        "explain_scene",
        [](const std::optional<Path>& scene, const std::optional<std::string>& text,
           const std::string& source, const std::optional<std::string>& mode, bool unplanned)
        {
            const Scene s = LoadScene(scene, text, source, mode);
            return unplanned ? ExplainUnplanned(s) : ExplainPlan(s, PlanScene(s));
        },
        py::arg("scene") = py::none(), py::kw_only(), py::arg("text") = py::none(),
        py::arg("source") = defaults::SCENE_SOURCE, py::arg("mode") = py::none(), py::arg("unplanned") = false,
        "What the planner evaluates for a scene, and why (``bandlight render --explain``).");
}

}  // namespace bandlight::python
