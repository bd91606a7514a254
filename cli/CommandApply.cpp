// SPDX-License-Identifier: BSD-3-Clause
// `bandlight apply`: re-light images (and frame sequences) through
// OpenImageIO (jobs/ApplyJob).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Diagnostics.h"
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

/// Notes as every command prints them; a line per frame on a terminal only
/// (a farm's log gets the summary).
class FrameReporter : public CommandReporter
{
public:
    void progress(const std::string& line, double fraction) override
    {
        if (fraction < 0.0 || StderrIsTerminal())
        {
            CommandReporter::progress(line, fraction);
        }
    }
};

void RunApply(ApplyOptions& o)
{
    FrameReporter reporter;
    if (o.request.look.empty() && o.relight.given())
    {
        o.request.relight = o.relight.relight(reporter);
    }
    const jobs::ApplyResult r = jobs::ApplyImages(o.request, reporter);
    if (!r.sequence)
    {
        return;
    }
    std::cout << "Applied " << r.applied << " to " << r.frames << " frames";
    if (o.request.skipExisting || o.request.keepGoing)
    {
        std::cout << " (" << r.skipped << " skipped, " << r.failed.size() << " failed)";
    }
    std::cout << " in " << Fixed(r.seconds, 2) << " s\n";
    if (!r.failed.empty())
    {
        // Exit code 2, and one line: how many, and the first of them.
        throw Exception(std::to_string(r.failed.size()) + " of " +
                        std::to_string(r.frames + r.skipped + r.failed.size()) +
                        " frames failed; the first, frame " + std::to_string(r.failed[0].frame) +
                        ": " + r.failed[0].error);
    }
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
    cmd->add_option("--frames", r.frames,
                    "Frames for patterns, as farms hand them out: 1001-1100, 1001-1100x2, "
                    "1001-1010,1020");
    cmd->add_flag("--skip-existing", r.skipExisting,
                  "Skip frames whose output exists (outputs are written whole or not at all)");
    cmd->add_flag("--keep-going", r.keepGoing,
                  "Go on after a frame fails; at the end name the failed frames and exit 2");
    cmd->add_option("--threads", r.threads, "Threads (0: all cores; at most 256)")
        ->check(CLI::Range(0, kMaxThreads))
        ->capture_default_str();
    cmd->callback([o] { RunApply(*o); });
}

}  // namespace bandlight::cli
