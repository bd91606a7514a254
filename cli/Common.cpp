// SPDX-License-Identifier: BSD-3-Clause
#include "cli/Common.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/Diagnostics.h"
#include "plugin/ConfigReferences.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

namespace bandlight::cli
{

namespace
{
bool FileExists(const std::string& path)
{
    std::ifstream f(path);
    return bool(f);
}

std::string Upper(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
    return s;
}
}  // namespace

NamedSpectrum ResolveIlluminant(const std::string& nameOrFile)
{
    if (IsBuiltinIlluminant(nameOrFile))
    {
        return {CanonicalIlluminantName(nameOrFile), BuiltinIlluminant(nameOrFile)};
    }
    if (!FileExists(nameOrFile))
    {
        return {nameOrFile, BuiltinIlluminant(nameOrFile)};  // throws, listing the choices
    }
    NamedSpectrum s = ReadSpectraFile(nameOrFile).front();
    s.spectrum = UsableIlluminant(s.spectrum, nameOrFile);
    if (const std::string note = CoverageNote(s, nameOrFile, false); !note.empty())
    {
        Note(note);
    }
    return s;
}

std::vector<NamedSpectrum> ResolveReflectances(const std::string& nameOrFile)
{
    const std::string u = Upper(nameOrFile);
    for (const NamedSpectrum& s : TestColourSamples())
    {
        if (s.name == u)
        {
            return {s};
        }
    }
    if (u == "TCS" || u == "TCS-ALL")
    {
        return TestColourSamples();
    }
    if (!FileExists(nameOrFile))
    {
        throw Exception("unknown reflectance '" + nameOrFile +
                        "' (TCS01-TCS15, TCS for all, or a spectrum file)");
    }
    std::vector<NamedSpectrum> spectra = ReadSpectraFile(nameOrFile);
    for (const NamedSpectrum& s : spectra)
    {
        CheckRemittanceMagnitude(s, nameOrFile);
        for (const std::string& note :
             {CoverageNote(s, nameOrFile, true), RemittanceRangeNote(s, nameOrFile)})
        {
            if (!note.empty())
            {
                Note(note);
            }
        }
    }
    return spectra;
}

namespace
{
/// The line number after the first "line " or "Line " in an OCIO message
/// (0 if none or implausible). Scanned by hand: messages quote file names
/// of any length, which a recursive regex matcher cannot take.
size_t LineInMessage(const std::string& what)
{
    for (size_t at = what.find("ine "); at != std::string::npos; at = what.find("ine ", at + 1))
    {
        if (at == 0 || (what[at - 1] != 'l' && what[at - 1] != 'L'))
        {
            continue;
        }
        size_t i = at + 4, line = 0, digits = 0;
        for (; i < what.size() && std::isdigit(static_cast<unsigned char>(what[i])); ++i, ++digits)
        {
            line = digits < 9 ? line * 10 + size_t(what[i] - '0') : line;
        }
        if (digits > 0)
        {
            return digits <= 9 ? line : 0;
        }
    }
    return 0;
}
}  // namespace

OCIO_NAMESPACE::ConstConfigRcPtr ReadConfigFile(const std::string& file)
{
    try
    {
        OCIO_NAMESPACE::ConstConfigRcPtr config =
            OCIO_NAMESPACE::Config::CreateFromFile(file.c_str());
        CheckConfigReferences(config, file);
        return config;
    }
    catch (const OCIO_NAMESPACE::Exception& e)
    {
        // "Error: Loading the OCIO profile 'F' failed. At line 6, ..." or
        // "... yaml-cpp: error at line 8, column 1: ...": keep what went wrong,
        // and put the line where every other parse error has it.
        std::string what = e.what();
        const std::string failed = "' failed. ";
        if (const size_t at = what.find(failed); at != std::string::npos)
        {
            what = what.substr(at + failed.size());
        }
        const size_t line = LineInMessage(what);
        for (char& c : what)
        {
            c = c == '\n' ? ' ' : c;
        }
        throw Exception(SourcePosition(file, line) + ": cannot read the config: " + what);
    }
}

CLI::Option* AddObserverOption(CLI::App& app, std::string& value)
{
    value = "1931";
    return app.add_option("--observer", value, "CIE standard observer: 1931 (2°) or 1964 (10°)")
        ->capture_default_str();
}

void AddRelightOptions(CLI::App& app, RelightOptions& o, bool required)
{
    CLI::Option* from =
        app.add_option("--from", o.from, "Illuminant the image is lit by (name or spectrum file)");
    CLI::Option* to =
        app.add_option("--to", o.to, "Illuminant it should look lit by (name or spectrum file)");
    app.add_option("--method", o.method,
                   "none, vonkries, bradford, cat02, band3, band3-wp, bandN, bandN-wp, "
                   "bandsE0-E1-...-En[-wp], fit3x3, prefilter, metamer, upsample, rootpoly, "
                   "rootpoly3, rootpoly-camera (with --camera)")
        ->capture_default_str();
    app.add_option("--working-space", o.workingSpace,
                   "Linear working space of the image: acescg, aces2065-1, lin-rec709, rec2020, "
                   "p3-d65, ebu3213")
        ->capture_default_str();
    AddPlatesOptions(app, o.plates);
    if (required)
    {
        from->required();
        to->required();
    }
}

void AddPlatesOptions(CLI::App& app, PlatesOptions& o, bool allowBoth)
{
    app.add_option("--plates", o.plates,
                   std::string("What the images are: balanced (white-balanced to the working "
                               "white, as every ACES IDT delivers them: the look keeps neutrals "
                               "neutral and changes only the light's colour rendering) or lit "
                               "(carrying the source light's cast, which the look removes)") +
                       (allowBoth ? "; both: measure the two" : ""))
        ->capture_default_str();
    app.add_option("--adaptation", o.adaptation,
                   "Chromatic adaptation the balanced plates were balanced with: cat02 "
                   "(rawtoaces) or bradford")
        ->capture_default_str();
    app.add_option(
        "--camera", o.camera,
        "SpectralCamera spectral sensitivities (rawtoaces JSON, or CSV/CGATS with R, G, B "
        "columns): enables rootpoly-camera, and accuracy simulates that camera's plates");
    app.add_option("--camera-idt", o.idtLight,
                   "The light the camera's one fixed IDT was fitted for (rootpoly-camera's "
                   "plates: that IDT plus white-balance gains)")
        ->capture_default_str();
}

Plates PlatesOptions::parsed() const
{
    return ParsePlates(plates, adaptation);
}

std::shared_ptr<const SpectralCamera> PlatesOptions::loadCamera() const
{
    if (camera.empty())
    {
        return nullptr;
    }
    return std::make_shared<const SpectralCamera>(ReadCameraFile(camera));
}

MethodSpec PlatesOptions::apply(MethodSpec method,
                                const std::shared_ptr<const SpectralCamera>& cam) const
{
    method.plates = parsed();
    method.camera = cam;
    if (method.method == ChangeMethod::ROOTPOLY_CAMERA)
    {
        if (!cam)
        {
            throw Exception("method '" + method.name +
                            "' needs the camera that shot the plates (--camera FILE)");
        }
        const NamedSpectrum idt = ResolveIlluminant(idtLight);
        method.idtLightName = idt.name;
        method.idtLight = idt.spectrum;
    }
    return method;
}

MethodSpec RelightOptions::methodSpec() const
{
    return plates.apply(ParseMethod(method), plates.loadCamera());
}

OCIO_NAMESPACE::GroupTransformRcPtr RelightTransform(const RelightOptions& o, bool* isMatrix)
{
    const NamedSpectrum from = ResolveIlluminant(o.from);
    const NamedSpectrum to = ResolveIlluminant(o.to);
    const MethodSpec method = o.methodSpec();
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    if (isMatrix)
    {
        *isMatrix = method.isLinear();
    }
    return IlluminantChangeTransform({from.name, from.spectrum}, {to.name, to.spectrum}, method,
                                     working);
}

std::vector<std::string> SplitList(const std::string& text)
{
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
    {
        if (!item.empty())
        {
            out.push_back(item);
        }
    }
    return out;
}

void RequireFinite(double value, const std::string& what)
{
    if (!std::isfinite(value))
    {
        throw Exception(what + " is not a finite number (the input is out of range)");
    }
}

std::string Fixed(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

}  // namespace bandlight::cli
