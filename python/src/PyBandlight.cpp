// SPDX-License-Identifier: BSD-3-Clause
// The module init, and how C++ errors become Python exceptions.
#include "PyBandlight.h"
#include "bandlight/jobs/Defaults.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight::python
{

namespace
{
/// bandlight.NoteWarning, created once at import (never released: the
/// interpreter owns it through the module).
PyObject* g_noteWarning = nullptr;

/// The OSError subclass Python itself would raise for `error`.
PyObject* OsErrorType(int error)
{
    switch (error)
    {
        case ENOENT:
            return PyExc_FileNotFoundError;
        case EACCES:
        case EPERM:
            return PyExc_PermissionError;
        case EISDIR:
            return PyExc_IsADirectoryError;
        case ENOTDIR:
            return PyExc_NotADirectoryError;
        case EEXIST:
            return PyExc_FileExistsError;
        default:
            return PyExc_OSError;
    }
}

/// Raises `type(message)` with `errno` set: str(exc) is the message alone,
/// exactly the line `bandlight` prints after "bandlight: ".
void RaiseOsError(int error, const std::string& message)
{
    PyObject* type = OsErrorType(error);
    py::object exc =
        py::reinterpret_steal<py::object>(PyObject_CallFunction(type, "s", message.c_str()));
    if (!exc)
    {
        return;  // the call set its own error
    }
    if (error != 0)
    {
        exc.attr("errno") = error;
    }
    PyErr_SetObject(type, exc.ptr());
}

/// The message as `bandlight` prints it (main.cpp): one line, bounded.
std::string Message(const char* what)
{
    return OneLine(what, 4000);
}
}  // namespace

int InputFileProblem(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        return errno ? errno : EIO;
    }
    struct stat st
    {
    };
    const int error = ::fstat(fd, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : 0;
    ::close(fd);
    return error;
}

int OutputFileProblem(const std::string& path, bool folder)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target(path);
    if (fs::is_directory(target, ec))
    {
        // An existing folder: a package folder is filled, a file cannot be one.
        return !folder ? EISDIR : ::access(path.c_str(), W_OK | X_OK) == 0 ? 0 : errno;
    }
    // A package folder is created with its parents; a file's folder must exist.
    fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (folder)
    {
        while (!dir.empty() && !fs::exists(dir, ec))
        {
            dir = dir.parent_path();
        }
        dir = dir.empty() ? fs::path(".") : dir;
    }
    if (!fs::exists(dir, ec))
    {
        return ENOENT;
    }
    if (!fs::is_directory(dir, ec))
    {
        return ENOTDIR;
    }
    return ::access(dir.c_str(), W_OK | X_OK) == 0 ? 0 : errno;
}

bool IsOutputFailure(const std::string& message)
{
    for (const char* phrase :
         {": cannot create output file (", ": write failed", ": cannot replace output file (",
          ": the output was not written", ": cannot create the directory ("})
    {
        if (message.find(phrase) != std::string::npos)
        {
            return true;
        }
    }
    return false;
}

void Warn(const std::string& note)
{
    py::gil_scoped_acquire gil;
    if (PyErr_WarnEx(g_noteWarning ? g_noteWarning : PyExc_UserWarning, OneLine(note).c_str(), 1) !=
        0)
    {
        throw py::error_already_set();  // warnings configured as errors
    }
}

PythonReporter::PythonReporter(py::object callback) : m_callback(std::move(callback)) {}

void PythonReporter::note(const std::string& line)
{
    Warn(SpellParameters(line, Face::PYTHON));
}

void PythonReporter::progress(const std::string&, double fraction)
{
    if (fraction < 0.0)
    {
        return;
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    py::gil_scoped_acquire gil;
    if (m_callback.is_none() || m_error)
    {
        return;
    }
    try
    {
        m_callback(fraction);
    }
    catch (py::error_already_set& e)
    {
        m_error = std::move(e);
    }
}

void PythonReporter::raiseIfFailed()
{
    if (m_error)
    {
        py::error_already_set e = std::move(*m_error);
        m_error.reset();
        throw std::move(e);
    }
}

jobs::Reporter& Warnings()
{
    static PythonReporter* warnings = new PythonReporter();  // never destroyed: holds py::none
    return *warnings;
}

void AddErrors(py::module_& m)
{
    g_noteWarning = PyErr_NewExceptionWithDoc(
        "bandlight.NoteWarning",
        "What the ``bandlight`` command prints as ``note: ...``: an assumption made about the\n"
        "input (a spectrum that stops short of 380-780 nm, a remittance outside [0, 1]).\n"
        "Silence or escalate it with the warnings module.",
        PyExc_UserWarning, nullptr);
    if (!g_noteWarning)
    {
        throw py::error_already_set();
    }
    m.attr("NoteWarning") = py::handle(g_noteWarning);

    // A local translator: it applies to this module's functions only, so
    // PyOpenColorIO's own translation of OCIO::Exception (the two modules
    // share pybind11's internals) is left as it is.
    py::register_local_exception_translator(
        [](std::exception_ptr p)
        {
            try
            {
                if (p)
                {
                    std::rethrow_exception(p);
                }
            }
            catch (const FileError& e)
            {
                RaiseOsError(e.error(), Message(e.what()));
            }
            catch (const ParameterError& e)
            {
                // The library names its parameters; Python spells them as keywords.
                PyErr_SetString(PyExc_ValueError, Message(e.spelled(Face::PYTHON).c_str()).c_str());
            }
            catch (const Exception& e)
            {
                PyErr_SetString(PyExc_ValueError, Message(e.what()).c_str());
            }
            catch (const OCIO_NAMESPACE::ExceptionMissingFile& e)
            {
                RaiseOsError(ENOENT, Message(e.what()));
            }
            catch (const OCIO_NAMESPACE::Exception& e)
            {
                // `bandlight` reports these as bad input too (exit code 2).
                PyErr_SetString(PyExc_ValueError, Message(e.what()).c_str());
            }
        });
}

}  // namespace bandlight::python

PYBIND11_MODULE(_bandlight, m)
{
    namespace py = pybind11;
    using namespace bandlight::python;
    // PyOpenColorIO's types must be registered before any function returns
    // one: the two modules share pybind11's type registry, so an
    // OCIO::GroupTransformRcPtr returned here is a PyOpenColorIO.GroupTransform.
    py::module_::import("PyOpenColorIO");
    py::module_::import("numpy");

    m.doc() =
        "bandlight: the 3-band model of coloured light and surfaces as OpenColorIO transforms,\n"
        "measured against an exact spectral core.\n\n"
        "Transforms are PyOpenColorIO objects, spectra and colours numpy arrays. Errors are\n"
        "ValueError (bad names and values, malformed files: the message names the file and\n"
        "line) or OSError (files that cannot be read or written), with the message the\n"
        "``bandlight`` command prints.";
    m.attr("__version__") = bandlight::defaults::VERSION;

    // Classes and functions say they live in `bandlight` (the package that
    // re-exports them), not in this extension's own name.
    const py::object ownName = m.attr("__name__");
    m.attr("__name__") = "bandlight";
    AddErrors(m);
    AddSpectrum(m);
    AddColorimetry(m);
    AddBands(m);
    AddTransforms(m);
    AddConfig(m);
    AddAccuracy(m);
    AddRender(m);
    AddApply(m);
    AddSpectralImage(m);
    m.attr("__name__") = ownName;
}
