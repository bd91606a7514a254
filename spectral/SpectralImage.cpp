// SPDX-License-Identifier: BSD-3-Clause
// Spectral channels: the tables of spectral kinds and samplings, the
// parsing and writing of Fichet 2021 channel names ("S0.550,000000nm"),
// and the reading of a CSV that gives channels their wavelengths. The
// layout of a whole image is found in spectral/SpectralLayout.cpp, its XYZ
// weights in spectral/SpectralWeights.cpp.
#include "spectral/SpectralImage.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "spectral/Exception.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"
#include "spectral/detail/SpectralImageParsing.h"

namespace bandlight
{

const std::vector<SpectralKindEntry>& SpectralKinds()
{
    static const std::vector<SpectralKindEntry> table = {
        {SpectralKind::EMISSIVE, "emissive"},
        {SpectralKind::REFLECTIVE, "reflective"},
    };
    return table;
}

const std::vector<SpectralSamplingEntry>& SpectralSamplings()
{
    static const std::vector<SpectralSamplingEntry> table = {
        {SpectralSampling::POINTS, "points", "values at the wavelengths"},
        {SpectralSampling::BUCKETS, "buckets", "means over each channel's interval"},
    };
    return table;
}

namespace detail
{

std::string In(const std::string& file)
{
    return file.empty() ? std::string() : file + ": ";
}

}  // namespace detail

namespace
{

using detail::In;

/// SI prefixes as Fichet 2021 allows them, with µ (U+00B5 and U+03BC) for
/// u, as powers of ten.
bool PrefixExponent(const std::string& p, int& exponent)
{
    static const std::pair<const char*, int> kPrefixes[] = {
        {"", 0},   {"Y", 24},        {"Z", 21},        {"E", 18}, {"P", 15},  {"T", 12},  {"G", 9},
        {"M", 6},  {"k", 3},         {"h", 2},         {"da", 1}, {"d", -1},  {"c", -2},  {"m", -3},
        {"u", -6}, {"\xC2\xB5", -6}, {"\xCE\xBC", -6}, {"n", -9}, {"p", -12}, {"f", -15},
    };
    for (const auto& [name, e] : kPrefixes)
    {
        if (p == name)
        {
            exponent = e;
            return true;
        }
    }
    return false;
}

/// "550,000000nm" → 550 nm; false when it does not parse.
bool ParseWavelength(const std::string& text, double& nm, std::string& unit)
{
    // The number: digits with one comma or period as the decimal separator
    // and an optional exponent.
    size_t i = 0;
    std::string number;
    bool digits = false, separator = false;
    for (; i < text.size(); ++i)
    {
        const char c = text[i];
        if (c >= '0' && c <= '9')
        {
            number += c;
            digits = true;
        }
        else if ((c == ',' || c == '.') && !separator)
        {
            number += '.';
            separator = true;
        }
        else
        {
            break;
        }
    }
    if (!digits)
    {
        return false;
    }
    if (i + 1 < text.size() && (text[i] == 'e' || text[i] == 'E') &&
        (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '+' ||
         text[i + 1] == '-'))
    {
        number += 'e';
        ++i;
        if (text[i] == '+' || text[i] == '-')
        {
            number += text[i++];
        }
        bool expDigits = false;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])))
        {
            number += text[i++];
            expDigits = true;
        }
        if (!expDigits)
        {
            return false;
        }
    }
    unit = text.substr(i);
    int exponent = 0;
    const double value = std::strtod(number.c_str(), nullptr);
    if (unit.size() >= 2 && unit.compare(unit.size() - 2, 2, "Hz") == 0)
    {
        if (!PrefixExponent(unit.substr(0, unit.size() - 2), exponent))
        {
            return false;
        }
        const double hz = value * std::pow(10.0, exponent);
        nm = hz > 0.0 ? 299792458.0 / hz * 1e9 : 0.0;
    }
    else if (!unit.empty() && unit.back() == 'm')
    {
        if (!PrefixExponent(unit.substr(0, unit.size() - 1), exponent))
        {
            return false;
        }
        // Scaled by a whole power of ten: nm, um and mm stay exact.
        const int toNm = exponent + 9;
        nm = toNm >= 0 ? value * std::pow(10.0, toNm) : value / std::pow(10.0, -toNm);
    }
    else
    {
        return false;
    }
    return std::isfinite(nm) && nm > 0.0;
}

}  // namespace

std::optional<SpectralChannel> ParseSpectralChannel(const std::string& name,
                                                    const std::string& file)
{
    SpectralChannel c;
    std::string rest;
    if (name.size() > 3 && name[0] == 'S' && name[1] >= '0' && name[1] <= '3' && name[2] == '.')
    {
        c.kind = SpectralKind::EMISSIVE;
        c.stokes = name[1] - '0';
        rest = name.substr(3);
    }
    else if (name.size() > 2 && name[0] == 'T' && name[1] == '.')
    {
        c.kind = SpectralKind::REFLECTIVE;
        rest = name.substr(2);
    }
    else
    {
        return std::nullopt;
    }
    const std::string quoted = "'" + OneLine(name, 80) + "'";
    // A bi-spectral channel T.<λi><unit>.<λo><unit>: the first wavelength's
    // unit is followed by a period.
    if (c.kind == SpectralKind::REFLECTIVE)
    {
        const size_t m = rest.find("m.");
        const size_t hz = rest.find("Hz.");
        if (m != std::string::npos || hz != std::string::npos)
        {
            throw Exception(In(file) + "channel " + quoted +
                            " is bi-spectral (fluorescent re-radiation from one wavelength to "
                            "another), which bandlight does not read; give an image of "
                            "non-fluorescent remittances (T.<wavelength> channels only)");
        }
    }
    if (!ParseWavelength(rest, c.wavelengthNm, c.unit))
    {
        throw Exception(In(file) + "channel " + quoted +
                        " is not a spectral channel name: expected S0.<wavelength><unit> or "
                        "T.<wavelength><unit> with a unit such as nm, um or THz "
                        "(\"S0.550,000000nm\")");
    }
    return c;
}

std::string SpectralChannelName(SpectralKind kind, double wavelengthNm)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", wavelengthNm);
    std::string number(buf);
    std::replace(number.begin(), number.end(), '.', ',');  // '.' separates EXR layers
    return (kind == SpectralKind::EMISSIVE ? "S0." : "T.") + number + "nm";
}

std::map<std::string, double> ReadChannelWavelengths(const std::string& path)
{
    std::string text = ReadTextFile(path, "channel wavelength file");
    CheckUtf8Text(text, path);
    // "channel,wavelength" rows: the first field of the first data row is
    // not a number.
    std::istringstream in(text);
    std::string line;
    size_t lineNo = 0;
    std::map<std::string, double> named;
    bool pairs = false, decided = false;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
        {
            line.pop_back();
        }
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        const size_t comma = line.find_first_of(",;\t");
        const std::string first = line.substr(0, comma);
        const std::string second = comma == std::string::npos ? "" : line.substr(comma + 1);
        char* end = nullptr;
        const double nm = std::strtod(second.c_str(), &end);
        const bool secondNumber = !second.empty() && end && *end == '\0';
        char* end1 = nullptr;
        std::strtod(first.c_str(), &end1);
        const bool firstNumber = !first.empty() && end1 && *end1 == '\0';
        if (!decided)
        {
            decided = true;
            if (firstNumber)
            {
                break;  // sensitivities without a header
            }
            if (!secondNumber)
            {
                // A header row: "wavelength_nm, channel, ..." heads
                // sensitivities, anything else "channel, wavelength".
                std::string lower;
                for (const char ch : first)
                {
                    lower += char(std::tolower(static_cast<unsigned char>(ch)));
                }
                if (lower.rfind("wavelength", 0) == 0 || lower == "nm" || lower == "lambda")
                {
                    break;
                }
                // "channel, wavelength" heads pairs only when its second
                // field reads as a heading; "band_00,abc" is a row whose
                // wavelength is wrong, not a header.
                std::string heading;
                for (const char ch : second)
                {
                    heading += char(std::tolower(static_cast<unsigned char>(ch)));
                }
                pairs = true;
                if (heading.find("wave") != std::string::npos ||
                    heading.find("nm") != std::string::npos ||
                    heading.find("lambda") != std::string::npos)
                {
                    continue;
                }
            }
            pairs = true;
        }
        if (secondNumber && !std::isfinite(nm))
        {
            throw Exception(SourcePosition(path, lineNo) + ": the wavelength of '" +
                            OneLine(first, 80) + "' is not a finite number: '" +
                            OneLine(second, 40) + "'");
        }
        if (!secondNumber || nm <= 0.0)
        {
            throw Exception(SourcePosition(path, lineNo) +
                            ": expected 'channel,wavelength_nm', got '" + OneLine(line, 80) + "'");
        }
        if (!named.emplace(first, nm).second)
        {
            throw Exception(SourcePosition(path, lineNo) + ": channel '" + OneLine(first, 80) +
                            "' is listed twice");
        }
    }
    if (pairs)
    {
        if (named.empty())
        {
            throw Exception(path + ": lists no channels");
        }
        return named;
    }
    for (const NamedSpectrum& s : ReadSpectraFile(path))
    {
        double sum = 0.0, moment = 0.0;
        for (size_t i = 0; i < s.spectrum.size(); ++i)
        {
            sum += s.spectrum[i];
            moment += s.spectrum[i] * s.spectrum.wavelength(i);
        }
        if (!(sum > 0.0))
        {
            throw Exception(path + ": the sensitivity of channel '" + OneLine(s.name, 80) +
                            "' has no positive sum");
        }
        if (!named.emplace(s.name, moment / sum).second)
        {
            throw Exception(path + ": channel '" + OneLine(s.name, 80) + "' is listed twice");
        }
    }
    return named;
}

}  // namespace bandlight
