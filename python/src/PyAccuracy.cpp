// SPDX-License-Identifier: BSD-3-Clause
// The accuracy report: every method against the spectral answer, ideal and
// as shipped, as `bandlight accuracy --json` measures it.
#include <optional>

#include "PyBandlight.h"
#include "jobs/AccuracyJob.h"
#include "requests/Defaults.h"

namespace bandlight::python
{

namespace
{

std::vector<ReflectanceSet> ToSets(const py::object& arg)
{
    std::vector<ReflectanceSet> sets;
    if (py::isinstance<py::dict>(arg))
    {
        for (const auto& [name, spectra] : arg.cast<py::dict>())
        {
            sets.push_back({py::str(name).cast<std::string>(), ToReflectances(spectra)});
        }
        return sets;
    }
    const py::list files = py::isinstance<py::str>(arg) || py::hasattr(arg, "__fspath__")
                               ? py::list(py::make_tuple(arg))
                               : py::list(arg);
    for (const py::handle f : files)
    {
        // As `--reflectances FILE`: the file read as it is, named by its path.
        sets.push_back(jobs::ReflectanceSetFromFile(PathText(f, "reflectances")));
    }
    return sets;
}

py::object Accuracy(const py::object& illuminants, const py::object& methods,
                    const py::object& reflectances, bool defaultSets, const std::string& working,
                    const py::object& observer, const py::object& exposures, int lutSize,
                    bool idealOnly, bool crossValidation, bool floor, bool cost,
                    const py::object& progress, const std::string& plates,
                    const std::string& adaptation, const py::object& camera,
                    const std::string& cameraIdt, const std::optional<Path>& json,
                    const std::optional<Path>& plot)
{
    jobs::AccuracyRequest r;
    r.plates = PlatesArgs{plates, adaptation, camera, cameraIdt}.options();
    r.plates.all();  // a bad convention or adaptation is refused before anything is read
    if (!r.plates.camera.empty())
    {
        PlatesArgs{plates, adaptation, camera, cameraIdt}.loadCamera();  // OSError when unreadable
    }
    r.workingSpace = working;
    r.observer = py::str(observer).cast<std::string>();
    if (!illuminants.is_none())
    {
        r.lights = ToLights(illuminants);
        if (r.lights.size() < 2)
        {
            throw Exception("accuracy needs at least two illuminants");
        }
    }
    if (!methods.is_none())
    {
        r.methods = py::isinstance<py::str>(methods)
                        ? jobs::SplitList(methods.cast<std::string>())
                        : CastTo<std::vector<std::string>>(methods, "methods",
                                                           "a sequence of method names");
        for (const std::string& m : r.methods)
        {
            ParseMethod(m);
        }
    }
    r.defaultSets = defaultSets;
    if (!reflectances.is_none())
    {
        r.sets = ToSets(reflectances);
    }
    if (!exposures.is_none())
    {
        r.exposures = CastTo<std::vector<double>>(exposures, "exposures", "a sequence of numbers");
        if (r.exposures.empty())
        {
            throw ParameterError("{exposures} must not be empty");
        }
    }
    r.lutSize = lutSize;
    r.idealOnly = idealOnly;
    r.crossValidation = crossValidation;
    r.floor = floor;
    r.cost = cost;
    r.json = json ? json->string() : "";
    r.plot = plot ? plot->string() : "";
    PythonReporter reporter(progress);
    jobs::AccuracyResult result;
    {
        py::gil_scoped_release release;
        result = jobs::MeasureAccuracyJob(r, reporter);
    }
    reporter.raiseIfFailed();
    return py::module_::import("json").attr("loads")(jobs::AccuracyDocument(result));
}
}  // namespace

void AddAccuracy(py::module_& m)
{
    m.def("accuracy", &Accuracy, py::arg("illuminants") = py::none(),
          py::arg("methods") = py::none(), py::kw_only(), py::arg("reflectances") = py::none(),
          py::arg("default_sets") = true, py::arg("working_space") = defaults::WORKING_SPACE,
          py::arg("observer") = defaults::OBSERVER, py::arg("exposures") = py::none(),
          py::arg("lut_size") = defaults::CONFIG_LUT_SIZE, py::arg("ideal_only") = false,
          py::arg("cross_validation") = true, py::arg("floor") = true, py::arg("cost") = true,
          py::arg("progress") = py::none(), py::arg("plates") = defaults::ACCURACY_PLATES,
          py::arg("adaptation") = defaults::ADAPTATION, py::arg("camera") = py::none(),
          py::arg("camera_idt") = defaults::IDT_LIGHT, py::arg("json") = py::none(),
          py::arg("plot") = py::none(), R"doc(
CIEDE2000 of illuminant-change methods against the spectral answer, and what
each costs: the accuracy job of ``bandlight accuracy``, returning the document
``bandlight accuracy --json`` writes, a dict:

- "rows": a list of dicts with keys method, from, to, set, plates
  ("balanced-cat02", "lit", and "balanced-cat02-through-lit-looks": lit looks
  on balanced plates, docs/plates.md), camera (the plates' source: "cie";
  with camera=, also "camera" and "camera-daylight-idt"), exposure, shipped,
  mean, p95, max, worst_sample;
- "cross_validation": the fitted methods on their own training data (sets
  "training, in-sample" and "training, 5-fold"), unless cross_validation=False;
- "floor": "floor-3x3" and "floor-rootpoly" fitted on each set itself,
  unless floor=False;
- "cost": each method timed on 1920x1080 float RGBA, {method, form,
  ns_per_pixel, mpixel_per_s, threads}, and "setup_cost": fitting and LUT
  baking, {what, seconds}; empty with cost=False;
- "camera": {name, file, idt_light}, or None.

plates: "both" (default), "balanced" or "lit"; adaptation: "cat02" or
"bradford"; camera: a camera sensitivities file whose plates are simulated
too (rootpoly-camera is added to the default methods); camera_idt: the
light of its one fixed daylight IDT.

For every ordered pair of illuminants, every method and reflectance set and
every exposure k (2^-8 ... 2^4 of the white by default), each remittance's
colour under "from" times k goes through the method, is divided by k and is
compared with its colour rendered under "to" (L*a*b* relative to that
light's white). Each method is measured ideal (its exact form) and, unless
ideal_only, shipped (the OCIO processor of the look a config holds, with
lut_size^3 LUTs for the non-linear methods: slow, ~1.5 s a pair for upsample
at 65).

illuminants: names, files or Spectrum (default A, C, D50, D65, E, F1-F12).
methods: names (default: every image method, see methods()); the
reference's own row, "spectral", is always measured. reflectances: more
sets, as files (each a set named by its path, as --reflectances) or a dict
{name: remittances}; the default sets tcs, tcs09-15 and random are measured
too unless default_sets=False. progress: a callable taking the fraction of
pairs done (called from worker threads). json, plot: files to write the
document and the accuracy-against-cost plot into, as one set. Runs with the
GIL released.
)doc");
    m.def(
        "reflectance_set",
        [](const std::string& name)
        {
            if (name == "tcs")
            {
                return AllTcs().samples;
            }
            if (name == "tcs09-15")
            {
                return HeldOutTcs().samples;
            }
            if (name == "training")
            {
                return TrainingSet().samples;
            }
            if (name == "random")
            {
                return RandomSmoothSet(100, 2, "random").samples;
            }
            if (name == "rawtoaces190")
            {
                return Rawtoaces190();
            }
            throw Exception("unknown reflectance set '" + OneLine(name, 80) +
                            "' (tcs, tcs09-15, training, random, rawtoaces190)");
        },
        py::arg("name"), R"doc(
A named set of remittances: "tcs" (TCS01-15), "tcs09-15" (the held-out test
colours), "training" (what fit3x3 is fitted on: TCS01-08 and 100 smooth
random remittances), "random" (accuracy's 100 smooth random remittances,
none in the training set), "rawtoaces190" (the Academy's 190 measured
training reflectances, what rootpoly is fitted on, with TCS01-15).
)doc");
}

}  // namespace bandlight::python
