// SPDX-License-Identifier: BSD-3-Clause
// The band model: band sets, band means of lights and surfaces, matching-
// function band matrices, the band <-> working-space matrices, the tables.
#include "PyBandlight.h"
#include "spectral/Illuminants.h"
#include "requests/Defaults.h"

namespace bandlight::python
{

namespace
{
void RowsOf(const Eigen::MatrixXd& m, std::initializer_list<const char*> names, py::dict& d)
{
    int k = 0;
    for (const char* name : names)
    {
        std::vector<double> row(size_t(m.cols()));
        for (Eigen::Index b = 0; b < m.cols(); ++b)
        {
            row[size_t(b)] = m(k, b);
        }
        d[name] = row;
        ++k;
    }
}

py::dict Tables(const py::object& bandsArg, const py::object& observerArg,
                const std::string& ruleArg)
{
    const BandSet bands = ToBands(bandsArg);
    const Observer observer = ToObserver(observerArg);
    const BandRule rule = ParseBandRule(ruleArg);
    const Eigen::MatrixXd xyz = MatchingBandMatrix(bands, MatchingSet::XYZ, observer, rule);
    const Eigen::MatrixXd rgb = MatchingBandMatrix(bands, MatchingSet::EBU_RGB, observer, rule);
    // The layout of `bandlight tables --json`.
    py::dict j;
    py::list bandList;
    for (const Band& b : bands)
    {
        py::dict d;
        d["name"] = b.name;
        d["min_nm"] = b.minNm;
        d["max_nm"] = b.maxNm;
        bandList.append(d);
    }
    j["bands"] = bandList;
    const std::string key = observer == Observer::CIE1931_2DEG ? "cie1931_xyz" : "cie1964_xyz";
    j["observer"] = observer == Observer::CIE1931_2DEG ? "1931" : "1964";
    j["rule"] = rule == BandRule::SAMPLE_MEAN ? "lecture" : "exact";
    py::dict matching, xyzRows, rgbRows;
    RowsOf(xyz, {"x", "y", "z"}, xyzRows);
    RowsOf(rgb, {"r", "g", "b"}, rgbRows);
    matching[key.c_str()] = xyzRows;
    matching["ebu_rgb"] = rgbRows;
    j["matching_functions"] = matching;
    py::dict condition;
    condition[key.c_str()] = ConditionNumber(xyz);
    condition["ebu_rgb"] = ConditionNumber(rgb);
    condition["limit"] = MAX_BAND_CONDITION;
    j["condition_number"] = condition;
    py::dict illuminants, remittances;
    for (const std::string& name : StandardIlluminantNames())
    {
        illuminants[name.c_str()] = IlluminantBands(BuiltinIlluminant(name), bands, rule);
    }
    for (const NamedSpectrum& s : TestColourSamples())
    {
        remittances[s.name.c_str()] = RemittanceBands(s.spectrum, bands, rule);
    }
    j["illuminants"] = illuminants;
    j["remittances"] = remittances;
    return j;
}

/// bandlight.BandSet.
void AddBandSetClass(py::module_& m)
{
    py::class_<BandSet>(m, "BandSet", R"doc(
An ordered set of wavelength bands [min_nm, max_nm), validated: edges
increasing, every band of positive width, no overlaps.

Wherever a function takes ``bands``, a BandSet, a sequence of edges
(``[400, 500, 600, 700]``) or a str ("400,500,600,700") will do, and None
means the lecture's VB [400, 500), VG [500, 600), VR [600, 700).
)doc")
        .def(py::init([](const std::string& text) { return BandSet::Parse(text); }),
             py::arg("edges"), "Adjacent bands from \"E0,E1,...,En\" (nm).")
        .def(py::init([](const std::vector<double>& edges) { return BandSet::FromEdges(edges); }),
             py::arg("edges"),
             "Adjacent bands from edges e0 < e1 < ... < en (nm); named B1..Bn (VB/VG/VR for "
             "three).")
        .def_static("lecture", &BandSet::Lecture,
                    "The lecture's three bands: VB [400, 500), VG [500, 600), VR [600, 700).")
        .def_static("equal", &BandSet::Equal, py::arg("n"), py::arg("min_nm") = defaults::EQUAL_BANDS_MIN_NM,
                    py::arg("max_nm") = defaults::EQUAL_BANDS_MAX_NM,
                    "n equal bands over [min_nm, max_nm), named B1..Bn (VB/VG/VR for the "
                    "lecture's range with n = 3).")
        .def_static(
            "named",
            [](const std::vector<std::tuple<std::string, double, double>>& bands)
            {
                std::vector<Band> b;
                for (const auto& [name, lo, hi] : bands)
                {
                    b.push_back({name, lo, hi});
                }
                return BandSet(b);
            },
            py::arg("bands"),
            "Any bands, adjacent or disjoint, as (name, min_nm, max_nm) tuples in order.")
        .def_property_readonly(
            "names",
            [](const BandSet& s)
            {
                std::vector<std::string> n;
                for (const Band& b : s)
                {
                    n.push_back(b.name);
                }
                return n;
            },
            "The bands' names.")
        .def_property_readonly(
            "bands",
            [](const BandSet& s)
            {
                std::vector<std::tuple<std::string, double, double>> out;
                for (const Band& b : s)
                {
                    out.emplace_back(b.name, b.minNm, b.maxNm);
                }
                return out;
            },
            "The bands as (name, min_nm, max_nm) tuples.")
        .def("describe", &BandSet::describe,
             "\"400,500,600,700\"-style edges, as --bands takes them.")
        .def("__len__", &BandSet::size)
        .def("__repr__", [](const BandSet& s) { return "BandSet('" + s.describe() + "')"; });
}

/// Band means of lights and of surfaces.
void AddBandMeans(py::module_& m)
{
    m.def(
        "illuminant_bands",
        [](const py::object& illuminant, const py::object& bands, const std::string& rule)
        {
            return ToArray(
                IlluminantBands(ToLight(illuminant).spectrum, ToBands(bands), ParseBandRule(rule)));
        },
        py::arg("illuminant"), py::arg("bands") = py::none(), py::kw_only(),
        py::arg("rule") = defaults::BAND_RULE, R"doc(
Illuminant band means (I_B, I_G, I_R, ...) normalised to the largest band = 1
(SPEC 1.2). illuminant: a name or file (str), a file (os.PathLike) or a
Spectrum. rule: "lecture" (sample average) or "exact".
)doc");
    m.def(
        "remittance_bands",
        [](const py::object& reflectance, const py::object& bandsArg,
           const std::string& ruleArg) -> py::object
        {
            const BandSet bands = ToBands(bandsArg);
            const BandRule rule = ParseBandRule(ruleArg);
            const std::vector<NamedSpectrum> samples = ToReflectances(reflectance);
            Eigen::MatrixXd rows(Eigen::Index(samples.size()), Eigen::Index(bands.size()));
            for (size_t i = 0; i < samples.size(); ++i)
            {
                const std::vector<double> v = RemittanceBands(samples[i].spectrum, bands, rule);
                for (size_t b = 0; b < v.size(); ++b)
                {
                    rows(Eigen::Index(i), Eigen::Index(b)) = v[b];
                }
            }
            if (IsSingleSpectrum(reflectance))
            {
                return ToArray(std::vector<double>(rows.data(), rows.data() + rows.size()));
            }
            return ToArray(rows);
        },
        py::arg("reflectance"), py::arg("bands") = py::none(), py::kw_only(),
        py::arg("rule") = defaults::BAND_RULE, R"doc(
Remittance band means (O_B, O_G, O_R, ...), raw (not normalised, so 0 <= O <= 1).
A Spectrum gives shape (bands,); a test-colour name or file ("TCS", "chart.sp")
or a sequence of Spectrum gives one row per surface, (N, bands).
)doc");
}

/// The matching-function band matrices, the band <-> working-space matrices and
/// their conditioning.
void AddBandMatrices(py::module_& m)
{
    m.def(
        "matching_band_matrix",
        [](const py::object& bands, const std::string& set, const py::object& observer,
           const std::string& rule)
        {
            return ToArray(MatchingBandMatrix(ToBands(bands), ToMatchingSet(set),
                                              ToObserver(observer), ParseBandRule(rule)));
        },
        py::arg("bands") = py::none(), py::kw_only(), py::arg("set") = defaults::MATCHING_SET,
        py::arg("observer") = defaults::OBSERVER, py::arg("rule") = defaults::BAND_RULE, R"doc(
The row-normalised matching-function band matrix, shape (3, bands): entry
(k, b) is the band mean of matching function k in band b divided by its row's
sum, so an equal-energy light on an ideal white gives (1, 1, 1) (SPEC 1.2).
set: "xyz" (x_bar y_bar z_bar) or "ebu_rgb" (r_bar g_bar b_bar, EBU 3213, D65).
)doc");
    m.def(
        "band_to_colour_matrix",
        [](const py::object& bands, const std::string& set, const py::object& observer,
           const std::string& rule)
        {
            const BandMatrix3 b = BandToColourMatrix(ToBands(bands), ToMatchingSet(set),
                                                     ToObserver(observer), ParseBandRule(rule));
            return py::make_tuple(ToArray(Eigen::MatrixXd(b.toColour)),
                                  ToArray(Eigen::MatrixXd(b.fromColour)), b.conditionNumber);
        },
        py::arg("bands") = py::none(), py::kw_only(), py::arg("set") = defaults::MATCHING_SET,
        py::arg("observer") = defaults::OBSERVER, py::arg("rule") = defaults::BAND_RULE, R"doc(
(to_colour, from_colour, condition_number) of a three-band set: the band ->
XYZ (or EBU RGB) 3x3, its inverse, and its 2-norm condition number (4.35 for
the lecture's bands, CIE 1931). Raises ValueError for other than three bands
or a singular matrix.
)doc");
    m.def(
        "working_to_band_matrix",
        [](const py::object& bands, const std::string& working, const py::object& observer)
        {
            return ToArray(
                WorkingToBandMatrix(ToBands(bands), FindRgbSpace(working), ToObserver(observer)));
        },
        py::arg("bands") = py::none(), py::kw_only(), py::arg("working_space") = defaults::WORKING_SPACE,
        py::arg("observer") = defaults::OBSERVER,
        "Working RGB -> band values, shape (bands, 3): the pseudo-inverse of the\n"
        "row-normalised band matrix times the working space's RGB -> XYZ.");
    m.def(
        "band_to_working_matrix",
        [](const py::object& bands, const std::string& working, const py::object& observer)
        {
            return ToArray(
                BandToWorkingMatrix(ToBands(bands), FindRgbSpace(working), ToObserver(observer)));
        },
        py::arg("bands") = py::none(), py::kw_only(), py::arg("working_space") = defaults::WORKING_SPACE,
        py::arg("observer") = defaults::OBSERVER, "Band values -> working RGB, shape (3, bands).");
    m.def(
        "condition_number",
        [](const py::handle& matrix)
        {
            using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
            const Array a = Array::ensure(matrix);
            if (!a || a.ndim() != 2)
            {
                throw Exception("condition_number needs a 2-D matrix");
            }
            Eigen::MatrixXd mat(a.shape(0), a.shape(1));
            for (py::ssize_t r = 0; r < a.shape(0); ++r)
            {
                for (py::ssize_t c = 0; c < a.shape(1); ++c)
                {
                    mat(r, c) = a.at(r, c);
                }
            }
            return ConditionNumber(mat);
        },
        py::arg("matrix"),
        "2-norm condition number sigma_max / sigma_min of a matrix (inf if singular).\n"
        "Band methods refuse band sets above MAX_BAND_CONDITION.");
    m.attr("MAX_BAND_CONDITION") = MAX_BAND_CONDITION;
}

/// tables(): the lecture's three tables, as `bandlight tables --json` prints them.
void AddTables(py::module_& m)
{
    m.def("tables", &Tables, py::arg("bands") = py::none(), py::kw_only(),
          py::arg("observer") = defaults::OBSERVER, py::arg("rule") = defaults::BAND_RULE, R"doc(
The lecture's three tables, as ``bandlight tables --json`` prints them: a dict
with "bands", "observer", "rule", "matching_functions" (rows summing to 1, CIE
xyz and EBU RGB), "condition_number", "illuminants" (band means, largest = 1,
for A, C, D50, D55, D65, D75, E, F1-F12) and "remittances" (TCS01-TCS15).
)doc");
}
}  // namespace

void AddBands(py::module_& m)
{
    AddBandSetClass(m);
    AddBandMeans(m);
    AddBandMatrices(m);
    AddTables(m);
}

}  // namespace bandlight::python
