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

/// Formats "FILE:LINE: what" (LINE omitted when 0), the prefix every parse error uses.
std::string SourcePosition(const std::string& source, size_t line);

}  // namespace bandlight
