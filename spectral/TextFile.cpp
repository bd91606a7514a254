// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/TextFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "spectral/Exception.h"

namespace bandlight
{

bool PathExists(const std::string& path)
{
    struct stat st
    {
    };
    return !path.empty() && ::stat(path.c_str(), &st) == 0;
}

void RequireRegularFile(const std::string& path, const std::string& what)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
    {
        throw Exception(PathInMessage(path) + ": not a regular file (a " + what +
                        " is a text file)");
    }
}

int InputFileError(const std::string& path)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) != 0)
    {
        return errno ? errno : EIO;
    }
    if (S_ISDIR(st.st_mode))
    {
        return EISDIR;
    }
    if (!S_ISREG(st.st_mode))
    {
        return 0;  // a device or a pipe is not opened here: opening one may wait or act
    }
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        return errno ? errno : EIO;
    }
    ::close(fd);
    return 0;
}

std::string ReadTextFile(const std::string& path, const std::string& what)
{
    // stat before open: a device or a pipe is refused without opening it.
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) != 0)
    {
        const int error = errno;
        throw FileError(path, error, "cannot open " + what);
    }
    if (S_ISDIR(st.st_mode))
    {
        throw FileError(path, EISDIR, "is a directory, not a " + what);
    }
    if (!S_ISREG(st.st_mode))
    {
        throw Exception(PathInMessage(path) + ": not a regular file (a " + what +
                        " is a text file)");
    }
    if (size_t(st.st_size) > MAX_TEXT_FILE_BYTES)
    {
        throw Exception(path + ": " + std::to_string(st.st_size) + " bytes is too large for a " +
                        what + " (limit " + std::to_string(MAX_TEXT_FILE_BYTES) + ")");
    }
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        const int error = errno;
        throw FileError(path, error, "cannot open " + what);
    }
    std::string text;
    text.reserve(size_t(st.st_size));
    char buffer[1 << 16];
    for (;;)
    {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
        {
            continue;
        }
        if (n < 0)
        {
            const int error = errno;
            ::close(fd);
            throw FileError(path, error, "read error");
        }
        if (n == 0)
        {
            break;
        }
        text.append(buffer, size_t(n));
    }
    ::close(fd);
    return text;
}

namespace
{

std::string HexByte(unsigned char c)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", unsigned(c));
    return buf;
}

}  // namespace

void CheckUtf8Text(std::string& text, const std::string& source)
{
    const auto* p = reinterpret_cast<const unsigned char*>(text.data());
    const size_t n = text.size();
    if ((n >= 2 && ((p[0] == 0xFF && p[1] == 0xFE) || (p[0] == 0xFE && p[1] == 0xFF))) ||
        (n >= 4 && p[0] == 0 && p[1] == 0 && p[2] == 0xFE && p[3] == 0xFF))
    {
        throw Exception(SourcePosition(source, 1) +
                        ": UTF-16/UTF-32 text (byte-order mark); save the file as UTF-8 or ASCII");
    }
    if (n >= 3 && p[0] == 0xEF && p[1] == 0xBB && p[2] == 0xBF)
    {
        text.erase(0, 3);
        p = reinterpret_cast<const unsigned char*>(text.data());
    }
    size_t line = 1;
    for (size_t i = 0; i < text.size();)
    {
        const unsigned char c = p[i];
        if (c == '\n')
        {
            ++line;
        }
        if (c == 0)
        {
            throw Exception(SourcePosition(source, line) +
                            ": NUL byte: binary data or UTF-16 text, not UTF-8");
        }
        if (c < 0x80)
        {
            ++i;
            continue;
        }
        // Lead byte: length and the smallest code point it may encode.
        size_t len = 0;
        unsigned cp = 0;
        unsigned minCp = 0;
        if (c >= 0xC2 && c <= 0xDF)
        {
            len = 2, cp = c & 0x1Fu, minCp = 0x80;
        }
        else if (c >= 0xE0 && c <= 0xEF)
        {
            len = 3, cp = c & 0x0Fu, minCp = 0x800;
        }
        else if (c >= 0xF0 && c <= 0xF4)
        {
            len = 4, cp = c & 0x07u, minCp = 0x10000;
        }
        bool ok = len != 0 && i + len <= text.size();
        for (size_t k = 1; ok && k < len; ++k)
        {
            ok = (p[i + k] & 0xC0u) == 0x80u;
            cp = (cp << 6) | (p[i + k] & 0x3Fu);
        }
        ok = ok && cp >= minCp && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF);
        if (!ok)
        {
            throw Exception(SourcePosition(source, line) + ": byte " + HexByte(c) +
                            " is not UTF-8 (Latin-1 or another legacy encoding?); save the file "
                            "as UTF-8");
        }
        i += len;
    }
}

std::string ToLower(std::string text)
{
    for (char& c : text)
    {
        if (c >= 'A' && c <= 'Z')
        {
            c = char(c - 'A' + 'a');
        }
    }
    return text;
}

std::vector<ListLine> ListLines(const std::string& text)
{
    std::vector<ListLine> items;
    size_t number = 0;
    size_t start = 0;
    while (start < text.size())
    {
        size_t end = text.find_first_of("\r\n", start);
        end = end == std::string::npos ? text.size() : end;
        std::string line = text.substr(start, end - start);
        // CRLF is one line end; CR alone (old Mac editors) and LF are one each.
        start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
        ++number;
        for (size_t hash = line.find('#'); hash != std::string::npos;
             hash = line.find('#', hash + 1))
        {
            if (hash == 0 || line[hash - 1] == ' ' || line[hash - 1] == '\t')
            {
                line.erase(hash);  // a comment, to the end of the line
                break;
            }
        }
        const size_t first = line.find_first_not_of(" \t");
        if (first != std::string::npos)
        {
            const size_t last = line.find_last_not_of(" \t");
            items.push_back({number, line.substr(first, last - first + 1)});
        }
    }
    return items;
}

}  // namespace bandlight
