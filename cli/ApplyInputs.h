// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `bandlight apply`'s options, and what its flags name resolved into its
// request: the sides of a matte and the light groups.

#include <optional>
#include <string>
#include <vector>

#include "cli/Common.h"
#include "jobs/ApplyJob.h"

namespace bandlight::cli
{

struct ApplyOptions
{
    jobs::ApplyRequest request;
    RelightOptions relight;
    std::vector<std::string> lightGroups;  ///< NAME=FROM:TO or NAME=LAYER
    /// Where each of lightGroups came from: "" for the command line,
    /// "FILE:LINE" for a --light-group-file line.
    std::vector<std::string> lightGroupSources;
    std::string lightGroupFile;  ///< one NAME=FROM:TO[@METHOD] per line
    std::string lookInside;      ///< FROM:TO, or a look of --config
    std::string lookOutside;
};

/// A side of the matte into the request: a look when --config has a look
/// of that name (`looks`), FROM:TO otherwise. A value that is neither is
/// named with the config's looks.
void ResolveSide(ApplyOptions& o, const std::string& option, const std::string& value,
                 const std::vector<std::string>& looks, std::string& look,
                 std::optional<jobs::RelightRequest>& relight, jobs::Reporter& reporter);

/// The lines of --light-group-file after the command line's groups: one
/// NAME=FROM:TO[@METHOD] (or NAME=LAYER) per line, blank lines and comments
/// skipped, each remembered with its line for the messages.
void ReadLightGroupFile(ApplyOptions& o, const CLI::App& cmd);

/// Every light group of the command line and the file into the request; a
/// file's line that is wrong is named by its position.
void AddLightGroups(ApplyOptions& o, const CLI::App& cmd, jobs::Reporter& reporter);

}  // namespace bandlight::cli
