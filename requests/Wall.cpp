// SPDX-License-Identifier: BSD-3-Clause
#include "requests/Wall.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "farm/OutputPaths.h"
#include "requests/Inputs.h"
#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"
#include "transforms/Plates.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight::jobs
{

namespace
{

/// The fields of a line of a spectrum file: separated by commas,
/// semicolons, tabs or spaces, quotes dropped.
std::vector<std::string> Fields(const std::string& line)
{
    std::vector<std::string> out;
    std::string cur;
    for (const char c : line)
    {
        if (c == ',' || c == ';' || c == '\t' || c == ' ' || c == '\r')
        {
            if (!cur.empty())
            {
                out.push_back(cur);
            }
            cur.clear();
        }
        else if (c != '"')
        {
            cur += c;
        }
    }
    if (!cur.empty())
    {
        out.push_back(cur);
    }
    return out;
}

bool Number(const std::string& token, double& v)
{
    char* end = nullptr;
    errno = 0;
    v = std::strtod(token.c_str(), &end);
    return !token.empty() && end && *end == '\0';
}

/// The line of the first negative sample of the file's first spectrum (0
/// when none is found): in a CSV file the second field of a data row, in a
/// CGATS file any value of the first data row (one spectrum a row).
size_t NegativeSampleLine(const std::string& text, std::string& value)
{
    std::istringstream in(text);
    const bool cgats = text.find("BEGIN_DATA_FORMAT") != std::string::npos;
    bool inData = false;
    std::string line;
    for (size_t number = 1; std::getline(in, line); ++number)
    {
        const std::vector<std::string> f = Fields(line);
        if (f.empty() || f[0][0] == '#')
        {
            continue;
        }
        if (cgats)
        {
            if (f[0] == "BEGIN_DATA")
            {
                inData = true;
                continue;
            }
            if (!inData)
            {
                continue;
            }
            for (const std::string& t : f)
            {
                double v = 0.0;
                if (Number(t, v) && v < 0.0)
                {
                    value = t;
                    return number;
                }
            }
            return 0;  // the first spectrum's row has none
        }
        double wavelength = 0.0, v = 0.0;
        if (f.size() >= 2 && Number(f[0], wavelength) && Number(f[1], v) && v < 0.0)
        {
            value = f[1];
            return number;
        }
    }
    return 0;
}

/// One emitter's file: its first spectrum, no negative sample, some power
/// where cameras see.
NamedSpectrum ReadEmitter(const WallEmitterSpec& e, Reporter& reporter)
{
    NamedSpectrum s = ReadSpectraFile(e.file).front();
    s.name = e.name;
    const auto& v = s.spectrum.values();
    if (std::any_of(v.begin(), v.end(), [](double x) { return x < 0.0; }))
    {
        std::string value;
        const size_t line = NegativeSampleLine(ReadTextFile(e.file, "emitter spectrum"), value);
        throw Exception(SourcePosition(e.file, line) + ": emitter " + e.name +
                        " has a negative sample" + (value.empty() ? "" : " (" + value + ")") +
                        ": an emission is not negative; set measurement noise below zero to 0");
    }
    double visible = 0.0;
    for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
    {
        visible += s.spectrum(SurfaceRenderer::Wavelength(i));
    }
    if (!(visible > 0.0) || !std::isfinite(visible))
    {
        throw Exception(e.file + ": emitter " + e.name +
                        " has no power over 380-780 nm: no camera sees it");
    }
    if (const std::string note = CoverageNote(s, e.file, false); !note.empty())
    {
        reporter.note(note);
    }
    return s;
}

}  // namespace

WallEmitterSpec ParseEmitter(const std::string& text)
{
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    {
        throw ParameterError("{emitter} is NAME=FILE (R=red.csv), not '" + OneLine(text, 80) + "'");
    }
    return {text.substr(0, eq), text.substr(eq + 1)};
}

void CheckWallRequest(const WallRequest& r)
{
    if (r.emitters.size() < 3)
    {
        throw ParameterError("a wall needs at least three emitters to show colour, not " +
                             std::to_string(r.emitters.size()) +
                             ": give {emitter=}NAME=FILE for "
                             "each (R, G, B, ...)");
    }
    if (r.emitters.size() > defaults::WALL_MAX_EMITTERS)
    {
        throw ParameterError("a wall of " + std::to_string(r.emitters.size()) +
                             " emitters is more than bandlight solves (at most " +
                             std::to_string(defaults::WALL_MAX_EMITTERS) +
                             "): give {emitter=}NAME=FILE for each drive channel of the wall");
    }
    for (size_t i = 0; i < r.emitters.size(); ++i)
    {
        const WallEmitterSpec& e = r.emitters[i];
        if (e.name.empty() || e.file.empty())
        {
            throw ParameterError("{emitter} is NAME=FILE: emitter " + std::to_string(i + 1) +
                                 " lacks its " + (e.name.empty() ? "name" : "file"));
        }
        for (size_t k = 0; k < i; ++k)
        {
            if (ToLower(r.emitters[k].name) == ToLower(e.name))
            {
                throw ParameterError("the emitter '" + OneLine(e.name, 40) +
                                     "' is named twice ({emitter}): each drive channel once");
            }
        }
    }
    if (r.camera.empty())
    {
        throw ParameterError("give the camera's sensitivities as {camera=}FILE");
    }
    if (r.whiteBalances.empty())
    {
        throw ParameterError("name the camera's white balances ({white_balance=}5600K ...)");
    }
    for (size_t i = 0; i < r.whiteBalances.size(); ++i)
    {
        for (size_t k = 0; k < i; ++k)
        {
            if (ToLower(r.whiteBalances[k]) == ToLower(r.whiteBalances[i]))
            {
                throw ParameterError("the white balance '" + OneLine(r.whiteBalances[i], 40) +
                                     "' is given twice ({white_balance}): give each once");
            }
        }
    }
    if (r.contentSpace.empty())
    {
        throw ParameterError("name the wall's content colour space ({content_space=}SPACE: " +
                             RgbSpaceChoices() + ")");
    }
    FindRgbSpace(r.contentSpace);
    FindRgbSpace(r.workingSpace);
    ParsePlates("balanced", r.adaptation);
    ParseObserver(r.observer);
    if (r.out.empty())
    {
        throw ParameterError("{out} is '' (an empty path): name the folder the config goes into");
    }
    OutputPlan plan;
    plan.folder("{out}", r.out, {"config.ocio", "report.json"});
    std::vector<std::string> inputs = {r.camera};
    for (const WallEmitterSpec& e : r.emitters)
    {
        inputs.push_back(e.file);
    }
    if (!r.training.empty())
    {
        inputs.push_back(r.training);
    }
    for (const std::string& in : inputs)
    {
        // The folder the config is written into cannot be a file it is
        // made from (OutputPlan would call it "a file, not a folder").
        if (SameFile(in, r.out))
        {
            throw ParameterError("{out} " + ShowPath(r.out) +
                                 " is an input of this run: give the config a folder of its own");
        }
        plan.input(in);
    }
    plan.check();
}

std::vector<NamedSpectrum> ReadEmitters(const WallRequest& r, Reporter& reporter)
{
    std::vector<NamedSpectrum> out;
    for (const WallEmitterSpec& e : r.emitters)
    {
        out.push_back(ReadEmitter(e, reporter));
    }
    return out;
}

}  // namespace bandlight::jobs
