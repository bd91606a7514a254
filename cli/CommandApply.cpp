// SPDX-License-Identifier: BSD-3-Clause
// `bandlight apply`: re-light images (and frame sequences) through
// OpenImageIO (jobs/ApplyJob).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Diagnostics.h"
#include "bandlight/jobs/ApplyJob.h"
#include "bandlight/spectral/Parallel.h"

namespace bandlight::cli
{

namespace
{

struct ApplyOptions
{
    jobs::ApplyRequest request;
    RelightOptions relight;
};

void RunApply(ApplyOptions& o, const CLI::App& cmd)
{
    FrameSetReporter reporter;
    const std::vector<std::string> given = GivenRelightOptions(cmd);
    if (!o.request.look.empty() && !given.empty())
    {
        std::string names;
        for (const std::string& n : given)
        {
            names += (names.empty() ? "" : ", ") + n;
        }
        throw ParameterError("{look} applies a look of {config} as it is: " + names +
                             " do not apply to it (give the look, or the change of light)");
    }
    if (o.request.look.empty() && o.relight.given())
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
    cmd->add_option("--config", r.config, "Config directory (or .ocio file) holding the look");
    cmd->add_option("--colorspace", r.colorspace,
                    "With --look: the image's colour space in the config (default: scene_linear, "
                    "the image converted to it from what the file says). Without: what the file "
                    "holds instead of what its tags say, a built-in space (acescg, rec709, ...) "
                    "or srgb");
    AddRelightOptions(*cmd, o->relight, false);
    AddFrameSetOptions(*cmd, r.frames, r.skipExisting, r.keepGoing, r.threads);
    cmd->callback([o, cmd] { RunApply(*o, *cmd); });
}

}  // namespace bandlight::cli
