// SPDX-License-Identifier: BSD-3-Clause
#include "bandlight/spectral/CieData.h"

#include <algorithm>
#include <cctype>

#include "bandlight/spectral/EmbeddedData.h"
#include "bandlight/spectral/Exception.h"

namespace bandlight
{
namespace detail
{

std::string EmbeddedText(const std::string& path)
{
    for (const EmbeddedFile& f : EmbeddedFiles())
    {
        if (path == f.path)
        {
            return f.text;
        }
    }
    throw Exception("no embedded data file '" + path + "'");
}

}  // namespace detail

namespace
{

std::vector<NamedSpectrum> ReadEmbedded(const std::string& path)
{
    return ReadSpectraText(detail::EmbeddedText(path), "embedded data/" + path);
}

MatchingFunctions LoadMatchingFunctions(const std::string& path)
{
    std::vector<NamedSpectrum> s = ReadEmbedded(path);
    return {s.at(0).spectrum, s.at(1).spectrum, s.at(2).spectrum};
}

}  // namespace

Observer ParseObserver(const std::string& text)
{
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    if (t == "1931" || t == "2" || t == "cie1931" || t == "2deg")
    {
        return Observer::CIE1931_2DEG;
    }
    if (t == "1964" || t == "10" || t == "cie1964" || t == "10deg")
    {
        return Observer::CIE1964_10DEG;
    }
    throw Exception("unknown observer '" + text + "' (expected 1931 or 1964)");
}

const char* ObserverName(Observer observer)
{
    return observer == Observer::CIE1931_2DEG ? "CIE 1931 2°" : "CIE 1964 10°";
}

const MatchingFunctions& GetMatchingFunctions(Observer observer)
{
    static const MatchingFunctions cie1931 = LoadMatchingFunctions("cmf/cie1931_2deg_xyz.csv");
    static const MatchingFunctions cie1964 = LoadMatchingFunctions("cmf/cie1964_10deg_xyz.csv");
    return observer == Observer::CIE1931_2DEG ? cie1931 : cie1964;
}

const DaylightBasis& GetDaylightBasis()
{
    static const DaylightBasis basis = []
    {
        std::vector<NamedSpectrum> s = ReadEmbedded("ref/daylight_basis.csv");
        return DaylightBasis{s.at(0).spectrum, s.at(1).spectrum, s.at(2).spectrum};
    }();
    return basis;
}

const std::vector<NamedSpectrum>& TestColourSamples()
{
    static const std::vector<NamedSpectrum> tcs = ReadEmbedded("ref/tcs.csv");
    return tcs;
}

const std::vector<NamedSpectrum>& Rawtoaces190()
{
    static const std::vector<NamedSpectrum> patches = ReadEmbedded("ref/rawtoaces_190.csv");
    return patches;
}

const std::vector<NamedSpectrum>& TabulatedIlluminants()
{
    static const std::vector<NamedSpectrum> all = []
    {
        std::vector<NamedSpectrum> out;
        for (const char* name : {"A", "C", "D50", "D55", "D65", "E", "F1", "F2", "F3", "F4", "F5",
                                 "F6", "F7", "F8", "F9", "F10", "F11", "F12"})
        {
            out.push_back(ReadEmbedded(std::string("illuminant/") + name + ".csv").at(0));
        }
        return out;
    }();
    return all;
}

}  // namespace bandlight
