// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/CieData.h"

#include <algorithm>
#include <cctype>

#include "spectral/EmbeddedData.h"
#include "spectral/Exception.h"

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

const std::vector<ObserverEntry>& Observers()
{
    static const std::vector<ObserverEntry> observers = {
        {Observer::CIE1931_2DEG, "1931", {"2", "cie1931", "2deg"}, "CIE 1931 2°"},
        {Observer::CIE1964_10DEG, "1964", {"10", "cie1964", "10deg"}, "CIE 1964 10°"},
    };
    return observers;
}

Observer ParseObserver(const std::string& text)
{
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    std::string keys;
    for (const ObserverEntry& e : Observers())
    {
        if (t == e.key || std::find(e.aliases.begin(), e.aliases.end(), t) != e.aliases.end())
        {
            return e.observer;
        }
        keys += (keys.empty() ? "" : " or ") + std::string(e.key);
    }
    throw Exception("unknown observer '" + text + "' (expected " + keys + ")");
}

const char* ObserverName(Observer observer)
{
    for (const ObserverEntry& e : Observers())
    {
        if (e.observer == observer)
        {
            return e.name;
        }
    }
    return "unknown observer";
}

const MatchingFunctions& GetMatchingFunctions(Observer observer)
{
    static const MatchingFunctions cie1931 = LoadMatchingFunctions("cmf/cie1931_2deg_xyz.csv");
    static const MatchingFunctions cie1964 = LoadMatchingFunctions("cmf/cie1964_10deg_xyz.csv");
    return observer == Observer::CIE1931_2DEG ? cie1931 : cie1964;
}

const MatchingFunctions& GetMatchingFunctions1nm(Observer observer)
{
    static const MatchingFunctions cie1931 = LoadMatchingFunctions("cmf/cie1931_2deg_xyz_1nm.csv");
    static const MatchingFunctions cie1964 = LoadMatchingFunctions("cmf/cie1964_10deg_xyz_1nm.csv");
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

const std::vector<NamedSpectrum>& ColourEvaluationSamples()
{
    static const std::vector<NamedSpectrum> ces = ReadEmbedded("ref/cie224_ces.csv");
    return ces;
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
