// SPDX-License-Identifier: BSD-3-Clause
// cli/Common.cpp, compiled into the module, reads and refuses input as the
// command does; the notes it makes (cli/Diagnostics.h) become Python
// warnings here instead of lines on stderr. This file takes the place of
// cli/Diagnostics.cpp, whose stderr capture belongs to the command's main().
#include "PyBandlight.h"
#include "cli/Diagnostics.h"

namespace bandlight::cli
{

void Note(const std::string& line)
{
    python::Warn(line);
}

void Progress(const std::string&)
{
    // The module reports progress through the callbacks its functions take.
}

}  // namespace bandlight::cli
