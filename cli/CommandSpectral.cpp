// SPDX-License-Identifier: BSD-3-Clause
// `bandlight spectral`: spectral EXRs integrated, or relit exactly, to RGB
// (jobs/SpectralJob).
#include <iostream>
#include <memory>

#include "requests/Defaults.h"
#include "jobs/SpectralJob.h"
#include "spectral/Parallel.h"
#include "spectral/RgbSpaces.h"
#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Diagnostics.h"

namespace bandlight::cli
{

namespace
{

struct SpectralCommandOptions
{
    jobs::SpectralRequest request;
    std::string from;
    std::string to;
    std::vector<std::string> channels;     ///< NAME=NM
    std::vector<std::string> lightGroups;  ///< NAME=FROM:TO
};

void RunSpectral(SpectralCommandOptions& o, const CLI::App& cmd)
{
    FrameSetReporter reporter;
    jobs::SpectralOptions& s = o.request.options;
    for (const std::string& item : o.lightGroups)
    {
        const size_t eq = item.find('=');
        const size_t colon = item.rfind(':');
        if (eq == std::string::npos || eq == 0 || colon == std::string::npos || colon < eq + 2 ||
            colon + 1 == item.size())
        {
            throw ParameterError("{light_group} takes NAME=FROM:TO, got '" + OneLine(item, 80) +
                                 "'");
        }
        s.lightGroups.push_back(
            {item.substr(0, eq),
             jobs::ResolveIlluminant(item.substr(eq + 1, colon - eq - 1), reporter),
             jobs::ResolveIlluminant(item.substr(colon + 1), reporter)});
    }
    const CLI::Option* plates = cmd.get_option_no_throw("--plates");
    if (!s.lightGroups.empty() && (!plates || plates->count() == 0))
    {
        s.plates.plates = defaults::LIGHT_GROUP_PLATES;
    }
    if (!o.from.empty())
    {
        s.from = jobs::ResolveIlluminant(o.from, reporter);
    }
    if (!o.to.empty())
    {
        s.to = jobs::ResolveIlluminant(o.to, reporter);
    }
    for (const std::string& c : o.channels)
    {
        const size_t eq = c.rfind('=');
        char* end = nullptr;
        const double nm = eq == std::string::npos ? 0.0 : std::strtod(c.c_str() + eq + 1, &end);
        if (eq == std::string::npos || eq == 0 || !end || *end != '\0' || !(nm > 0.0))
        {
            throw Exception("--channel takes NAME=WAVELENGTH_NM, got '" + OneLine(c, 80) + "'");
        }
        s.channelWavelengths[c.substr(0, eq)] = nm;
    }
    const jobs::SpectralResult r = jobs::ConvertSpectralImages(o.request, reporter);
    std::cout << "Read " << r.layout << "; " << r.applied << "\n";
    if (r.run.sequence)
    {
        FinishFrameRun("Wrote", r.run, o.request.files.skipExisting || o.request.files.keepGoing);
    }
}

}  // namespace

void AddSpectralCommand(CLI::App& app)
{
    auto o = std::make_shared<SpectralCommandOptions>();
    jobs::SpectralRequest& r = o->request;
    jobs::SpectralOptions& s = r.options;
    CLI::App* cmd = app.add_subcommand(
        "spectral",
        "Integrate a spectral EXR (Fichet 2021, pbrt-v4 spectral film, named channels) to an "
        "RGB EXR, or relight it exactly");
    cmd->add_option("IN", r.files.input, "Spectral EXR, or a pattern such as shot.####.exr")
        ->required();
    cmd->add_option("OUT", r.files.output, "RGB EXR, or a pattern")->required();
    cmd->add_option("--from", o->from,
                    "Emissive images: the light the scene was lit by (with --to: relight)");
    cmd->add_option("--to", o->to,
                    "Emissive images: the light to relight to (scaled to --from's luminance); "
                    "reflective images: the light to render under");
    cmd->add_option("--working-space", s.workingSpace,
                    "Linear RGB space of the output: " + RgbSpaceChoices())
        ->capture_default_str();
    cmd->add_option("--plates", s.plates.plates,
                    "balanced: white-balance the result from the light it shows to the working "
                    "white; lit: do not")
        ->check(CLI::IsMember(PlateConventionKeys(), CLI::ignore_case))
        ->capture_default_str();
    cmd->add_option("--adaptation", s.plates.adaptation,
                    "Balance with one of " + PlateAdaptationChoices())
        ->check(CLI::IsMember(PlateAdaptationKeys(), CLI::ignore_case))
        ->capture_default_str();
    AddObserverOption(*cmd, s.observer);
    cmd->add_option("--channel", o->channels,
                    "A channel named otherwise and its wavelength: NAME=NM (repeatable; Mitsuba "
                    "3's specfilm)");
    cmd->add_option("--channel-wavelengths", s.channelWavelengthsFile,
                    "CSV of 'channel,wavelength_nm' rows, or of sensitivities (a wavelength "
                    "column, one column per channel: each at its centroid)");
    cmd->add_option("--kind", s.kind, "What named channels hold: " + jobs::SpectralKindChoices())
        ->check(CLI::IsMember(jobs::SpectralKindKeys(), CLI::ignore_case))
        ->capture_default_str();
    cmd->add_option("--sampling", s.sampling, jobs::SpectralSamplingHelp())
        ->check(CLI::IsMember(jobs::SpectralSamplingKeys(), CLI::ignore_case))
        ->capture_default_str();
    AddFrameSetOptions(*cmd, r.files.frames, r.files.skipExisting, r.files.keepGoing, r.threads);
    cmd->add_option("--light-group", o->lightGroups,
                    "Relight one spectral light group (<group>.S0.<nm> channels, as render "
                    "--spectra --light-groups writes them) exactly: NAME=FROM:TO (repeatable; "
                    "groups not named and the residual are integrated as they are; --plates "
                    "defaults to " +
                        std::string(defaults::LIGHT_GROUP_PLATES) +
                        " here). Writes the beauty and each group's R, G, B");
    cmd->callback([o, cmd] { RunSpectral(*o, *cmd); });
}

}  // namespace bandlight::cli
