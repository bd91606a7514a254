// SPDX-License-Identifier: BSD-3-Clause
// `bandlight tables`: the lecture's three tables (SPEC §1.2) — matching-function
// band rows, illuminant band means, remittance band means.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

namespace bandlight::cli
{

namespace
{

struct TablesOptions
{
    std::string bands = "400,500,600,700";
    std::string observer;
    std::string rule = "lecture";
    bool json = false;
};

nlohmann::ordered_json RowsJson(const Eigen::MatrixXd& m, const char* names[3])
{
    nlohmann::ordered_json j;
    for (int k = 0; k < 3; ++k)
    {
        std::vector<double> row(size_t(m.cols()));
        for (Eigen::Index b = 0; b < m.cols(); ++b)
        {
            row[size_t(b)] = m(k, b);
        }
        j[names[k]] = row;
    }
    return j;
}

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
    const BandSet bands = BandSet::Parse(o.bands);
    const Observer observer = ParseObserver(o.observer);
    const BandRule rule = ParseBandRule(o.rule);
    const Eigen::MatrixXd xyz = MatchingBandMatrix(bands, MatchingSet::XYZ, observer, rule);
    const Eigen::MatrixXd rgb = MatchingBandMatrix(bands, MatchingSet::EBU_RGB, observer, rule);

    std::vector<std::pair<std::string, std::vector<double>>> illuminants;
    for (const std::string& name : StandardIlluminantNames())
    {
        illuminants.emplace_back(name, IlluminantBands(BuiltinIlluminant(name), bands, rule));
    }
    std::vector<std::pair<std::string, std::vector<double>>> remittances;
    for (const NamedSpectrum& s : TestColourSamples())
    {
        remittances.emplace_back(s.name, RemittanceBands(s.spectrum, bands, rule));
    }

    if (o.json)
    {
        const char* xyzNames[3] = {"x", "y", "z"};
        const char* rgbNames[3] = {"r", "g", "b"};
        nlohmann::ordered_json j;
        j["bands"] = nlohmann::ordered_json::array();
        for (const Band& b : bands)
        {
            j["bands"].push_back({{"name", b.name}, {"min_nm", b.minNm}, {"max_nm", b.maxNm}});
        }
        const std::string key = observer == Observer::CIE1931_2DEG ? "cie1931_xyz" : "cie1964_xyz";
        j["observer"] = observer == Observer::CIE1931_2DEG ? "1931" : "1964";
        j["rule"] = rule == BandRule::SAMPLE_MEAN ? "lecture" : "exact";
        j["matching_functions"][key] = RowsJson(xyz, xyzNames);
        j["matching_functions"]["ebu_rgb"] = RowsJson(rgb, rgbNames);
        j["condition_number"] = {{key, ConditionNumber(xyz)},
                                 {"ebu_rgb", ConditionNumber(rgb)},
                                 {"limit", MAX_BAND_CONDITION}};
        j["illuminants"] = nlohmann::ordered_json::object();
        for (const auto& [name, v] : illuminants)
        {
            j["illuminants"][name] = v;
        }
        j["remittances"] = nlohmann::ordered_json::object();
        for (const auto& [name, v] : remittances)
        {
            j["remittances"][name] = v;
        }
        std::cout << j.dump(2) << "\n";
        return;
    }

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
    cmd->add_option("--bands", o->bands, "Band edges in nm, comma separated")
        ->capture_default_str();
    AddObserverOption(*cmd, o->observer);
    cmd->add_option("--rule", o->rule, "Band mean rule: lecture (sample average) or exact")
        ->capture_default_str();
    cmd->add_flag("--json", o->json, "Write JSON instead of text tables");
    cmd->callback([o] { RunTables(*o); });
}

}  // namespace bandlight::cli
