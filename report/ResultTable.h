// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A typed result table — named columns of text, numbers or flags, a row per
// result — written once for every format: a JSON array of objects, CSV
// (RFC 4180) and a Markdown table. Accuracy rows, cost rows, heat-map
// summaries and lights' scores are each built as one, so a column added to
// a result appears in every format with one line.

#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "spectral/Statistics.h"

namespace bandlight
{

/// One cell: empty (JSON null, an empty CSV cell), text, a number, a count
/// (written without a decimal point) or a flag. Pass text as std::string
/// and counts as long long: a const char* or an int would convert to
/// another alternative.
using ResultCell = std::variant<std::monostate, std::string, double, long long, bool>;

class ResultTable
{
public:
    /// A table of these columns (the JSON keys and the CSV/Markdown
    /// headers), numbers written in CSV and Markdown to `digits`
    /// significant digits (JSON keeps every digit).
    explicit ResultTable(std::vector<std::string> columns, int digits = 6);

    /// Appends a row, one cell per column; throws std::invalid_argument
    /// for another count.
    void add(std::vector<ResultCell> row);

    const std::vector<std::string>& columns() const noexcept { return m_columns; }
    size_t size() const noexcept { return m_rows.size(); }

    /// An array with an object per row, keys in column order; non-finite
    /// numbers as null (JSON has none).
    nlohmann::ordered_json json() const;
    /// A header row and a row per row, quoted where a cell needs it.
    std::string csv() const;
    /// A Markdown table (`|` in a cell escaped).
    std::string markdown() const;

private:
    std::string text(const ResultCell& cell) const;

    std::vector<std::string> m_columns;
    std::vector<std::vector<ResultCell>> m_rows;
    int m_digits;
};

/// `cell` quoted for CSV (RFC 4180) when it holds a comma, a quote or a
/// line break.
std::string CsvQuote(const std::string& cell);

/// The figures of a Statistics a document gives: all of them (count, mean,
/// median, p95, max) or, in `idt`'s documents, mean, p95 and max.
enum class StatisticsFields
{
    ALL,
    MEAN_P95_MAX,
};

/// A summary as a JSON object, its figures in the order above: every
/// document writes a summary through this.
nlohmann::ordered_json StatisticsJson(const Statistics& s,
                                      StatisticsFields fields = StatisticsFields::ALL);

/// A matrix as JSON: an array of its rows, each an array of numbers.
nlohmann::ordered_json MatrixJson(const Eigen::MatrixXd& m);

}  // namespace bandlight
