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
