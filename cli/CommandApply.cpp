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

#include "jobs/ApplyJob.h"
#include "requests/Defaults.h"
#include "requests/Inputs.h"
#include "spectral/Parallel.h"
#include "spectral/TextFile.h"
#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Diagnostics.h"

namespace bandlight::cli
{

namespace
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

/// --look-inside / --look-outside FROM:TO as a change of light with the
/// command's --method, --working-space and plates.
jobs::RelightRequest SideChange(const ApplyOptions& o, const std::string& option,
                                const std::string& value, jobs::Reporter& reporter)
{
    const size_t colon = value.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == value.size())
    {
        throw ParameterError("{" + option + "} takes FROM:TO, or a look of {config=}DIR, got '" +
                             OneLine(value, 80) + "'");
    }
    RelightOptions side = o.relight;
    side.from = value.substr(0, colon);
    side.to = value.substr(colon + 1);
    return side.relight(reporter);
}

/// The looks of a config named in a message: every one of a small config;
/// of a large one, how many and the nearest to `value` (bandlight's own
/// configs hold 120 and more).
std::string LooksNear(const std::vector<std::string>& looks, const std::string& value)
{
    constexpr size_t kListed = 12;
    std::vector<std::string> shown = looks;
    if (looks.size() > kListed)
    {
        std::stable_sort(shown.begin(), shown.end(),
                         [&](const std::string& a, const std::string& b)
                         { return EditDistance(value, a) < EditDistance(value, b); });
        shown.resize(kListed);
    }
    std::string list;
    for (const std::string& name : shown)
    {
        list += (list.empty() ? "" : ", ") + name;
    }
    if (looks.empty())
    {
        return "it has no looks";
    }
    return looks.size() > kListed
               ? "it has " + std::to_string(looks.size()) + " looks, the nearest " + list
               : "its looks: " + list;
}

/// A side of the matte into the request: a look when --config has a look
/// of that name, FROM:TO otherwise. A value that is neither is named with
/// the config's looks.
void ResolveSide(ApplyOptions& o, const std::string& option, const std::string& value,
                 const std::vector<std::string>& looks, std::string& look,
                 std::optional<jobs::RelightRequest>& relight, jobs::Reporter& reporter)
{
    if (std::find(looks.begin(), looks.end(), value) != looks.end())
    {
        look = value;
        return;
    }
    if (o.request.config.empty())
    {
        relight = SideChange(o, option, value, reporter);
        return;
    }
    // Why it is no FROM:TO either, when it reads like one.
    std::string why;
    try
    {
        relight = SideChange(o, option, value, reporter);
        return;
    }
    catch (const ParameterError& e)
    {
        why = e.spelled(Face::COMMAND);
    }
    catch (const Exception& e)
    {
        why = e.what();
    }
    throw ParameterError(
        "{" + option + "} '" + OneLine(value, 80) + "' is no look of " + o.request.config +
        (value.find(':') == std::string::npos ? "" : ", nor FROM:TO (" + why + ")") + "; " +
        LooksNear(looks, value));
}

/// --light-group NAME=FROM:TO[@METHOD] (a change of light, with its own
/// method) or NAME=LAYER (where a file names the group otherwise) into the
/// request.
void AddLightGroup(ApplyOptions& o, const CLI::App& cmd, const std::string& item,
                   jobs::Reporter& reporter)
{
    {
        const size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
        {
            throw ParameterError(
                "{light_group} takes NAME=FROM:TO (or NAME=LAYER for a group "
                "the file names otherwise), got '" +
                OneLine(item, 80) + "'");
        }
        const std::string name = item.substr(0, eq);
        std::string value = item.substr(eq + 1);
        // A method of its own after '@' (key=A:D65@rootpoly); --method otherwise.
        std::string method;
        const size_t at = value.rfind('@');
        if (at != std::string::npos)
        {
            method = value.substr(at + 1);
            value = value.substr(0, at);
            if (method.empty() || value.find(':') == std::string::npos)
            {
                throw ParameterError("{light_group} " + OneLine(item, 80) +
                                     ": a group's own method follows its change of light, "
                                     "NAME=FROM:TO@METHOD");
            }
        }
        const size_t colon = value.rfind(':');
        if (colon == std::string::npos)
        {
            o.request.lightGroupLayers[name] = value;
            return;
        }
        if (colon == 0 || colon + 1 == value.size())
        {
            throw ParameterError("{light_group} " + OneLine(item, 80) +
                                 ": give both lights, NAME=FROM:TO");
        }
        RelightOptions group = o.relight;
        group.from = value.substr(0, colon);
        group.to = value.substr(colon + 1);
        if (!method.empty())
        {
            (void)ParseMethod(method);  // an unknown one is named at its line, now
            group.method = method;
        }
        const CLI::Option* plates = cmd.get_option_no_throw("--plates");
        if (!plates || plates->count() == 0)
        {
            // A render's group holds its own light's cast: lit, unless the
            // user says the render was balanced.
            group.plates.plates = defaults::LIGHT_GROUP_PLATES;
        }
        o.request.lightGroups.push_back({name, group.relight(reporter)});
    }
}

/// The lines of --light-group-file after the command line's groups: one
/// NAME=FROM:TO[@METHOD] (or NAME=LAYER) per line, blank lines and comments
/// skipped (a '#' that starts a line or follows a space or tab, to the end
/// of the line), lines ended by LF, CRLF or CR alone; each remembered with
/// its line for the messages.
void ReadLightGroupFile(ApplyOptions& o, const CLI::App& cmd)
{
    o.lightGroupSources.assign(o.lightGroups.size(), "");
    if (o.lightGroupFile.empty())
    {
        if (cmd.count("--light-group-file") > 0)
        {
            throw ParameterError("{light_group_file} is an empty path: give the file of "
                                 "NAME=FROM:TO lines");
        }
        return;
    }
    std::string text = ReadTextFile(o.lightGroupFile, "light-group file");
    CheckUtf8Text(text, o.lightGroupFile);
    // CRLF and CR-only line ends (old Mac editors) as LF.
    std::string lines;
    lines.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i)
    {
        if (text[i] == '\r')
        {
            lines += '\n';
            i += i + 1 < text.size() && text[i + 1] == '\n' ? 1 : 0;
        }
        else
        {
            lines += text[i];
        }
    }
    std::istringstream in(lines);
    std::string line;
    size_t number = 0;
    while (std::getline(in, line))
    {
        ++number;
        for (size_t hash = line.find('#'); hash != std::string::npos; hash = line.find('#', hash + 1))
        {
            if (hash == 0 || line[hash - 1] == ' ' || line[hash - 1] == '\t')
            {
                line.erase(hash);  // a comment, to the end of the line
                break;
            }
        }
        const size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos)
        {
            continue;
        }
        const size_t last = line.find_last_not_of(" \t");
        o.lightGroups.push_back(line.substr(first, last - first + 1));
        o.lightGroupSources.push_back(SourcePosition(o.lightGroupFile, number));
    }
    if (o.lightGroups.size() == o.lightGroupSources.size() &&
        std::all_of(o.lightGroupSources.begin(), o.lightGroupSources.end(),
                    [](const std::string& s) { return s.empty(); }))
    {
        throw Exception(o.lightGroupFile + ": lists no light group (one NAME=FROM:TO per line)");
    }
}

void AddLightGroups(ApplyOptions& o, const CLI::App& cmd, jobs::Reporter& reporter)
{
    for (size_t i = 0; i < o.lightGroups.size(); ++i)
    {
        try
        {
            AddLightGroup(o, cmd, o.lightGroups[i], reporter);
        }
        catch (const ParameterError& e)
        {
            if (o.lightGroupSources[i].empty())
            {
                throw;
            }
            // A file's line: named by its position, not by the option.
            throw Exception(o.lightGroupSources[i] + ": " + e.spelled(Face::COMMAND));
        }
        catch (const FileError& e)
        {
            if (o.lightGroupSources[i].empty())
            {
                throw;
            }
            throw Exception(o.lightGroupSources[i] + ": " + e.spelled(Face::COMMAND));
        }
        catch (const Exception& e)
        {
            if (o.lightGroupSources[i].empty())
            {
                throw;
            }
            // An unknown illuminant or method of a file's line: its position too.
            throw Exception(o.lightGroupSources[i] + ": " + e.what());
        }
    }
}

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
