// SPDX-License-Identifier: BSD-3-Clause
// Illuminant changes as PyOpenColorIO transforms and as matrices, the band
// space and material tint transforms, and relighting numpy images in memory
// through the C++ Relighter (the GIL released, on `threads` threads).
#include <cstring>
#include <memory>

#include <OpenColorIO/OpenColorIO.h>

#include "PyBandlight.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"
#include "requests/Defaults.h"

namespace bandlight::python
{

namespace
{
namespace OCIO = OCIO_NAMESPACE;

/// A Relighter with the names it was made from.
struct PyRelighter
{
    std::string src;
    std::string dst;
    std::string method;
    std::string workingSpace;
    std::string plates;  ///< the plates' key: "lit", "balanced-cat02"
    std::unique_ptr<Relighter> relighter;
    /// What it was made from, resolved (the lights and training as
    /// Spectrum, the camera file's path): its pickled state, so that a
    /// worker process (a Dask cluster's) makes the same relighter.
    py::tuple spec;
};

PyRelighter MakeRelighter(const py::object& src, const py::object& dst, const std::string& method,
                          const std::string& working, const py::object& observer,
                          const py::object& training, const PlatesArgs& plates)
{
    const Light from = ToLight(src);
    const Light to = ToLight(dst);
    const MethodSpec spec = ToMethod(method, training, plates);
    const RgbSpace& space = FindRgbSpace(working);
    const Observer o = ToObserver(observer);
    py::list trainingState;
    for (const NamedSpectrum& t : spec.training)
    {
        trainingState.append(py::cast(t));
    }
    const py::tuple state = py::make_tuple(
        py::cast(NamedSpectrum{from.name, from.spectrum}),
        py::cast(NamedSpectrum{to.name, to.spectrum}), method, working, py::str(observer),
        spec.training.empty() ? py::object(py::none()) : py::object(trainingState), plates.plates,
        plates.adaptation,
        plates.camera.is_none()
            ? py::object(py::none())
            : py::object(py::module_::import("os").attr("fspath")(plates.camera)),
        plates.cameraIdt);
    return {from.name,
            to.name,
            spec.name,
            space.name,
            spec.plates.key(),
            std::make_unique<Relighter>(from, to, spec, space, o),
            state};
}

PyRelighter RelighterFromState(const py::tuple& t)
{
    if (t.size() != 10)
    {
        throw Exception("Relighter: invalid pickled state");
    }
    return MakeRelighter(
        t[0], t[1], t[2].cast<std::string>(), t[3].cast<std::string>(), t[4], t[5],
        PlatesArgs{t[6].cast<std::string>(), t[7].cast<std::string>(),
                   py::reinterpret_borrow<py::object>(t[8]), t[9].cast<std::string>()});
}

std::string ShapeOf(const py::array& a)
{
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
    {
        s += (i ? ", " : "") + std::to_string(a.shape(i));
    }
    return s + (a.ndim() == 1 ? ",)" : ")");
}

/// Pixels per block of the copying path: 48 KB of RGB, in cache while it is
/// copied and re-lit.
constexpr size_t kBlockPixels = 4096;

py::array_t<float> Apply(const PyRelighter& self, const py::object& image, int threadsArg,
                         const py::object& out)
{
    const int threads = ToThreads(threadsArg);
    using F32 = py::array_t<float, py::array::c_style | py::array::forcecast>;
    // float32, C order: the array itself when it is already so.
    const F32 in = F32::ensure(image);
    if (!in)
    {
        throw Exception("image must be an array of numbers");
    }
    if (in.ndim() < 1 || in.shape(in.ndim() - 1) < 3)
    {
        throw Exception(
            "image must hold R, G, B (then any other channels, which pass through) "
            "in its last dimension, e.g. (height, width, 3) or (pixels, 3); got "
            "shape " +
            ShapeOf(in));
    }
    const std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
    const size_t channels = size_t(shape.back());
    const size_t pixels = channels ? size_t(in.size()) / channels : 0;

    py::array_t<float> result;
    if (out.is_none())
    {
        result = py::array_t<float>(shape);
    }
    else
    {
        const py::array o = py::array::ensure(out);
        const bool ok = o && o.dtype().is(py::dtype::of<float>()) &&
                        (o.flags() & py::array::c_style) && o.writeable() &&
                        std::vector<py::ssize_t>(o.shape(), o.shape() + o.ndim()) == shape;
        if (!ok)
        {
            throw Exception(
                "out must be a writeable, C-contiguous float32 array of the image's "
                "shape " +
                ShapeOf(in));
        }
        result = py::reinterpret_borrow<py::array_t<float>>(o);
    }
    const float* src = in.data();
    float* dst = result.mutable_data();
    const size_t bytes = pixels * channels * sizeof(float);
    const auto* s8 = reinterpret_cast<const char*>(src);
    const auto* d8 = reinterpret_cast<const char*>(dst);
    if (src != dst && s8 < d8 + bytes && d8 < s8 + bytes)
    {
        throw Exception(
            "out overlaps the image without being it (give out=image to re-light "
            "in place)");
    }
    const Relighter& r = *self.relighter;
    {
        py::gil_scoped_release release;
        if (src == dst)
        {
            // In place: exactly the C++ API's call, RGB or RGBA (strided).
            r.apply(dst, pixels, channels, threads);
        }
        else
        {
            // Copy block by block and re-light each block while it is in cache.
            const size_t blocks = (pixels + kBlockPixels - 1) / kBlockPixels;
            ParallelFor(blocks, threads,
                        [&](size_t b0, size_t b1)
                        {
                            for (size_t b = b0; b < b1; ++b)
                            {
                                const size_t p0 = b * kBlockPixels;
                                const size_t n = std::min(kBlockPixels, pixels - p0);
                                std::memcpy(dst + p0 * channels, src + p0 * channels,
                                            n * channels * sizeof(float));
                                r.apply(dst + p0 * channels, n, channels, 1);
                            }
                        });
        }
    }
    return result;
}

constexpr const char* kApplyDoc = R"doc(
Re-lights an image: a float array whose last dimension holds R, G, B in the
working space (then any other channels, e.g. alpha, which pass through),
such as (height, width, 3), (height, width, 4) or (pixels, 3).

Returns a new float32 array, or writes into ``out`` (a C-contiguous float32
array of the same shape); ``out=image`` re-lights a float32 image in place,
which is exactly the C++ ``Relighter::apply`` call (the SIMD kernel of
this CPU for the 3x3 and rootpoly). Other
dtypes and layouts are converted to float32 first. Runs with the GIL
released on ``threads`` threads (0: all cores). Any input, NaN and Inf
included, gives a finite result (NaN and Inf are clamped to +-1e16 first).
)doc";

/// The methods by name: the lists, their descriptions, their canonical and look names.
void AddMethodNames(py::module_& m)
{
    m.def("methods", &AllMethodNames,
          "Every image method `bandlight accuracy` compares: none, vonkries, bradford, cat02,\n"
          "band3, band3-wp, band6, band6-wp, fit3x3, prefilter, metamer, upsample, rootpoly,\n"
          "rootpoly3. Also accepted: bandN[-wp], bandsE0-E1-...-En[-wp], spectral.");
    m.def("linear_methods", &LinearMethodNames,
          "The methods a config gets by default: none, vonkries, bradford, cat02, band3,\n"
          "band3-wp.");
    m.def(
        "describe_method",
        [](const std::string& method) { return DescribeMethod(ParseMethod(method)); },
        py::arg("method"), "One sentence on what a method does and how accurate it is.");
    m.def(
        "method_name", [](const std::string& method) { return ParseMethod(method).name; },
        py::arg("method"),
        "The canonical name of a method (case-insensitive input), as look names use it;\n"
        "ValueError listing the choices for an unknown one.");
    m.def(
        "look_name",
        [](const std::string& method, const std::string& src, const std::string& dst)
        {
            const auto canonical = [](const std::string& n)
            { return IsBuiltinIlluminant(n) ? CanonicalIlluminantName(n) : n; };
            return LookName(ParseMethod(method).name, canonical(src), canonical(dst));
        },
        py::arg("method"), py::arg("src"), py::arg("dst"),
        "The name a config gives the look: \"<method>_<SRC>_to_<DST>\" (\"band3_A_to_D65\");\n"
        "its named transform is \"relight_\" + that.");
}

/// An illuminant change as a PyOpenColorIO transform and as a 3x3.
void AddIlluminantChanges(py::module_& m)
{
    m.def(
        "illuminant_change",
        [](const py::object& src, const py::object& dst, const std::string& method,
           const std::string& working, const py::object& observer, int lutSize,
           const py::object& training, const std::string& plates, const std::string& adaptation,
           const py::object& camera, const std::string& cameraIdt) -> OCIO::GroupTransformRcPtr
        {
            const Light from = ToLight(src);
            const Light to = ToLight(dst);
            return IlluminantChangeTransform(
                from, to,
                ToMethod(method, training, PlatesArgs{plates, adaptation, camera, cameraIdt}),
                FindRgbSpace(working), ToObserver(observer), lutSize);
        },
        py::arg("src"), py::arg("dst"), py::arg("method") = defaults::METHOD, py::kw_only(),
        py::arg("working_space") = defaults::WORKING_SPACE, py::arg("observer") = defaults::OBSERVER, py::arg("lut_size") = defaults::TRANSFORM_LUT_SIZE,
        py::arg("training") = py::none(), py::arg("plates") = defaults::PLATES,
        py::arg("adaptation") = defaults::ADAPTATION, py::arg("camera") = py::none(),
        py::arg("camera_idt") = defaults::IDT_LIGHT,
        (std::string(R"doc(
The illuminant change from src to dst as a PyOpenColorIO.GroupTransform, for
images in the linear RGB space working_space: what ``bandlight lut`` and
``bandlight apply --from --to --method`` use, and what a config's look holds.

src, dst: a name or file (str), a file (os.PathLike) or a Spectrum. Linear
methods give the +-1e16 guard and one MatrixTransform; upsample and rootpoly
the log2 shaper, a lut_size^3 3D LUT and the inverse shaper. training:
remittances to fit fit3x3 / rootpoly on (default: their built-in sets).
Raises ValueError for an unknown method (the message lists them), for
"spectral" (not an image transform) and for unusable lights.
)doc") + kPlatesDoc)
            .c_str());
    m.def(
        "illuminant_change_matrix",
        [](const py::object& src, const py::object& dst, const std::string& method,
           const std::string& working, const py::object& observer, const py::object& training,
           const std::string& plates, const std::string& adaptation)
        {
            const Light from = ToLight(src);
            const Light to = ToLight(dst);
            return ToArray(Eigen::MatrixXd(IlluminantChangeMatrix(
                from, to, ToMethod(method, training, PlatesArgs{plates, adaptation}),
                FindRgbSpace(working), ToObserver(observer))));
        },
        py::arg("src"), py::arg("dst"), py::arg("method") = defaults::METHOD, py::kw_only(),
        py::arg("working_space") = defaults::WORKING_SPACE, py::arg("observer") = defaults::OBSERVER,
        py::arg("training") = py::none(), py::arg("plates") = defaults::PLATES,
        py::arg("adaptation") = defaults::ADAPTATION, R"doc(
The 3x3 in working_space that makes an image lit by src look lit by dst, for
the linear methods (every method but the non-linear ones: upsample, hueplane,
rootpoly, rootpoly-camera, rootpoly-plate and their degree-3 forms; and
spectral). plates, adaptation: as illuminant_change (default balanced by
CAT02: balance(dst) . M . balance(src)^-1; "lit" gives M itself).
)doc");
}

/// The band space and the material tint as PyOpenColorIO transforms.
void AddBandTransforms(py::module_& m)
{
    m.def(
        "band_space",
        [](const py::object& bands, const std::string& working,
           const py::object& observer) -> OCIO::GroupTransformRcPtr
        { return BandSpaceTransform(ToBands(bands), FindRgbSpace(working), ToObserver(observer)); },
        py::arg("bands") = py::none(), py::kw_only(), py::arg("working_space") = defaults::WORKING_SPACE,
        py::arg("observer") = defaults::OBSERVER, R"doc(
Working RGB -> the band space of a three-band set (radiometric band values;
VB, VG, VR for the lecture's bands) as a PyOpenColorIO.GroupTransform.
)doc");
    m.def(
        "material_tint",
        [](const py::object& remittance, const py::object& bandsArg, const std::string& working,
           const py::object& observer) -> OCIO::GroupTransformRcPtr
        {
            const BandSet bands = ToBands(bandsArg);
            std::vector<double> values;
            if (py::isinstance<NamedSpectrum>(remittance))
            {
                values = RemittanceBands(remittance.cast<const NamedSpectrum&>().spectrum, bands);
            }
            else
            {
                values = CastTo<std::vector<double>>(remittance, "remittance",
                                                     "one number per band or a bandlight.Spectrum");
            }
            return MaterialTintTransform(values, bands, FindRgbSpace(working),
                                         ToObserver(observer));
        },
        py::arg("remittance"), py::arg("bands") = py::none(), py::kw_only(),
        py::arg("working_space") = defaults::WORKING_SPACE, py::arg("observer") = defaults::OBSERVER, R"doc(
The lecture's material tint as a PyOpenColorIO.GroupTransform: working RGB ->
band space, band b times remittance[b] (R_diff), -> working RGB. remittance:
one value per band in band order (VB, VG, VR: blue first), or a Spectrum
whose band means are taken.
)doc");
}

/// The 3x3 of a PyOpenColorIO processor.
void AddMeasureMatrix(py::module_& m)
{
    m.def(
        "measure_matrix",
        [](const OCIO::ConstProcessorRcPtr& processor)
        { return ToArray(Eigen::MatrixXd(MeasureMatrix(processor))); },
        py::arg("processor"),
        "The 3x3 a PyOpenColorIO.Processor applies, measured by running the basis\n"
        "vectors through it.");
}

/// bandlight.Relighter: an illuminant change applied to pixels in memory.
void AddRelighterClass(py::module_& m)
{
    py::class_<PyRelighter>(m, "Relighter", R"doc(
An illuminant change ready to apply to pixels in memory (the C++ Relighter):
one 3x3 for the linear methods, the native root polynomial for rootpoly, the
per-pixel spectral fit for upsample (about 27 us a pixel: use its LUT,
illuminant_change(), for images). Make it once, apply it to many images.
plates, adaptation, camera, camera_idt: as illuminant_change (default:
white-balanced plates, CAT02).
)doc")
        .def(py::init(
                 [](const py::object& src, const py::object& dst, const std::string& method,
                    const std::string& working, const py::object& observer,
                    const py::object& training, const std::string& plates,
                    const std::string& adaptation, const py::object& camera,
                    const std::string& cameraIdt)
                 {
                     return MakeRelighter(src, dst, method, working, observer, training,
                                          PlatesArgs{plates, adaptation, camera, cameraIdt});
                 }),
             py::arg("src"), py::arg("dst"), py::arg("method") = defaults::METHOD, py::kw_only(),
             py::arg("working_space") = defaults::WORKING_SPACE, py::arg("observer") = defaults::OBSERVER,
             py::arg("training") = py::none(), py::arg("plates") = defaults::PLATES,
             py::arg("adaptation") = defaults::ADAPTATION, py::arg("camera") = py::none(),
             py::arg("camera_idt") = defaults::IDT_LIGHT,
             "src, dst: a name or file (str), a file (os.PathLike) or a Spectrum; method: any\n"
             "image method (not \"spectral\").")
        .def(py::pickle([](const PyRelighter& r) { return r.spec; }, &RelighterFromState),
             "Pickles by its specification (lights and training as spectra, the camera\n"
             "file by path), so dask.array.map_blocks(relighter.apply) runs on a cluster of\n"
             "processes: each worker makes the same relighter.")
        .def("apply", &Apply, py::arg("image"), py::kw_only(), py::arg("threads") = defaults::THREADS,
             py::arg("out") = py::none(), kApplyDoc)
        .def("__call__", &Apply, py::arg("image"), py::kw_only(), py::arg("threads") = defaults::THREADS,
             py::arg("out") = py::none(), "The same as apply().")
        .def_property_readonly(
            "is_linear", [](const PyRelighter& r) { return r.relighter->isLinear(); },
            "True when the method is one 3x3 (matrix).")
        .def_property_readonly(
            "matrix",
            [](const PyRelighter& r) { return ToArray(Eigen::MatrixXd(r.relighter->matrix())); },
            "The 3x3 of a linear method (upsample: its fallback for pixels with no positive\n"
            "channel, the metamer matrix).")
        .def_readonly("src", &PyRelighter::src, "The name of the light the image is lit by.")
        .def_readonly("dst", &PyRelighter::dst, "The name of the light it will look lit by.")
        .def_readonly("method", &PyRelighter::method, "The method's canonical name.")
        .def_readonly("working_space", &PyRelighter::workingSpace,
                      "The working space's canonical name.")
        .def_readonly("plates", &PyRelighter::plates,
                      "The plates it is for: \"lit\", or \"balanced-<adaptation>\".")
        .def("__repr__",
             [](const PyRelighter& r)
             {
                 return "<Relighter " + r.method + " " + OneLine(r.src, 80) + " -> " +
                        OneLine(r.dst, 80) + " in " + r.workingSpace + ", " + r.plates +
                        " plates>";
             });
}

/// relight(): a Relighter made and applied in one call.
void AddRelight(py::module_& m)
{
    m.def(
        "relight",
        [](const py::object& image, const py::object& src, const py::object& dst,
           const std::string& method, const std::string& working, const py::object& observer,
           const py::object& training, int threads, const py::object& out,
           const std::string& plates, const std::string& adaptation, const py::object& camera,
           const std::string& cameraIdt)
        {
            const PyRelighter r = MakeRelighter(src, dst, method, working, observer, training,
                                                PlatesArgs{plates, adaptation, camera, cameraIdt});
            return Apply(r, image, threads, out);
        },
        py::arg("image"), py::arg("src"), py::arg("dst"), py::arg("method") = defaults::METHOD,
        py::kw_only(), py::arg("working_space") = defaults::WORKING_SPACE, py::arg("observer") = defaults::OBSERVER,
        py::arg("training") = py::none(), py::arg("threads") = defaults::THREADS, py::arg("out") = py::none(),
        py::arg("plates") = defaults::PLATES, py::arg("adaptation") = defaults::ADAPTATION,
        py::arg("camera") = py::none(), py::arg("camera_idt") = defaults::IDT_LIGHT,
        (std::string("Relighter(src, dst, method, ...).apply(image, threads=threads, out=out):\n") +
         kApplyDoc)
            .c_str());
}
}  // namespace

void AddTransforms(py::module_& m)
{
    AddMethodNames(m);
    AddIlluminantChanges(m);
    AddBandTransforms(m);
    AddMeasureMatrix(m);
    AddRelighterClass(m);
    AddRelight(m);
}

}  // namespace bandlight::python
