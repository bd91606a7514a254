// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <stdexcept>
#include <string>

namespace bandlight
{

/// The one exception type bandlight throws at API and file boundaries.
/// Messages name what was wrong and, for files, the file, line and value.
class Exception : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

/// How a face of bandlight spells a parameter in messages: the C++ API by
/// its name (`camera`), the command as a flag (`--camera`), Python as a
/// keyword (`camera=`).
enum class Face
{
    CPP,
    COMMAND,
    PYTHON,
};

/// An Exception about a file that could not be opened, read, created,
/// renamed or written: it carries the path and the errno that says why (0
/// when the system gave none). Content that was read and refused (a
/// malformed spectrum, a config OpenColorIO cannot parse) is an Exception,
/// never a FileError. Python raises it as the OSError subclass of its errno
/// (FileNotFoundError, PermissionError, ...).
class FileError : public Exception
{
public:
    /// The message is "PATH: what", the path as PathInMessage() writes it.
    FileError(const std::string& path, int error, const std::string& what);

    /// A FileError with a message already made (passed on from elsewhere,
    /// as the image module reports its errors).
    static FileError WithMessage(const std::string& path, int error, const std::string& message);

    /// A FileError whose message names a parameter of the request, in a
    /// template as ParameterError takes it ("{out} '/x' is a folder, not a
    /// file"): what() spells it as the C++ API does, spelled() as a face does.
    static FileError ForParameter(const std::string& path, int error,
                                  const std::string& messageTemplate);

    /// The file, as given (may be empty).
    const std::string& path() const noexcept { return m_path; }
    /// errno: ENOENT, EACCES, EISDIR, ...; 0 when the system gave none.
    int error() const noexcept { return m_error; }
    /// The message with its parameters spelled as `face` spells them (the
    /// message itself when it names none).
    std::string spelled(Face face) const;

private:
    struct Whole
    {
    };
    FileError(Whole, const std::string& message, const std::string& path, int error);

    std::string m_path;
    int m_error;
    std::string m_template;  ///< empty: the message names no parameter
};

/// A path as messages name it: the path itself, or "'' (an empty path)",
/// so that an empty name does not leave a message starting with ": ".
std::string PathInMessage(const std::string& path);

/// An Exception about parameters of a request. The message is a template in
/// which `{name}` names a parameter (`{working_space}`: "--working-space" to
/// the command, "working_space" to Python) and `{name=}` gives it a value
/// (`{camera=}FILE`: "--camera FILE", "camera=FILE"); what() spells them as
/// the C++ API does and spelled() as a face does, so library messages name
/// the parameter, never a command-line flag.
class ParameterError : public Exception
{
public:
    explicit ParameterError(const std::string& messageTemplate);
    /// The message with its parameters spelled as `face` spells them.
    std::string spelled(Face face) const;

private:
    std::string m_template;
};

/// `messageTemplate` with its `{name}` parameters spelled as `face` spells them.
std::string SpellParameters(const std::string& messageTemplate, Face face);

/// `text` with line breaks and other control characters written as escapes
/// ("\\n", "\\x01"), so that a value quoted from a file keeps a message on one line.
std::string OneLine(const std::string& text);

/// OneLine(text), cut to at most `maxBytes` bytes of the original with
/// "...(N more bytes)" after it: for echoing user input (names, patterns,
/// arguments) that may be of any length.
std::string OneLine(const std::string& text, size_t maxBytes);

/// Formats "FILE:LINE: what" (LINE omitted when 0), the prefix every parse error uses.
std::string SourcePosition(const std::string& source, size_t line);

}  // namespace bandlight
