// SPDX-License-Identifier: BSD-3-Clause
// `bandlight methods`: every illuminant-change method, as it describes itself.
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "jobs/MethodsJob.h"

namespace bandlight::cli
{

namespace
{
void RunMethods(bool json)
{
    const std::vector<jobs::MethodInfo> methods = jobs::ListMethods();
    if (json)
    {
        std::cout << jobs::MethodsDocument(methods) << "\n";
        return;
    }
    for (const jobs::MethodInfo& m : methods)
    {
        std::cout << m.names << " (" << m.exactness << (m.native ? ", native in apply" : "")
                  << (m.needsCamera ? ", needs --camera" : "");
        if (m.trainingSize > 0)
        {
            std::cout << ", fitted on " << m.trainingSize << " remittances"
                      << (m.takesTraining ? " or --training" : "");
        }
        std::cout << ")\n  " << m.description << "\n";
    }
}
}  // namespace

void AddMethodsCommand(CLI::App& app)
{
    auto json = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand(
        "methods", "Every illuminant-change method: its names, how exact it is, what it does");
    cmd->add_flag("--json", *json, "Write JSON");
    cmd->callback([json] { RunMethods(*json); });
}

}  // namespace bandlight::cli
