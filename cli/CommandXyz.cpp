// SPDX-License-Identifier: BSD-3-Clause
// `bandlight xyz`: colorimetry of an illuminant, or of surfaces under it.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{

namespace
{

struct XyzOptions
{
    std::string illuminant;
    std::string reflectance;
    std::string observer;
    bool json = false;
};

void RunXyz(const XyzOptions& o)
{
    const NamedSpectrum illuminant = ResolveIlluminant(o.illuminant);
    const Observer observer = ParseObserver(o.observer);
    const Vec3 white = IlluminantWhiteXyz(illuminant.spectrum, observer);

    struct Row
    {
        std::string id;
        Vec3 xyz;
    };
    std::vector<Row> rows;
    if (o.reflectance.empty())
    {
        rows.push_back({illuminant.name, white});
    }
    else
    {
        const XyzIntegrator integrate(illuminant.spectrum, observer);
        for (const NamedSpectrum& r : ResolveReflectances(o.reflectance))
        {
            rows.push_back({r.name, integrate(r.spectrum)});
        }
    }

    for (const Row& r : rows)
    {
        const Vec3 lab = XyzToLab(r.xyz, white);
        for (int c = 0; c < 3; ++c)
        {
            RequireFinite(r.xyz[c], "XYZ of '" + OneLine(r.id, 80) + "'");
            RequireFinite(lab[c], "L*a*b* of '" + OneLine(r.id, 80) + "'");
        }
    }
    if (o.json)
    {
        nlohmann::ordered_json j;
        j["illuminant"] = illuminant.name;
        j["observer"] = observer == Observer::CIE1931_2DEG ? "1931" : "1964";
        j["white_XYZ"] = {white.x(), white.y(), white.z()};
        j["samples"] = nlohmann::ordered_json::array();
        for (const Row& r : rows)
        {
            const Vec3 xyY = XyzToxyY(r.xyz);
            const Vec3 lab = XyzToLab(r.xyz, white);
            j["samples"].push_back({{"id", r.id},
                                    {"XYZ", {r.xyz.x(), r.xyz.y(), r.xyz.z()}},
                                    {"xy", {xyY.x(), xyY.y()}},
                                    {"Lab", {lab.x(), lab.y(), lab.z()}}});
        }
        std::cout << j.dump(2) << "\n";
        return;
    }
    std::cout << "Illuminant " << illuminant.name << ", " << ObserverName(observer)
              << " observer; XYZ with the white reflector at Y = 100, L*a*b* relative to the "
                 "illuminant's white\n";
    std::cout << "  id              X         Y         Z        x        y        L*       a*    "
                 "   b*\n";
    for (const Row& r : rows)
    {
        const Vec3 xyY = XyzToxyY(r.xyz);
        const Vec3 lab = XyzToLab(r.xyz, white);
        std::string id = r.id.substr(0, 12);
        id.resize(12, ' ');
        std::cout << "  " << id;
        for (double v : {r.xyz.x(), r.xyz.y(), r.xyz.z()})
        {
            const std::string s = Fixed(v, 4);
            std::cout << std::string(s.size() < 10 ? 10 - s.size() : 1, ' ') << s;
        }
        for (double v : {xyY.x(), xyY.y()})
        {
            std::cout << "   " << Fixed(v, 5) << (v < 0 ? "" : " ");
        }
        for (double v : {lab.x(), lab.y(), lab.z()})
        {
            const std::string s = Fixed(v, 3);
            std::cout << std::string(s.size() < 9 ? 9 - s.size() : 1, ' ') << s;
        }
        std::cout << "\n";
    }
}

}  // namespace

void AddXyzCommand(CLI::App& app)
{
    auto o = std::make_shared<XyzOptions>();
    CLI::App* cmd = app.add_subcommand(
        "xyz", "CIE XYZ, xy and L*a*b* of an illuminant, or of surfaces lit by it");
    cmd->add_option(
           "--illuminant", o->illuminant,
           "Built-in illuminant (A, D65, F11, D75, 3200K, ...) or a CSV/CGATS spectrum file")
        ->required();
    cmd->add_option("--reflectance", o->reflectance,
                    "Test colour (TCS01-TCS15, TCS for all) or a CSV/CGATS file of spectra");
    AddObserverOption(*cmd, o->observer);
    cmd->add_flag("--json", o->json, "Write JSON");
    cmd->callback([o] { RunXyz(*o); });
}

}  // namespace bandlight::cli
