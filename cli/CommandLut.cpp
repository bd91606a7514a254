// SPDX-License-Identifier: BSD-3-Clause
// `bandlight lut`: an illuminant change as a LUT file, written by OCIO.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "luts/LutWriter.h"
#include "transforms/IlluminantChange.h"

namespace bandlight::cli
{

namespace
{

struct LutCommandOptions
{
    RelightOptions relight;
    std::string format = "clf";
    int size = 33;
    std::string shaper = "log2";
    std::string out;
};

void RunLut(const LutCommandOptions& o, bool sizeGiven)
{
    LutOptions options;
    options.format = ParseLutFormat(o.format);
    options.size = o.size;
    options.forceLattice = sizeGiven;
    options.shaper = ShaperSpec::Parse(o.shaper);
    const MethodSpec method = o.relight.methodSpec();
    LutFiles files;
    if (method.isLinear())
    {
        bool isMatrix = true;
        const OCIO::GroupTransformRcPtr exact = RelightTransform(o.relight, &isMatrix);
        files = WriteLut(exact, isMatrix, options, o.out);
    }
    else
    {
        // Bake straight from the per-pixel spectral fit, not from a lattice.
        const NamedSpectrum from = ResolveIlluminant(o.relight.from);
        const NamedSpectrum to = ResolveIlluminant(o.relight.to);
        const auto relighter = std::make_shared<Relighter>(Light{from.name, from.spectrum},
                                                           Light{to.name, to.spectrum}, method,
                                                           FindRgbSpace(o.relight.workingSpace));
        if (options.shaper.kind == ShaperSpec::Kind::LOG2)
        {
            options.shaper = ShaperSpec::ForNonLinear();
        }
        options.description =
            "Relight from " + from.name + " to " + to.name + " in " +
            FindRgbSpace(o.relight.workingSpace).displayName + ". " + DescribeMethod(method) + " " +
            method.plates.describe(FindRgbSpace(o.relight.workingSpace).displayName);
        files = WriteLut([relighter](float* rgb, size_t n) { relighter->apply(rgb, n); }, options,
                         o.out);
    }
    std::cout << "Wrote " << files.lut << ": ";
    if (!files.lattice)
    {
        std::cout << "the exact 3x3 matrix\n";
        return;
    }
    std::cout << o.size << "^3 3D LUT, shaper " << options.shaper.alignedTo(o.size).describe()
              << "\n";
    if (!files.shaper.empty())
    {
        std::cout << "Wrote " << files.shaper
                  << ": the shaper; apply it before the LUT and its inverse after\n";
    }
}

}  // namespace

void AddLutCommand(CLI::App& app)
{
    auto o = std::make_shared<LutCommandOptions>();
    CLI::App* cmd = app.add_subcommand("lut",
                                       "Write an illuminant change as a LUT file (CLF, CTF, cube, "
                                       "spi3d, 3dl, resolve_cube, csp, houdini) through "
                                       "OpenColorIO's writers");
    AddRelightOptions(*cmd, o->relight, true);
    cmd->add_option("--format", o->format,
                    "clf, ctf, cube, spi3d, 3dl (scene-linear HDR through the shaper); "
                    "resolve_cube, csp, houdini (display-referred [0, 1], with --shaper none). "
                    "ICC is not offered: an ICC profile describes a device, not a scene-linear "
                    "look")
        ->capture_default_str();
    CLI::Option* size = cmd->add_option(
        "--size", o->size,
        "3D LUT size per axis; for CLF/CTF, giving it bakes a 3D LUT instead of the matrix");
    size->capture_default_str();
    cmd->add_option(
           "--shaper", o->shaper,
           "Shaper into the 3D LUT's domain: log2 (scene-linear -0.0005 to 131072) or none "
           "(linear 0 to 1)")
        ->capture_default_str();
    cmd->add_option("-o,--out", o->out, "Output file")->required();
    cmd->callback([o, size] { RunLut(*o, size->count() > 0); });
}

}  // namespace bandlight::cli
