// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace bandlight::detail
{

/// One data file compiled into the binary (see cmake/EmbedData.cmake and
/// data/): its path relative to data/ and its full text.
struct EmbeddedFile
{
    const char* path;
    const char* text;
};

/// Every embedded data file, in the order CMake listed them.
const std::vector<EmbeddedFile>& EmbeddedFiles();

/// The text of one embedded file; throws Exception if there is none.
std::string EmbeddedText(const std::string& path);

}  // namespace bandlight::detail
