// SPDX-License-Identifier: BSD-3-Clause
// What `bandlight apply`'s flags name, resolved into its request: the two
// sides of a matte (a look of --config, or FROM:TO) and the light groups of
// --light-group and --light-group-file.
#include "cli/ApplyInputs.h"

#include <algorithm>

#include "cli/Diagnostics.h"
#include "requests/Inputs.h"
#include "spectral/TextFile.h"

namespace bandlight::cli
{

namespace
{

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

}  // namespace

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
            throw ParameterError(
                "{light_group_file} is an empty path: give the file of "
                "NAME=FROM:TO lines");
        }
        return;
    }
    std::string text = ReadTextFile(o.lightGroupFile, "light-group file");
    CheckUtf8Text(text, o.lightGroupFile);
    for (const ListLine& line : ListLines(text))
    {
        o.lightGroups.push_back(line.text);
        o.lightGroupSources.push_back(SourcePosition(o.lightGroupFile, line.number));
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

}  // namespace bandlight::cli
