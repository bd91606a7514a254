// SPDX-License-Identifier: BSD-3-Clause
#include "cli/Common.h"
#include "spectral/Parallel.h"

#include <algorithm>
#include <iostream>
#include <vector>

#include "cli/Diagnostics.h"
#include "requests/Defaults.h"
#include "spectral/RgbSpaces.h"
#include "transforms/Plates.h"

namespace bandlight::cli
{

void CommandReporter::note(const std::string& line)
{
    Note(SpellParameters(line, Face::COMMAND));
}

void CommandReporter::progress(const std::string& line, double)
{
    if (!line.empty())
    {
        Progress(line);
    }
}

CLI::Option* AddObserverOption(CLI::App& app, std::string& value)
{
    value = defaults::OBSERVER;
    return app.add_option("--observer", value, "CIE standard observer: 1931 (2°) or 1964 (10°)")
        ->capture_default_str();
}

CLI::Option* AddLutSizeOption(CLI::App& app, int& value, const std::string& help)
{
    return app.add_option("--lut-size", value, help)
        ->check(CLI::Range(defaults::MIN_LUT_SIZE, defaults::MAX_LUT_SIZE))
        ->capture_default_str();
}

std::string JoinNames(const std::vector<std::string>& names)
{
    std::string out;
    for (const std::string& n : names)
    {
        out += (out.empty() ? "" : ", ") + n;
    }
    return out;
}

void AddRelightOptions(CLI::App& app, RelightOptions& o, bool required)
{
    CLI::Option* from =
        app.add_option("--from", o.from, "Illuminant the image is lit by (name or spectrum file)");
    CLI::Option* to =
        app.add_option("--to", o.to, "Illuminant it should look lit by (name or spectrum file)");
    app.add_option("--method", o.method, MethodHelp())->capture_default_str();
    app.add_option("--working-space", o.workingSpace,
                   "Linear working space of the image: " + RgbSpaceChoices())
        ->capture_default_str();
    AddPlatesOptions(app, o.plates);
    if (required)
    {
        from->required();
        to->required();
    }
}

std::vector<std::string> GivenRelightOptions(const CLI::App& app)
{
    std::vector<std::string> given;
    const std::pair<const char*, const char*> options[] = {
        {"--from", "src"},           {"--to", "dst"},       {"--method", "method"},
        {"--working-space", "working_space"}, {"--plates", "plates"}, {"--adaptation", "adaptation"},
        {"--camera", "camera"},      {"--camera-idt", "camera_idt"}};
    for (const auto& [flag, parameter] : options)
    {
        const CLI::Option* option = app.get_option_no_throw(flag);
        if (option && option->count() > 0)
        {
            given.push_back(parameter);
        }
    }
    return given;
}

jobs::RelightRequest RelightOptions::relight(jobs::Reporter& reporter) const
{
    jobs::RelightRequest r;
    r.src = jobs::ResolveIlluminant(from, reporter);
    r.dst = jobs::ResolveIlluminant(to, reporter);
    r.method = method;
    r.workingSpace = workingSpace;
    r.plates = plates;
    return r;
}

std::vector<std::string> PlateConventionKeys()
{
    std::vector<std::string> keys;
    for (const PlateConventionEntry& e : PlateConventions())
    {
        keys.push_back(e.key);
    }
    return keys;
}

std::vector<std::string> PlateAdaptationKeys()
{
    std::vector<std::string> keys;
    for (const AdaptationEntry& e : PlateAdaptations())
    {
        keys.push_back(e.key);
    }
    return keys;
}

void AddPlatesOptions(CLI::App& app, jobs::PlatesRequest& o, bool allowBoth)
{
    std::string plates = "What the images are:";
    for (const PlateConventionEntry& e : PlateConventions())
    {
        plates += std::string(plates.back() == ':' ? " " : " or ") + e.key + " (" + e.help + ")";
    }
    app.add_option("--plates", o.plates, plates + (allowBoth ? "; both: measure the two" : ""))
        ->capture_default_str();
    app.add_option("--adaptation", o.adaptation,
                   "Chromatic adaptation the balanced plates were balanced with: " +
                       PlateAdaptationChoices() + " (cat02 as rawtoaces)")
        ->capture_default_str();
    // The methods that need a camera, as the registry names them.
    std::string cameraMethods;
    for (const MethodEntry& e : Methods())
    {
        if (e.needsCamera)
        {
            cameraMethods += (cameraMethods.empty() ? "" : ", ") + std::string(e.syntax);
        }
    }
    app.add_option("--camera", o.camera,
                   "The camera's spectral sensitivities (rawtoaces JSON, or CSV/CGATS with R, G, B "
                   "columns): enables " +
                       cameraMethods + ", and accuracy simulates that camera's plates");
    app.add_option("--camera-idt", o.idtLight,
                   "The light the camera's one fixed IDT was fitted for (the plates of " +
                       cameraMethods + ": that IDT plus white-balance gains)")
        ->capture_default_str();
}

void FrameSetReporter::progress(const std::string& line, double fraction)
{
    if (fraction < 0.0 || StderrIsTerminal())
    {
        CommandReporter::progress(line, fraction);
    }
}

void AddFrameSetOptions(CLI::App& app, std::string& frames, bool& skipExisting, bool& keepGoing,
                        int& threads)
{
    app.add_option("--frames", frames,
                   "Frames for patterns, as farms hand them out: 1001-1100, 1001-1100x2, "
                   "1001-1010,1020");
    app.add_flag("--skip-existing", skipExisting,
                 "Skip frames whose output exists (outputs are written whole or not at all)");
    app.add_flag("--keep-going", keepGoing,
                 "Go on after a frame fails; at the end name the failed frames and exit 2");
    app.add_option("--threads", threads, "Threads (0: all cores; at most 256)")
        ->check(CLI::Range(0, kMaxThreads))
        ->capture_default_str();
}

void FinishFrameRun(const std::string& verb, const jobs::FrameRun& run, bool counts)
{
    std::cout << verb << " " << run.frames << (run.frames == 1 ? " frame" : " frames");
    if (counts)
    {
        std::cout << " (" << run.skipped << " skipped, " << run.failed.size() << " failed)";
    }
    std::cout << " in " << Fixed(run.seconds, 2) << " s\n";
    if (!run.failed.empty())
    {
        // Every failed frame by number (the first twenty), the first's reason.
        std::string frames;
        for (size_t i = 0; i < run.failed.size() && i < 20; ++i)
        {
            frames += (i ? ", " : "") + std::to_string(run.failed[i].frame);
        }
        if (run.failed.size() > 20)
        {
            frames += " and " + std::to_string(run.failed.size() - 20) + " more";
        }
        throw Exception(std::to_string(run.failed.size()) + " of " +
                        std::to_string(run.frames + run.skipped + run.failed.size()) +
                        " frames failed (" + frames + "); the first, frame " +
                        std::to_string(run.failed[0].frame) + ": " + run.failed[0].error);
    }
}

size_t EditDistance(const std::string& a, const std::string& b)
{
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i)
    {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace bandlight::cli
