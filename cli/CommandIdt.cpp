// SPDX-License-Identifier: BSD-3-Clause
// `bandlight idt`: camera input transforms from spectral sensitivities or a
// chart, as OCIO input colour spaces (jobs/IdtJob).
#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "jobs/IdtJob.h"
#include "spectral/RgbSpaces.h"
#include "cli/Commands.h"
#include "cli/Common.h"

namespace bandlight::cli
{

namespace
{

struct IdtCommandOptions
{
    jobs::IdtRequest request;
    std::string lights;
    std::string interpolate;
    std::string asShot;
};

/// "R,G,B" as numbers; a value that is not a number is refused here, its
/// meaning (three, positive) by the job.
std::vector<double> Numbers(const std::string& text, const char* option)
{
    std::vector<double> out;
    for (const std::string& item : jobs::SplitList(text))
    {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (!end || *end != '\0')
        {
            throw ParameterError(std::string(option) + " takes numbers R,G,B: '" +
                                 OneLine(item, 40) + "' is not one");
        }
        out.push_back(v);
    }
    if (out.empty())
    {
        throw ParameterError(std::string(option) + " is empty: give R,G,B");
    }
    return out;
}

void RunIdt(IdtCommandOptions& o, const CLI::App& cmd)
{
    CommandReporter reporter;
    jobs::IdtRequest& r = o.request;
    r.lights = jobs::SplitList(o.lights);
    if (cmd.count("--lights") > 0 && r.lights.empty())
    {
        throw ParameterError("--lights is empty: name at least one light");
    }
    if (cmd.count("--interpolate") > 0)
    {
        r.interpolate = jobs::SplitList(o.interpolate);
        if (r.interpolate.size() != 2)
        {
            throw ParameterError("--interpolate takes two lights L1,L2, not " +
                                 std::to_string(r.interpolate.size()));
        }
    }
    if (cmd.count("--as-shot-neutral") > 0)
    {
        r.asShotNeutral = Numbers(o.asShot, "--as-shot-neutral");
    }
    for (const char* name : {"--json", "--config", "--out", "--base"})
    {
        const CLI::Option* option = cmd.get_option_no_throw(name);
        if (option && option->count() > 0 && option->as<std::string>().empty())
        {
            throw ParameterError(std::string(name) +
                                 " is '' (an empty path): name it, or leave the option out");
        }
    }
    if (!r.chartRgb.empty() && cmd.count("--test-set") > 0)
    {
        throw ParameterError(
            "--test-set is for IDTs from sensitivities: a chart IDT's error is "
            "measured on the chart");
    }
    // With --json - stdout carries the JSON alone.
    const bool toStdout = r.json == "-";
    if (toStdout)
    {
        r.json.clear();
    }
    const jobs::IdtResult result = jobs::MakeIdt(r, reporter);
    if (toStdout)
    {
        std::cout << jobs::IdtDocument(result) << "\n";
    }
    else
    {
        std::cout << jobs::IdtReport(result);
    }
    for (const std::string& file : result.written)
    {
        std::cerr << "idt: wrote " << file << "\n";
    }
}

}  // namespace

void AddIdtCommand(CLI::App& app)
{
    auto o = std::make_shared<IdtCommandOptions>();
    jobs::IdtRequest& r = o->request;
    CLI::App* cmd = app.add_subcommand(
        "idt",
        "Camera input transforms (IDTs) for each light, fitted as rawtoaces fits them, as OCIO "
        "input colour spaces");
    cmd->add_option("--camera", r.camera,
                    "Camera sensitivities: rawtoaces JSON, CSV or CGATS with R, G, B");
    cmd->add_option("--lights", o->lights,
                    "Comma-separated lights: built-in names (A, D55, F11), colour temperatures "
                    "(3200K: daylight from 4000 K, Planckian below) or spectrum files");
    cmd->add_option("--working-space", r.workingSpace,
                    "Linear space the IDTs land in: " + RgbSpaceChoices())
        ->capture_default_str();
    cmd->add_option("--adaptation", r.adaptation,
                    "Chromatic adaptation of the light's white to the working white: " +
                        PlateAdaptationChoices() + " (cat02 as rawtoaces)")
        ->check(CLI::IsMember(PlateAdaptationKeys()))
        ->capture_default_str();
    AddObserverOption(*cmd, r.observer);
    cmd->add_option("--training", r.training,
                    "Remittances to fit on (a file, or TCS); default rawtoaces' 190");
    cmd->add_option("--test-set", r.testSet,
                    "Remittances the error is also measured on (a file, or TCS)")
        ->capture_default_str();
    cmd->add_option("--interpolate", o->interpolate,
                    "Two lights L1,L2: fit both and report the IDT interpolated between them as "
                    "DNG does (colour matrix in mired, white balance and CAT for each light) "
                    "against one fitted at each CCT over 2800-6500 K");
    cmd->add_option("--as-shot-neutral", o->asShot,
                    "The camera's neutral R,G,B (raw, any scale): the daylight or Planckian light "
                    "it stands for, its CCT and Duv, and its IDT");
    cmd->add_option("--as-shot-light", r.asShotLight,
                    "The lights --as-shot-neutral is matched among: daylight, planckian, "
                    "fluorescent (F1-F12) or a list of lights (names, 3200K, spectrum files); "
                    "default daylight or Planckian. A neutral further than 2 dE00 from every one "
                    "is refused, naming the closest");
    cmd->add_option("--chart-rgb", r.chartRgb,
                    "CSV of a photographed chart's camera RGB, one row per patch ([name,] R, G, "
                    "B): the IDT without sensitivities");
    cmd->add_option("--chart", r.chart,
                    "With --chart-rgb: the chart's remittances (a file, or TCS)");
    cmd->add_option("--light", r.chartLight,
                    "With --chart-rgb: the light the chart was shot under");
    cmd->add_option("--rootpoly", r.chartRootPolynomial,
                    "With --chart-rgb: also fit a root polynomial of degree 2 or 3 on the chart "
                    "(exposure invariant) and report its error");
    cmd->add_option("--json", r.json, "Write the IDTs as JSON to FILE (- for stdout)");
    cmd->add_option("--config", r.config,
                    "Write an OCIO v2 config with one input colour space per light (and a CLF "
                    "file per IDT) into DIR");
    cmd->add_option("--base", r.base,
                    "Existing config to add the input colour spaces to (with --out)");
    cmd->add_option("--out", r.out, "With --base: the folder the extended config is written into");
    cmd->add_option("--base-space", r.baseSpace,
                    "With --base: the primaries of its scene_linear space (" + RgbSpaceChoices() +
                        "), when the base does not tell them");
    cmd->callback([o, cmd] { RunIdt(*o, *cmd); });
}

}  // namespace bandlight::cli
