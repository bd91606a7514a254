// SPDX-License-Identifier: BSD-3-Clause
// `bandlight apply`: re-light images (and frame sequences) through
// OpenImageIO (jobs/ApplyJob).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/ApplyJob.h"
#include "spectral/Parallel.h"

namespace bandlight::cli
{

namespace
{

struct ApplyOptions
{
    jobs::ApplyRequest request;
    RelightOptions relight;
};

void RunApply(ApplyOptions& o)
{
    CommandReporter reporter;
    if (o.request.look.empty() && o.relight.given())
    {
        o.request.relight = o.relight.relight(reporter);
    }
    const jobs::ApplyResult result = jobs::ApplyImages(o.request, reporter);
    if (result.sequence)
    {
        std::cout << "Applied " << result.applied << " to " << result.frames << " frames\n";
    }
}

}  // namespace

void AddApplyCommand(CLI::App& app)
{
    auto o = std::make_shared<ApplyOptions>();
    jobs::ApplyRequest& r = o->request;
    CLI::App* cmd = app.add_subcommand(
        "apply", "Re-light an image or a frame sequence through OpenImageIO and OpenColorIO");
    cmd->add_option("IN", r.input, "Input image, or a pattern such as plate.####.exr")
        ->required();
    cmd->add_option("OUT", r.output, "Output image, or a pattern")->required();
    cmd->add_option("--look", r.look, "Look to apply, from --config");
    cmd->add_option("--config", r.config, "Config directory (or .ocio file) holding the look");
    cmd->add_option("--colorspace", r.colorspace,
                    "Colour space of the image in the config (default: its scene_linear role)");
    AddRelightOptions(*cmd, o->relight, false);
    cmd->add_option("--frames", r.frames, "Frame range for patterns, e.g. 1001-1100");
    cmd->add_option("--threads", r.threads, "Threads (0: all cores; at most 256)")
        ->check(CLI::Range(0, kMaxThreads))
        ->capture_default_str();
    cmd->callback([o] { RunApply(*o); });
}

}  // namespace bandlight::cli
