// SPDX-License-Identifier: BSD-3-Clause
// `bandlight config`: an OCIO config package with illuminant-change looks, or
// the same looks added into an existing config (jobs/ConfigJob).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/ConfigJob.h"
#include "requests/Defaults.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::cli
{

namespace
{

struct ConfigCommandOptions
{
    jobs::ConfigRequest request;
    std::string out;
    std::string illuminants = defaults::CONFIG_ILLUMINANTS;
    std::string methods;
};

void RunConfig(ConfigCommandOptions& o, const CLI::App& cmd)
{
    CommandReporter reporter;
    jobs::ConfigRequest& r = o.request;
    r.out = o.out;
    for (const char* list : {"--illuminants", "--methods"})
    {
        const CLI::Option* option = cmd.get_option_no_throw(list);
        if (option && option->count() > 0 &&
            jobs::SplitList(list == std::string("--methods") ? o.methods : o.illuminants).empty())
        {
            throw ParameterError(std::string(list) +
                                 " is empty: name at least one, or leave it out for the "
                                 "defaults");
        }
    }
    const CLI::Option* basePaths = cmd.get_option_no_throw("--base-paths");
    if (basePaths && basePaths->count() > 0 && r.base.empty())
    {
        throw ParameterError("{base_paths} rewrites the search paths of a {base}: give the base "
                             "config, or leave {base_paths} out");
    }
    for (const std::string& name : jobs::SplitList(o.illuminants))
    {
        r.lights.push_back(jobs::ResolveIlluminant(name, reporter));
    }
    r.methods = jobs::SplitList(o.methods);
    const jobs::ConfigResult result = jobs::MakeConfig(r, reporter);
    const ConfigPackage& package = result.package;
    std::cout << "Wrote " << o.out << "/config.ocio: " << package.config->getNumLooks()
              << " looks and " << package.config->getNumNamedTransforms()
              << " named transforms for " << result.identified << " ("
              << result.options.lights.size() << " illuminants, " << result.options.methods.size()
              << " methods) for " << (result.options.plates.balanced() ? "white-balanced" : "lit")
              << " plates";
    if (!package.lutFiles.empty())
    {
        std::cout << ", and " << package.lutFiles.size() << " LUT files in " << o.out << "/luts";
    }
    std::cout << "\n";
    if (!package.evidence.empty())
    {
        std::cout << "scene_linear identified as " << result.identified << ": " << package.evidence
                  << "\n";
    }
    if (package.v1)
    {
        std::cout << "the base is an OCIO v1 config and so is the result: its looks are CLF files "
                     "(read by OpenColorIO 2 hosts), and v1 has no named transforms\n";
    }
}

}  // namespace

void AddConfigCommand(CLI::App& app)
{
    auto o = std::make_shared<ConfigCommandOptions>();
    jobs::ConfigRequest& r = o->request;
    CLI::App* cmd = app.add_subcommand(
        "config", "Write an OCIO v2 config with one look per illuminant pair and method");
    cmd->add_option("--out", o->out, "Directory to write config.ocio into (created if needed)")
        ->required();
    cmd->add_option("--base", r.base,
                    "Existing config (OCIO v1 or v2) to add the looks and band space to, leaving "
                    "the rest intact");
    AddLutSizeOption(*cmd, r.lutSize,
                     "3D LUT size of non-linear looks (upsample, rootpoly): 65 (about 12 MB a "
                     "look) or 33 (1.6 MB, up to 0.25 dE00 less accurate)");
    cmd->add_option("--base-paths", r.basePaths,
                    "With --base: the base's relative LUT search paths, rewritten to reach the "
                    "base's folder from --out: relative (the two folders move together) or "
                    "absolute (the output moves alone)")
        ->check(CLI::IsMember({"relative", "absolute"}))
        ->capture_default_str();
    cmd->add_option("--working-space", r.workingSpace,
                    "Linear working space: " + RgbSpaceChoices() + " (default " +
                        defaults::WORKING_SPACE +
                        "); with --base, the base's scene_linear primaries (detected when "
                        "omitted)");
    cmd->add_option("--illuminants", o->illuminants,
                    "Comma-separated built-in illuminants or spectrum files")
        ->capture_default_str();
    cmd->add_option(
        "--methods", o->methods,
        "Comma-separated methods (default: " + JoinNames(LinearMethodNames()) +
            "; also bandN, bandN-wp, bandsE0-E1-...-En[-wp], fit3x3, prefilter, metamer, and "
            "the non-linear upsample, rootpoly, rootpoly3, hueplane as 3D LUT files, and "
            "rootpoly-camera, rootpoly-plate with --camera)");
    AddObserverOption(*cmd, r.observer);
    AddPlatesOptions(*cmd, r.plates);
    cmd->callback([o, cmd] { RunConfig(*o, *cmd); });
}

}  // namespace bandlight::cli
