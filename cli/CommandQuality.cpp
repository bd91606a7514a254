// SPDX-License-Identifier: BSD-3-Clause
// `bandlight quality`: every light-quality score of a light or many (the
// quality job, jobs/QualityJob.h), as a table, JSON or CSV.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/QualityJob.h"
#include "report/LightQualityReport.h"

namespace bandlight::cli
{

namespace
{

struct QualityOptions
{
    jobs::QualityRequest request;
    std::string reference;
    std::string plot;
    bool json = false;
    bool csv = false;
};

}  // namespace

void AddQualityCommand(CLI::App& app)
{
    auto o = std::make_shared<QualityOptions>();
    CLI::App* cmd = app.add_subcommand(
        "quality",
        "Light-quality scores of lights: CCT/Duv, CIE 13.3 Ra/R1-R15, CIE 224:2017 Rf, "
        "TM-30 Rf/Rg/hue bins, SSI, TLCI-2012 (and TLMF against --reference)");
    cmd->add_option("light", o->request.lights,
                    "Lights: built-in names (D65, F11, 3200K), daylight:K, planck:K or "
                    "spectrum files (CSV, CGATS .sp/.ti3)")
        ->required();
    CLI::Option* reference =
        cmd->add_option("--reference", o->reference,
                        "A reference light for TLMF (and for SSI instead of its default)");
    CLI::Option* json = cmd->add_flag("--json", o->json, "Write JSON: a list, one object a light");
    cmd->add_flag("--csv", o->csv, "Write CSV: a row a light")->excludes(json);
    CLI::Option* plot =
        cmd->add_option("--plot", o->plot,
                        "Also draw FILE.png or FILE.svg: spectra against their references and "
                        "the TM-30 colour vector graphic");
    cmd->callback(
        [o, reference, plot]
        {
            // Given, even empty, is not the same as not given.
            if (reference->count() > 0)
            {
                o->request.reference = o->reference;
            }
            if (plot->count() > 0)
            {
                o->request.plot = o->plot;
            }
            CommandReporter reporter;
            const jobs::QualityResult r = jobs::MakeQuality(o->request, reporter);
            std::cout << (o->json  ? QualityJson(r.lights) + "\n"
                          : o->csv ? QualityCsv(r.lights)
                                   : QualityText(r.lights));
            if (!r.plot.empty())
            {
                std::cerr << "Wrote " << r.plot << "\n";
            }
        });
}

}  // namespace bandlight::cli
