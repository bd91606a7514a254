// SPDX-License-Identifier: BSD-3-Clause
// `bandlight package`: the main job (jobs/PackageJob). Writes the default
// config package and an example chart re-lit from A to D65.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/PackageJob.h"
#include "requests/Defaults.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::cli
{

void AddPackageCommand(CLI::App& app)
{
    auto request = std::make_shared<jobs::PackageRequest>();
    CLI::App* cmd = app.add_subcommand(
        "package",
        "Write the default OCIO config package (ACEScg, A/C/D65/F2/F11, every linear "
        "method; for white-balanced plates, and in lit/ for lit ones) and an example chart "
        "re-lit from A to D65");
    cmd->add_option("--out", request->out, "Directory to write into")->capture_default_str();
    cmd->callback(
        [request]
        {
            CommandReporter reporter;
            const jobs::PackageResult r = jobs::MakePackage(*request, reporter);
            const std::string& dir = request->out;
            std::cout << "Wrote " << dir << "/config.ocio: " << r.looks << " looks (" << r.lights
                      << " illuminants, " << r.methods
                      << " methods) for white-balanced plates (the ACES convention), working "
                         "space "
                      << r.workingSpace << "\n"
                      << "Wrote " << dir
                      << "/lit/config.ocio: the same looks for lit plates (images that "
                         "carry the light's cast)\n";
            for (const std::string& chart : r.charts)
            {
                std::cout << "Wrote " << dir << "/" << chart << ".exr (" << r.workingSpace
                          << ") and .png (sRGB preview)\n";
            }
            std::cout << "The TCS01-TCS15 chart rendered spectrally under A, as shot (lit: "
                         "orange) and white-balanced (as an ACES IDT delivers it), re-lit to D65 "
                         "by the band3 and bradford looks of the config for each, and the "
                         "spectral truth under D65 to compare with.\n";
        });
}

}  // namespace bandlight::cli
