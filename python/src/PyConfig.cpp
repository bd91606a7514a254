// SPDX-License-Identifier: BSD-3-Clause
// The jobs that write files: OCIO configs (new, or a studio config
// extended) and LUT files, as `bandlight config` and `bandlight lut` do.
#include <memory>

#include <OpenColorIO/OpenColorIO.h>

#include "PyBandlight.h"
#include "cli/Common.h"
#include "luts/LutWriter.h"
#include "plugin/ConfigBuilder.h"
#include "plugin/SceneLinearEvidence.h"

namespace bandlight::python
{

namespace
{
namespace OCIO = OCIO_NAMESPACE;

std::vector<std::string> ToNames(const py::object& arg)
{
    if (py::isinstance<py::str>(arg))
    {
        return cli::SplitList(arg.cast<std::string>());
    }
    return CastTo<std::vector<std::string>>(arg, "methods", "a sequence of method names");
}

/// A base config: a file (str or os.PathLike, read as `--base` reads it) or
/// a PyOpenColorIO.Config.
OCIO::ConstConfigRcPtr ToConfig(const py::object& arg)
{
    if (py::isinstance<py::str>(arg) || py::hasattr(arg, "__fspath__"))
    {
        const std::string path =
            py::str(py::module_::import("os").attr("fspath")(arg)).cast<std::string>();
        return ReadingFile(path, [&] { return cli::ReadConfigFile(path); });
    }
    return CastTo<OCIO::ConstConfigRcPtr>(arg, "a config",
                                          "a file (str, os.PathLike) or a PyOpenColorIO.Config");
}

OCIO::ConfigRcPtr Config(const std::optional<Path>& out, const std::optional<std::string>& working,
                         const py::object& illuminants, const py::object& methods,
                         const py::object& observer, int lutSize, const py::object& base,
                         const std::string& basePaths, const std::string& plates,
                         const std::string& adaptation, const py::object& camera,
                         const std::string& cameraIdt)
{
    const PlatesArgs platesArgs{plates, adaptation, camera, cameraIdt};
    const cli::PlatesOptions platesOptions = platesArgs.options();
    ConfigOptions options;
    options.plates = platesOptions.parsed();
    options.camera = platesArgs.loadCamera();
    {
        const NamedSpectrum idt = cli::ResolveIlluminant(cameraIdt);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
    }
    options.observer = ToObserver(observer);
    options.lights = ToLights(illuminants);
    options.methods = methods.is_none() ? LinearMethodNames() : ToNames(methods);
    options.workingSpace = working ? *working : "acescg";
    options.outputDir = out ? out->string() : "";
    if (lutSize < 2 || lutSize > 129)
    {
        throw Exception("lut_size must be 2 to 129, got " + std::to_string(lutSize));
    }
    options.lutSize = lutSize;
    if (basePaths != "relative" && basePaths != "absolute")
    {
        throw Exception("base_paths must be 'relative' or 'absolute', not '" +
                        OneLine(basePaths, 80) + "'");
    }
    options.absoluteBasePaths = basePaths == "absolute";

    ConfigPackage package;
    if (base.is_none())
    {
        package = BuildConfig(options);
    }
    else
    {
        const OCIO::ConstConfigRcPtr b = ToConfig(base);
        package = ExtendConfig(b, options, !working.has_value());
    }
    if (out)
    {
        const std::string dir = out->string();
        WritingFile(dir, true, [&] { WriteConfigPackage(package, dir); });
        // Its LUT-file looks resolve from the folder they were written to.
        package.config->setWorkingDir(dir.c_str());
    }
    else if (!package.lutFiles.empty())
    {
        throw Exception(std::to_string(package.lutFiles.size()) +
                        " looks of this config are LUT files (upsample, rootpoly; every look of "
                        "an OCIO v1 base): give out=DIR to write them with config.ocio");
    }
    return package.config;
}

py::dict Lut(const Path& pathArg, const py::object& src, const py::object& dst,
             const std::string& method, const std::string& format, const std::optional<int>& size,
             const std::string& shaper, const std::string& workingName,
             const py::object& observerArg, const py::object& training, const std::string& plates,
             const std::string& adaptation, const py::object& camera, const std::string& cameraIdt)
{
    // What `bandlight lut` does (cli/CommandLut.cpp).
    const std::string path = pathArg.string();
    LutOptions options;
    options.format = ParseLutFormat(format);
    options.size = size.value_or(33);
    options.forceLattice = size.has_value();
    options.shaper = ShaperSpec::Parse(shaper);
    const MethodSpec spec =
        ToMethod(method, training, PlatesArgs{plates, adaptation, camera, cameraIdt});
    const Light from = ToLight(src);
    const Light to = ToLight(dst);
    const RgbSpace& working = FindRgbSpace(workingName);
    const Observer observer = ToObserver(observerArg);
    LutFiles files;
    {
        py::gil_scoped_release release;
        if (spec.isLinear())
        {
            const OCIO::GroupTransformRcPtr exact =
                IlluminantChangeTransform(from, to, spec, working, observer);
            files = WritingFile(path, false, [&] { return WriteLut(exact, true, options, path); });
        }
        else
        {
            // Baked straight from the per-pixel fit, not from a lattice.
            const auto relighter = std::make_shared<Relighter>(from, to, spec, working, observer);
            if (options.shaper.kind == ShaperSpec::Kind::LOG2)
            {
                options.shaper = ShaperSpec::ForNonLinear();
            }
            options.description = "Relight from " + from.name + " to " + to.name + " in " +
                                  working.displayName + ". " + DescribeMethod(spec) + " " +
                                  spec.plates.describe(working.displayName);
            files = WritingFile(path, false,
                                [&]
                                {
                                    return WriteLut([relighter](float* rgb, size_t n)
                                                    { relighter->apply(rgb, n); },
                                                    options, path);
                                });
        }
    }
    py::dict d;
    d["lut"] = files.lut;
    d["shaper"] = files.shaper.empty() ? py::object(py::none()) : py::str(files.shaper);
    d["lattice"] = files.lattice;
    d["output_encoded"] = files.outputEncoded;
    d["shaper_description"] =
        files.lattice ? py::object(py::str(options.shaper.alignedTo(options.size).describe()))
                      : py::object(py::none());
    return d;
}
}  // namespace

void AddConfig(py::module_& m)
{
    m.def("config", &Config, py::arg("out") = py::none(), py::kw_only(),
          py::arg("working_space") = py::none(),
          py::arg("illuminants") = py::make_tuple("A", "C", "D65", "F2", "F11"),
          py::arg("methods") = py::none(), py::arg("observer") = "1931", py::arg("lut_size") = 65,
          py::arg("base") = py::none(), py::arg("base_paths") = "relative",
          py::arg("plates") = "balanced", py::arg("adaptation") = "cat02",
          py::arg("camera") = py::none(), py::arg("camera_idt") = "D55",
          (std::string(R"doc(
An OCIO v2 config with one look per ordered pair of illuminants and method
(``<method>_<FROM>_to_<TO>``, and the same as named transforms
``relight_<look>``), as ``bandlight config`` writes it; returns the
PyOpenColorIO.Config.

out: the folder to write config.ocio and its LUT files into (created if
needed, all files replaced together or none); the returned config's working
folder is set to it. Without out nothing is written, which is refused when
the config needs LUT files (upsample, rootpoly looks; an OCIO v1 base).
working_space: the linear working space (default acescg); with base, the
base's scene_linear primaries, identified from the config when omitted.
illuminants: names, files or Spectrum (or "A,C,D65"). methods: method names
(default: none, vonkries, bradford, cat02, band3, band3-wp). lut_size: the 3D
LUT size of the non-linear looks (65: ~12 MB a look; 33: 1.6 MB). base: a
studio config (a file, or a PyOpenColorIO.Config) to extend, leaving all it
has intact; base_paths: its relative search paths rewritten "relative" to
out or "absolute".
)doc") + kPlatesDoc)
              .c_str());
    m.def(
        "identify_scene_linear",
        [](const py::object& config)
        {
            const SceneLinearIdentity id = IdentifySceneLinear(ToConfig(config));
            return py::make_tuple(id.space->name, id.evidence);
        },
        py::arg("config"), R"doc(
(space, evidence): the built-in primaries of a config's scene_linear space
(e.g. "rec709") and the one line of evidence that identified them
(interchange roles, or standard colour spaces of the config, measured), as
``bandlight config --base`` does. config: a file or a PyOpenColorIO.Config.
)doc");
    m.def("lut", &Lut, py::arg("path"), py::arg("src"), py::arg("dst"),
          py::arg("method") = "bradford", py::kw_only(), py::arg("format") = "clf",
          py::arg("size") = py::none(), py::arg("shaper") = "log2",
          py::arg("working_space") = "acescg", py::arg("observer") = "1931",
          py::arg("training") = py::none(), py::arg("plates") = "balanced",
          py::arg("adaptation") = "cat02", py::arg("camera") = py::none(),
          py::arg("camera_idt") = "D55",
          (std::string(R"doc(
Writes the illuminant change from src to dst as a LUT file, as ``bandlight
lut`` does, through OpenColorIO's own writers. Returns {"lut": path,
"shaper": companion shaper file or None, "lattice": bool, "output_encoded":
bool, "shaper_description": str or None}.

format: clf, ctf (the exact matrix for linear methods, unless size is
given), cube, spi3d, 3dl (scene-linear HDR through the log2 shaper; the
shaper is written beside as <stem>.shaper.clf: apply it before the LUT and
its inverse after), resolve_cube, csp, houdini (display-referred [0, 1] data,
shaper="none"). size: 3D LUT points per axis (default 33). The LUT and its
shaper are replaced together or not at all.
)doc") + kPlatesDoc)
              .c_str());
}

}  // namespace bandlight::python
