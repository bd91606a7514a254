// SPDX-License-Identifier: BSD-3-Clause
// The module init, and how C++ errors become Python exceptions.
#include "PyBandlight.h"
#include "requests/Defaults.h"

#include <cerrno>

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight::python
{

namespace
{
/// bandlight.NoteWarning, created once at import (never released: the
/// interpreter owns it through the module).
PyObject* g_noteWarning = nullptr;

/// The classes a FileError is raised as: for each OSError subclass an errno
/// implies, a subclass of it whose str() is the library's message alone (an
/// OSError with `filename` set would print "[Errno 2] message: 'path'").
/// Created once at import, kept by the module under these private names (so
/// that pickle finds them by name).
struct FileErrorClass
{
    PyObject* base;
    const char* name;
    PyObject* type;
};
FileErrorClass g_fileErrors[] = {
    {PyExc_FileNotFoundError, "_FileNotFoundError", nullptr},
    {PyExc_PermissionError, "_PermissionError", nullptr},
    {PyExc_IsADirectoryError, "_IsADirectoryError", nullptr},
    {PyExc_NotADirectoryError, "_NotADirectoryError", nullptr},
    {PyExc_FileExistsError, "_FileExistsError", nullptr},
    {PyExc_OSError, "_OSError", nullptr},
};

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

/// str() of the exceptions a FileError is raised as: the message, which
/// they hold as strerror.
py::object MessageOnly(py::handle self)
{
    py::object message = self.attr("strerror");
    if (py::isinstance<py::str>(message))
    {
        return message;
    }
    return py::handle(PyExc_OSError).attr("__str__")(self);  // made another way
}

/// Raises the OSError subclass of `error` (see g_fileErrors) with errno
/// (None when 0), the message as strerror and str(), and `filename` the
/// path (None when not known).
void RaiseFileError(int error, const std::string& message, const std::string* path)
{
    PyObject* base = OsErrorType(error);
    PyObject* type = base;
    for (const FileErrorClass& c : g_fileErrors)
    {
        type = c.base == base && c.type ? c.type : type;
    }
    const py::object code = error != 0 ? py::object(py::int_(error)) : py::object(py::none());
    // A message quoting bytes that are not UTF-8 keeps the rest; a path is
    // decoded as os.fsdecode() decodes file names.
    const py::object text = py::reinterpret_steal<py::object>(
        PyUnicode_DecodeUTF8(message.data(), py::ssize_t(message.size()), "replace"));
    const py::object filename =
        path ? py::reinterpret_steal<py::object>(PyUnicode_DecodeFSDefault(path->c_str()))
             : py::object(py::none());
    if (!text || !filename)
    {
        return;  // the decoding set its own error
    }
    const py::object exc = py::reinterpret_steal<py::object>(
        PyObject_CallFunctionObjArgs(type, code.ptr(), text.ptr(), filename.ptr(), nullptr));
    if (!exc)
    {
        return;  // the call set its own error
    }
    PyErr_SetObject(type, exc.ptr());
}

/// The message as `bandlight` prints it (main.cpp): one line, bounded.
std::string Message(const char* what)
{
    return OneLine(what, 4000);
}
}  // namespace

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

    // The classes a FileError is raised as, named in this extension module
    // (called before the module takes the package's name).
    const std::string moduleName = py::str(m.attr("__name__"));
    for (FileErrorClass& c : g_fileErrors)
    {
        const std::string name = moduleName + "." + c.name;
        const std::string doc =
            std::string("A ") + py::str(py::handle(c.base).attr("__name__")).cast<std::string>() +
            " about a file bandlight could not open, read, create or write: str() is the\n"
            "library's message (the line ``bandlight`` prints), filename the file.";
        c.type = PyErr_NewExceptionWithDoc(name.c_str(), doc.c_str(), c.base, nullptr);
        if (!c.type)
        {
            throw py::error_already_set();
        }
        const py::handle cls(c.type);
        cls.attr("__str__") =
            py::cpp_function(&MessageOnly, py::name("__str__"), py::is_method(cls));
        m.attr(c.name) = cls;
    }

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
                RaiseFileError(e.error(), Message(e.spelled(Face::PYTHON).c_str()), &e.path());
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
                // A file a config refers to (a LUT), named in the message only.
                RaiseFileError(ENOENT, Message(e.what()), nullptr);
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
        "line) or the OSError subclass of the system's reason (FileNotFoundError,\n"
        "PermissionError, IsADirectoryError, ...; files that cannot be opened, read or\n"
        "written, with errno and filename set), with the message the ``bandlight`` command\n"
        "prints.";
    m.attr("__version__") = bandlight::defaults::VERSION;

    // The error classes live in this extension (pickle finds them there).
    AddErrors(m);
    // Classes and functions say they live in `bandlight` (the package that
    // re-exports them), not in this extension's own name.
    const py::object ownName = m.attr("__name__");
    m.attr("__name__") = "bandlight";
    AddSpectrum(m);
    AddColorimetry(m);
    AddBands(m);
    AddTransforms(m);
    AddConfig(m);
    AddAccuracy(m);
    AddIdt(m);
    AddRender(m);
    AddApply(m);
    AddSpectralImage(m);
    AddLightGroups(m);
    m.attr("__name__") = ownName;
}
