// SPDX-License-Identifier: BSD-3-Clause
// `bandlight accuracy`: every method against the spectral answer, and what
// each costs — one table, one JSON document, one picture (jobs/AccuracyJob).
#include <cstdio>
#include <iostream>
#include <memory>

#include "jobs/AccuracyJob.h"
#include "requests/Defaults.h"
#include "measure/LightGroupAccuracy.h"
#include "spectral/RgbSpaces.h"
#include "cli/Commands.h"
#include "cli/Common.h"

namespace bandlight::cli
{

namespace
{

struct AccuracyCommandOptions
{
    std::string illuminants;
    std::string methods;
    std::vector<std::string> reflectances;
    bool noCost = false;
    std::string from;
    std::string to;
    std::vector<std::string> lightGroups;  ///< NAME=FROM:TO
    jobs::AccuracyRequest request;
};

/// `accuracy --image SHOT.exr --light-group NAME=FROM:TO …`: one global look
/// against a look per group, per method, against the exact spectral groups.
void RunLightGroupAccuracy(const AccuracyCommandOptions& o, const CLI::App& cmd)
{
    for (const char* name : {"--from", "--to", "--illuminants", "--reflectances", "--json",
                             "--plot", "--heatmaps", "--plates", "--camera"})
    {
        const CLI::Option* option = cmd.get_option_no_throw(name);
        if (option && option->count() > 0)
        {
            throw ParameterError(std::string(name) +
                                 " does not apply with --light-group (each group takes its "
                                 "lights, NAME=FROM:TO; the groups are lit)");
        }
    }
    if (o.request.images.size() != 1)
    {
        throw ParameterError(
            "--light-group measures one light-group render: give one --image "
            "(render --spectra --light-groups writes one)");
    }
    FrameSetReporter reporter;
    jobs::LightGroupAccuracyRequest r;
    r.image = o.request.images[0];
    r.methods = jobs::SplitList(o.methods);
    r.workingSpace = o.request.workingSpace;
    for (const std::string& item : o.lightGroups)
    {
        const size_t eq = item.find('=');
        const size_t colon = item.rfind(':');
        if (eq == std::string::npos || eq == 0 || colon == std::string::npos || colon < eq + 2 ||
            colon + 1 == item.size())
        {
            throw ParameterError("--light-group takes NAME=FROM:TO, got '" + OneLine(item, 80) +
                                 "'");
        }
        r.changes.push_back({item.substr(0, eq),
                             jobs::ResolveIlluminant(item.substr(eq + 1, colon - eq - 1), reporter),
                             jobs::ResolveIlluminant(item.substr(colon + 1), reporter)});
    }
    const jobs::LightGroupAccuracyResult res = jobs::MeasureLightGroups(r, reporter);
    std::cout << "Light groups of " << r.image << ": " << res.pixels
              << " pixels lit, CIEDE2000 against the spectral groups relit exactly (L*a*b* "
                 "relative to the brightest pixel's luminance)\n";
    std::cout << "global look: from " << res.globalFrom << " to " << res.globalTo
              << ", each light at its group's share of the luminance\n";
    std::cout << "no change: mean " << Fixed(res.noChangeMean, 2)
              << "; spectral groups: 0 (the reference), " << Fixed(res.spectralSeconds, 2)
              << " s\n\n";
    std::cout << "method       global mean  global p95  per-group mean  per-group p95  "
                 "per-group/global  global s  per-group s\n";
    for (const jobs::LightGroupAccuracyRow& row : res.rows)
    {
        char line[256];
        std::snprintf(line, sizeof line, "%-12s %11s %11s %15s %14s %17s %9s %12s\n",
                      row.method.c_str(), Fixed(row.globalMean, 2).c_str(),
                      Fixed(row.globalP95, 2).c_str(), Fixed(row.groupsMean, 2).c_str(),
                      Fixed(row.groupsP95, 2).c_str(),
                      Fixed(row.groupsMean / row.globalMean, 2).c_str(),
                      Fixed(row.globalSeconds, 2).c_str(), Fixed(row.groupsSeconds, 2).c_str());
        std::cout << line;
    }
}

void RunAccuracy(AccuracyCommandOptions& o, const CLI::App& cmd)
{
    if (!o.lightGroups.empty())
    {
        RunLightGroupAccuracy(o, cmd);
        return;
    }
    jobs::AccuracyRequest& r = o.request;
    CommandReporter reporter;
    for (const std::string& name : jobs::SplitList(o.illuminants))
    {
        r.lights.push_back(jobs::ResolveIlluminant(name, reporter));
    }
    r.methods = jobs::SplitList(o.methods);
    for (const std::string& file : o.reflectances)
    {
        r.sets.push_back(jobs::ReflectanceSetFromFile(file));
    }
    if (!o.from.empty())
    {
        r.imageOptions.from = jobs::ResolveIlluminant(o.from, reporter);
    }
    if (!o.to.empty())
    {
        r.imageOptions.to = jobs::ResolveIlluminant(o.to, reporter);
    }
    if ((!o.from.empty() || !o.to.empty()) && r.images.empty())
    {
        throw Exception("--from and --to name the lights of --image");
    }
    r.cost = !o.noCost;
    // An output option given as '' would write nothing: refused, not ignored.
    for (const char* name : {"--json", "--plot", "--heatmaps"})
    {
        const CLI::Option* option = cmd.get_option_no_throw(name);
        if (option && option->count() > 0 && option->as<std::string>().empty())
        {
            throw ParameterError(std::string(name) +
                                 " is '' (an empty path): name the file to write, or leave "
                                 "the option out");
        }
    }
    // With --json - stdout carries the JSON alone.
    const bool toStdout = r.json == "-";
    if (toStdout)
    {
        r.json.clear();
    }
    const jobs::AccuracyResult result = jobs::MeasureAccuracyJob(r, reporter);
    if (toStdout)
    {
        std::cout << jobs::AccuracyDocument(result) << "\n";
    }
    else
    {
        std::cout << jobs::AccuracyReport(result);
    }
    for (const jobs::HeatmapSummary& h : result.heatmaps)
    {
        std::cerr << "accuracy: " << h.method << " over the image: CIEDE2000 mean "
                  << Fixed(h.mean, 3) << ", p95 " << Fixed(h.p95, 3) << ", max " << Fixed(h.max, 3)
                  << "\n";
    }
    for (const std::string& file : result.written)
    {
        std::cerr << "accuracy: wrote " << file << "\n";
    }
}

}  // namespace

void AddAccuracyCommand(CLI::App& app)
{
    auto o = std::make_shared<AccuracyCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "accuracy",
        "CIEDE2000 of every method against the spectral answer, and what each costs per pixel");
    cmd->add_option("--illuminants", o->illuminants,
                    "Comma-separated illuminants (default: A,C,D50,D65,E,F1-F12)");
    cmd->add_option("--methods", o->methods,
                    "Comma-separated methods (default: all image methods: " +
                        JoinNames(AllMethodNames()) + ")");
    cmd->add_option("--reflectances", o->reflectances,
                    "CSV or CGATS file of remittances to add as a set (repeatable)");
    cmd->add_option("--image", o->request.images,
                    "Spectral EXR to add as a set, its pixels as remittances (repeatable; see "
                    "`spectral`)");
    cmd->add_option("--from", o->from,
                    "With --image: the light of the shot (emissive images are divided by it)");
    cmd->add_option("--to", o->to, "With --image: the light to relight to");
    cmd->add_option("--light-group", o->lightGroups,
                    "With one --image of a render with spectral light groups (render --spectra "
                    "--light-groups): NAME=FROM:TO for every group (repeatable); measures one "
                    "global look on the beauty against a look per group, for each of "
                    "--methods, against the exact spectral relight of the groups");
    cmd->add_option("--heatmaps", o->request.heatmaps,
                    "With --image: write a CIEDE2000 map per method into DIR (EXR, and PNG "
                    "with its scale)");
    cmd->add_option("--working-space", o->request.workingSpace,
                    "Linear working space: " + RgbSpaceChoices())
        ->capture_default_str();
    cmd->add_option("--json", o->request.json,
                    "Write all rows and costs as JSON to FILE (- for stdout)");
    cmd->add_option("--plot", o->request.plot,
                    "Draw accuracy against cost into FILE.png or FILE.svg");
    cmd->add_flag("--no-cost", o->noCost, "Skip the timing");
    AddLutSizeOption(*cmd, o->request.lutSize,
                     "3D LUT size of the shipped non-linear looks (as `config --lut-size`)");
    cmd->add_flag("--ideal-only", o->request.idealOnly,
                  "Measure only the methods' exact forms, not the OCIO transforms that ship");
    AddPlatesOptions(*cmd, o->request.plates, true);
    cmd->callback([o, cmd] { RunAccuracy(*o, *cmd); });
}

}  // namespace bandlight::cli
