// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Exception.h"

#include <cstdio>

namespace bandlight
{

std::string PathInMessage(const std::string& path)
{
    return path.empty() ? "'' (an empty path)" : path;
}

FileError::FileError(const std::string& path, int error, const std::string& what)
    : FileError(Whole{}, PathInMessage(path) + ": " + what, path, error)
{
}

FileError::FileError(Whole, const std::string& message, const std::string& path, int error)
    : Exception(message), m_path(path), m_error(error)
{
}

FileError FileError::WithMessage(const std::string& path, int error, const std::string& message)
{
    return FileError(Whole{}, message, path, error);
}

FileError FileError::ForParameter(const std::string& path, int error,
                                  const std::string& messageTemplate)
{
    FileError e(Whole{}, SpellParameters(messageTemplate, Face::CPP), path, error);
    e.m_template = messageTemplate;
    return e;
}

std::string FileError::spelled(Face face) const
{
    return m_template.empty() ? std::string(what()) : SpellParameters(m_template, face);
}

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

namespace bandlight
{

std::string SpellParameters(const std::string& messageTemplate, Face face)
{
    std::string out;
    out.reserve(messageTemplate.size() + 16);
    const size_t n = messageTemplate.size();
    for (size_t i = 0; i < n; ++i)
    {
        const char c = messageTemplate[i];
        size_t end = i + 1;
        while (c == '{' && end < n &&
               ((messageTemplate[end] >= 'a' && messageTemplate[end] <= 'z') ||
                messageTemplate[end] == '_'))
        {
            ++end;
        }
        const bool given = end < n && end > i + 1 && messageTemplate[end] == '=';
        const size_t close = given ? end + 1 : end;
        if (c != '{' || end == i + 1 || close >= n || messageTemplate[close] != '}')
        {
            out += c;
            continue;
        }
        std::string name = messageTemplate.substr(i + 1, end - i - 1);
        i = close;
        switch (face)
        {
            case Face::CPP:
                out += given ? name + " = " : name;
                break;
            case Face::COMMAND:
                // The command calls the two lights --from and --to.
                name = name == "src" ? "from" : name == "dst" ? "to" : name;
                for (char& ch : name)
                {
                    ch = ch == '_' ? '-' : ch;
                }
                out += "--" + name + (given ? " " : "");
                break;
            case Face::PYTHON:
                // A command's --no-X flag is Python's X=False.
                if (name.rfind("no_", 0) == 0)
                {
                    out += name.substr(3) + "=False";
                    break;
                }
                out += given ? name + "=" : name;
                break;
        }
    }
    return out;
}

ParameterError::ParameterError(const std::string& messageTemplate)
    : Exception(SpellParameters(messageTemplate, Face::CPP)), m_template(messageTemplate)
{
}

std::string ParameterError::spelled(Face face) const
{
    return SpellParameters(m_template, face);
}

}  // namespace bandlight
