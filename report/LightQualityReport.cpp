// SPDX-License-Identifier: BSD-3-Clause
#include "report/LightQualityReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "report/ResultTable.h"

namespace bandlight
{

namespace
{

/// The label of element i of a list field: its own, else "<name><i+1>".
std::string ElementLabel(const ScoreField& f, size_t i)
{
    return i < f.labels.size() ? f.labels[i] : f.name + std::to_string(i + 1);
}

/// A finite number as JSON writes it; NaN and infinity as null (JSON has
/// no such numbers).
nlohmann::ordered_json Number(double v)
{
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}

/// Warnings of every score of a light, each naming its score.
std::vector<std::string> Warnings(const LightQuality& q)
{
    std::vector<std::string> w;
    for (const Score& s : q.scores)
    {
        for (const std::string& line : s.warnings)
        {
            w.push_back(s.key + ": " + line);
        }
    }
    return w;
}

/// The CSV columns of one light: (column, cell).
std::vector<std::pair<std::string, ResultCell>> CsvCells(const LightQuality& q)
{
    std::vector<std::pair<std::string, ResultCell>> cells;
    for (const Score& s : q.scores)
    {
        const bool top = FindLightScore(s.key).topLevel;
        const std::string prefix = top ? "" : s.key + ".";
        if (!s.reference.empty())
        {
            cells.push_back({prefix + "reference", s.reference});
        }
        for (const ScoreField& f : s.fields)
        {
            if (!f.list)
            {
                cells.push_back({prefix + f.name, f.values.at(0)});
                continue;
            }
            for (size_t i = 0; i < f.values.size(); ++i)
            {
                cells.push_back({prefix + ElementLabel(f, i), f.values[i]});
            }
        }
    }
    return cells;
}

/// The value a table shows for headline `ref` of a score: a field's value,
/// or the element of a list field labelled `ref` ("R9").
std::optional<double> Headline(const Score& s, const std::string& ref)
{
    for (const ScoreField& f : s.fields)
    {
        if (!f.list && f.name == ref)
        {
            return f.values.at(0);
        }
        for (size_t i = 0; f.list && i < f.values.size(); ++i)
        {
            if (ElementLabel(f, i) == ref)
            {
                return f.values[i];
            }
        }
    }
    return std::nullopt;
}

std::vector<std::string> Split(const std::string& list)
{
    std::vector<std::string> parts;
    std::stringstream in(list);
    for (std::string part; std::getline(in, part, ',');)
    {
        parts.push_back(part);
    }
    return parts;
}

}  // namespace

std::string QualityJson(const std::vector<LightQuality>& lights)
{
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (const LightQuality& q : lights)
    {
        nlohmann::ordered_json j;
        j["light"] = q.light;
        for (const Score& s : q.scores)
        {
            const bool top = FindLightScore(s.key).topLevel;
            nlohmann::ordered_json o = nlohmann::ordered_json::object();
            if (!s.reference.empty())
            {
                o["reference"] = s.reference;
            }
            for (const ScoreField& f : s.fields)
            {
                if (f.list)
                {
                    nlohmann::ordered_json a = nlohmann::ordered_json::array();
                    for (const double v : f.values)
                    {
                        a.push_back(Number(v));
                    }
                    o[f.name] = a;
                }
                else
                {
                    o[f.name] = Number(f.values.at(0));
                }
            }
            if (top)
            {
                for (auto& [k, v] : o.items())
                {
                    j[k] = v;
                }
            }
            else
            {
                j[s.key] = s.fields.empty() ? nlohmann::ordered_json() : o;
            }
        }
        j["warnings"] = Warnings(q);
        all.push_back(j);
    }
    return all.dump(2);
}

std::string QualityCsv(const std::vector<LightQuality>& lights)
{
    std::vector<std::vector<std::pair<std::string, ResultCell>>> rows;
    std::vector<std::string> columns;
    for (const LightQuality& q : lights)
    {
        rows.push_back(CsvCells(q));
        // Columns in first-seen order: a light without a score's values
        // leaves them to the next light that has them, after those before.
        auto at = columns.begin();
        for (const auto& cell : rows.back())
        {
            const auto found = std::find(columns.begin(), columns.end(), cell.first);
            at = found != columns.end() ? found + 1 : columns.insert(at, cell.first) + 1;
        }
    }
    std::vector<std::string> header = {"light"};
    header.insert(header.end(), columns.begin(), columns.end());
    header.push_back("warnings");
    ResultTable table(header);
    for (size_t r = 0; r < lights.size(); ++r)
    {
        std::vector<ResultCell> row = {lights[r].light};
        for (const std::string& c : columns)
        {
            const auto cell = std::find_if(rows[r].begin(), rows[r].end(),
                                           [&](const auto& x) { return x.first == c; });
            row.push_back(cell == rows[r].end() ? ResultCell() : cell->second);
        }
        std::string warnings;
        for (const std::string& w : Warnings(lights[r]))
        {
            warnings += (warnings.empty() ? "" : " | ") + w;
        }
        row.push_back(warnings);
        table.add(std::move(row));
    }
    return table.csv();
}

std::string QualityText(const std::vector<LightQuality>& lights)
{
    struct Column
    {
        std::string key, ref, header;
        int decimals;
    };
    std::vector<Column> columns;
    for (const LightScoreEntry& e : LightScores())
    {
        if (!e.headline)
        {
            continue;
        }
        const bool used = std::any_of(lights.begin(), lights.end(),
                                      [&](const LightQuality& q) { return q.score(e.key); });
        for (std::string ref : Split(e.headline))
        {
            // "field[=Header][:decimals]" (spectral/LightScores.h).
            int decimals = 1;
            if (const size_t colon = ref.find(':'); colon != std::string::npos)
            {
                decimals = std::stoi(ref.substr(colon + 1));
                ref.resize(colon);
            }
            std::string header = ref;
            if (const size_t eq = ref.find('='); eq != std::string::npos)
            {
                header = ref.substr(eq + 1);
                ref.resize(eq);
            }
            if (used)
            {
                columns.push_back({e.key, ref, header, decimals});
            }
        }
    }
    size_t nameWidth = 5;
    for (const LightQuality& q : lights)
    {
        nameWidth = std::max(nameWidth, q.light.size());
    }
    nameWidth = std::min<size_t>(nameWidth, 40);
    std::ostringstream out;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%-*s", int(nameWidth), "light");
    out << "     " << buf;
    for (const Column& c : columns)
    {
        std::snprintf(buf, sizeof buf, " %8s", c.header.c_str());
        out << buf;
    }
    out << "\n";
    bool anyWarning = false;
    for (size_t i = 0; i < lights.size(); ++i)
    {
        const LightQuality& q = lights[i];
        const bool warned = !Warnings(q).empty();
        anyWarning = anyWarning || warned;
        // A long name (a file's path) keeps its end, where files differ.
        const std::string name = q.light.size() > nameWidth
                                     ? "~" + q.light.substr(q.light.size() - nameWidth + 1)
                                     : q.light;
        // A light with warnings is marked with its number, the warnings
        // listed under the table by that number.
        std::snprintf(buf, sizeof buf, "%-4s %-*s",
                      warned ? (std::to_string(i + 1) + "!").c_str() : "", int(nameWidth),
                      name.c_str());
        out << buf;
        for (const Column& c : columns)
        {
            const Score* s = q.score(c.key);
            const std::optional<double> v = s ? Headline(*s, c.ref) : std::nullopt;
            if (v && std::isfinite(*v))
            {
                std::snprintf(buf, sizeof buf, " %8.*f", c.decimals, *v);
            }
            else
            {
                std::snprintf(buf, sizeof buf, " %8s", "-");
            }
            out << buf;
        }
        out << "\n";
    }
    if (anyWarning)
    {
        for (size_t i = 0; i < lights.size(); ++i)
        {
            for (const std::string& w : Warnings(lights[i]))
            {
                out << (i + 1) << "! " << w << "\n";
            }
        }
    }
    return out.str();
}

}  // namespace bandlight
