// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The Python module's shared pieces: one Add<Area>() per Py<Area>.cpp (as
// PyOpenColorIO's bindings are organised), converters from Python values to
// the jobs' requests (jobs/: the same library the command calls), numpy
// helpers, the reporter that makes Python warnings of the jobs' notes, the
// exceptions' translation, and the file-path argument type.

#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "farm/Frames.h"
#include "requests/Inputs.h"
#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/SpectrumIO.h"
#include "transforms/BandModel.h"
#include "transforms/BandSet.h"
#include "transforms/IlluminantChange.h"

namespace bandlight::python
{
namespace py = pybind11;

/// A file argument: a str or an os.PathLike, as PathText() reads it (so a
/// NUL byte in it is a ValueError). Functions take it as `const Path&` or
/// `std::optional<Path>` (None).
struct Path
{
    std::string text;
    const std::string& string() const noexcept { return text; }
};

// ---------------------------------------------------------------------------
// One registration per area (PyOpenColorIO's layout: one Py<Area>.cpp each).
void AddErrors(py::module_& m);
void AddSpectrum(py::module_& m);
void AddColorimetry(py::module_& m);
void AddBands(py::module_& m);
void AddTransforms(py::module_& m);
void AddConfig(py::module_& m);
void AddAccuracy(py::module_& m);
void AddIdt(py::module_& m);
void AddRender(py::module_& m);
void AddApply(py::module_& m);
void AddSpectralImage(py::module_& m);
void AddLightGroups(py::module_& m);

// ---------------------------------------------------------------------------
// Errors (PyBandlight.cpp). AddErrors registers how the library's exceptions
// become Python's, by their C++ type (as PyOpenColorIO registers
// ExceptionMissingFile): FileError is the OSError subclass of its errno
// (FileNotFoundError, PermissionError, IsADirectoryError, NotADirectoryError,
// FileExistsError, else OSError) with `errno` and `filename` set;
// ParameterError and every other Exception are ValueError. str() of each is
// the library's message, the line `bandlight` prints after "bandlight: ".

/// Issues a bandlight.NoteWarning (what `bandlight` prints as "note: ...").
void Warn(const std::string& note);

/// The jobs' reporter for Python: each note a bandlight.NoteWarning (taking
/// the GIL, so jobs may note from threads that released it), and progress
/// fractions passed to `callback` (None: none). The first exception the
/// callback raises stops further calls; raise() raises it after the job.
class PythonReporter : public jobs::Reporter
{
public:
    explicit PythonReporter(py::object callback = py::none());
    void note(const std::string& line) override;
    void progress(const std::string& line, double fraction) override;
    /// Raises what the callback raised, if anything (call with the GIL held).
    void raiseIfFailed();

private:
    py::object m_callback;
    std::mutex m_mutex;
    std::optional<py::error_already_set> m_error;
};

/// A PythonReporter without a callback, for the converters' notes.
jobs::Reporter& Warnings();

// ---------------------------------------------------------------------------
// Arguments (PyArgs.cpp). Strings are read as the command reads its options.

/// A light: a str is a built-in illuminant name or a spectrum file, as
/// `--illuminant`, `--from` and `--to` take it (the file's first spectrum);
/// an os.PathLike is a spectrum file; a Spectrum is used as given. Either
/// is checked and scaled by UsableIlluminant.
Light ToLight(const py::handle& arg);

/// Lights: a sequence of lights, or a comma-separated str as `--illuminants`.
std::vector<Light> ToLights(const py::handle& arg);

/// Remittances: a str is a test colour (TCS01–TCS15, TCS for all) or a file
/// as `--reflectance` takes it; an os.PathLike a file; a Spectrum or a
/// sequence of them as given (magnitude-checked like a file's).
std::vector<NamedSpectrum> ToReflectances(const py::handle& arg);

/// True when `arg` names one remittance (a Spectrum), not a set of them.
bool IsSingleSpectrum(const py::handle& arg);

/// "1931"/"1964" (or 1931, 1964, 2, 10).
Observer ToObserver(const py::handle& arg);

/// plates=, adaptation=, camera=, camera_idt=: what the images are and the
/// camera that shot them, as the command's --plates, --adaptation,
/// --camera, --camera-idt (default: white-balanced by CAT02, no camera).
struct PlatesArgs
{
    std::string plates = "balanced";
    std::string adaptation = "cat02";
    py::object camera = py::none();  ///< None, a file (str or os.PathLike)
    std::string cameraIdt = "D55";

    /// The request's plates for these arguments (the camera file's path).
    jobs::PlatesRequest options() const;
    /// The camera read (nullptr for None); unreadable files raise OSError.
    std::shared_ptr<const SpectralCamera> loadCamera() const;
};

/// The docstring paragraph of the plates keywords.
extern const char* const kPlatesDoc;

/// A method by name, with fit3x3's / rootpoly's training remittances
/// (None: their defaults) and the plates it is for.
MethodSpec ToMethod(const std::string& name, const py::handle& training, const PlatesArgs& plates);

/// The bands argument: None is the band model's VB/VG/VR; a BandSet, a str of
/// edges ("400,500,600,700", parsed as --bands is) or a sequence of edges.
BandSet ToBands(const py::handle& arg);

/// "xyz" or "ebu_rgb" (also "ebu-rgb", "rgb").
MatchingSet ToMatchingSet(const std::string& text);

/// A file argument (str or os.PathLike) as text; TypeError naming `what`
/// otherwise. A NUL byte is an Exception (ValueError): the system would
/// read the name only up to it and use another file. Every file name Python
/// hands the library passes here.
std::string PathText(const py::handle& arg, const std::string& what);

/// A frame set's summary: {"frames", "skipped", "failed": [(frame, error)],
/// "seconds"}.
py::dict FrameRunDict(size_t frames, size_t skipped, const std::vector<jobs::FrameFailure>& failed,
                      double seconds);

/// The thread count argument: 0 (all cores) to 256.
int ToThreads(int threads);

/// `arg` as a T, or a TypeError saying that `what` must be `expected`.
template <typename T>
T CastTo(const py::handle& arg, const std::string& what, const std::string& expected)
{
    try
    {
        return arg.cast<T>();
    }
    catch (const py::cast_error&)
    {
        throw py::type_error(
            what + " must be " + expected + ", not " +
            py::str(py::type::handle_of(arg).attr("__name__")).cast<std::string>());
    }
}

// ---------------------------------------------------------------------------
// numpy (PyArgs.cpp).

py::array_t<double> ToArray(const Vec3& v);
py::array_t<double> ToArray(const Eigen::MatrixXd& m);
py::array_t<double> ToArray(const std::vector<double>& v);
/// A (3, 3) array_like as a matrix; throws Exception naming `what` otherwise.
Mat3 ToMat3(const py::handle& arg, const std::string& what);
/// A (3,) array_like; throws Exception naming `what` otherwise.
Vec3 ToVec3(const py::handle& arg, const std::string& what);

/// An array_like of colours (..., 3) as a C-contiguous float64 array, and
/// the shape of its colours (the leading dimensions).
struct Colours
{
    py::array_t<double, py::array::c_style> data;
    std::vector<py::ssize_t> shape;  ///< without the trailing 3
    size_t count = 0;
    const double* at(size_t i) const { return data.data() + 3 * i; }
};
Colours ToColours(const py::handle& arg, const std::string& what);

/// numpy.broadcast_arrays of two colour arrays (..., 3), each as Colours of
/// the common shape.
std::pair<Colours, Colours> BroadcastColours(const py::handle& a, const py::handle& b,
                                             const std::string& whatA, const std::string& whatB);

/// An empty array of `shape` + `trailing` (trailing 0: none), float64.
py::array_t<double> NewArray(std::vector<py::ssize_t> shape, py::ssize_t trailing);

/// A float result for a single colour (shape ()), else the array.
py::object ScalarOrArray(py::array_t<double> a, const std::vector<py::ssize_t>& shape);

}  // namespace bandlight::python

namespace pybind11::detail
{
/// bandlight::python::Path from a str or an os.PathLike (named os.PathLike
/// in signatures, as pybind11 names std::filesystem::path).
template <>
struct type_caster<bandlight::python::Path>
{
    PYBIND11_TYPE_CASTER(bandlight::python::Path, const_name("os.PathLike"));

    bool load(handle src, bool)
    {
        if (!isinstance<str>(src) && !hasattr(src, "__fspath__"))
        {
            return false;
        }
        value.text = bandlight::python::PathText(src, "a path");
        return true;
    }

    static handle cast(const bandlight::python::Path& path, return_value_policy, handle)
    {
        return str(path.text).release();
    }
};
}  // namespace pybind11::detail
