// SPDX-License-Identifier: BSD-3-Clause
// Colorimetry: XYZ of lights and surfaces, CIELAB, colour differences, CCT,
// colour rendering, chromatic adaptation, RGB spaces — vectorised over
// arrays of colours (..., 3) with the GIL released around the loops.
#include "PyBandlight.h"
#include "jobs/ColourJobs.h"
#include "jobs/QualityJob.h"
#include "report/LightQualityReport.h"
#include "requests/Defaults.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/ColourRendering.h"

namespace bandlight::python
{

namespace
{
/// out[i] = f(colour i) for every colour of `in`, three values each.
template <typename Fn>
py::array_t<double> MapColours(const Colours& in, Fn&& f)
{
    py::array_t<double> out = NewArray(in.shape, 3);
    double* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        for (size_t i = 0; i < in.count; ++i)
        {
            const double* p = in.at(i);
            const Vec3 r = f(Vec3(p[0], p[1], p[2]));
            o[3 * i] = r[0];
            o[3 * i + 1] = r[1];
            o[3 * i + 2] = r[2];
        }
    }
    return out;
}

/// The same for pairs of colours broadcast together.
template <typename Fn>
py::array_t<double> MapPairs(const Colours& a, const Colours& b, Fn&& f)
{
    py::array_t<double> out = NewArray(a.shape, 3);
    double* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        for (size_t i = 0; i < a.count; ++i)
        {
            const double* p = a.at(i);
            const double* q = b.at(i);
            const Vec3 r = f(Vec3(p[0], p[1], p[2]), Vec3(q[0], q[1], q[2]));
            o[3 * i] = r[0];
            o[3 * i + 1] = r[1];
            o[3 * i + 2] = r[2];
        }
    }
    return out;
}

/// One number per pair.
template <typename Fn>
py::object ReducePairs(const Colours& a, const Colours& b, Fn&& f)
{
    py::array_t<double> out = NewArray(a.shape, 0);
    double* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        for (size_t i = 0; i < a.count; ++i)
        {
            const double* p = a.at(i);
            const double* q = b.at(i);
            o[i] = f(Vec3(p[0], p[1], p[2]), Vec3(q[0], q[1], q[2]));
        }
    }
    return ScalarOrArray(out, a.shape);
}

/// XYZ rows of `samples` under `light`, checked finite as `bandlight xyz` does.
py::array_t<double> SurfaceRows(const XyzIntegrator& integrate, const Vec3& white,
                                const std::vector<NamedSpectrum>& samples)
{
    py::array_t<double> out({py::ssize_t(samples.size()), py::ssize_t(3)});
    auto w = out.mutable_unchecked<2>();
    for (size_t i = 0; i < samples.size(); ++i)
    {
        const Vec3 xyz = integrate(samples[i].spectrum);
        const Vec3 lab = XyzToLab(xyz, white);
        for (int c = 0; c < 3; ++c)
        {
            jobs::RequireFinite(xyz[c], "XYZ of '" + OneLine(samples[i].name, 80) + "'");
            jobs::RequireFinite(lab[c], "L*a*b* of '" + OneLine(samples[i].name, 80) + "'");
            w(py::ssize_t(i), c) = xyz[c];
        }
    }
    return out;
}

/// An XyzIntegrator with what Python shows of it.
struct PyXyzIntegrator
{
    std::string illuminant;
    Observer observer;
    Vec3 white;
    XyzIntegrator integrator;
};

PyXyzIntegrator MakeIntegrator(const py::object& illuminant, const py::object& observer)
{
    const Light l = ToLight(illuminant);
    const Observer o = ToObserver(observer);
    return {l.name, o, IlluminantWhiteXyz(l.spectrum, o), XyzIntegrator(l.spectrum, o)};
}

py::object Integrate(const PyXyzIntegrator& self, const py::object& remittances)
{
    const Spectrum& grid = self.integrator.grid();
    if (py::isinstance<NamedSpectrum>(remittances) || py::isinstance<py::str>(remittances) ||
        py::hasattr(remittances, "__fspath__") ||
        (py::isinstance<py::sequence>(remittances) && py::len(remittances) > 0 &&
         py::isinstance<NamedSpectrum>(py::sequence(remittances)[0])))
    {
        const std::vector<NamedSpectrum> samples = ToReflectances(remittances);
        py::array_t<double> rows = SurfaceRows(self.integrator, self.white, samples);
        if (IsSingleSpectrum(remittances))
        {
            return ToArray(Vec3(rows.at(0, 0), rows.at(0, 1), rows.at(0, 2)));
        }
        return std::move(rows);
    }
    // Raw samples on the integrator's grid, any leading shape.
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    const Array a = Array::ensure(remittances);
    const py::ssize_t k = py::ssize_t(grid.size());
    if (!a || a.ndim() < 1 || a.shape(a.ndim() - 1) != k)
    {
        throw Exception("remittance samples must be an array (..., " + std::to_string(k) +
                        ") on the integrator's grid (" + std::to_string(k) + " wavelengths), " +
                        "a Spectrum or a sequence of them");
    }
    const std::vector<py::ssize_t> shape(a.shape(), a.shape() + a.ndim() - 1);
    py::array_t<double> out = NewArray(shape, 3);
    const size_t n = size_t(a.size() / k);
    const double* in = a.data();
    double* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        for (size_t i = 0; i < n; ++i)
        {
            const Vec3 xyz = self.integrator.integrate(in + i * size_t(k));
            o[3 * i] = xyz[0];
            o[3 * i + 1] = xyz[1];
            o[3 * i + 2] = xyz[2];
        }
    }
    return std::move(out);
}

/// xyz(): CIE XYZ of a light, or of surfaces under it, as `bandlight xyz`.
void AddXyz(py::module_& m)
{
    m.def(
        "xyz",
        [](const py::object& illuminant, const py::object& reflectance,
           const py::object& observer) -> py::object
        {
            const PyXyzIntegrator integ = MakeIntegrator(illuminant, observer);
            if (reflectance.is_none())
            {
                for (int c = 0; c < 3; ++c)
                {
                    jobs::RequireFinite(integ.white[c], "XYZ of '" + integ.illuminant + "'");
                }
                return ToArray(integ.white);
            }
            return Integrate(integ, reflectance);
        },
        py::arg("illuminant"), py::arg("reflectance") = py::none(), py::kw_only(),
        py::arg("observer") = defaults::OBSERVER, R"doc(
CIE XYZ, the perfect white reflector at Y = 100 (CIE 15:2004 7.1), as
``bandlight xyz`` computes it.

illuminant: a name or file (str), a file (os.PathLike) or a Spectrum.
reflectance None: the illuminant's white, shape (3,). A Spectrum: that
surface lit by the illuminant, shape (3,). A test-colour name or file (as
``--reflectance``: "TCS01", "TCS", "chart.sp") or a sequence of Spectrum:
one row per surface, in order, shape (N, 3). Remittances are extended at
their ends where they stop short of the illuminant's grid.
observer: "1931" or "1964".
)doc");
}

/// bandlight.XyzIntegrator: the fast path for many remittances under one light.
void AddXyzIntegrator(py::module_& m)
{
    py::class_<PyXyzIntegrator>(m, "XyzIntegrator", R"doc(
Precomputed weights w_k(lambda) = k * S(lambda) * cmf_k(lambda) * step for one
illuminant and observer, so that a surface's XYZ (white reflector Y = 100) is
three dot products: the fast path for many remittances on one grid.

Call it with a Spectrum (shape (3,)), a sequence of Spectrum (N, 3), or an
array of remittance samples (..., K) on ``wavelengths`` (..., 3); arrays are
integrated with the GIL released.
)doc")
        .def(py::init(&MakeIntegrator), py::arg("illuminant"),
             py::arg("observer") = defaults::OBSERVER,
             "The weights of a light (a name or file, an os.PathLike or a Spectrum) on its own\n"
             "grid, for observer \"1931\" or \"1964\".")
        .def_property_readonly(
            "wavelengths",
            [](const PyXyzIntegrator& s)
            {
                const Spectrum& g = s.integrator.grid();
                py::array_t<double> a(py::ssize_t(g.size()));
                for (size_t i = 0; i < g.size(); ++i)
                {
                    a.mutable_at(py::ssize_t(i)) = g.wavelength(i);
                }
                return a;
            },
            "The illuminant's grid, nm: remittance samples are given on it.")
        .def_property_readonly(
            "weights",
            [](const PyXyzIntegrator& s)
            {
                const size_t k = s.integrator.grid().size();
                py::array_t<double> a({py::ssize_t(k), py::ssize_t(3)});
                std::vector<double> unit(k, 0.0);
                for (size_t i = 0; i < k; ++i)
                {
                    unit[i] = 1.0;
                    const Vec3 w = s.integrator.integrate(unit.data());
                    unit[i] = 0.0;
                    for (int c = 0; c < 3; ++c)
                    {
                        a.mutable_at(py::ssize_t(i), c) = w[c];
                    }
                }
                return a;
            },
            "The weights, shape (K, 3): XYZ = samples @ weights.")
        .def_property_readonly(
            "white", [](const PyXyzIntegrator& s) { return ToArray(s.white); },
            "XYZ of the illuminant's white (Y = 100).")
        .def_readonly("illuminant", &PyXyzIntegrator::illuminant, "The illuminant's name.")
        .def("__call__", &Integrate, py::arg("remittances"),
             "XYZ (white Y = 100) of a Spectrum (3,), of remittances given as ``xyz`` takes\n"
             "them (N, 3), or of samples on ``wavelengths`` (..., K) -> (..., 3).")
        .def("__repr__",
             [](const PyXyzIntegrator& s)
             {
                 return "<XyzIntegrator '" + OneLine(s.illuminant, 80) + "', " +
                        ObserverName(s.observer) + ">";
             });
}

/// Conversions between XYZ, xyY and CIELAB.
void AddColourConversions(py::module_& m)
{
    m.def(
        "xyz_to_xyy",
        [](const py::object& xyz)
        { return MapColours(ToColours(xyz, "xyz"), [](const Vec3& v) { return XyzToxyY(v); }); },
        py::arg("xyz"),
        "xyY of XYZ colours (..., 3); XYZ = 0 has no chromaticity and gives (0, 0, 0).");
    m.def(
        "xyy_to_xyz",
        [](const py::object& xyy)
        { return MapColours(ToColours(xyy, "xyy"), [](const Vec3& v) { return xyYToXyz(v); }); },
        py::arg("xyy"), "XYZ of xyY colours (..., 3).");
    m.def(
        "xyz_to_lab",
        [](const py::object& xyz, const py::object& white)
        {
            const auto [c, w] = BroadcastColours(xyz, white, "xyz", "white");
            return MapPairs(c, w, [](const Vec3& v, const Vec3& wp) { return XyzToLab(v, wp); });
        },
        py::arg("xyz"), py::arg("white"),
        "CIELAB (CIE 15:2004 8.2.1) of XYZ colours (..., 3) relative to white, on the\n"
        "same scale (e.g. xyz(light) for Y = 100); white broadcasts (one (3,) white,\n"
        "or one per colour).");
    m.def(
        "lab_to_xyz",
        [](const py::object& lab, const py::object& white)
        {
            const auto [c, w] = BroadcastColours(lab, white, "lab", "white");
            return MapPairs(c, w, [](const Vec3& v, const Vec3& wp) { return LabToXyz(v, wp); });
        },
        py::arg("lab"), py::arg("white"), "XYZ of CIELAB colours (..., 3) relative to white.");
}

/// Colour differences of CIELAB pairs.
void AddColourDifferences(py::module_& m)
{
    m.def(
        "delta_e76",
        [](const py::object& lab1, const py::object& lab2)
        {
            const auto [a, b] = BroadcastColours(lab1, lab2, "lab1", "lab2");
            return ReducePairs(a, b, [](const Vec3& p, const Vec3& q) { return DeltaE76(p, q); });
        },
        py::arg("lab1"), py::arg("lab2"),
        "Delta E*ab (CIE 1976), the distance in CIELAB, of colour pairs (..., 3)\n"
        "broadcast together: a float for one pair, else an array of shape (...).");
    m.def(
        "delta_e2000",
        [](const py::object& lab1, const py::object& lab2, double kL, double kC, double kH)
        {
            const auto [a, b] = BroadcastColours(lab1, lab2, "lab1", "lab2");
            return ReducePairs(
                a, b, [=](const Vec3& p, const Vec3& q) { return DeltaE2000(p, q, kL, kC, kH); });
        },
        py::arg("lab1"), py::arg("lab2"), py::arg("kL") = defaults::CIEDE2000_K,
        py::arg("kC") = defaults::CIEDE2000_K, py::arg("kH") = defaults::CIEDE2000_K, R"doc(
CIEDE2000 (CIE 142-2001, with the notes of Sharma, Wu & Dalal 2005) of
CIELAB colour pairs (..., 3) broadcast together: a float for one pair, else
an array of shape (...). Agrees with all 34 pairs of Sharma's table to 5e-5.
)doc");
}

/// What a light is: its CCT and Duv, its colour rendering.
void AddLightQuality(py::module_& m)
{
    m.def(
        "cct",
        [](const py::object& xyz) -> py::object
        {
            const Colours c = ToColours(xyz, "xyz");
            py::array_t<double> t = NewArray(c.shape, 0), d = NewArray(c.shape, 0);
            for (size_t i = 0; i < c.count; ++i)
            {
                const double* p = c.at(i);
                const CctDuv r = ComputeCct(Vec3(p[0], p[1], p[2]));
                t.mutable_data()[i] = r.cctK;
                d.mutable_data()[i] = r.duv;
            }
            return py::make_tuple(ScalarOrArray(t, c.shape), ScalarOrArray(d, c.shape));
        },
        py::arg("xyz"), R"doc(
(cct, duv) of XYZ colours (CIE 1931 observer): the temperature of the nearest
Planckian radiator in CIE 1960 UCS (CIE 15:2004 9.5), searched over
1000-100000 K, and the signed distance from the locus (positive above it).
Floats for one colour (3,), arrays (...) for (..., 3).
)doc");
    m.def(
        "cri",
        [](const py::object& illuminant)
        {
            // The command's document, through the one job.
            return py::module_::import("json").attr("loads")(
                jobs::CriDocument(jobs::MakeCri(ToLight(illuminant))));
        },
        py::arg("illuminant"), R"doc(
CIE 13.3-1995 colour rendering of a light, as ``bandlight cri --json``:
{"illuminant", "cct_K", "duv", "Ra", "R" (R1-R15), "outside_duv_tolerance"}.
The reference is a Planckian radiator below 5000 K and CIE daylight from
5000 K on; outside_duv_tolerance is |Duv| > 5.4e-3, where CIE 13.3 does not
consider Ra meaningful. Raises ValueError for a CCT outside 1000-25000 K.
)doc");
}

/// `quality`: the JSON of the score registry, made typed by the package
/// (bandlight.quality builds its Quality records from it).
void AddQuality(py::module_& m)
{
    m.def(
        "_quality",
        [](const py::object& lights, const py::object& reference, int threads)
        {
            std::vector<Light> resolved;
            for (const py::handle& l : lights)
            {
                resolved.push_back(ToLight(l));
                // Named as given, as the command names its arguments.
                if (py::isinstance<py::str>(l) || py::hasattr(l, "__fspath__"))
                {
                    resolved.back().name =
                        py::str(py::module_::import("os").attr("fspath")(l)).cast<std::string>();
                }
            }
            const Light ref = reference.is_none() ? Light() : ToLight(reference);
            std::string json;
            {
                py::gil_scoped_release release;
                json = QualityJson(jobs::ScoreLights(resolved, ref, threads));
            }
            return json;
        },
        py::arg("lights"), py::arg("reference") = py::none(), py::arg("threads") = 0, R"doc(
The scores of ``bandlight quality --json`` for a list of lights (names,
daylight:K, planck:K, files or Spectrum objects) as its JSON text, the GIL
released; bandlight.quality() returns them as Quality records.
)doc");
}

/// Chromatic adaptation between two whites.
void AddChromaticAdaptation(py::module_& m)
{
    m.def(
        "adaptation_matrix",
        [](const py::object& src, const py::object& dst, const std::string& method)
        {
            return ToArray(
                Eigen::MatrixXd(AdaptationMatrix(ToVec3(src, "src_white"), ToVec3(dst, "dst_white"),
                                                 ParseAdaptationMethod(method))));
        },
        py::arg("src_white"), py::arg("dst_white"), py::arg("method") = defaults::WHITE_ADAPTATION,
        R"doc(
The 3x3 that maps XYZ seen under src_white to the corresponding XYZ under
dst_white: M^-1 diag(M dst / M src) M. method: "vonkries" (XYZ scaling),
"bradford", "cat02" or "sharp". Whites on any common scale.
)doc");
}

/// The built-in RGB spaces and their matrices.
void AddRgbSpaces(py::module_& m)
{
    m.def(
        "rgb_spaces",
        []
        {
            py::list out;
            for (const RgbSpace& s : BuiltinRgbSpaces())
            {
                const Chromaticities& c = s.chromaticities;
                py::dict d;
                d["name"] = s.name;
                d["display_name"] = s.displayName;
                d["description"] = s.description;
                d["aliases"] = s.aliases;
                d["primaries"] =
                    py::make_tuple(py::make_tuple(c.rx, c.ry), py::make_tuple(c.gx, c.gy),
                                   py::make_tuple(c.bx, c.by));
                d["white"] = py::make_tuple(c.wx, c.wy);
                out.append(d);
            }
            return out;
        },
        ("The built-in linear RGB spaces (" + RgbSpaceChoices() +
         "): name, display_name, description, aliases, primaries ((x, y) of R, G, B)\n"
         "and white (x, y).")
            .c_str());
    m.def(
        "rgb_to_xyz_matrix",
        [](const std::string& space)
        { return ToArray(Eigen::MatrixXd(RgbToXyzMatrix(FindRgbSpace(space).chromaticities))); },
        py::arg("space") = defaults::WORKING_SPACE,
        ("The RGB -> XYZ matrix of a built-in space (SMPTE RP 177): RGB (1, 1, 1) is its\n"
         "white with Y = 1. space: a name or alias (" +
         RgbSpaceChoices() + "; aliases such as \"ap1\" and \"lin-rec709\").")
            .c_str());
}
}  // namespace

void AddColorimetry(py::module_& m)
{
    AddXyz(m);
    AddXyzIntegrator(m);
    AddColourConversions(m);
    AddColourDifferences(m);
    AddLightQuality(m);
    AddQuality(m);
    AddChromaticAdaptation(m);
    AddRgbSpaces(m);
}

}  // namespace bandlight::python
