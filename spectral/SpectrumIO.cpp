// SPDX-License-Identifier: BSD-3-Clause
// Reading spectra: the parsing every reader shares (numbers, quoting,
// grid limits), building a spectrum from (wavelength, value) samples, the
// CSV reader, the notes and checks on what was read, and the choice of
// reader by a file's content. The CGATS reader is spectral/SpectrumCgats.cpp.
#include "spectral/SpectrumIO.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "spectral/Exception.h"
#include "spectral/TextFile.h"
#include "spectral/detail/SpectrumParsing.h"

namespace bandlight
{
namespace detail
{

std::string Nm(double v)
{
    std::ostringstream o;
    o << v;
    return o.str();
}

[[noreturn]] void Fail(const std::string& source, size_t line, const std::string& what)
{
    throw Exception(SourcePosition(source, line) + ": " + OneLine(what, 2000));
}

/// A value from a file, as messages quote it: one line, at most 80 bytes.
std::string Quoted(const std::string& token)
{
    return "'" + OneLine(token, 80) + "'";
}

/// Parses a whole token as a finite double; NaN, Inf and trailing garbage
/// are errors (a spectrum with them would poison every integral).
double ParseNumber(const std::string& token, const std::string& source, size_t line,
                   const char* what)
{
    const char* begin = token.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0')
    {
        Fail(source, line, std::string("expected a number for ") + what + ", got " + Quoted(token));
    }
    if (std::isnan(v))
    {
        Fail(source, line, std::string("NaN (") + Quoted(token) + ") is not allowed for " + what);
    }
    if (!std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1.0))
    {
        Fail(source, line, std::string("value out of range for ") + what + ": " + Quoted(token));
    }
    return v;
}

bool LooksNumeric(const std::string& s)
{
    if (s.empty())
    {
        return false;
    }
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

/// Refuses a grid that would need more than MAX_SPECTRUM_SAMPLES samples
/// once it spans the visible range too (spectra are extended over 380–780 nm
/// on their own step): a step of 1e-6 nm, or wavelengths of 1e16 nm.
void CheckGrid(double first, double last, double step, const std::string& source, size_t line)
{
    const double span = std::max(last, 780.0) - std::min(first, 380.0);
    if (!(step > 0.0) || !(span / step + 1.0 <= double(MAX_SPECTRUM_SAMPLES)))
    {
        Fail(source, line,
             "a " + Nm(step) + " nm grid over " + Nm(first) + "–" + Nm(last) +
                 " nm (and 380–780 nm) needs more than " + std::to_string(MAX_SPECTRUM_SAMPLES) +
                 " samples");
    }
}

}  // namespace detail

namespace
{

using detail::CheckGrid;
using detail::Fail;
using detail::LooksNumeric;
using detail::Nm;
using detail::ParseNumber;
using detail::Quoted;

std::string Trim(const std::string& s)
{
    const size_t a = s.find_first_not_of(" \t\r\n\"");
    if (a == std::string::npos)
    {
        return {};
    }
    const size_t b = s.find_last_not_of(" \t\r\n\"");
    return s.substr(a, b - a + 1);
}

std::vector<std::string> SplitCsv(const std::string& line)
{
    std::vector<std::string> out;
    const bool hasDelimiter = line.find_first_of(",;\t") != std::string::npos;
    std::string cur;
    for (char c : line)
    {
        const bool sep = hasDelimiter ? (c == ',' || c == ';' || c == '\t') : (c == ' ');
        if (sep)
        {
            if (hasDelimiter || !cur.empty())
            {
                out.push_back(Trim(cur));
            }
            cur.clear();
        }
        else
        {
            cur += c;
        }
    }
    if (hasDelimiter || !Trim(cur).empty())
    {
        out.push_back(Trim(cur));
    }
    return out;
}

}  // namespace

/// Builds a regular-grid spectrum from increasing (wavelength, value)
/// pairs; an irregular grid is resampled onto its smallest step, which must
/// not need more than MAX_SPECTRUM_SAMPLES samples.
Spectrum SpectrumFromSamples(const std::vector<double>& wl, const std::vector<double>& v,
                             const std::string& source, size_t lastLine)
{
    if (wl.size() == 1)
    {
        return Spectrum(wl[0], 1.0, v);
    }
    double minStep = wl[1] - wl[0];
    double maxStep = minStep;
    for (size_t i = 1; i < wl.size(); ++i)
    {
        minStep = std::min(minStep, wl[i] - wl[i - 1]);
        maxStep = std::max(maxStep, wl[i] - wl[i - 1]);
    }
    if (maxStep - minStep <= 1e-6 * maxStep)
    {
        const double step = (wl.back() - wl.front()) / double(wl.size() - 1);
        CheckGrid(wl.front(), wl.back(), step, source, lastLine);
        return Spectrum(wl.front(), step, v);
    }
    // Irregular: resampled onto the smallest step.
    CheckGrid(wl.front(), wl.back(), minStep, source, lastLine);
    const size_t count = size_t(std::floor((wl.back() - wl.front()) / minStep + 1e-9)) + 1;
    std::vector<double> out(count);
    size_t j = 0;
    for (size_t i = 0; i < count; ++i)
    {
        const double x = wl.front() + minStep * double(i);
        while (j + 2 < wl.size() && wl[j + 1] < x)
        {
            ++j;
        }
        const double f = std::clamp((x - wl[j]) / (wl[j + 1] - wl[j]), 0.0, 1.0);
        out[i] = v[j] + f * (v[j + 1] - v[j]);
    }
    return Spectrum(wl.front(), minStep, std::move(out));
}

std::vector<NamedSpectrum> ReadCsvSpectra(std::istream& in, const std::string& source)
{
    std::vector<std::string> names;
    std::vector<double> wl;
    std::vector<std::vector<double>> columns;
    std::string line;
    size_t lineNo = 0;
    size_t columnCount = 0;
    size_t headerLine = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const std::string t = Trim(line);
        if (t.empty() || t[0] == '#')
        {
            continue;
        }
        std::vector<std::string> cells = SplitCsv(line);
        if (columnCount == 0)
        {
            columnCount = cells.size();
            if (columnCount < 2)
            {
                Fail(source, lineNo,
                     "expected a wavelength column and at least one spectrum, got " + Quoted(t));
            }
            columns.resize(columnCount - 1);
            if (!LooksNumeric(cells[0]))
            {
                headerLine = lineNo;
                names.assign(cells.begin() + 1, cells.end());
                continue;
            }
            for (size_t c = 1; c < columnCount; ++c)
            {
                names.push_back(std::to_string(c));
            }
        }
        if (cells.size() != columnCount)
        {
            Fail(source, lineNo,
                 "expected " + std::to_string(columnCount) + " columns, got " +
                     std::to_string(cells.size()) + " in " + Quoted(t));
        }
        const double w = ParseNumber(cells[0], source, lineNo, "the wavelength");
        if (!wl.empty() && !(w > wl.back()))
        {
            Fail(source, lineNo,
                 "wavelengths must increase: " + cells[0] + " nm follows " + Nm(wl.back()) + " nm");
        }
        if (w <= 0.0)
        {
            Fail(source, lineNo, "wavelength must be positive, got " + Quoted(cells[0]));
        }
        wl.push_back(w);
        for (size_t c = 1; c < columnCount; ++c)
        {
            columns[c - 1].push_back(ParseNumber(cells[c], source, lineNo, "a spectral value"));
        }
    }
    if (wl.size() < 2)
    {
        Fail(source, wl.empty() ? headerLine : lineNo,
             "fewer than two wavelength rows: not a spectrum");
    }
    std::vector<NamedSpectrum> out;
    for (size_t c = 0; c < columns.size(); ++c)
    {
        out.push_back({names[c], SpectrumFromSamples(wl, columns[c], source, lineNo)});
    }
    return out;
}

std::string CoverageNote(const NamedSpectrum& spectrum, const std::string& source, bool remittance)
{
    constexpr double kFirst = 380.0;
    constexpr double kLast = 780.0;
    const Spectrum& sp = spectrum.spectrum;
    const bool low = sp.start() > kFirst + 1e-9;
    const bool high = sp.end() < kLast - 1e-9;
    if (!low && !high)
    {
        return {};
    }
    std::string ranges;
    if (low)
    {
        ranges = Nm(kFirst) + "–" + Nm(std::min(sp.start(), kLast)) + " nm";
    }
    if (high)
    {
        ranges += (ranges.empty() ? "" : " and ") + Nm(std::max(sp.end(), kFirst)) + "–" +
                  Nm(kLast) + " nm";
    }
    return source + ": " + spectrum.name + " covers " + Nm(sp.start()) + "–" + Nm(sp.end()) +
           " nm; over " + ranges +
           (remittance ? " its end values are held constant (CIE 15:2004 §7.2.1)"
                       : " it is taken as zero");
}

std::string RemittanceRangeNote(const NamedSpectrum& spectrum, const std::string& source)
{
    const std::vector<double>& v = spectrum.spectrum.values();
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    if (v.empty() || (*lo >= 0.0 && *hi <= 1.0))
    {
        return {};
    }
    return source + ": " + spectrum.name + " has remittance values outside [0, 1] (" + Nm(*lo) +
           " to " + Nm(*hi) + "): used as given, not clipped";
}

void CheckRemittanceMagnitude(const NamedSpectrum& spectrum, const std::string& source)
{
    for (const double v : spectrum.spectrum.values())
    {
        if (!(std::abs(v) <= MAX_REMITTANCE))
        {
            throw Exception(source + ": '" + OneLine(spectrum.name, 80) + "' has a remittance of " +
                            Nm(v) + "; remittances beyond ±" + Nm(MAX_REMITTANCE) + " are refused");
        }
    }
}

std::vector<NamedSpectrum> ReadSpectraText(const std::string& text, const std::string& source)
{
    std::string checked = text;
    CheckUtf8Text(checked, source);
    std::istringstream in(checked);
    if (checked.find("BEGIN_DATA_FORMAT") != std::string::npos)
    {
        return ReadCgatsSpectra(in, source);
    }
    return ReadCsvSpectra(in, source);
}

std::vector<NamedSpectrum> ReadSpectraFile(const std::string& path)
{
    return ReadSpectraText(ReadTextFile(path, "spectrum file"), path);
}

}  // namespace bandlight
