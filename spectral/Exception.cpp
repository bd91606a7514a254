// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Exception.h"

namespace bandlight
{

std::string SourcePosition(const std::string& source, size_t line)
{
    return line ? source + ":" + std::to_string(line) : source;
}

}  // namespace bandlight
