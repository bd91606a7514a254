// SPDX-License-Identifier: BSD-3-Clause
// `bandlight xyz`: colorimetry of an illuminant, or of surfaces under it.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/ColourJobs.h"

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
    CommandReporter reporter;
    jobs::XyzRequest request;
    request.illuminant = jobs::ResolveIlluminant(o.illuminant, reporter);
    request.observer = o.observer;
    if (!o.reflectance.empty())
    {
        request.reflectances = jobs::ResolveReflectances(o.reflectance, reporter);
    }
    const jobs::XyzResult result = jobs::MakeXyz(request);
    if (o.json)
    {
        std::cout << jobs::XyzDocument(result) << "\n";
        return;
    }
    const Observer observer = result.observer;
    std::cout << "Illuminant " << result.illuminant << ", " << ObserverName(observer)
              << " observer; XYZ with the white reflector at Y = 100, L*a*b* relative to the "
                 "illuminant's white\n";
    std::cout << "  id              X         Y         Z        x        y        L*       a*    "
                 "   b*\n";
    for (const jobs::XyzSample& r : result.samples)
    {
        const Vec3& xyY = r.xyY;
        const Vec3& lab = r.lab;
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
