// SPDX-License-Identifier: BSD-3-Clause
#include "report/ResultTable.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace bandlight
{

ResultTable::ResultTable(std::vector<std::string> columns, int digits)
    : m_columns(std::move(columns)), m_digits(digits)
{
}

void ResultTable::add(std::vector<ResultCell> row)
{
    if (row.size() != m_columns.size())
    {
        throw std::invalid_argument("ResultTable: a row of " + std::to_string(row.size()) +
                                    " cells for " + std::to_string(m_columns.size()) + " columns");
    }
    m_rows.push_back(std::move(row));
}

nlohmann::ordered_json ResultTable::json() const
{
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const std::vector<ResultCell>& row : m_rows)
    {
        nlohmann::ordered_json o = nlohmann::ordered_json::object();
        for (size_t c = 0; c < m_columns.size(); ++c)
        {
            const ResultCell& cell = row[c];
            nlohmann::ordered_json& v = o[m_columns[c]];
            if (const auto* s = std::get_if<std::string>(&cell))
            {
                v = *s;
            }
            else if (const auto* d = std::get_if<double>(&cell))
            {
                v = std::isfinite(*d) ? nlohmann::ordered_json(*d) : nlohmann::ordered_json();
            }
            else if (const auto* n = std::get_if<long long>(&cell))
            {
                v = *n;
            }
            else if (const auto* b = std::get_if<bool>(&cell))
            {
                v = *b;
            }
        }
        a.push_back(std::move(o));
    }
    return a;
}

std::string ResultTable::text(const ResultCell& cell) const
{
    if (const auto* s = std::get_if<std::string>(&cell))
    {
        return *s;
    }
    if (const auto* d = std::get_if<double>(&cell))
    {
        if (!std::isfinite(*d))
        {
            return "";
        }
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.*g", m_digits, *d);
        return buf;
    }
    if (const auto* n = std::get_if<long long>(&cell))
    {
        return std::to_string(*n);
    }
    if (const auto* b = std::get_if<bool>(&cell))
    {
        return *b ? "true" : "false";
    }
    return "";
}

std::string ResultTable::csv() const
{
    std::string out;
    for (size_t c = 0; c < m_columns.size(); ++c)
    {
        out += (c ? "," : "") + CsvQuote(m_columns[c]);
    }
    out += "\n";
    for (const std::vector<ResultCell>& row : m_rows)
    {
        for (size_t c = 0; c < row.size(); ++c)
        {
            out += (c ? "," : "") + CsvQuote(text(row[c]));
        }
        out += "\n";
    }
    return out;
}

std::string ResultTable::markdown() const
{
    const auto escaped = [](const std::string& s)
    {
        std::string e;
        for (const char ch : s)
        {
            e += ch == '|'    ? std::string("\\|")
                 : ch == '\n' ? std::string(" ")
                              : std::string(1, ch);
        }
        return e;
    };
    std::string out = "|";
    std::string rule = "|";
    for (const std::string& c : m_columns)
    {
        out += " " + escaped(c) + " |";
        rule += "---|";
    }
    out += "\n" + rule + "\n";
    for (const std::vector<ResultCell>& row : m_rows)
    {
        out += "|";
        for (const ResultCell& cell : row)
        {
            out += " " + escaped(text(cell)) + " |";
        }
        out += "\n";
    }
    return out;
}

std::string CsvQuote(const std::string& cell)
{
    if (cell.find_first_of(",\"\r\n") == std::string::npos)
    {
        return cell;
    }
    std::string q = "\"";
    for (const char c : cell)
    {
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return q + "\"";
}

nlohmann::ordered_json StatisticsJson(const Statistics& s, StatisticsFields fields)
{
    if (fields == StatisticsFields::MEAN_P95_MAX)
    {
        return {{"mean", s.mean}, {"p95", s.p95}, {"max", s.max}};
    }
    return {
        {"count", s.count}, {"mean", s.mean}, {"median", s.median}, {"p95", s.p95}, {"max", s.max}};
}

nlohmann::ordered_json MatrixJson(const Eigen::MatrixXd& m)
{
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (Eigen::Index r = 0; r < m.rows(); ++r)
    {
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (Eigen::Index c = 0; c < m.cols(); ++c)
        {
            row.push_back(m(r, c));
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace bandlight
