// SPDX-License-Identifier: BSD-3-Clause
// `bandlight cri`: CCT, Duv and the CIE 13.3 colour rendering indices.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/ColourJobs.h"

namespace bandlight::cli
{

namespace
{

struct CriOptions
{
    std::string illuminant;
    bool json = false;
};

void RunCri(const CriOptions& o)
{
    CommandReporter reporter;
    const jobs::CriResult result = jobs::MakeCri(jobs::ResolveIlluminant(o.illuminant, reporter));
    if (o.json)
    {
        std::cout << jobs::CriDocument(result) << "\n";
        return;
    }
    const ColourRendering& cr = result.rendering;
    std::cout << "Illuminant " << result.illuminant << " (CIE 13.3-1995, CIE 1931 observer)\n"
              << "  CCT " << Fixed(cr.cctK, 1) << " K, Duv " << Fixed(cr.duv, 5) << "\n"
              << "  Ra  " << Fixed(cr.ra, 1) << "\n";
    for (size_t i = 0; i < cr.r.size(); ++i)
    {
        std::cout << "  R" << i + 1 << (i + 1 < 10 ? "  " : " ") << Fixed(cr.r[i], 1) << "\n";
    }
    if (cr.outsideTolerance)
    {
        std::cout << "  note: |Duv| > 5.4e-3: CIE 13.3 does not consider Ra meaningful here\n";
    }
}

}  // namespace

void AddCriCommand(CLI::App& app)
{
    auto o = std::make_shared<CriOptions>();
    CLI::App* cmd = app.add_subcommand(
        "cri", "Correlated colour temperature, Duv and colour rendering index (Ra, R1-R15)");
    cmd->add_option("--illuminant", o->illuminant, "Built-in illuminant or spectrum file")
        ->required();
    cmd->add_flag("--json", o->json, "Write JSON");
    cmd->callback([o] { RunCri(*o); });
}

}  // namespace bandlight::cli
