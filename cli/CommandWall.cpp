// SPDX-License-Identifier: BSD-3-Clause
// `bandlight wall`: an LED wall or fixture as the camera sees it in the
// frustum and as a light outside it, as an OCIO config (jobs/WallJob).
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/WallJob.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::cli
{

namespace
{

struct WallCommandOptions
{
    jobs::WallRequest request;
    std::vector<std::string> emitters;
    std::vector<std::string> whiteBalances;
    bool json = false;
};

void RunWall(WallCommandOptions& o, const CLI::App& cmd)
{
    jobs::WallRequest& r = o.request;
    for (const std::string& e : o.emitters)
    {
        r.emitters.push_back(jobs::ParseEmitter(e));
    }
    // Each value may also be a comma-separated list: 5600K,3200K.
    for (const std::string& w : o.whiteBalances)
    {
        for (const std::string& item : jobs::SplitList(w))
        {
            r.whiteBalances.push_back(item);
        }
    }
    if (cmd.count("--out") == 0)
    {
        throw ParameterError("give the folder the config goes into as {out=}DIR");
    }
    CommandReporter reporter;
    const jobs::WallResult result = jobs::MakeWall(r, reporter);
    std::cout << (o.json ? jobs::WallDocument(result) + "\n" : jobs::WallReport(result));
    std::cerr << "wall: wrote " << result.written[0] << ", " << result.written[1] << " and "
              << result.written.size() - 2 << " transform files\n";
}

}  // namespace

void AddWallCommand(CLI::App& app)
{
    auto o = std::make_shared<WallCommandOptions>();
    jobs::WallRequest& r = o->request;
    CLI::App* cmd = app.add_subcommand(
        "wall",
        "An LED wall or fixture: the in-frustum drive that makes the camera record the content as "
        "intended, and the out-of-frustum corrections (lighting content, plate) with their "
        "errors, per camera white balance, as an OCIO config selected by $WALL_WB");
    cmd->add_option("--emitter", o->emitters,
                    "NAME=FILE for each emitter, at least three, in drive-channel order: its "
                    "spectrum at full drive (CSV or CGATS, any grid)");
    cmd->add_option("--camera", r.camera,
                    "Camera sensitivities: rawtoaces JSON, CSV or CGATS with R, G, B");
    cmd->add_option("--white-balance", o->whiteBalances,
                    "The camera's white balances: colour temperatures (5600K: daylight from 4000 "
                    "K, Planckian below), built-in names or spectrum files; the first is the "
                    "config's default");
    cmd->add_option("--content-space", r.contentSpace,
                    "The RGB space of the wall's content: " + RgbSpaceChoices());
    cmd->add_option("--out", r.out,
                    "The folder config.ocio, its CLF files and report.json go into");
    cmd->add_option("--training", r.training,
                    "Remittances the IDTs and corrections are fitted on (a file, or TCS); default "
                    "rawtoaces' 190");
    cmd->add_option("--test-set", r.testSet,
                    "Remittances the errors are also measured on (a file, or TCS)")
        ->capture_default_str();
    cmd->add_flag("--json", o->json, "Print report.json's document instead of the text report");
    cmd->callback([o, cmd] { RunWall(*o, *cmd); });
}

}  // namespace bandlight::cli
