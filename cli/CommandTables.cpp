// SPDX-License-Identifier: BSD-3-Clause
// `bandlight tables`: the band model's three tables (docs/science.md §1.2) — matching-function
// band rows, illuminant band means, remittance band means.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/ColourJobs.h"

namespace bandlight::cli
{

namespace
{

struct TablesOptions
{
    jobs::TablesRequest request;
    bool json = false;
};

void PrintRow(const std::string& label, const std::vector<double>& v, int decimals)
{
    std::cout << "  " << label;
    for (size_t i = label.size(); i < 12; ++i)
    {
        std::cout << ' ';
    }
    for (double x : v)
    {
        const std::string s = Fixed(x, decimals);
        std::cout << std::string(s.size() < 9 ? 9 - s.size() : 1, ' ') << s;
    }
    std::cout << "\n";
}

void PrintHeader(const std::string& title, const BandSet& bands)
{
    std::cout << "\n" << title << "\n  " << std::string(10, ' ');
    for (const Band& b : bands)
    {
        std::cout << std::string(b.name.size() < 9 ? 9 - b.name.size() : 1, ' ') << b.name;
    }
    std::cout << "\n";
}

void RunTables(const TablesOptions& o)
{
    const jobs::TablesResult t = jobs::MakeTables(o.request);
    if (o.json)
    {
        std::cout << jobs::TablesDocument(t) << "\n";
        return;
    }
    const BandSet& bands = t.bands;
    const Observer observer = t.observer;
    const BandRule rule = t.rule;
    const Eigen::MatrixXd& xyz = t.xyz;
    const Eigen::MatrixXd& rgb = t.rgb;
    const auto& illuminants = t.illuminants;
    const auto& remittances = t.remittances;
    std::cout << "Band model tables: bands " << bands.describe() << " nm, "
              << ObserverName(observer) << " observer, "
              << (rule == BandRule::SAMPLE_MEAN ? "lecture" : "exact") << " band means\n";
    auto row = [](const Eigen::MatrixXd& m, int k)
    {
        std::vector<double> v(size_t(m.cols()));
        for (Eigen::Index b = 0; b < m.cols(); ++b)
        {
            v[size_t(b)] = m(k, b);
        }
        return v;
    };
    const char* xyzLabels[3] = {"x_bar", "y_bar", "z_bar"};
    const char* rgbLabels[3] = {"r_bar", "g_bar", "b_bar"};
    PrintHeader("Matching functions, band means, rows normalised to sum 1:", bands);
    for (int k = 0; k < 3; ++k)
    {
        PrintRow(xyzLabels[k], row(xyz, k), 4);
    }
    for (int k = 0; k < 3; ++k)
    {
        PrintRow(rgbLabels[k] + std::string(" (EBU)"), row(rgb, k), 4);
    }
    const double condition = ConditionNumber(xyz);
    std::cout << "Condition number of the xyz band matrix: " << Fixed(condition, 2)
              << (condition > MAX_BAND_CONDITION
                      ? " (above the limit " + Fixed(MAX_BAND_CONDITION, 0) +
                            ": band methods refuse this set)"
                      : " (band methods accept up to " + Fixed(MAX_BAND_CONDITION, 0) + ")")
              << "\n";
    PrintHeader("Illuminants, band means normalised to the largest band:", bands);
    for (const auto& [name, v] : illuminants)
    {
        PrintRow(name, v, 4);
    }
    PrintHeader("Remittances (test colour samples), band means:", bands);
    for (const auto& [name, v] : remittances)
    {
        PrintRow(name, v, 4);
    }
}

}  // namespace

void AddTablesCommand(CLI::App& app)
{
    auto o = std::make_shared<TablesOptions>();
    CLI::App* cmd = app.add_subcommand(
        "tables", "Print the lecture's band tables: matching functions, illuminants, remittances");
    cmd->add_option("--bands", o->request.bands, "Band edges in nm, comma separated")
        ->capture_default_str();
    AddObserverOption(*cmd, o->request.observer);
    cmd->add_option("--rule", o->request.rule, "Band mean rule: lecture (sample average) or exact")
        ->capture_default_str();
    cmd->add_flag("--json", o->json, "Write JSON instead of text tables");
    cmd->callback([o] { RunTables(*o); });
}

}  // namespace bandlight::cli
