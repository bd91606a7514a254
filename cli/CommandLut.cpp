// SPDX-License-Identifier: BSD-3-Clause
// `bandlight lut`: an illuminant change as a LUT file, written by OCIO
// (jobs/LutJob).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/LutJob.h"
#include "requests/Defaults.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::cli
{

namespace
{

struct LutCommandOptions
{
    RelightOptions relight;
    jobs::LutRequest request;
    int size = defaults::LUT_SIZE;
};

void RunLut(LutCommandOptions& o, bool sizeGiven, bool shaperGiven)
{
    if (shaperGiven && ParseLutEncoding(o.request.encoding) != LutEncoding::LINEAR)
    {
        throw ParameterError("{shaper} is for {encoding=}linear: a LUT for " + o.request.encoding +
                             " input takes encoded values and needs no shaper");
    }
    CommandReporter reporter;
    jobs::LutRequest& r = o.request;
    r.relight = o.relight.relight(reporter);
    if (sizeGiven)
    {
        r.size = o.size;
    }
    const jobs::LutResult result = jobs::MakeLut(r, reporter);
    std::cout << "Wrote " << result.files.lut << ": ";
    if (!result.files.lattice)
    {
        std::cout << "the exact 3x3 matrix\n";
        return;
    }
    if (result.files.encoding != LutEncoding::LINEAR)
    {
        std::cout << result.size << "^3 3D LUT. " << result.encodingDescription << "\n";
        return;
    }
    std::cout << result.size << "^3 3D LUT, shaper " << result.shaper.describe() << "\n";
    if (!result.files.shaper.empty())
    {
        std::cout << "Wrote " << result.files.shaper
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
    cmd->add_option("--format", o->request.format,
                    "Default: the format of the output's extension (.clf, .ctf, .cube, .spi3d, "
                    ".3dl, .csp, .lut). clf, ctf, cube, spi3d, 3dl (scene-linear HDR through the "
                    "shaper); "
                    "resolve_cube, csp, houdini (display-referred [0, 1], with --shaper none; "
                    "or any with --encoding acescct/acescc). "
                    "ICC is not offered: an ICC profile describes a device, not a scene-linear "
                    "look");
    CLI::Option* size = cmd->add_option(
        "--size", o->size,
        "3D LUT size per axis; for CLF/CTF, giving it bakes a 3D LUT instead of the matrix");
    size->capture_default_str();
    CLI::Option* shaper =
        cmd->add_option("--shaper", o->request.shaper,
                        "Shaper into the 3D LUT's domain, for --encoding linear: log2 "
                        "(scene-linear -0.0005 to 131072) or none (linear 0 to 1)")
            ->capture_default_str();
    cmd->add_option("--encoding", o->request.encoding,
                    "What the LUT takes and returns: linear (the working space's linear values, "
                    "through --shaper), acescct or acescc (the 3D LUT takes and returns ACEScct "
                    "(S-2016-001) or ACEScc (S-2014-003) encoded values, encoded 0 to 1 = linear "
                    "-0.0069 (ACEScc: 0.0012) to 222.9; no shaper; every format). The encoding "
                    "is of the working space's linear values, as ACEScct encodes ACEScg (AP1): "
                    "with the default acescg the LUT is for ACEScct (ACEScc) itself")
        ->capture_default_str();
    cmd->add_option("-o,--out", o->request.out, "Output file")->required();
    cmd->callback([o, size, shaper] { RunLut(*o, size->count() > 0, shaper->count() > 0); });
}

}  // namespace bandlight::cli
