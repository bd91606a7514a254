// SPDX-License-Identifier: BSD-3-Clause
// Arguments as the command reads them, and numpy arrays in and out.
#include <sstream>

#include "PyBandlight.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"

namespace bandlight::python
{

namespace
{
std::string TypeName(const py::handle& arg)
{
    return py::str(py::type::handle_of(arg).attr("__name__")).cast<std::string>();
}

bool IsPathLike(const py::handle& arg)
{
    return !py::isinstance<py::str>(arg) && py::hasattr(arg, "__fspath__");
}

std::string ShapeText(const py::array& a)
{
    std::ostringstream s;
    s << "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
    {
        s << (i ? ", " : "") << a.shape(i);
    }
    s << (a.ndim() == 1 ? ",)" : ")");
    return s.str();
}

}  // namespace

Light ToLight(const py::handle& arg)
{
    if (py::isinstance<NamedSpectrum>(arg))
    {
        const NamedSpectrum& s = arg.cast<const NamedSpectrum&>();
        const std::string name = s.name.empty() ? "spectrum" : s.name;
        return {name, UsableIlluminant(s.spectrum, "illuminant '" + OneLine(name, 80) + "'")};
    }
    if (py::isinstance<py::str>(arg))
    {
        // A name or a file: as a file name, it must hold no NUL byte.
        return jobs::ResolveIlluminant(PathText(arg, "an illuminant"), Warnings());
    }
    if (IsPathLike(arg))
    {
        // A path is always a file, even one named like a built-in.
        const std::string path = PathText(arg, "an illuminant");
        return jobs::CheckedIlluminant(ReadSpectraFile(path).front(), path, Warnings());
    }
    throw py::type_error(
        "an illuminant is a name or file (str), a file (os.PathLike) or a "
        "bandlight.Spectrum, not " +
        TypeName(arg));
}

std::vector<Light> ToLights(const py::handle& arg)
{
    std::vector<Light> lights;
    if (py::isinstance<py::str>(arg))
    {
        for (const std::string& name : jobs::SplitList(arg.cast<std::string>()))
        {
            lights.push_back(ToLight(py::str(name)));
        }
        return lights;
    }
    if (py::isinstance<NamedSpectrum>(arg) || IsPathLike(arg) || !py::isinstance<py::iterable>(arg))
    {
        throw py::type_error(
            "illuminants are a sequence of names, files or bandlight.Spectrum, "
            "or a comma-separated str, not " +
            TypeName(arg));
    }
    for (const py::handle item : arg)
    {
        lights.push_back(ToLight(item));
    }
    return lights;
}

bool IsSingleSpectrum(const py::handle& arg)
{
    return py::isinstance<NamedSpectrum>(arg);
}

std::vector<NamedSpectrum> ToReflectances(const py::handle& arg)
{
    if (py::isinstance<NamedSpectrum>(arg))
    {
        const NamedSpectrum& s = arg.cast<const NamedSpectrum&>();
        jobs::CheckRemittance(s, "remittance '" + OneLine(s.name, 80) + "'", Warnings());
        return {s};
    }
    if (py::isinstance<py::str>(arg))
    {
        // A name or a file: as a file name, it must hold no NUL byte.
        return jobs::ResolveReflectances(PathText(arg, "remittances"), Warnings());
    }
    if (IsPathLike(arg))
    {
        // A path is always a file, read and checked as ResolveReflectances
        // reads one.
        const std::string path = PathText(arg, "remittances");
        std::vector<NamedSpectrum> spectra = ReadSpectraFile(path);
        for (const NamedSpectrum& s : spectra)
        {
            jobs::CheckRemittance(s, path, Warnings());
        }
        return spectra;
    }
    if (!py::isinstance<py::iterable>(arg))
    {
        throw py::type_error(
            "remittances are a bandlight.Spectrum, a sequence of them, or a test "
            "colour name or file, not " +
            TypeName(arg));
    }
    std::vector<NamedSpectrum> out;
    for (const py::handle item : arg)
    {
        if (!py::isinstance<NamedSpectrum>(item))
        {
            throw py::type_error("a sequence of remittances holds bandlight.Spectrum, not " +
                                 TypeName(item));
        }
        const NamedSpectrum& s = item.cast<const NamedSpectrum&>();
        jobs::CheckRemittance(s, "remittance '" + OneLine(s.name, 80) + "'", Warnings());
        out.push_back(s);
    }
    if (out.empty())
    {
        throw Exception("no remittances given (an empty sequence)");
    }
    return out;
}

Observer ToObserver(const py::handle& arg)
{
    return ParseObserver(py::str(arg).cast<std::string>());
}

const char* const kPlatesDoc = R"doc(
plates: "balanced" (default: white-balanced to the working white, as every
ACES IDT delivers them; neutrals stay neutral) or "lit" (carrying src's
cast); adaptation: how they were balanced, "cat02" or "bradford"; camera:
the camera sensitivities file (rawtoaces JSON, CSV, CGATS) rootpoly-camera
needs, camera_idt: the light its one fixed IDT was fitted for
(docs/plates.md). The defaults are the command's.
)doc";

jobs::PlatesRequest PlatesArgs::options() const
{
    jobs::PlatesRequest o;
    o.plates = plates;
    o.adaptation = adaptation;
    o.idtLight = cameraIdt;
    if (!camera.is_none())
    {
        if (!py::isinstance<py::str>(camera) && !IsPathLike(camera))
        {
            throw py::type_error("camera is a file (str or os.PathLike) or None, not " +
                                 TypeName(camera));
        }
        o.camera = PathText(camera, "camera");
    }
    return o;
}

std::shared_ptr<const SpectralCamera> PlatesArgs::loadCamera() const
{
    const jobs::PlatesRequest o = options();
    if (o.camera.empty())
    {
        return nullptr;
    }
    return o.loadCamera();
}

MethodSpec ToMethod(const std::string& name, const py::handle& training, const PlatesArgs& plates)
{
    const jobs::PlatesRequest o = plates.options();
    o.parsed();  // a bad convention or adaptation is refused before anything is read
    MethodSpec method = o.apply(ParseMethod(name), plates.loadCamera(), Warnings());
    return training.is_none() ? method : jobs::WithTraining(method, ToReflectances(training));
}

BandSet ToBands(const py::handle& arg)
{
    if (arg.is_none())
    {
        return BandSet::Lecture();
    }
    if (py::isinstance<BandSet>(arg))
    {
        return arg.cast<BandSet>();
    }
    if (py::isinstance<py::str>(arg))
    {
        return BandSet::Parse(arg.cast<std::string>());
    }
    if (py::isinstance<py::sequence>(arg) || py::hasattr(arg, "__array__"))
    {
        return BandSet::FromEdges(
            CastTo<std::vector<double>>(arg, "bands", "a sequence of edges in nm"));
    }
    throw py::type_error(
        "bands are a BandSet, edges in nm (a sequence or \"400,500,600,700\") "
        "or None, not " +
        TypeName(arg));
}

MatchingSet ToMatchingSet(const std::string& text)
{
    if (text == "xyz")
    {
        return MatchingSet::XYZ;
    }
    if (text == "ebu_rgb" || text == "ebu-rgb" || text == "rgb")
    {
        return MatchingSet::EBU_RGB;
    }
    throw Exception("unknown matching-function set '" + OneLine(text, 80) + "' (xyz or ebu_rgb)");
}

int ToThreads(int threads)
{
    if (threads < 0 || threads > kMaxThreads)
    {
        throw ParameterError("{threads} must be 0 (all cores) to " + std::to_string(kMaxThreads) +
                             ", got " + std::to_string(threads));
    }
    return threads;
}

py::array_t<double> ToArray(const Vec3& v)
{
    py::array_t<double> a(3);
    for (int i = 0; i < 3; ++i)
    {
        a.mutable_at(i) = v[i];
    }
    return a;
}

py::array_t<double> ToArray(const Eigen::MatrixXd& m)
{
    py::array_t<double> a({py::ssize_t(m.rows()), py::ssize_t(m.cols())});
    auto w = a.mutable_unchecked<2>();
    for (Eigen::Index r = 0; r < m.rows(); ++r)
    {
        for (Eigen::Index c = 0; c < m.cols(); ++c)
        {
            w(r, c) = m(r, c);
        }
    }
    return a;
}

py::array_t<double> ToArray(const std::vector<double>& v)
{
    py::array_t<double> a(py::ssize_t(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

Mat3 ToMat3(const py::handle& arg, const std::string& what)
{
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arg);
    if (!a || a.ndim() != 2 || a.shape(0) != 3 || a.shape(1) != 3)
    {
        throw Exception(what + " must be a 3x3 matrix" +
                        (a ? ", got shape " + ShapeText(a) : std::string()));
    }
    Mat3 m;
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
        {
            m(r, c) = a.at(r, c);
        }
    }
    return m;
}

Vec3 ToVec3(const py::handle& arg, const std::string& what)
{
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arg);
    if (!a || a.ndim() != 1 || a.shape(0) != 3)
    {
        throw Exception(what + " must be 3 values" +
                        (a ? ", got shape " + ShapeText(a) : std::string()));
    }
    return Vec3(a.at(0), a.at(1), a.at(2));
}

Colours ToColours(const py::handle& arg, const std::string& what)
{
    Colours c;
    if (py::isinstance<py::str>(arg) || py::isinstance<py::bytes>(arg))
    {
        // numpy would take a string as an array of one string and fail inside.
        throw py::type_error(what + " must be colours, numbers of shape (..., 3), not a string ('" +
                             OneLine(py::str(arg), 40) +
                             "'); a light's CCT is bandlight.cri(light)[\"cct_K\"]");
    }
    c.data = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arg);
    if (!c.data)
    {
        PyErr_Clear();
        throw py::type_error(what + " must be an array of numbers, got " +
                             std::string(py::str(py::type::of(arg).attr("__name__"))));
    }
    if (c.data.ndim() < 1 || c.data.shape(c.data.ndim() - 1) != 3)
    {
        throw Exception(what + " must hold colours of 3 values in its last dimension, got shape " +
                        ShapeText(c.data));
    }
    c.shape.assign(c.data.shape(), c.data.shape() + c.data.ndim() - 1);
    c.count = size_t(c.data.size() / 3);
    return c;
}

std::pair<Colours, Colours> BroadcastColours(const py::handle& a, const py::handle& b,
                                             const std::string& whatA, const std::string& whatB)
{
    const Colours ca = ToColours(a, whatA);
    const Colours cb = ToColours(b, whatB);
    py::tuple both;
    try
    {
        both = py::module_::import("numpy").attr("broadcast_arrays")(ca.data, cb.data);
    }
    catch (const py::error_already_set&)
    {
        throw Exception(whatA + " and " + whatB + " do not broadcast together: shapes " +
                        ShapeText(ca.data) + " and " + ShapeText(cb.data));
    }
    return {ToColours(both[0], whatA), ToColours(both[1], whatB)};
}

py::array_t<double> NewArray(std::vector<py::ssize_t> shape, py::ssize_t trailing)
{
    if (trailing > 0)
    {
        shape.push_back(trailing);
    }
    return py::array_t<double>(shape);
}

py::object ScalarOrArray(py::array_t<double> a, const std::vector<py::ssize_t>& shape)
{
    if (shape.empty())
    {
        return py::float_(a.data()[0]);
    }
    return std::move(a);
}

std::string PathText(const py::handle& arg, const std::string& what)
{
    if (!py::isinstance<py::str>(arg) && !py::hasattr(arg, "__fspath__"))
    {
        throw py::type_error(what + " is a file (str or os.PathLike), not " + TypeName(arg));
    }
    const std::string path =
        py::str(py::module_::import("os").attr("fspath")(arg)).cast<std::string>();
    if (path.find('\0') != std::string::npos)
    {
        // The system would read the name only up to it: another file.
        throw Exception(what + " '" + OneLine(path, 200) +
                        "' holds a NUL byte, which no file name can");
    }
    return path;
}

py::dict FrameRunDict(size_t frames, size_t skipped, const std::vector<jobs::FrameFailure>& failed,
                      double seconds)
{
    py::dict d;
    d["frames"] = frames;
    d["skipped"] = skipped;
    py::list list;
    for (const jobs::FrameFailure& f : failed)
    {
        list.append(py::make_tuple(f.frame, f.error));
    }
    d["failed"] = list;
    d["seconds"] = seconds;
    return d;
}

}  // namespace bandlight::python
