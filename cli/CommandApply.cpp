// SPDX-License-Identifier: BSD-3-Clause
// `bandlight apply`: re-light images (and frame sequences) through
// OpenImageIO (jobs/ApplyJob).
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/ApplyInputs.h"
#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Diagnostics.h"
#include "jobs/ApplyJob.h"
#include "requests/Defaults.h"
#include "requests/Inputs.h"
#include "spectral/Parallel.h"
#include "spectral/TextFile.h"

namespace bandlight::cli
{

namespace
{

void RunApply(ApplyOptions& o, const CLI::App& cmd)
{
    FrameSetReporter reporter;
    ReadLightGroupFile(o, cmd);
    const std::vector<std::string> given = GivenRelightOptions(cmd);
    o.request.changeGiven = given;
    jobs::CheckLookAlone(o.request);
    if (!o.request.matte.empty() || !o.lookInside.empty() || !o.lookOutside.empty())
    {
        const bool lights =
            std::any_of(given.begin(), given.end(),
                        [](const std::string& n) { return n == "src" || n == "dst"; });
        if (!o.request.look.empty() || !o.lightGroups.empty() || !o.lightGroupFile.empty() ||
            lights)
        {
            throw ParameterError(
                "{matte} relights each side with its own change of light: "
                "{look}, {src}/{dst} and {light_group} do not apply to it");
        }
        if (o.request.matte.empty() || o.lookInside.empty() || o.lookOutside.empty())
        {
            throw ParameterError(
                "give {matte=}MATTE.exr[:CHANNEL] with {look_inside=}FROM:TO "
                "and {look_outside=}FROM:TO (or looks of {config=}DIR)");
        }
        std::vector<std::string> looks;
        if (!o.request.config.empty())
        {
            const OCIO_NAMESPACE::ConstConfigRcPtr config = jobs::LoadConfig(o.request.config);
            for (int i = 0; i < config->getNumLooks(); ++i)
            {
                looks.emplace_back(config->getLookNameByIndex(i));
            }
        }
        ResolveSide(o, "look_inside", o.lookInside, looks, o.request.insideLook,
                    o.request.insideRelight, reporter);
        ResolveSide(o, "look_outside", o.lookOutside, looks, o.request.outsideLook,
                    o.request.outsideRelight, reporter);
        if (!o.request.insideLook.empty() && !o.request.outsideLook.empty() && !given.empty())
        {
            std::string names;
            for (const std::string& n : given)
            {
                names += (names.empty() ? "{" : ", {") + n + "}";
            }
            throw ParameterError(
                "{look_inside} and {look_outside} are looks of {config}, "
                "applied as they are: " +
                names + " do not apply to them");
        }
    }
    else if (!o.lightGroups.empty())
    {
        if (!o.request.look.empty())
        {
            throw ParameterError(
                "{look} applies one look to the whole image: {light_group} "
                "does not apply to it (give the change of light per group)");
        }
        for (const char* name : {"--from", "--to"})
        {
            const CLI::Option* option = cmd.get_option_no_throw(name);
            if (option && option->count() > 0)
            {
                throw ParameterError(
                    std::string(name == std::string("--from") ? "{src}" : "{dst}") +
                    " does not apply with {light_group}: each group takes its "
                    "own, NAME=FROM:TO");
            }
        }
        AddLightGroups(o, cmd, reporter);
        if (o.request.lightGroups.empty())
        {
            throw ParameterError(
                "{light_group} NAME=LAYER only says where a group is: relight "
                "at least one group with NAME=FROM:TO");
        }
    }
    else if (o.request.look.empty() && o.relight.given())
    {
        o.request.relight = o.relight.relight(reporter);
    }
    const jobs::ApplyResult r = jobs::ApplyImages(o.request, reporter);
    if (!r.sequence)
    {
        // One line on success, as every command that writes says what it wrote.
        std::cout << "Applied " << r.applied << " to " << o.request.input << "; wrote "
                  << o.request.output << "\n";
        return;
    }
    jobs::FrameRun run;
    run.frames = r.frames;
    run.skipped = r.skipped;
    run.failed = r.failed;
    run.seconds = r.seconds;
    FinishFrameRun("Applied " + r.applied + " to", run,
                   o.request.skipExisting || o.request.keepGoing);
}

}  // namespace

void AddApplyCommand(CLI::App& app)
{
    auto o = std::make_shared<ApplyOptions>();
    jobs::ApplyRequest& r = o->request;
    CLI::App* cmd = app.add_subcommand(
        "apply", "Re-light an image or a frame sequence through OpenImageIO and OpenColorIO");
    cmd->add_option("IN", r.input, "Input image, or a pattern such as plate.####.exr")->required();
    cmd->add_option("OUT", r.output, "Output image, or a pattern")->required();
    cmd->add_option("--look", r.look, "Look to apply, from --config");
    cmd->add_option("--config", r.config,
                    "Config directory (or .ocio file) holding the look (or a matte's looks)");
    cmd->add_option("--colorspace", r.colorspace,
                    "With --look (or a matte's looks): the image's colour space in the config "
                    "(default: scene_linear, the image converted to it from what the file says). "
                    "Without: what the file holds instead of what its tags say, a built-in space "
                    "(acescg, rec709, ...) or srgb");
    AddRelightOptions(*cmd, o->relight, false);
    cmd->add_option("--light-group", o->lightGroups,
                    "Relight one light group of a multi-layer EXR on its own: NAME=FROM:TO, "
                    "or NAME=FROM:TO@METHOD with a method of its own (repeatable; --method, "
                    "--working-space and the plates apply to each; "
                    "--plates defaults to " +
                        std::string(defaults::LIGHT_GROUP_PLATES) +
                        " here). The beauty becomes the sum of the groups plus the residual. "
                        "NAME=LAYER names where a group is when the file's naming is not "
                        "Blender's, Arnold's or bandlight's (a layer prefix, or r,g,b channels)");
    cmd->add_option("--light-group-beauty", o->request.lightGroupBeauty,
                    "What a relit light-group file's beauty is made of: residual (the relit "
                    "groups + beauty - groups as read; the default, the groups checked to sum to "
                    "the beauty), rebuild (the relit groups alone: a denoised beauty whose groups "
                    "are noisy) or difference (the denoised beauty's difference from the groups "
                    "carried); the output's bandlight:transform says which");
    cmd->add_option("--light-group-file", o->lightGroupFile,
                    "The light groups of a shot with many: one --light-group value per line "
                    "(NAME=FROM:TO[@METHOD] or NAME=LAYER; # comments), after any given on "
                    "the command line");
    cmd->add_option("--matte", r.matte,
                    "A matte (MATTE.exr, or MATTE.exr:CHANNEL; default its A, Y or only "
                    "channel) for a plate lit by two lights: --look-inside relights where the "
                    "matte is 1, --look-outside where it is 0, mixed by it between");
    cmd->add_option("--look-inside", o->lookInside,
                    "With --matte: the change of light inside the matte, a look of --config "
                    "(applied as --look is, in --colorspace of the config or its scene_linear) "
                    "or FROM:TO (--method and the plates apply)");
    cmd->add_option("--look-outside", o->lookOutside,
                    "With --matte: the change of light outside the matte, a look of --config "
                    "or FROM:TO");
    AddFrameSetOptions(*cmd, r.frames, r.skipExisting, r.keepGoing, r.threads);
    cmd->callback([o, cmd] { RunApply(*o, *cmd); });
}

}  // namespace bandlight::cli
