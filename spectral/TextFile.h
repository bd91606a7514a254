// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace bandlight
{

/// The largest text file the readers accept (spectra and scenes are small;
/// this stops a mistaken path to a device or a huge file early).
constexpr size_t MAX_TEXT_FILE_BYTES = size_t(64) << 20;

/// Reads a whole text file. Throws FileError "PATH: ..." when the path
/// cannot be opened or read (with its errno; a directory is EISDIR), and
/// Exception when it is not a regular file (a device, a pipe) or is larger
/// than MAX_TEXT_FILE_BYTES. `what` names the kind of file in the message
/// ("spectrum file").
std::string ReadTextFile(const std::string& path, const std::string& what);

/// Whether anything is at `path` (a file, a folder, a pipe), asked without
/// opening it: opening a pipe waits for a writer. Readers then refuse what is
/// not a regular file (ReadTextFile, InputFileError) before they open it.
bool PathExists(const std::string& path);

/// Throws Exception "PATH: not a regular file (a WHAT is a text file)" when
/// something that is not a regular file or a folder is at `path` (a pipe,
/// a device), asked without opening it: for files another library opens
/// (OpenColorIO's configs), which would wait on a pipe for ever.
void RequireRegularFile(const std::string& path, const std::string& what);

/// 0 when `path` is a regular file that opens for reading (or a device or
/// pipe, which is not opened), else the errno that says why not: ENOENT,
/// EACCES, ENOTDIR, EISDIR for a directory. For files that another library
/// opens (OpenImageIO, OpenColorIO), whose errors do not say why.
int InputFileError(const std::string& path);

/// One line of a list file: its text, trimmed, and its number (from 1).
struct ListLine
{
    size_t number = 0;
    std::string text;
};

/// The items of a list file, one per line: lines ended by LF, CRLF or CR
/// alone; a comment (a '#' that starts a line or follows a space or tab, to
/// the end of the line) removed; spaces and tabs around an item trimmed;
/// blank lines skipped. Each keeps its line's number for messages.
std::vector<ListLine> ListLines(const std::string& text);

/// `text` with its ASCII letters in lower case (names compared without
/// regard to case; other bytes, UTF-8 included, unchanged).
std::string ToLower(std::string text);

/// Checks that `text` is UTF-8 (ASCII included) and removes a leading UTF-8
/// byte-order mark. UTF-16/UTF-32 (byte-order mark or NUL bytes) and byte
/// sequences that are not UTF-8 are an Exception "SOURCE:LINE: ...", naming
/// the offending byte.
void CheckUtf8Text(std::string& text, const std::string& source);

}  // namespace bandlight
