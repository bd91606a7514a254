// SPDX-License-Identifier: BSD-3-Clause
// Camera input transforms, as `bandlight idt --json` reports them: the
// document as a dict, its matrices and gains as numpy arrays, and the config
// it wrote as a PyOpenColorIO.Config.
#include <optional>

#include "PyBandlight.h"
#include "jobs/IdtJob.h"
#include "jobs/WallJob.h"
#include "requests/Defaults.h"

namespace bandlight::python
{

namespace
{

/// Lights or remittance names as the command's lists take them: a
/// comma-separated str, or a sequence of names and files.
std::vector<std::string> ToNames(const py::object& arg, const std::string& what)
{
    if (arg.is_none())
    {
        return {};
    }
    if (py::isinstance<py::str>(arg))
    {
        return jobs::SplitList(arg.cast<std::string>());
    }
    std::vector<std::string> out;
    for (const py::handle item : CastTo<py::list>(py::list(arg), what, "a sequence"))
    {
        out.push_back(PathText(item, what));
    }
    return out;
}

std::string OptionalPath(const std::optional<Path>& p)
{
    return p ? p->string() : "";
}

py::object Idt(const std::optional<Path>& camera, const py::object& lights,
               const std::string& workingSpace, const std::string& adaptation,
               const py::object& observer, const std::optional<Path>& training,
               const py::object& testSet, const py::object& interpolate,
               const py::object& asShotNeutral, const py::object& asShotLight,
               const std::optional<Path>& chartRgb, const py::object& chart,
               const py::object& light, int rootpoly, const std::optional<Path>& json,
               const std::optional<Path>& config, const std::optional<Path>& base,
               const std::optional<Path>& out, const std::optional<std::string>& baseSpace)
{
    using namespace pybind11::literals;
    jobs::IdtRequest r;
    r.camera = OptionalPath(camera);
    r.lights = ToNames(lights, "lights");
    r.workingSpace = workingSpace;
    r.adaptation = adaptation;
    r.observer = py::str(observer).cast<std::string>();
    r.training = OptionalPath(training);
    r.testSet = PathText(testSet, "test_set");
    r.interpolate = ToNames(interpolate, "interpolate");
    if (!interpolate.is_none() && r.interpolate.size() != 2)
    {
        throw ParameterError("{interpolate} takes two lights, not " +
                             std::to_string(r.interpolate.size()));
    }
    if (!asShotNeutral.is_none())
    {
        r.asShotNeutral =
            CastTo<std::vector<double>>(asShotNeutral, "as_shot_neutral", "three numbers R, G, B");
    }
    if (!asShotLight.is_none())
    {
        for (const std::string& name : ToNames(asShotLight, "as_shot_light"))
        {
            r.asShotLight += (r.asShotLight.empty() ? "" : ",") + name;
        }
    }
    r.chartRgb = OptionalPath(chartRgb);
    r.chart = chart.is_none() ? "" : PathText(chart, "chart");
    r.chartLight = light.is_none() ? "" : PathText(light, "light");
    r.chartRootPolynomial = rootpoly;
    r.json = OptionalPath(json);
    r.config = OptionalPath(config);
    r.base = OptionalPath(base);
    r.out = OptionalPath(out);
    r.baseSpace = baseSpace.value_or("");
    jobs::IdtResult result;
    {
        py::gil_scoped_release release;
        result = jobs::MakeIdt(r, Warnings());
    }
    py::dict doc = py::module_::import("json").attr("loads")(jobs::IdtDocument(result));
    const py::object array = py::module_::import("numpy").attr("array");
    for (const py::handle i : doc["idts"].cast<py::list>())
    {
        for (const char* key : {"gains", "matrix", "first_order_matrix", "raw_to_working"})
        {
            i[key] = array(i[key], "dtype"_a = "float64");
        }
    }
    if (doc.contains("interpolation"))
    {
        for (const py::handle c : doc["interpolation"]["calibrations"].cast<py::list>())
        {
            c["color_matrix"] = array(c["color_matrix"], "dtype"_a = "float64");
        }
    }
    const std::string written = !r.config.empty() ? r.config : r.out;
    doc["config"] = written.empty() ? py::object(py::none())
                                    : py::module_::import("PyOpenColorIO")
                                          .attr("Config")
                                          .attr("CreateFromFile")(written + "/config.ocio");
    // Each light's input colour space as the written config holds it.
    py::dict spaces;
    if (!written.empty())
    {
        for (const py::handle i : doc["idts"].cast<py::list>())
        {
            if (i.contains("colorspace"))
            {
                spaces[i["light"]] = doc["config"].attr("getColorSpace")(i["colorspace"]);
            }
        }
    }
    doc["colorspaces"] = spaces;
    return std::move(doc);
}

/// `wall`: the emitters as a mapping {name: file} (in drive-channel
/// order) or "NAME=FILE" strings, the job's report.json as a dict.
py::object Wall(const py::object& emitters, const Path& camera, const py::object& whiteBalances,
                const std::string& contentSpace, const Path& out,
                const std::optional<Path>& training, const py::object& testSet)
{
    jobs::WallRequest r;
    if (py::isinstance<py::dict>(emitters))
    {
        for (const auto& [name, file] : emitters.cast<py::dict>())
        {
            r.emitters.push_back({py::str(name).cast<std::string>(), PathText(file, "emitters")});
        }
    }
    else
    {
        for (const std::string& e : ToNames(emitters, "emitters"))
        {
            r.emitters.push_back(jobs::ParseEmitter(e));
        }
    }
    r.camera = camera.string();
    r.whiteBalances = ToNames(whiteBalances, "white_balances");
    r.contentSpace = contentSpace;
    r.out = out.string();
    r.training = OptionalPath(training);
    if (!testSet.is_none())
    {
        r.testSet = PathText(testSet, "test_set");
    }
    jobs::WallResult result;
    {
        py::gil_scoped_release release;
        result = jobs::MakeWall(r, Warnings());
    }
    return py::module_::import("json").attr("loads")(jobs::WallDocument(result));
}

}  // namespace

void AddIdt(py::module_& m)
{
    m.def("wall", &Wall, py::arg("emitters"), py::arg("camera"), py::arg("white_balances"),
          py::kw_only(), py::arg("content_space"), py::arg("out"), py::arg("training") = py::none(),
          py::arg("test_set") = py::none(), R"doc(
An LED wall or fixture as a light: the job of ``bandlight wall``, returning
its report.json as a dict (docs/wall.md). emitters: {name: file} in
drive-channel order, or "NAME=FILE" strings; camera: a sensitivities file;
white_balances: the camera's white balances ("5600K", names or files, a
sequence or a comma-separated str); content_space: the content's RGB space;
out: the folder config.ocio, its transform files and report.json are written
into. Per white balance the report holds the in-frustum drive, the errors
out of the frustum before and after the lighting pre-correction and the
post-camera look, and the wall's light scored as bandlight.quality scores a
light. The GIL is released while it runs.
)doc");
    m.def("idt", &Idt, py::arg("camera") = py::none(), py::arg("lights") = py::none(),
          py::kw_only(), py::arg("working_space") = defaults::IDT_WORKING_SPACE,
          py::arg("adaptation") = defaults::ADAPTATION, py::arg("observer") = defaults::OBSERVER,
          py::arg("training") = py::none(), py::arg("test_set") = defaults::IDT_TEST_SET,
          py::arg("interpolate") = py::none(), py::arg("as_shot_neutral") = py::none(),
          py::arg("as_shot_light") = py::none(), py::arg("chart_rgb") = py::none(),
          py::arg("chart") = py::none(), py::arg("light") = py::none(),
          py::arg("rootpoly") = defaults::IDT_CHART_ROOTPOLY, py::arg("json") = py::none(),
          py::arg("config") = py::none(), py::arg("base") = py::none(), py::arg("out") = py::none(),
          py::arg("base_space") = py::none(), R"doc(
Camera input transforms (IDTs): the job of ``bandlight idt``, returning the
document ``bandlight idt --json`` writes as a dict, its "gains", "matrix",
"first_order_matrix" and "raw_to_working" as numpy arrays:

- "camera", "working_space", "adaptation", "training", "test_set";
- "idts": per light {"light", "cct", "duv", "gains" (raw -> balanced, green
  1), "matrix" (balanced camera RGB -> working space, white kept, fitted as
  rawtoaces fits it and iterated to the optimum), "first_order_matrix" (the
  first-order fit it started from), "raw_to_working" (matrix . diag(gains)),
  "objective_rms_de76", "error": {SET: {"mean", "p95", "max"}} (CIEDE2000 on
  the training set and the test set), "colorspace" (with a config)};
- "as_shot" with as_shot_neutral: {"cct", "duv", "nearest", "family",
  "family_kelvin", "light", "grey_de00"} (the IDT for it is the last of
  "idts"); as_shot_light: the lights searched ("daylight", "planckian",
  "fluorescent" or a list), daylight or Planckian by default; a neutral
  whose grey is more than 2 ΔE00 from the closest light's white is refused;
- "interpolation" with interpolate: the IDT interpolated between the two
  lights as DNG does (their "calibrations": {"light", "cct", "color_matrix"},
  XYZ -> raw as numpy arrays, interpolated in mired; white balance and CAT
  for each light) against one fitted at each CCT, 2800-6500 K, on the test
  set: "curve" [{"cct", "mean_vs_direct", "p95_vs_direct", "max_vs_direct",
  "dng_clamped_mean_vs_direct", "interpolated_mean", "direct_mean",
  "dng_clamped_mean"}] (CIEDE2000);
- "chart" with chart_rgb: {"patches", "neutral_patch"}, and with rootpoly=2
  or 3 "rootpoly": {"degree", "matrix", "error"}, a root polynomial fitted
  on the chart (exposure invariant);
- "config": the config written (config= or base= with out=), as a
  PyOpenColorIO.Config, else None;
- "colorspaces": {light: its input colour space, a PyOpenColorIO.ColorSpace
  of that config} (empty without a config).

camera: sensitivities (rawtoaces JSON, CSV, CGATS). lights: a
comma-separated str or a sequence of built-in names, colour temperatures
("3200K": CIE daylight from 4000 K, Planckian below) and spectrum files.
chart_rgb, chart, light: a photographed chart's camera RGB (CSV), its
remittances and the light, instead of camera. json, config, base/out: the
outputs, written together; base_space: the primaries of the base's
scene_linear when the base does not tell them. Runs with the GIL released.
)doc");
}

}  // namespace bandlight::python
