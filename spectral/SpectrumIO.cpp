// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/SpectrumIO.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "spectral/Exception.h"
#include "spectral/TextFile.h"

namespace bandlight
{
namespace
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

namespace
{

struct Token
{
    std::string text;
    size_t line;
};

/// At most this many tokens in a CGATS file: 2000 spectra of 1 nm data
/// over 300–830 nm hold about 1.1 million; the limit keeps a hostile file
/// of 64 MiB of one-character tokens from taking gigabytes.
constexpr size_t kMaxCgatsTokens = size_t(4) << 20;

/// Splits CGATS text into tokens, honouring "quoted strings" and '#' comments.
std::vector<Token> TokenizeCgats(std::istream& in, const std::string& source)
{
    std::vector<Token> tokens;
    std::string line;
    size_t lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        size_t i = 0;
        while (i < line.size())
        {
            if (tokens.size() >= kMaxCgatsTokens)
            {
                Fail(source, lineNo,
                     "more than " + std::to_string(kMaxCgatsTokens) +
                         " values and keywords, the limit for a CGATS file");
            }
            const char c = line[i];
            if (c == ' ' || c == '\t' || c == '\r')
            {
                ++i;
            }
            else if (c == '#')
            {
                break;
            }
            else if (c == '"')
            {
                const size_t close = line.find('"', i + 1);
                const size_t stop = close == std::string::npos ? line.size() : close;
                tokens.push_back({line.substr(i + 1, stop - i - 1), lineNo});
                i = stop + 1;
            }
            else
            {
                const size_t stop = line.find_first_of(" \t\r", i);
                const size_t e = stop == std::string::npos ? line.size() : stop;
                tokens.push_back({line.substr(i, e - i), lineNo});
                i = e;
            }
        }
    }
    return tokens;
}

/// Wavelength encoded in a SPEC_ field name: "SPEC_380" is 380 nm; ArgyllCMS
/// writes fractional grids with more digits ("SPEC_300000" in a 1 nm table
/// of 531 bands), which the SPECTRAL_* keywords then resolve.
double FieldWavelength(const std::string& field)
{
    return std::strtod(field.c_str() + 5, nullptr);
}

/// The first table of a CGATS file that holds spectra: the file type, the
/// keywords before the table, its fields and its values in row order.
struct CgatsTable
{
    std::string fileType;
    std::map<std::string, Token> keywords;
    std::vector<Token> fields;
    std::vector<Token> data;

    /// The keyword's value; empty text on line 0 when the file has none.
    Token keyword(const std::string& key) const
    {
        const auto it = keywords.find(key);
        return it == keywords.end() ? Token{} : it->second;
    }
    /// The keyword as a number, or `fallback` when the file has none.
    double number(const char* key, double fallback, const std::string& source) const
    {
        const auto it = keywords.find(key);
        return it == keywords.end() ? fallback
                                    : ParseNumber(it->second.text, source, it->second.line, key);
    }
};

/// The tokens after tokens[i] up to the word `end`; leaves i at `end`, or
/// at tokens.size() when the file has no `end`.
std::vector<Token> Section(const std::vector<Token>& tokens, size_t& i, const char* end)
{
    std::vector<Token> section;
    for (++i; i < tokens.size() && tokens[i].text != end; ++i)
    {
        section.push_back(tokens[i]);
    }
    return section;
}

bool HasSpecFields(const std::vector<Token>& fields)
{
    return std::any_of(fields.begin(), fields.end(),
                       [](const Token& f) { return f.text.rfind("SPEC_", 0) == 0; });
}

/// Reads keywords and tables up to the first table with SPEC_ fields.
CgatsTable FindSpectralTable(const std::vector<Token>& tokens, const std::string& source)
{
    if (tokens.empty())
    {
        Fail(source, 0, "empty file: not a CGATS file");
    }
    CgatsTable table;
    table.fileType = tokens[0].text;
    size_t i = 1;
    while (i < tokens.size())
    {
        const Token& t = tokens[i];
        if (t.text == "BEGIN_DATA_FORMAT")
        {
            table.fields = Section(tokens, i, "END_DATA_FORMAT");
            if (i == tokens.size())
            {
                Fail(source, t.line, "BEGIN_DATA_FORMAT without END_DATA_FORMAT");
            }
            ++i;
        }
        else if (t.text == "BEGIN_DATA")
        {
            table.data = Section(tokens, i, "END_DATA");
            if (i == tokens.size())
            {
                Fail(source, table.data.empty() ? t.line : table.data.back().line,
                     "BEGIN_DATA without END_DATA (truncated file?)");
            }
            ++i;
            if (HasSpecFields(table.fields))
            {
                return table;
            }
            // A table without spectra (a ti3's calibration table): skip it
            // and start the next table's keywords afresh.
            table.keywords.clear();
        }
        else if (t.text == "KEYWORD")
        {
            i += 2;
        }
        else if (i + 1 < tokens.size() && !LooksNumeric(t.text))
        {
            table.keywords[t.text] = tokens[i + 1];
            i += 2;
        }
        else
        {
            ++i;
        }
    }
    Fail(source, 0, "no spectral data (no SPEC_ fields in a BEGIN_DATA_FORMAT table)");
}

/// Where a table keeps its spectra and its sample names.
struct CgatsColumns
{
    std::vector<size_t> spec;  ///< the SPEC_ fields, in the file's order
    size_t id;                 ///< SAMPLE_ID, _NAME or _LOC; fields.size() when none
};

CgatsColumns FindColumns(const std::vector<Token>& fields, const std::string& source)
{
    CgatsColumns columns{{}, fields.size()};
    std::map<std::string, size_t> seen;
    for (size_t c = 0; c < fields.size(); ++c)
    {
        const std::string& f = fields[c].text;
        if (!seen.emplace(f, c).second)
        {
            Fail(source, fields[c].line,
                 "field " + Quoted(f) + " appears twice in BEGIN_DATA_FORMAT (column " +
                     std::to_string(seen[f] + 1) + " and " + std::to_string(c + 1) + ")");
        }
        if (f.rfind("SPEC_", 0) == 0)
        {
            columns.spec.push_back(c);
        }
        else if ((f == "SAMPLE_ID" || f == "SAMPLE_NAME" || f == "SAMPLE_LOC") &&
                 columns.id == fields.size())
        {
            columns.id = c;
        }
    }
    return columns;
}

/// The wavelength grid (nm) and the scale of the values.
struct CgatsGrid
{
    double start;
    double end;
    double step;
    double norm;  ///< values are divided by it: 100 for a ti3's percent
};

/// The grid from the SPECTRAL_* keywords, or else from the SPEC_ field
/// names; SPECTRAL_BANDS must count the fields.
CgatsGrid ReadGrid(const CgatsTable& table, const CgatsColumns& columns, const std::string& source)
{
    const size_t bands = columns.spec.size();
    const Token& first = table.fields[columns.spec.front()];
    CgatsGrid grid;
    grid.start = table.number("SPECTRAL_START_NM", FieldWavelength(first.text), source);
    grid.end = table.number("SPECTRAL_END_NM",
                            FieldWavelength(table.fields[columns.spec.back()].text), source);
    if (table.number("SPECTRAL_BANDS", double(bands), source) != double(bands))
    {
        const Token declared = table.keyword("SPECTRAL_BANDS");
        Fail(source, declared.line,
             "SPECTRAL_BANDS says " + declared.text + " but the format has " +
                 std::to_string(bands) + " SPEC_ fields");
    }
    if (bands < 2 || !(grid.end > grid.start))
    {
        Fail(source, first.line, "spectral range must hold at least two increasing wavelengths");
    }
    grid.norm = table.number("SPECTRAL_NORM", table.fileType == "CTI3" ? 100.0 : 1.0, source);
    if (!(grid.norm > 0.0))
    {
        Fail(source, table.keyword("SPECTRAL_NORM").line, "SPECTRAL_NORM must be positive");
    }
    grid.step = (grid.end - grid.start) / double(bands - 1);
    return grid;
}

/// The number of data sets (rows): whole rows, at least one, as many as
/// NUMBER_OF_SETS says.
size_t CountSets(const CgatsTable& table, const std::string& source)
{
    const size_t nf = table.fields.size();
    if (table.data.size() % nf != 0)
    {
        Fail(source, table.data.empty() ? 0 : table.data.back().line,
             "data has " + std::to_string(table.data.size()) + " values, not a multiple of the " +
                 std::to_string(nf) + " fields (truncated row?)");
    }
    const size_t sets = table.data.size() / nf;
    if (sets == 0)
    {
        Fail(source, 0, "the spectral table holds no data sets (empty BEGIN_DATA ... END_DATA)");
    }
    const auto declared = table.keywords.find("NUMBER_OF_SETS");
    if (declared != table.keywords.end() &&
        ParseNumber(declared->second.text, source, declared->second.line, "NUMBER_OF_SETS") !=
            double(sets))
    {
        Fail(source, declared->second.line,
             "NUMBER_OF_SETS says " + declared->second.text + " but the data has " +
                 std::to_string(sets) + " sets");
    }
    return sets;
}

/// One spectrum per data set, named by its sample column or else its row
/// number from 1.
std::vector<NamedSpectrum> ReadSets(const CgatsTable& table, const CgatsColumns& columns,
                                    const CgatsGrid& grid, size_t sets, const std::string& source)
{
    const size_t nf = table.fields.size();
    const size_t bands = columns.spec.size();
    std::vector<NamedSpectrum> out;
    for (size_t s = 0; s < sets; ++s)
    {
        std::vector<double> v(bands);
        for (size_t b = 0; b < bands; ++b)
        {
            const Token& tok = table.data[s * nf + columns.spec[b]];
            v[b] = ParseNumber(tok.text, source, tok.line,
                               table.fields[columns.spec[b]].text.c_str()) /
                   grid.norm;
            if (!std::isfinite(v[b]))
            {
                Fail(source, tok.line,
                     "value " + Quoted(tok.text) + " divided by SPECTRAL_NORM " +
                         table.keyword("SPECTRAL_NORM").text + " is out of range");
            }
        }
        std::string name =
            columns.id < nf ? table.data[s * nf + columns.id].text : std::to_string(s + 1);
        out.push_back({std::move(name), Spectrum(grid.start, grid.step, std::move(v))});
    }
    return out;
}

}  // namespace

std::vector<NamedSpectrum> ReadCgatsSpectra(std::istream& in, const std::string& source)
{
    const CgatsTable table = FindSpectralTable(TokenizeCgats(in, source), source);
    const CgatsColumns columns = FindColumns(table.fields, source);
    const CgatsGrid grid = ReadGrid(table, columns, source);
    const size_t sets = CountSets(table, source);
    CheckGrid(grid.start, grid.end, grid.step, source, table.fields[columns.spec.front()].line);
    return ReadSets(table, columns, grid, sets, source);
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
