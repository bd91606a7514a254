// SPDX-License-Identifier: BSD-3-Clause
// bandlight.Spectrum (a sampled spectrum with its name) and the spectral
// data: built-in illuminants, matching functions, test colours, files.
#include <cmath>
#include <cstdio>

#include "PyBandlight.h"
#include "spectral/Illuminants.h"
#include "requests/Defaults.h"

namespace bandlight::python
{

namespace
{
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string Num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

/// A regular grid from wavelengths, checked: at least two, increasing,
/// evenly spaced (to 1e-6 of the step), within the readers' limits.
NamedSpectrum MakeSpectrum(const py::handle& wavelengths, const py::handle& values,
                           const std::string& name)
{
    const Array w = Array::ensure(wavelengths);
    const Array v = Array::ensure(values);
    const std::string what = "Spectrum '" + OneLine(name, 80) + "'";
    if (!w || w.ndim() != 1 || !v || v.ndim() != 1)
    {
        throw Exception(what + ": wavelengths and values must be 1-D arrays of numbers");
    }
    const py::ssize_t n = w.shape(0);
    if (v.shape(0) != n)
    {
        throw Exception(what + ": " + std::to_string(n) + " wavelengths but " +
                        std::to_string(v.shape(0)) + " values");
    }
    if (n < 2 || size_t(n) > MAX_SPECTRUM_SAMPLES)
    {
        throw Exception(what + ": " + std::to_string(n) + " samples; a spectrum has 2 to " +
                        std::to_string(MAX_SPECTRUM_SAMPLES));
    }
    const double start = w.at(0);
    const double step = (w.at(n - 1) - start) / double(n - 1);
    if (!std::isfinite(start) || !std::isfinite(step) || !(step > 0.0) || !(start > 0.0) ||
        !(w.at(n - 1) <= 100000.0))
    {
        throw Exception(what + ": wavelengths must increase within (0, 100000] nm");
    }
    std::vector<double> samples(static_cast<size_t>(n));
    for (py::ssize_t i = 0; i < n; ++i)
    {
        if (std::abs(w.at(i) - (start + step * double(i))) > 1e-6 * step)
        {
            throw Exception(what + ": wavelengths must be evenly spaced (" + Num(w.at(i)) +
                            " nm at index " + std::to_string(i) + ", expected " +
                            Num(start + step * double(i)) +
                            "); resample the data onto a regular grid first (numpy.interp)");
        }
        if (!std::isfinite(v.at(i)))
        {
            throw Exception(what + ": the value at " + Num(w.at(i)) + " nm is not a finite number");
        }
        samples[size_t(i)] = v.at(i);
    }
    return {name, Spectrum(start, step, std::move(samples))};
}

/// values as a read-only array on the spectrum's own storage.
py::array ValuesView(const py::object& self)
{
    const NamedSpectrum& s = self.cast<const NamedSpectrum&>();
    py::array_t<double> a(py::ssize_t(s.spectrum.size()), s.spectrum.values().data(), self);
    a.attr("setflags")(py::arg("write") = false);
    return std::move(a);
}

py::array_t<double> Wavelengths(const Spectrum& s)
{
    py::array_t<double> a(py::ssize_t(s.size()));
    double* p = a.mutable_data();
    for (size_t i = 0; i < s.size(); ++i)
    {
        p[i] = s.wavelength(i);
    }
    return a;
}

std::string Repr(const NamedSpectrum& s)
{
    return "<Spectrum '" + OneLine(s.name, 80) + "': " + std::to_string(s.spectrum.size()) +
           " samples, " + Num(s.spectrum.start()) + "-" + Num(s.spectrum.end()) + " nm every " +
           Num(s.spectrum.step()) + " nm>";
}

std::vector<NamedSpectrum> Named(const std::vector<Spectrum>& spectra,
                                 std::initializer_list<const char*> names)
{
    std::vector<NamedSpectrum> out;
    auto name = names.begin();
    for (const Spectrum& s : spectra)
    {
        out.push_back({*name++, s});
    }
    return out;
}

/// The constructor, the name, and the grid and samples it is read by.
void AddSpectrumData(py::class_<NamedSpectrum>& spectrum)
{
    spectrum
        .def(py::init(&MakeSpectrum), py::arg("wavelengths"), py::arg("values"),
             py::arg("name") = std::string(),
             "Spectrum from evenly spaced, increasing wavelengths (nm) and one value each.\n"
             "Raises ValueError for an irregular grid (resample with numpy.interp first),\n"
             "mismatched lengths, fewer than 2 samples or non-finite values.")
        .def_readwrite("name", &NamedSpectrum::name,
                       "The name it is known by: a built-in name, a file's column header or "
                       "CGATS SAMPLE_ID, or its 1-based position in a file that names none.")
        .def_property_readonly(
            "wavelengths", [](const NamedSpectrum& s) { return Wavelengths(s.spectrum); },
            "The sample wavelengths in nm (a new float64 array).")
        .def_property_readonly("values", &ValuesView,
                               "The samples (a read-only float64 view of the spectrum's data).")
        .def_property_readonly(
            "start", [](const NamedSpectrum& s) { return s.spectrum.start(); },
            "First wavelength, nm.")
        .def_property_readonly(
            "step", [](const NamedSpectrum& s) { return s.spectrum.step(); }, "Grid step, nm.")
        .def_property_readonly(
            "end", [](const NamedSpectrum& s) { return s.spectrum.end(); }, "Last wavelength, nm.")
        .def("__len__", [](const NamedSpectrum& s) { return s.spectrum.size(); })
        .def("__repr__", &Repr);
}

/// Values at wavelengths, other grids, integrals and band means.
void AddSpectrumSampling(py::class_<NamedSpectrum>& spectrum)
{
    spectrum
        .def(
            "__call__",
            [](const NamedSpectrum& s, const py::handle& wavelength) -> py::object
            {
                const Array w = Array::ensure(wavelength);
                if (!w)
                {
                    throw Exception("wavelength must be a number or an array of numbers");
                }
                py::array_t<double> out(std::vector<py::ssize_t>(w.shape(), w.shape() + w.ndim()));
                const double* in = w.data();
                double* o = out.mutable_data();
                for (py::ssize_t i = 0; i < w.size(); ++i)
                {
                    o[i] = s.spectrum(in[i]);
                }
                if (w.ndim() == 0)
                {
                    return py::float_(o[0]);
                }
                return std::move(out);
            },
            py::arg("wavelength"),
            "The value at a wavelength (nm) or an array of them, by linear interpolation;\n"
            "0 outside [start, end].")
        .def(
            "resampled",
            [](const NamedSpectrum& s, double start, double step, size_t count)
            {
                if (count == 0 || count > MAX_SPECTRUM_SAMPLES || !(step > 0.0))
                {
                    throw Exception("resampled: count must be 1 to " +
                                    std::to_string(MAX_SPECTRUM_SAMPLES) + " and step positive");
                }
                return NamedSpectrum{s.name, s.spectrum.resampled(start, step, count)};
            },
            py::arg("start"), py::arg("step"), py::arg("count"),
            "The spectrum linearly resampled onto start + i * step (nm), i < count; zero\n"
            "outside the data's range.")
        .def(
            "extended",
            [](const NamedSpectrum& s, double start, double end) {
                return NamedSpectrum{s.name, s.spectrum.extended(start, end)};
            },
            py::arg("start"), py::arg("end"),
            "The same spectrum over [start, end] nm on its own step, the first and last\n"
            "value held constant outside the data (CIE 15:2004 7.2.1, for remittances).")
        .def(
            "sum", [](const NamedSpectrum& s) { return s.spectrum.sum(); },
            "Rectangle-rule integral sum(values) * step (CIE 15:2004 7.1), value*nm.")
        .def(
            "integrate",
            [](const NamedSpectrum& s, double a, double b)
            { return s.spectrum.integrateLinear(a, b); },
            py::arg("start"), py::arg("end"),
            "Exact integral of the piecewise-linear spectrum over [start, end] nm (zero\n"
            "outside the data), value*nm.")
        .def(
            "band_means",
            [](const NamedSpectrum& s, const py::object& bands, const std::string& rule)
            { return ToArray(BandMeans(s.spectrum, ToBands(bands), ParseBandRule(rule))); },
            py::arg("bands") = py::none(), py::arg("rule") = defaults::BAND_RULE,
            "Band means m_b = (1/width) * integral over band b, one per band, not\n"
            "normalised. bands: a BandSet, edges in nm or \"400,500,600,700\"; None is the\n"
            "lecture's VB/VG/VR. rule: \"lecture\" (the average of the samples with\n"
            "a <= lambda < b, SPEC 1.2) or \"exact\" (the integral of the interpolant).");
}

/// Arithmetic with numbers (the name kept) and with spectra (on the left
/// operand's grid). Each operator's overloads are registered in this order,
/// which is the order their docstrings list them in.
void AddSpectrumArithmetic(py::class_<NamedSpectrum>& spectrum)
{
    spectrum
        .def(
            "__mul__",
            [](const NamedSpectrum& a, double k) {
                return NamedSpectrum{a.name, a.spectrum * k};
            },
            py::is_operator(), py::arg("other"), "The spectrum times a number (its name kept).")
        .def(
            "__rmul__",
            [](const NamedSpectrum& a, double k) {
                return NamedSpectrum{a.name, k * a.spectrum};
            },
            py::is_operator(), py::arg("other"), "A number times the spectrum (its name kept).")
        .def(
            "__truediv__",
            [](const NamedSpectrum& a, double k) {
                return NamedSpectrum{a.name, a.spectrum * (1.0 / k)};
            },
            py::is_operator(), py::arg("other"),
            "The spectrum divided by a number (its name kept).")
        .def(
            "__mul__",
            [](const NamedSpectrum& a, const NamedSpectrum& b) {
                return NamedSpectrum{"", a.spectrum * b.spectrum};
            },
            py::is_operator(), py::arg("other"),
            "Pointwise product on this spectrum's grid (the other resampled onto it).")
        .def(
            "__add__",
            [](const NamedSpectrum& a, const NamedSpectrum& b) {
                return NamedSpectrum{"", a.spectrum + b.spectrum};
            },
            py::is_operator(), py::arg("other"),
            "Pointwise sum on this spectrum's grid (the other resampled onto it).")
        .def(
            "__truediv__",
            [](const NamedSpectrum& a, const NamedSpectrum& b)
            {
                // Pointwise, on a's grid; 0/0 and x/0 are refused, not Inf or NaN.
                Spectrum q = a.spectrum;
                const Spectrum d = b.spectrum.resampledLike(a.spectrum);
                for (size_t i = 0; i < q.size(); ++i)
                {
                    if (d[i] == 0.0)
                    {
                        throw Exception("Spectrum division: '" + OneLine(b.name, 40) +
                                        "' is 0 at " + std::to_string(q.wavelength(i)) + " nm");
                    }
                    q.values()[i] /= d[i];
                }
                return NamedSpectrum{"", q};
            },
            py::is_operator(), py::arg("other"),
            "Pointwise quotient on this spectrum's grid (the other resampled onto it); a\n"
            "divisor that is 0 anywhere on the grid is refused.")
        .def(
            "__add__",
            [](const NamedSpectrum& a, double k)
            {
                Spectrum s = a.spectrum;
                s += k;
                return NamedSpectrum{a.name, s};
            },
            py::is_operator(), py::arg("other"), "The spectrum plus a number (its name kept).")
        .def(
            "__radd__",
            [](const NamedSpectrum& a, double k)
            {
                Spectrum s = a.spectrum;
                s += k;
                return NamedSpectrum{a.name, s};
            },
            py::is_operator(), py::arg("other"), "A number plus the spectrum (its name kept).")
        .def(
            "__sub__",
            [](const NamedSpectrum& a, double k)
            {
                Spectrum s = a.spectrum;
                s += -k;
                return NamedSpectrum{a.name, s};
            },
            py::is_operator(), py::arg("other"), "The spectrum minus a number (its name kept).")
        .def(
            "__sub__",
            [](const NamedSpectrum& a, const NamedSpectrum& b) {
                return NamedSpectrum{"", a.spectrum - b.spectrum};
            },
            py::is_operator(), py::arg("other"),
            "Pointwise difference on this spectrum's grid (the other resampled onto it).");
}

/// Pickling by name, grid and samples.
void AddSpectrumPickling(py::class_<NamedSpectrum>& spectrum)
{
    spectrum.def(py::pickle(
        [](const NamedSpectrum& s) {
            return py::make_tuple(s.name, s.spectrum.start(), s.spectrum.step(),
                                  s.spectrum.values());
        },
        [](const py::tuple& t)
        {
            if (t.size() != 4)
            {
                throw Exception("Spectrum: invalid pickled state");
            }
            return NamedSpectrum{t[0].cast<std::string>(),
                                 Spectrum(t[1].cast<double>(), t[2].cast<double>(),
                                          t[3].cast<std::vector<double>>())};
        }));
}

/// bandlight.Spectrum.
void AddSpectrumClass(py::module_& m)
{
    py::class_<NamedSpectrum> spectrum(m, "Spectrum", R"doc(
A spectrum sampled on a regular wavelength grid, with a name.

Value i belongs to wavelength ``start + i * step`` (nm). Between samples the
spectrum is the piecewise-linear interpolant; outside [start, end] it is
zero. The unit of the values is the caller's: relative spectral power for
illuminants, a factor in [0, 1] for remittances, a tristimulus weight for
matching functions.

``wavelengths`` and ``values`` are numpy arrays; ``values`` is a read-only
view of the spectrum's own samples (copy it to change it, and make a new
Spectrum). Spectra multiply (``illuminant * remittance``, resampled onto the
left operand's grid) and scale (``2.0 * s``). They pickle.
)doc");
    AddSpectrumData(spectrum);
    AddSpectrumSampling(spectrum);
    AddSpectrumArithmetic(spectrum);
    AddSpectrumPickling(spectrum);
}

/// Built-in and computed lights: named illuminants, CIE daylight, Planckian
/// radiators and the daylight basis.
void AddIlluminants(py::module_& m)
{
    m.def(
        "illuminant",
        [](const py::object& nameOrFile)
        {
            const Light l = ToLight(nameOrFile);
            return NamedSpectrum{l.name, l.spectrum};
        },
        py::arg("name_or_file"), R"doc(
An illuminant's relative spectral power, as ``bandlight --illuminant`` reads it.

A str is a built-in name (case-insensitive: A, C, D50, D55, D65, E, F1-F12
as tabulated; D75 or any Dnn from the CIE daylight basis at the nominal CCT;
"3200K" or "BB3200" a Planckian radiator) or a CSV/CGATS spectrum file (its
first spectrum); an os.PathLike is always a file. A file's spectrum is scaled
by a power of two into [0.5, 1) (its scale never matters) and must have a
white. Raises ValueError for an unknown name (the message lists the choices)
or a malformed file (file and line), OSError for a file that cannot be read.
)doc");
    m.def("illuminant_names", &StandardIlluminantNames,
          "The standard illuminants in table order: A, C, D50, D55, D65, D75, E, F1-F12.");
    m.def(
        "daylight",
        [](double cct) {
            return NamedSpectrum{"daylight_" + Num(cct) + "K", Daylight(cct)};
        },
        py::arg("cct"),
        "CIE daylight at correlated colour temperature cct (4000-25000 K), 300-830 nm at\n"
        "5 nm: S0 + M1*S1 + M2*S2 with M1, M2 rounded as CIE 15:2004 3.1 prescribes\n"
        "(D65 itself is daylight(6504)).");
    m.def(
        "planckian",
        [](double kelvin, double start, double step, size_t count)
        {
            if (count == 0 || count > MAX_SPECTRUM_SAMPLES)
            {
                throw Exception("planckian: count must be 1 to " +
                                std::to_string(MAX_SPECTRUM_SAMPLES));
            }
            return NamedSpectrum{"BB" + Num(kelvin), Planckian(kelvin, start, step, count)};
        },
        py::arg("kelvin"), py::arg("start") = defaults::PLANCK_START_NM,
        py::arg("step") = defaults::PLANCK_STEP_NM, py::arg("count") = defaults::PLANCK_COUNT,
        "A Planckian radiator at kelvin (0 < T <= 1e6 K), normalised to 100 at 560 nm as\n"
        "CIE tables are; 300-830 nm at 5 nm unless a grid is given.");
    m.def(
        "daylight_basis",
        []
        {
            const DaylightBasis& b = GetDaylightBasis();
            return py::make_tuple(NamedSpectrum{"S0", b.s0}, NamedSpectrum{"S1", b.s1},
                                  NamedSpectrum{"S2", b.s2});
        },
        "The CIE daylight basis (S0, S1, S2), 300-830 nm at 5 nm (CIE 15:2004 Table T.2).");
}

/// The observers' colour-matching functions.
void AddMatchingFunctions(py::module_& m)
{
    m.def(
        "cmf",
        [](const py::object& observer, const std::string& set)
        {
            const MatchingSet which = ToMatchingSet(set);
            const std::vector<NamedSpectrum> s =
                which == MatchingSet::XYZ ? Named(MatchingFunctionsOf(which, ToObserver(observer)),
                                                  {"x_bar", "y_bar", "z_bar"})
                                          : Named(MatchingFunctionsOf(which, ToObserver(observer)),
                                                  {"r_bar", "g_bar", "b_bar"});
            return py::make_tuple(s[0], s[1], s[2]);
        },
        py::arg("observer") = defaults::OBSERVER, py::arg("set") = defaults::MATCHING_SET, R"doc(
The colour-matching functions of an observer as three Spectrum, 360-830 nm at 5 nm.

observer: "1931" (CIE 1931 2 degree, Table T.4) or "1964" (CIE 1964 10 degree,
Table T.5). set: "xyz" for x_bar, y_bar, z_bar as tabulated (y_bar peaks at
1.0 at 555 nm), "ebu_rgb" for r_bar, g_bar, b_bar: x_bar y_bar z_bar
converted to the EBU Tech 3213 primaries, D65 white.
)doc");
}

/// Remittances by name or file, and spectrum files and text read whole.
void AddSpectrumReaders(py::module_& m)
{
    m.def(
        "reflectances", [](const py::object& nameOrFile) { return ToReflectances(nameOrFile); },
        py::arg("name_or_file") = defaults::REFLECTANCES, R"doc(
Remittances as ``bandlight --reflectance`` reads them, as a list of Spectrum.

"TCS01" ... "TCS15" (case-insensitive) is one CIE 13.3 test colour sample
(360-830 nm at 5 nm), "TCS" all fifteen; anything else is a CSV or CGATS
file of spectra (os.PathLike: always a file). A file's remittances beyond
+-1000 are refused; ends short of 380-780 nm and values outside [0, 1] give a
NoteWarning.
)doc");
    m.def(
        "read_spectra", [](const Path& path) { return ReadSpectraFile(path.string()); },
        py::arg("path"), R"doc(
Every spectrum of a CSV or CGATS (.sp, .cmf, .ti3, .cie) file, in file order.

The reader is chosen by content (a CGATS file has BEGIN_DATA_FORMAT). CSV:
'#' comments, an optional header row naming the columns, then rows
"wavelength, v1, v2, ..." (commas, semicolons, tabs or spaces); an irregular
grid is resampled onto its smallest step. CGATS: the grid from
SPECTRAL_START_NM/END_NM/BANDS, values divided by SPECTRAL_NORM (.ti3: by 100
when it gives none). Raises ValueError "FILE:LINE: what" for malformed
content, OSError for a file that cannot be read.
)doc");
    m.def(
        "parse_spectra",
        [](const std::string& text, const std::string& source)
        { return ReadSpectraText(text, source); },
        py::arg("text"), py::arg("source") = defaults::TEXT_SOURCE,
        "The same as read_spectra for text in memory; source names it in error messages.");
}
}  // namespace

void AddSpectrum(py::module_& m)
{
    AddSpectrumClass(m);
    AddIlluminants(m);
    AddMatchingFunctions(m);
    AddSpectrumReaders(m);
}

}  // namespace bandlight::python
