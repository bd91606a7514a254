// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What the command's subcommands share: the options that map onto the
// jobs' requests, and the reporter that prints the jobs' notes.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "farm/Frames.h"
#include "requests/Inputs.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{

using jobs::Fixed;

/// The jobs' notes as "note: ..." lines and their progress lines on stderr
/// (cli/Diagnostics.h: shown when the run succeeds, progress at once on a
/// terminal).
class CommandReporter : public jobs::Reporter
{
public:
    void note(const std::string& line) override;
    void progress(const std::string& line, double fraction) override;
};

/// Notes as every command prints them; a progress line per frame on a
/// terminal only (a farm's log gets the closing summary).
class FrameSetReporter : public CommandReporter
{
public:
    void progress(const std::string& line, double fraction) override;
};

/// Adds --observer with its check and default.
CLI::Option* AddObserverOption(CLI::App& app, std::string& value);

/// Adds --lut-size with its range and default.
CLI::Option* AddLutSizeOption(CLI::App& app, int& value, const std::string& help);

/// Adds --plates/--adaptation/--camera/--camera-idt. `allowBoth`: --plates
/// also takes "both" (accuracy measures the two conventions).
void AddPlatesOptions(CLI::App& app, jobs::PlatesRequest& o, bool allowBoth = false);

/// The plate conventions' and the plates' adaptations' keys, from their
/// tables (transforms/Plates.h), for CLI11's IsMember checks.
std::vector<std::string> PlateConventionKeys();
std::vector<std::string> PlateAdaptationKeys();

/// --from/--to/--method/--working-space and the plates: an illuminant
/// change without a config, as the command takes it (the lights by name or
/// file, resolved by relight()).
struct RelightOptions
{
    std::string from;
    std::string to;
    std::string method = defaults::METHOD;
    std::string workingSpace = defaults::WORKING_SPACE;
    jobs::PlatesRequest plates;

    bool given() const { return !from.empty() && !to.empty(); }
    /// The request: the two lights resolved.
    jobs::RelightRequest relight(jobs::Reporter& reporter) const;
};

/// Adds the options above to a command.
void AddRelightOptions(CLI::App& app, RelightOptions& o, bool required);

/// The options of AddRelightOptions that the command line gave, by their
/// parameter names ("src" for --from, "method", "working_space", ...), to
/// refuse them where they do not apply (jobs::ApplyRequest::changeGiven).
std::vector<std::string> GivenRelightOptions(const CLI::App& app);

/// --frames, --skip-existing, --keep-going and --threads, as `apply` and
/// `spectral` take them.
void AddFrameSetOptions(CLI::App& app, std::string& frames, bool& skipExisting, bool& keepGoing,
                        int& threads);

/// After a frame set: "VERB N frames (S skipped, F failed) in T s" on stdout
/// (the counts when `counts`), and, when frames failed, an Exception (exit
/// code 2) in one line naming how many and the first of them.
void FinishFrameRun(const std::string& verb, const jobs::FrameRun& run, bool counts);

/// The --method help: every method name.
inline std::string MethodHelp()
{
    return SpellParameters(MethodSyntax(), Face::COMMAND);
}

/// "a, b, c".
std::string JoinNames(const std::vector<std::string>& names);

/// Levenshtein distance (insertions, deletions, substitutions), for "did
/// you mean" on a mistyped command.
size_t EditDistance(const std::string& a, const std::string& b);

}  // namespace bandlight::cli
