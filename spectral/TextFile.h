// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace bandlight
{

/// The largest text file the readers accept (spectra and scenes are small;
/// this stops a mistaken path to a device or a huge file early).
constexpr size_t MAX_TEXT_FILE_BYTES = size_t(64) << 20;

/// Reads a whole text file. Throws Exception "PATH: ..." when the path cannot
/// be opened, is not a regular file or is larger than MAX_TEXT_FILE_BYTES.
/// `what` names the kind of file in the message ("spectrum file").
std::string ReadTextFile(const std::string& path, const std::string& what);

/// Checks that `text` is UTF-8 (ASCII included) and removes a leading UTF-8
/// byte-order mark. UTF-16/UTF-32 (byte-order mark or NUL bytes) and byte
/// sequences that are not UTF-8 are an Exception "SOURCE:LINE: ...", naming
/// the offending byte.
void CheckUtf8Text(std::string& text, const std::string& source);

}  // namespace bandlight
