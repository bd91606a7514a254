// SPDX-License-Identifier: BSD-3-Clause
// Image files and frame sequences through a look or an illuminant change,
// as `bandlight apply` applies them (jobs/ApplyJob).
#include "PyBandlight.h"
#include "jobs/ApplyJob.h"
#include "requests/Defaults.h"
#include "farm/Frames.h"

namespace bandlight::python
{

namespace
{
/// The keywords of a change of light, the plates resolved.
struct ChangeArgs
{
    py::object src;
    py::object dst;
    std::string method;
    std::string working;
    py::object observer;
    py::object training;
    PlatesArgs plates;
};

/// The request's files, frames, look and how it runs; the change of light
/// is added to it apart.
jobs::ApplyRequest FilesRequest(const py::object& input, const py::object& output,
                                const std::optional<std::string>& frames,
                                const std::optional<std::string>& look, const py::object& config,
                                const std::optional<std::string>& colorspace, int threads,
                                bool skipExisting, bool keepGoing)
{
    jobs::ApplyRequest r;
    r.input = PathText(input, "input");
    r.output = PathText(output, "output");
    r.frames = frames.value_or("");
    r.look = look.value_or("");
    r.config = config.is_none() ? "" : PathText(config, "config");
    r.colorspace = colorspace.value_or("");
    r.threads = ToThreads(threads);
    r.skipExisting = skipExisting;
    r.keepGoing = keepGoing;
    return r;
}

/// The keywords of a change of light that were given (not None), by name.
struct Given
{
    bool method, working, plates, adaptation, cameraIdt;
};

/// Refuses keywords that contradict each other: src without dst, or a
/// change of light beside a look (jobs::CheckLookAlone, as the command).
void RefuseConflicts(jobs::ApplyRequest& r, const ChangeArgs& change, const Given& given,
                     const py::object& lightGroups)
{
    if (change.src.is_none() != change.dst.is_none())
    {
        throw ParameterError("give both {src} and {dst}, or a {look}");
    }
    const auto add = [&](bool on, const char* name)
    {
        if (on)
        {
            r.changeGiven.push_back(name);
        }
    };
    add(!change.src.is_none(), "src");
    add(!change.dst.is_none(), "dst");
    add(given.method, "method");
    add(given.working, "working_space");
    add(!change.training.is_none(), "training");
    add(given.plates, "plates");
    add(!lightGroups.is_none(), "light_groups");
    add(given.adaptation, "adaptation");
    add(!change.plates.camera.is_none(), "camera");
    add(given.cameraIdt, "camera_idt");
    jobs::CheckLookAlone(r);
}

/// light_group_layers: {group: layer} (None: none).
std::map<std::string, std::string> ToLightGroupLayers(const py::object& lightGroupLayers)
{
    std::map<std::string, std::string> layers;
    if (!lightGroupLayers.is_none())
    {
        for (const auto& [name, layer] :
             CastTo<py::dict>(lightGroupLayers, "light_group_layers", "a dict {group: layer}"))
        {
            layers[CastTo<std::string>(name, "a group's name", "str")] =
                CastTo<std::string>(layer, "a group's layer", "str");
        }
    }
    return layers;
}

/// light_groups: each group's change, {group: (src, dst)} or (src, dst,
/// method), instead of src and dst.
std::vector<jobs::LightGroupRelight> ToLightGroups(const py::object& lightGroups,
                                                   const ChangeArgs& change)
{
    if (!change.src.is_none())
    {
        throw ParameterError(
            "{src} and {dst} do not apply with {light_groups}: each group "
            "takes its own, {name: (src, dst)}");
    }
    std::vector<jobs::LightGroupRelight> groups;
    for (const auto& [key, value] :
         CastTo<py::dict>(lightGroups, "light_groups", "a dict {group: (src, dst)}"))
    {
        const py::tuple lights = CastTo<py::tuple>(value, "a light group's change",
                                                   "a tuple (src, dst) or (src, dst, method)");
        if (lights.size() != 2 && lights.size() != 3)
        {
            throw ParameterError(
                "{light_groups} takes {group: (src, dst)} or {group: (src, dst, method)}");
        }
        jobs::LightGroupRelight g;
        g.group = CastTo<std::string>(key, "a group's name", "str");
        g.relight.plates = change.plates.options();
        g.relight.src = ToLight(lights[0]);
        g.relight.dst = ToLight(lights[1]);
        g.relight.method = lights.size() == 3
                               ? CastTo<std::string>(lights[2], "a group's method", "str")
                               : change.method;
        g.relight.workingSpace = change.working;
        g.relight.observer = py::str(change.observer).cast<std::string>();
        if (!change.training.is_none())
        {
            g.relight.training = ToReflectances(change.training);
        }
        groups.push_back(g);
    }
    return groups;
}

/// src and dst: one change of light for the whole image.
jobs::RelightRequest ToRelight(const ChangeArgs& change)
{
    jobs::RelightRequest relight;
    relight.plates = change.plates.options();
    relight.plates.parsed();
    if (!relight.plates.camera.empty())
    {
        change.plates.loadCamera();  // OSError when unreadable
    }
    relight.src = ToLight(change.src);
    relight.dst = ToLight(change.dst);
    relight.method = change.method;
    relight.workingSpace = change.working;
    relight.observer = py::str(change.observer).cast<std::string>();
    if (!change.training.is_none())
    {
        relight.training = ToReflectances(change.training);
    }
    return relight;
}

/// The job, the GIL released.
jobs::ApplyResult RunApply(const jobs::ApplyRequest& r)
{
    py::gil_scoped_release release;
    return jobs::ApplyImages(r, Warnings());
}

/// The job's summary (FrameRunDict) and what it applied.
py::dict ResultDict(const jobs::ApplyResult& result)
{
    py::dict d = FrameRunDict(result.frames, result.skipped, result.failed, result.seconds);
    d["applied"] = result.applied;
    return d;
}

py::dict Apply(const py::object& input, const py::object& output,
               const std::optional<std::string>& frames, const std::optional<std::string>& look,
               const py::object& config, const std::optional<std::string>& colorspace,
               const py::object& src, const py::object& dst,
               const std::optional<std::string>& method,
               const std::optional<std::string>& working, const py::object& observer,
               const py::object& training, const std::optional<std::string>& platesArg,
               const std::optional<std::string>& adaptation, const py::object& camera,
               const std::optional<std::string>& cameraIdt, int threads,
               bool skipExisting, bool keepGoing, const py::object& lightGroups,
               const py::object& lightGroupLayers,
               const std::optional<std::string>& lightGroupBeauty)
{
    // A render's light group carries its own light's cast: lit unless said.
    const std::string plates =
        platesArg.value_or(lightGroups.is_none() ? defaults::PLATES : defaults::LIGHT_GROUP_PLATES);
    jobs::ApplyRequest r = FilesRequest(input, output, frames, look, config, colorspace, threads,
                                        skipExisting, keepGoing);
    // Not given (None): the defaults table's value, and nothing to refuse.
    const PlatesArgs platesArgs{plates, adaptation.value_or(defaults::ADAPTATION), camera,
                                cameraIdt.value_or(defaults::IDT_LIGHT)};
    const ChangeArgs change{src,      dst,     method.value_or(defaults::METHOD),
                            working.value_or(defaults::WORKING_SPACE),
                            observer, training, platesArgs};
    const Given given{method.has_value(), working.has_value(), platesArg.has_value(),
                      adaptation.has_value(), cameraIdt.has_value()};
    RefuseConflicts(r, change, given, lightGroups);
    r.lightGroupLayers = ToLightGroupLayers(lightGroupLayers);
    r.lightGroupBeauty = lightGroupBeauty.value_or("");
    if (r.look.empty() && !lightGroups.is_none())
    {
        r.lightGroups = ToLightGroups(lightGroups, change);
    }
    else if (r.look.empty() && !src.is_none())
    {
        r.relight = ToRelight(change);
    }
    return ResultDict(RunApply(r));
}
}  // namespace

void AddApply(py::module_& m)
{
    m.def(
        "frame_set", [](const std::string& text) { return jobs::ParseFrameRange(text); },
        py::arg("text"), R"doc(
The frames a frame set names, as ``--frames`` reads it: "1001-1100",
"1001-1100x2", "1001-1010,1020"; in the order given, each once.
)doc");
    m.def("_apply", &Apply, py::arg("input"), py::arg("output"), py::kw_only(),
          py::arg("frames") = py::none(), py::arg("look") = py::none(),
          py::arg("config") = py::none(), py::arg("colorspace") = py::none(),
          py::arg("src") = py::none(), py::arg("dst") = py::none(),
          py::arg("method") = py::none(), py::arg("working_space") = py::none(),
          py::arg("observer") = defaults::OBSERVER, py::arg("training") = py::none(),
          py::arg("plates") = py::none(), py::arg("adaptation") = py::none(),
          py::arg("camera") = py::none(), py::arg("camera_idt") = py::none(),
          py::arg("threads") = defaults::THREADS, py::arg("skip_existing") = false,
          py::arg("keep_going") = false, py::arg("light_groups") = py::none(),
          py::arg("light_group_layers") = py::none(),
          py::arg("light_group_beauty") = py::none(),
          (std::string(R"doc(
Applies a look, or an illuminant change, to an image file or a frame
sequence through OpenImageIO: the job of ``bandlight apply``. Returns
{"applied": what was applied, "frames": the frames written, "skipped": the
frames skipped, "failed": [(frame, error)], "seconds": wall time}.

input, output: image files (any format OpenImageIO reads), or frame patterns
such as "plate.####.exr" with frames="1001-1100". Each output keeps its
input's pixel type, channels, alpha and metadata, and appears only when it
is complete. look, config: a look of a config (its folder or .ocio file),
applied in colorspace (default: the config's scene_linear role). Otherwise
src, dst (names, files or Spectrum) and method: the illuminant change in
working_space (rootpoly natively, the other methods through OCIO). Images
say what they are: sRGB-encoded files (PNG, JPEG, 8- and 16-bit TIFF) are
decoded to linear Rec.709, and files whose colorInteropID or chromaticities
name other primaries converted, to the space the work runs in and back;
untagged float files are taken as that space (a NoteWarning says so).
Without a look, colorspace names what the file holds instead (a built-in
space such as "acescg" or "rec709", or "srgb").
training: fit3x3's / rootpoly's remittances. Runs with the GIL released on
threads threads (0: all cores). frames: a frame set as farms hand them out
("1001-1100", "1001-1100x2", "1001-1010,1020"). skip_existing: frames whose
output exists are skipped (outputs are written whole or not at all).
keep_going: a frame that fails does not stop the others; it is listed in
"failed" (without it, the first failure raises).
light_groups: {group: (src, dst)}, instead of src and dst: each light group
of a multi-layer EXR (Blender/Cycles, Arnold or bandlight naming) relit on
its own with method (or its own, {group: (src, dst, method)}), the beauty written as the relit groups plus the
residual, everything else kept (docs/lightgroups.md); plates then defaults
to "lit". light_group_layers: {group: layer prefix or "r,g,b"} for a file
that names its groups otherwise. light_group_beauty: what the relit beauty is
made of, "residual" (default), "rebuild" (the relit groups alone: a denoised
beauty) or "difference" (the denoised beauty's difference carried).
)doc") + kPlatesDoc)
              .c_str());
}

}  // namespace bandlight::python
