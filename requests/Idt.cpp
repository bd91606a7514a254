// SPDX-License-Identifier: BSD-3-Clause
#include "requests/Idt.h"

#include "farm/OutputPaths.h"
#include "plugin/SceneLinearEvidence.h"
#include "requests/Inputs.h"
#include "spectral/Exception.h"
#include "spectral/TextFile.h"

namespace bandlight::jobs
{

Vec3 CheckedNeutral(const std::vector<double>& n)
{
    if (n.size() != 3)
    {
        throw ParameterError("{as_shot_neutral} is three numbers R,G,B, not " +
                             std::to_string(n.size()));
    }
    for (const double v : n)
    {
        if (!(v > 0.0) || !std::isfinite(v))
        {
            throw ParameterError(
                "{as_shot_neutral} has a channel that is zero, negative or not "
                "finite: a neutral has three positive channels");
        }
    }
    return {n[0], n[1], n[2]};
}

/// Any chart option asks for a chart IDT (CheckChartOptions then asks for
/// all three).
IdtSource SourceOf(const IdtRequest& r)
{
    const bool chart = !r.chartRgb.empty() || !r.chart.empty() || !r.chartLight.empty();
    return chart ? IdtSource::CHART : IdtSource::SENSITIVITIES;
}

namespace
{

/// A chart IDT: the chart's three options together, none of the
/// sensitivities'.
void CheckChartOptions(const IdtRequest& r)
{
    if (r.chartRgb.empty() || r.chart.empty() || r.chartLight.empty())
    {
        throw ParameterError("a chart IDT needs {chart_rgb}, {chart} and {light} together");
    }
    if (r.chartRootPolynomial != 0 && r.chartRootPolynomial != 2 && r.chartRootPolynomial != 3)
    {
        throw ParameterError(
            "{rootpoly} is the degree of the chart's root polynomial: 2 "
            "or 3, not " +
            std::to_string(r.chartRootPolynomial));
    }
    if (!r.camera.empty() || !r.lights.empty() || !r.interpolate.empty() ||
        !r.asShotNeutral.empty() || !r.training.empty())
    {
        throw ParameterError(
            "a chart IDT is fitted on the chart under its {light}: "
            "{camera}, {lights}, {training}, {interpolate} and "
            "{as_shot_neutral} are for sensitivities");
    }
}

/// A sensitivity IDT: a camera, something to fit for it, and no chart's
/// root polynomial.
void CheckSensitivityOptions(const IdtRequest& r)
{
    if (r.camera.empty())
    {
        throw ParameterError(
            "give the camera's sensitivities as {camera=}FILE (or a chart "
            "with {chart_rgb}, {chart} and {light})");
    }
    if (r.lights.empty() && r.interpolate.empty() && r.asShotNeutral.empty())
    {
        throw ParameterError(
            "name the lights to fit IDTs for ({lights}), two to "
            "{interpolate} between, or an {as_shot_neutral}");
    }
    if (r.chartRootPolynomial != 0)
    {
        throw ParameterError(
            "{rootpoly} is fitted on a chart: give {chart_rgb}, {chart} and "
            "{light}");
    }
}

/// The config outputs: a new one into {config}, or {base} extended into
/// {out} ({base_space} only with a base).
void CheckConfigOptions(const IdtRequest& r)
{
    if (!r.base.empty() && r.out.empty())
    {
        throw ParameterError("{base} is extended into a folder of its own: give {out=}DIR");
    }
    if (!r.out.empty() && r.base.empty())
    {
        throw ParameterError(
            "{out} is where an extended {base} config goes; for a new config "
            "give {config=}DIR");
    }
    if (!r.baseSpace.empty() && r.base.empty())
    {
        throw ParameterError(
            "{base_space} names the primaries of a {base} config's "
            "scene_linear: give the base, or leave {base_space} out");
    }
    if (!r.config.empty() && !r.base.empty())
    {
        throw ParameterError(
            "{config} writes a new config, {base} with {out} extends one: "
            "give one of them");
    }
}

/// Options that do not go together, refused before anything is read.
void CheckOptions(const IdtRequest& r)
{
    if (!r.asShotLight.empty() && r.asShotNeutral.empty())
    {
        throw ParameterError("{as_shot_light} names the lights {as_shot_neutral} is matched "
                             "among: give the neutral too");
    }
    switch (SourceOf(r))
    {
        case IdtSource::CHART:
            CheckChartOptions(r);
            break;
        case IdtSource::SENSITIVITIES:
            CheckSensitivityOptions(r);
            break;
    }
    if (!r.interpolate.empty() && r.interpolate.size() != 2)
    {
        throw ParameterError("{interpolate} takes two lights, not " +
                             std::to_string(r.interpolate.size()));
    }
    if (!r.asShotNeutral.empty())
    {
        CheckedNeutral(r.asShotNeutral);
    }
    CheckConfigOptions(r);
}

/// Every output can be written and no input is written over, before any
/// work (OutputPlan::check).
void CheckOutputPaths(const IdtRequest& r)
{
    OutputPlan plan;
    if (!r.json.empty())
    {
        plan.file("{json}", r.json);
    }
    if (!r.config.empty())
    {
        plan.folder("{config}", r.config, {"config.ocio"});
    }
    if (!r.out.empty())
    {
        plan.folder("{out}", r.out, {"config.ocio"});
    }
    for (const std::string* in : {&r.camera, &r.training, &r.chartRgb, &r.base})
    {
        if (!in->empty())
        {
            plan.input(*in);
        }
    }
    plan.check();
}

}  // namespace

void CheckIdtRequest(const IdtRequest& r)
{
    CheckOptions(r);
    CheckOutputPaths(r);
}

std::string ExistingIdtConfig(const IdtRequest& r)
{
    if (r.config.empty())
    {
        return "";
    }
    const std::string file = r.config + "/config.ocio";
    return PathExists(file) ? file : "";
}

OCIO_NAMESPACE::ConstConfigRcPtr ReadIdtBase(const IdtRequest& r)
{
    if (const std::string existing = ExistingIdtConfig(r); !existing.empty())
    {
        // {config} holds a config already (another camera's): the input
        // spaces are added to it, its primaries identified as a base's.
        OCIO_NAMESPACE::ConstConfigRcPtr config = ReadConfigFile(existing, false);
        try
        {
            IdentifySceneLinear(config);
        }
        catch (const ParameterError&)
        {
            throw ParameterError("cannot tell the primaries of the scene_linear space of " +
                                 ShowPath(existing) +
                                 ", which the input spaces would be added to: write them into a "
                                 "folder of their own, or extend it with {base} and {base_space}");
        }
        return config;
    }
    if (r.base.empty())
    {
        return nullptr;
    }
    OCIO_NAMESPACE::ConstConfigRcPtr base = ReadConfigFile(r.base, false);
    if (r.baseSpace.empty())
    {
        try
        {
            IdentifySceneLinear(base);
        }
        catch (const ParameterError&)
        {
            throw ParameterError("cannot tell the primaries of the scene_linear space of {base} " +
                                 ShowPath(r.base) + ": name them with {base_space} (" +
                                 RgbSpaceChoices() + ")");
        }
    }
    else
    {
        FindRgbSpace(r.baseSpace);
    }
    return base;
}

}  // namespace bandlight::jobs
