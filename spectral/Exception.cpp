// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Exception.h"

#include <cstdio>

namespace bandlight
{

std::string SourcePosition(const std::string& source, size_t line)
{
    return line ? source + ":" + std::to_string(line) : source;
}

std::string OneLine(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (const char c : text)
    {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n')
        {
            out += "\\n";
        }
        else if (c == '\r')
        {
            out += "\\r";
        }
        else if (c == '\t')
        {
            out += "\\t";
        }
        else if (u < 0x20 || u == 0x7F)
        {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(u));
            out += buf;
        }
        else
        {
            out += c;
        }
    }
    return out;
}

std::string OneLine(const std::string& text, size_t maxBytes)
{
    if (text.size() <= maxBytes)
    {
        return OneLine(text);
    }
    size_t cut = maxBytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
    {
        --cut;  // do not split a UTF-8 sequence
    }
    return OneLine(text.substr(0, cut)) + "...(" + std::to_string(text.size() - cut) +
           " more bytes)";
}

}  // namespace bandlight
