// SPDX-License-Identifier: BSD-3-Clause
// `bandlight config`: an OCIO config package with illuminant-change looks, or
// the same looks added into an existing config.
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "plugin/ConfigBuilder.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{

namespace
{

struct ConfigCommandOptions
{
    std::string out;
    std::string base;
    std::string workingSpace;
    std::string illuminants = "A,C,D65,F2,F11";
    std::string methods;
    std::string observer;
    std::string basePaths = "relative";
    int lutSize = 65;
    PlatesOptions plates;
};

void RunConfig(const ConfigCommandOptions& o)
{
    ConfigOptions options;
    options.observer = ParseObserver(o.observer);
    for (const std::string& name : SplitList(o.illuminants))
    {
        const NamedSpectrum s = ResolveIlluminant(name);
        options.lights.push_back({s.name, s.spectrum});
    }
    options.methods = o.methods.empty() ? LinearMethodNames() : SplitList(o.methods);
    options.workingSpace = o.workingSpace.empty() ? "acescg" : o.workingSpace;
    options.outputDir = o.out;
    options.lutSize = o.lutSize;
    options.absoluteBasePaths = o.basePaths == "absolute";
    options.plates = o.plates.parsed();
    options.camera = o.plates.loadCamera();
    {
        const NamedSpectrum idt = ResolveIlluminant(o.plates.idtLight);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
    }

    ConfigPackage package;
    std::string identified;
    if (o.base.empty())
    {
        package = BuildConfig(options);
        identified = FindRgbSpace(options.workingSpace).name;
    }
    else
    {
        const OCIO::ConstConfigRcPtr base = ReadConfigFile(o.base);
        package = ExtendConfig(base, options, o.workingSpace.empty(), &identified);
    }
    WriteConfigPackage(package, o.out);
    std::cout << "Wrote " << o.out << "/config.ocio: " << package.config->getNumLooks()
              << " looks and " << package.config->getNumNamedTransforms()
              << " named transforms for " << identified << " (" << options.lights.size()
              << " illuminants, " << options.methods.size() << " methods) for "
              << (options.plates.balanced() ? "white-balanced" : "lit") << " plates";
    if (!package.lutFiles.empty())
    {
        std::cout << ", and " << package.lutFiles.size() << " LUT files in " << o.out << "/luts";
    }
    std::cout << "\n";
    if (!package.evidence.empty())
    {
        std::cout << "scene_linear identified as " << identified << ": " << package.evidence
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
    CLI::App* cmd = app.add_subcommand(
        "config", "Write an OCIO v2 config with one look per illuminant pair and method");
    cmd->add_option("--out", o->out, "Directory to write config.ocio into (created if needed)")
        ->required();
    cmd->add_option("--base", o->base,
                    "Existing config (OCIO v1 or v2) to add the looks and band space to, leaving "
                    "the rest intact");
    cmd->add_option("--lut-size", o->lutSize,
                    "3D LUT size of non-linear looks (upsample, rootpoly): 65 (about 12 MB a "
                    "look) or 33 (1.6 MB, up to 0.25 dE00 less accurate)")
        ->check(CLI::Range(2, 129))
        ->capture_default_str();
    cmd->add_option("--base-paths", o->basePaths,
                    "With --base: the base's relative LUT search paths, rewritten to reach the "
                    "base's folder from --out: relative (the two folders move together) or "
                    "absolute (the output moves alone)")
        ->check(CLI::IsMember({"relative", "absolute"}))
        ->capture_default_str();
    cmd->add_option("--working-space", o->workingSpace,
                    "Linear working space: acescg (default), aces2065-1, lin-rec709, rec2020, "
                    "p3-d65, ebu3213; with --base, the base's scene_linear primaries (detected "
                    "when omitted)");
    cmd->add_option("--illuminants", o->illuminants,
                    "Comma-separated built-in illuminants or spectrum files")
        ->capture_default_str();
    cmd->add_option(
        "--methods", o->methods,
        "Comma-separated methods (default: none,vonkries,bradford,cat02,band3,band3-wp; also "
        "bandN, bandN-wp, bandsE0-E1-...-En[-wp], fit3x3, prefilter, metamer, and the "
        "non-linear upsample, rootpoly, rootpoly3 as 3D LUT files, and rootpoly-camera with "
        "--camera)");
    AddObserverOption(*cmd, o->observer);
    AddPlatesOptions(*cmd, o->plates);
    cmd->callback([o] { RunConfig(*o); });
}

}  // namespace bandlight::cli
