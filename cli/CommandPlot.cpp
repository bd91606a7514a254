// SPDX-License-Identifier: BSD-3-Clause
// `bandlight plot`: the band model's pictures — a spectrum and its band means as
// steps, for the matching functions, an illuminant or a test colour (the plot
// job, jobs/PlotJob.h).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/PlotJob.h"

namespace bandlight::cli
{

void AddPlotCommand(CLI::App& app)
{
    auto o = std::make_shared<jobs::PlotRequest>();
    CLI::App* cmd = app.add_subcommand(
        "plot",
        "Draw a spectrum with its band means as steps (matching functions, an illuminant "
        "or remittances)");
    cmd->add_flag("--cmf", o->cmf, "The colour-matching functions of --observer");
    cmd->add_option("--illuminant", o->illuminant, "An illuminant (name or spectrum file)");
    cmd->add_option("--reflectance", o->reflectance,
                    "Remittances (TCS01-TCS15, TCS, or a spectrum file)");
    cmd->add_option("--bands", o->bands, "Band edges in nm")->capture_default_str();
    AddObserverOption(*cmd, o->observer);
    cmd->add_option("-o,--out", o->out, "Output FILE.png or FILE.svg")->required();
    cmd->callback(
        [o]
        {
            CommandReporter reporter;
            const jobs::PlotResult result = jobs::MakePlot(*o, reporter);
            std::cout << "Wrote " << result.out << "\n";
        });
}

}  // namespace bandlight::cli
