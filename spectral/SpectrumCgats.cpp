// SPDX-License-Identifier: BSD-3-Clause
// The CGATS reader (ReadCgatsSpectra): the spectral sets of a CGATS file as
// ArgyllCMS and colord write them, tokenised, the first table with SPEC_
// fields found, its grid taken from the SPECTRAL_* keywords or the field
// names, and one spectrum read per data set.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <map>

#include "spectral/SpectrumIO.h"
#include "spectral/detail/SpectrumParsing.h"

namespace bandlight
{
namespace
{

using detail::CheckGrid;
using detail::Fail;
using detail::LooksNumeric;
using detail::ParseNumber;
using detail::Quoted;

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

}  // namespace bandlight
