// SPDX-License-Identifier: BSD-3-Clause
// The accuracy report: every method against the spectral answer, ideal and
// as shipped, as `bandlight accuracy --json` measures it.
#include <cmath>
#include <mutex>
#include <optional>

#include <OpenColorIO/OpenColorIO.h>

#include "PyBandlight.h"
#include "cli/Common.h"
#include "plugin/OcioTransforms.h"
#include "transforms/Accuracy.h"

namespace bandlight::python
{

namespace
{
namespace OCIO = OCIO_NAMESPACE;

py::list Rows(const std::vector<AccuracyRow>& rows)
{
    py::list out;
    for (const AccuracyRow& r : rows)
    {
        py::dict d;
        d["method"] = r.method;
        d["from"] = r.from;
        d["to"] = r.to;
        d["set"] = r.set;
        d["plates"] = r.plates;
        d["camera"] = r.source;  // the command's JSON key for it
        d["exposure"] = r.exposure;
        d["shipped"] = r.shipped;
        d["mean"] = r.mean;
        d["p95"] = r.p95;
        d["max"] = r.max;
        d["worst_sample"] = r.worstSample;
        out.append(d);
    }
    return out;
}

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
        const std::string path =
            py::str(py::module_::import("os").attr("fspath")(f)).cast<std::string>();
        sets.push_back({path, ReadingFile(path, [&] { return ReadSpectraFile(path); })});
    }
    return sets;
}

py::list Accuracy(const py::object& illuminants, const py::object& methods,
                  const py::object& reflectances, bool defaultSets, const std::string& working,
                  const py::object& observer, const py::object& exposures, int lutSize,
                  bool idealOnly, bool crossValidation, bool floor, const py::object& progress,
                  const std::string& plates, const std::string& adaptation,
                  const py::object& camera, const std::string& cameraIdt)
{
    AccuracyOptions options = DefaultAccuracyOptions();
    // As the command: both conventions unless one is named.
    const PlatesArgs platesArgs{plates == "both" ? "balanced" : plates, adaptation, camera,
                                cameraIdt};
    const cli::PlatesOptions platesOptions = platesArgs.options();
    options.plates = {platesOptions.parsed()};
    if (plates == "both")
    {
        options.plates.push_back(ParsePlates("lit", adaptation));
    }
    options.camera = platesArgs.loadCamera();
    if (options.camera)
    {
        const NamedSpectrum idt = cli::ResolveIlluminant(cameraIdt);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
        if (methods.is_none())
        {
            options.methods.push_back("rootpoly-camera");
        }
    }
    options.workingSpace = working;
    FindRgbSpace(working);
    options.observer = ToObserver(observer);
    if (!illuminants.is_none())
    {
        options.lights = ToLights(illuminants);
        if (options.lights.size() < 2)
        {
            throw Exception("accuracy needs at least two illuminants");
        }
    }
    if (!methods.is_none())
    {
        options.methods = py::isinstance<py::str>(methods)
                              ? cli::SplitList(methods.cast<std::string>())
                              : CastTo<std::vector<std::string>>(methods, "methods",
                                                                 "a sequence of method names");
    }
    for (const std::string& m : options.methods)
    {
        ParseMethod(m);
    }
    if (!defaultSets)
    {
        options.sets.clear();
    }
    if (!reflectances.is_none())
    {
        for (ReflectanceSet& s : ToSets(reflectances))
        {
            options.sets.push_back(std::move(s));
        }
    }
    if (options.sets.empty())
    {
        throw Exception(
            "no reflectance sets to measure: give reflectances, or keep the default "
            "sets");
    }
    if (!exposures.is_none())
    {
        options.exposures =
            CastTo<std::vector<double>>(exposures, "exposures", "a sequence of numbers");
        for (const double k : options.exposures)
        {
            if (!(k > 0.0) || !std::isfinite(k))
            {
                throw Exception("exposures must be positive and finite");
            }
        }
    }
    if (lutSize < 2 || lutSize > 129)
    {
        throw Exception("lut_size must be 2 to 129, got " + std::to_string(lutSize));
    }
    if (!idealOnly)
    {
        // The shipped form, as the command measures it: the OCIO processor
        // of the transform a config's look holds.
        const RgbSpace& space = FindRgbSpace(options.workingSpace);
        const Observer o = options.observer;
        options.shipped = [&space, o, lutSize](const Light& from, const Light& to,
                                               const MethodSpec& method) -> PixelBatch
        {
            const OCIO::ConstCPUProcessorRcPtr cpu =
                OCIO::Config::CreateRaw()
                    ->getProcessor(IlluminantChangeTransform(from, to, method, space, o, lutSize))
                    ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                               OCIO::OPTIMIZATION_DEFAULT);
            return [cpu](float* rgb, size_t n)
            {
                OCIO::PackedImageDesc desc(rgb, long(n), 1, 3);
                cpu->apply(desc);
            };
        };
    }

    // The callback runs on the measuring threads: it takes the GIL, and the
    // first exception it raises stops further calls and is raised at the end.
    std::mutex mu;
    std::optional<py::error_already_set> callbackError;
    std::function<void(double)> report;
    if (!progress.is_none())
    {
        report = [&](double fraction)
        {
            std::lock_guard<std::mutex> lock(mu);
            if (callbackError)
            {
                return;
            }
            py::gil_scoped_acquire gil;
            try
            {
                progress(fraction);
            }
            catch (py::error_already_set& e)
            {
                callbackError = std::move(e);
            }
        };
    }
    std::vector<AccuracyRow> rows, cv, floorRows;
    {
        py::gil_scoped_release release;
        rows = MeasureAccuracy(options, report);
        if (crossValidation)
        {
            cv = CrossValidate(options, 5);
        }
        if (floor)
        {
            floorRows = MeasureFloor(options);
        }
    }
    if (callbackError)
    {
        throw std::move(*callbackError);
    }
    py::list out = Rows(rows);
    for (const py::handle r : Rows(cv))
    {
        out.append(r);
    }
    for (const py::handle r : Rows(floorRows))
    {
        out.append(r);
    }
    return out;
}
}  // namespace

void AddAccuracy(py::module_& m)
{
    m.def("accuracy", &Accuracy, py::arg("illuminants") = py::none(),
          py::arg("methods") = py::none(), py::kw_only(), py::arg("reflectances") = py::none(),
          py::arg("default_sets") = true, py::arg("working_space") = "acescg",
          py::arg("observer") = "1931", py::arg("exposures") = py::none(), py::arg("lut_size") = 65,
          py::arg("ideal_only") = false, py::arg("cross_validation") = false,
          py::arg("floor") = false, py::arg("progress") = py::none(), py::arg("plates") = "both",
          py::arg("adaptation") = "cat02", py::arg("camera") = py::none(),
          py::arg("camera_idt") = "D55", R"doc(
CIEDE2000 of illuminant-change methods against the spectral answer, as
``bandlight accuracy --json`` measures it; returns its rows, a list of dicts
with the command's keys: method, from, to, set, plates ("balanced-cat02",
"lit", and "balanced-cat02-through-lit-looks": lit looks on balanced plates,
README "Plates"), camera (the plates' source: "cie"; with camera=, also
"camera" and "camera-daylight-idt"), exposure, shipped, mean, p95, max,
worst_sample.

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
methods: names (default: every image method, see methods(); add "spectral"
for the reference's own row). reflectances: more sets, as files (each a set
named by its path, as --reflectances) or a dict {name: remittances}; the
default sets tcs, tcs09-15 and random are measured too unless
default_sets=False. cross_validation adds rows of the fitted methods on
their own training data (sets "training, in-sample" and "training,
5-fold"); floor adds "floor-3x3" and "floor-rootpoly" rows. progress: a
callable taking the fraction of pairs done (called from worker threads).
Runs with the GIL released.
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
