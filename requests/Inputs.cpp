// SPDX-License-Identifier: BSD-3-Clause
#include "requests/Inputs.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "requests/Defaults.h"
#include "plugin/ConfigReferences.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/TextFile.h"

namespace bandlight::jobs
{

namespace
{
/// A path names a file when anything is there (asked without opening it: a
/// pipe is then refused by the reader, not waited on).
bool FileExists(const std::string& path)
{
    return PathExists(path);
}

std::string Upper(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
    return s;
}

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

Light CheckedIlluminant(const NamedSpectrum& s, const std::string& source, Reporter& reporter)
{
    NamedSpectrum checked = s;
    checked.spectrum = UsableIlluminant(s.spectrum, source);
    if (const std::string note = CoverageNote(checked, source, false); !note.empty())
    {
        reporter.note(note);
    }
    if (checked.spectrum.step() > 5.0 + 1e-9)
    {
        char step[32];
        std::snprintf(step, sizeof step, "%g", checked.spectrum.step());
        reporter.note(source + ": " + checked.name + " is sampled every " + step +
                      " nm, coarser than the CIE's 5 nm: it is integrated through its linear "
                      "interpolant, exact only where the light is linear between its samples");
    }
    return {checked.name, checked.spectrum};
}

Light IlluminantFromFile(const std::string& path, Reporter& reporter)
{
    NamedSpectrum light = ReadSpectraFile(path).front();
    // A column headed with a word for "the values" names no light: looks
    // would read bradford_A_to_value. The file's name does.
    std::string lower;
    for (const char c : light.name)
    {
        lower += char(std::tolower(static_cast<unsigned char>(c)));
    }
    static const std::set<std::string> generic = {
        "",         "value",    "values", "power", "relative_power", "relative power", "intensity",
        "spd",      "data",     "y",      "s",     "radiance",       "irradiance",     "emission",
        "spectrum", "relative", "energy", "counts"};
    if (generic.count(lower) != 0)
    {
        const std::string stem = std::filesystem::path(path).stem().string();
        if (!stem.empty())
        {
            light.name = stem;
        }
    }
    return CheckedIlluminant(light, path, reporter);
}

Light ResolveIlluminant(const std::string& nameOrFile, Reporter& reporter)
{
    if (IsBuiltinIlluminant(nameOrFile))
    {
        return {CanonicalIlluminantName(nameOrFile), BuiltinIlluminant(nameOrFile)};
    }
    if (!FileExists(nameOrFile))
    {
        // A name with a folder or a file extension is a file that is not
        // there, not an unknown built-in name.
        const std::string ext = std::filesystem::path(nameOrFile).extension().string();
        if (nameOrFile.find('/') != std::string::npos || ext.size() > 1)
        {
            throw FileError(nameOrFile, ENOENT, "no such spectrum file");
        }
        return {nameOrFile, BuiltinIlluminant(nameOrFile)};  // throws, listing the choices
    }
    return IlluminantFromFile(nameOrFile, reporter);
}

void CheckRemittance(const NamedSpectrum& s, const std::string& source, Reporter& reporter)
{
    CheckRemittanceMagnitude(s, source);
    for (const std::string& note : {CoverageNote(s, source, true), RemittanceRangeNote(s, source)})
    {
        if (!note.empty())
        {
            reporter.note(note);
        }
    }
}

std::vector<NamedSpectrum> RemittancesFromFile(const std::string& path, Reporter& reporter)
{
    std::vector<NamedSpectrum> spectra = ReadSpectraFile(path);
    for (const NamedSpectrum& s : spectra)
    {
        CheckRemittance(s, path, reporter);
    }
    return spectra;
}

std::vector<NamedSpectrum> ResolveReflectances(const std::string& nameOrFile, Reporter& reporter)
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
    return RemittancesFromFile(nameOrFile, reporter);
}

OCIO_NAMESPACE::ConstConfigRcPtr ReadConfigFile(const std::string& file, bool checkReferences)
{
    // A pipe is refused before OpenColorIO opens it (it would wait for a
    // writer); OpenColorIO says only that it could not read the file, the
    // errno says why.
    RequireRegularFile(file, "config");
    const int fileError = InputFileError(file);
    try
    {
        OCIO_NAMESPACE::ConstConfigRcPtr config =
            OCIO_NAMESPACE::Config::CreateFromFile(file.c_str());
        if (checkReferences)
        {
            CheckConfigReferences(config, file);
        }
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
        if (fileError != 0)
        {
            throw FileError(file, fileError, "cannot read the config: " + what);
        }
        throw Exception(SourcePosition(file, line) + ": cannot read the config: " + what);
    }
}

OCIO_NAMESPACE::ConstConfigRcPtr LoadConfig(const std::string& path)
{
    const std::string file =
        path.size() > 5 && path.substr(path.size() - 5) == ".ocio" ? path : path + "/config.ocio";
    return ReadConfigFile(file);
}

Plates PlatesRequest::parsed() const
{
    return ParsePlates(plates, adaptation);
}

bool PlatesRequest::both() const
{
    return plates == defaults::ACCURACY_PLATES;
}

std::vector<Plates> PlatesRequest::all() const
{
    if (!both())
    {
        return {parsed()};
    }
    // Balanced first, as reports list them, then lit, with one adaptation
    // (parsed, so a wrong one is refused as for one convention).
    Plates balanced = ParsePlates(defaults::PLATES, adaptation);
    balanced.convention = PlateConvention::BALANCED;
    Plates lit = balanced;
    lit.convention = PlateConvention::LIT;
    return {balanced, lit};
}

std::shared_ptr<const SpectralCamera> PlatesRequest::loadCamera() const
{
    if (camera.empty())
    {
        return nullptr;
    }
    return std::make_shared<const SpectralCamera>(ReadCameraFile(camera));
}

Light PlatesRequest::idt(Reporter& reporter) const
{
    return ResolveIlluminant(idtLight, reporter);
}

MethodSpec PlatesRequest::apply(MethodSpec method, const std::shared_ptr<const SpectralCamera>& cam,
                                Reporter& reporter) const
{
    method.plates = parsed();
    RequireCamera(method, bool(cam));
    const Light idtLight = method.entry().needsCamera ? idt(reporter) : Light{};
    return WithCamera(std::move(method), cam, idtLight);
}

MethodSpec MethodFor(const std::string& name, const std::vector<NamedSpectrum>& training,
                     const PlatesRequest& plates, Reporter& reporter)
{
    plates.parsed();  // a bad convention or adaptation is refused before anything is read
    MethodSpec spec = plates.apply(ParseMethod(name), plates.loadCamera(), reporter);
    return training.empty() ? spec : WithTraining(std::move(spec), training);
}

MethodSpec WithTraining(MethodSpec method, const std::vector<NamedSpectrum>& training)
{
    if (!method.entry().takesTraining)
    {
        throw ParameterError("method '" + method.name +
                             "' is not fitted: {training} remittances are for fit3x3, "
                             "rootpoly and rootpoly3");
    }
    method.training = training;
    return method;
}

MethodSpec RelightRequest::methodSpec(Reporter& reporter) const
{
    return MethodFor(method, training, plates, reporter);
}

const RgbSpace& RelightRequest::working() const
{
    return FindRgbSpace(workingSpace);
}

Relighter RelightRequest::relighter(Reporter& reporter) const
{
    return Relighter(src, dst, methodSpec(reporter), working(), ParseObserver(observer));
}

std::vector<std::string> SplitList(const std::string& text)
{
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
    {
        // "A, D65" names A and D65: spaces around an item are not part of it.
        const size_t first = item.find_first_not_of(" \t");
        if (first != std::string::npos)
        {
            out.push_back(item.substr(first, item.find_last_not_of(" \t") - first + 1));
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

int CheckedLutSize(int size, const std::string& parameter)
{
    if (size < defaults::MIN_LUT_SIZE || size > defaults::MAX_LUT_SIZE)
    {
        throw ParameterError(
            "{" + parameter + "} must be " + std::to_string(defaults::MIN_LUT_SIZE) + " to " +
            std::to_string(defaults::MAX_LUT_SIZE) + ", got " + std::to_string(size));
    }
    return size;
}

std::string Fixed(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

}  // namespace bandlight::jobs
