// SPDX-License-Identifier: BSD-3-Clause
// The jobs that write files: OCIO configs (new, or a studio config
// extended) and LUT files, as `bandlight config` and `bandlight lut` do.
#include <memory>

#include <OpenColorIO/OpenColorIO.h>

#include "PyBandlight.h"
#include "jobs/ConfigJob.h"
#include "jobs/LutJob.h"
#include "plugin/SceneLinearEvidence.h"
#include "requests/Defaults.h"

namespace bandlight::python
{

namespace
{
namespace OCIO = OCIO_NAMESPACE;

std::vector<std::string> ToNames(const py::object& arg)
{
    if (py::isinstance<py::str>(arg))
    {
        return jobs::SplitList(arg.cast<std::string>());
    }
    return CastTo<std::vector<std::string>>(arg, "methods", "a sequence of method names");
}

/// A base config: a file (str or os.PathLike, read as `--base` reads it) or
/// a PyOpenColorIO.Config.
OCIO::ConstConfigRcPtr ToConfig(const py::object& arg)
{
    if (py::isinstance<py::str>(arg) || py::hasattr(arg, "__fspath__"))
    {
        return jobs::ReadConfigFile(PathText(arg, "base"));
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
    jobs::ConfigRequest r;
    r.plates = PlatesArgs{plates, adaptation, camera, cameraIdt}.options();
    r.plates.parsed();
    r.observer = py::str(observer).cast<std::string>();
    r.lights = ToLights(illuminants);
    if (!methods.is_none())
    {
        r.methods = ToNames(methods);
    }
    r.workingSpace = working.value_or("");
    if (out)
    {
        r.out = out->string();
    }
    r.lutSize = lutSize;
    r.basePaths = basePaths;
    if (!base.is_none())
    {
        r.baseConfig = ToConfig(base);
    }
    if (!r.plates.camera.empty())
    {
        PlatesArgs{plates, adaptation, camera, cameraIdt}.loadCamera();  // OSError when unreadable
    }
    return jobs::MakeConfig(r, Warnings()).package.config;
}

py::dict Lut(const Path& pathArg, const py::object& src, const py::object& dst,
             const std::string& method, const std::optional<std::string>& format, const std::optional<int>& size,
             const std::string& shaper, const std::string& encoding, const std::string& workingName,
             const py::object& observerArg, const py::object& training, const std::string& plates,
             const std::string& adaptation, const py::object& camera, const std::string& cameraIdt)
{
    jobs::LutRequest r;
    r.out = pathArg.string();
    r.format = format.value_or("");
    r.size = size;
    r.shaper = shaper;
    r.encoding = encoding;
    r.relight.plates = PlatesArgs{plates, adaptation, camera, cameraIdt}.options();
    r.relight.plates.parsed();
    r.relight.method = method;
    if (!training.is_none())
    {
        r.relight.training = ToReflectances(training);
    }
    r.relight.src = ToLight(src);
    r.relight.dst = ToLight(dst);
    r.relight.workingSpace = workingName;
    r.relight.observer = py::str(observerArg).cast<std::string>();
    if (!r.relight.plates.camera.empty())
    {
        PlatesArgs{plates, adaptation, camera, cameraIdt}.loadCamera();  // OSError when unreadable
    }
    jobs::LutResult result;
    {
        py::gil_scoped_release release;
        result = jobs::MakeLut(r, Warnings());
    }
    py::dict d;
    d["lut"] = result.files.lut;
    d["shaper"] =
        result.files.shaper.empty() ? py::object(py::none()) : py::str(result.files.shaper);
    d["lattice"] = result.files.lattice;
    d["output_encoded"] = result.files.outputEncoded;
    d["shaper_description"] = result.files.lattice && result.files.encoding == LutEncoding::LINEAR
                                  ? py::object(py::str(result.shaper.describe()))
                                  : py::object(py::none());
    d["encoding"] = LutEncodingName(result.files.encoding);
    d["encoding_description"] = result.encodingDescription;
    return d;
}
}  // namespace

void AddConfig(py::module_& m)
{
    m.def(
        "config", &Config, py::arg("out") = py::none(), py::kw_only(),
        py::arg("working_space") = py::none(),
        py::arg("illuminants") = py::tuple(py::cast(jobs::SplitList(defaults::CONFIG_ILLUMINANTS))),
        py::arg("methods") = py::none(), py::arg("observer") = defaults::OBSERVER,
        py::arg("lut_size") = defaults::CONFIG_LUT_SIZE, py::arg("base") = py::none(),
        py::arg("base_paths") = defaults::BASE_PATHS, py::arg("plates") = defaults::PLATES,
        py::arg("adaptation") = defaults::ADAPTATION, py::arg("camera") = py::none(),
        py::arg("camera_idt") = defaults::IDT_LIGHT,
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
          py::arg("method") = defaults::METHOD, py::kw_only(),
          py::arg("format") = py::none(), py::arg("size") = py::none(),
          py::arg("shaper") = defaults::LUT_SHAPER, py::arg("encoding") = defaults::LUT_ENCODING,
          py::arg("working_space") = defaults::WORKING_SPACE,
          py::arg("observer") = defaults::OBSERVER, py::arg("training") = py::none(),
          py::arg("plates") = defaults::PLATES, py::arg("adaptation") = defaults::ADAPTATION,
          py::arg("camera") = py::none(), py::arg("camera_idt") = defaults::IDT_LIGHT,
          (std::string(R"doc(
Writes the illuminant change from src to dst as a LUT file, as ``bandlight
lut`` does, through OpenColorIO's own writers. Returns {"lut": path,
"shaper": companion shaper file or None, "lattice": bool, "output_encoded":
bool, "shaper_description": str or None, "encoding": str,
"encoding_description": str}.

format: None (the format follows the path's extension: .clf, .ctf, .cube,
.spi3d, .3dl, .csp, .lut), or one of clf, ctf (the exact matrix for linear methods, unless size is
given), cube, spi3d, 3dl (scene-linear HDR through the log2 shaper; the
shaper is written beside as <stem>.shaper.clf: apply it before the LUT and
its inverse after), resolve_cube, csp, houdini (display-referred [0, 1] data,
shaper="none"). size: 3D LUT points per axis (default 65, which GPUs
filtering the LUT texture linearly agree with; see docs/luts.md). encoding:
"linear" (the working space's linear values, through the shaper), "acescct"
or "acescc": the 3D LUT takes and returns ACEScct (S-2016-001) or ACEScc
(S-2014-003) encoded values, encoded 0 to 1 = linear -0.0069 (ACEScc: 0.0012)
to 222.9, with no shaper, in every format; the encoding is of the working
space's linear values, as ACEScct encodes ACEScg (AP1). The LUT and its
shaper are replaced together or not at all.
)doc") + kPlatesDoc)
              .c_str());
}

}  // namespace bandlight::python
