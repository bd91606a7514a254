// SPDX-License-Identifier: BSD-3-Clause
#include "requests/Apply.h"

#include "spectral/Exception.h"

namespace bandlight::jobs
{

FrameSetRequest FrameSet(const ApplyRequest& r)
{
    FrameSetRequest f{r.input, r.output, r.frames, r.skipExisting, r.keepGoing};
    f.mayReplaceInput = true;
    return f;
}

void Counted(const FrameRun& run, ApplyResult& result)
{
    result.frames = run.frames;
    result.skipped = run.skipped;
    result.failed = run.failed;
    result.seconds = run.seconds;
    result.sequence = run.sequence;
}


void CheckMatteRequest(const ApplyRequest& r)
{
    const bool insideIsLook = !r.insideLook.empty();
    const bool outsideIsLook = !r.outsideLook.empty();
    if (r.matte.empty() || (!r.insideRelight && !insideIsLook) ||
        (!r.outsideRelight && !outsideIsLook))
    {
        throw ParameterError(
            "{matte=}MATTE.exr[:CHANNEL] takes a change of light (or a look of "
            "{config}) inside the matte and one outside it: give {matte}, "
            "{look_inside} and {look_outside}");
    }
    if ((r.insideRelight && insideIsLook) || (r.outsideRelight && outsideIsLook))
    {
        throw ParameterError(
            "{matte}: each side is a change of light or a look of {config}, not both");
    }
    if (r.relight || !r.look.empty() || !r.lightGroups.empty())
    {
        throw ParameterError(
            "{matte} relights each side with its own change of light: {look}, "
            "{src}/{dst} and {light_group} do not apply to it");
    }
    if ((insideIsLook || outsideIsLook) && r.config.empty())
    {
        throw ParameterError("{matte}: a side's look '" +
                             OneLine(insideIsLook ? r.insideLook : r.outsideLook, 80) +
                             "' is a look of {config=}DIR: give the config");
    }
    if (!insideIsLook && !outsideIsLook && !r.config.empty())
    {
        throw ParameterError(
            "{config} holds looks, and neither {look_inside} nor {look_outside} "
            "names one of them (give a side as a look of it, or leave {config} out)");
    }
    if (r.insideRelight && r.outsideRelight &&
        &r.insideRelight->working() != &r.outsideRelight->working())
    {
        throw ParameterError("{matte}: both sides are relit in one working space");
    }
}

void CheckLookAlone(const ApplyRequest& r)
{
    if (r.look.empty() || (r.changeGiven.empty() && !r.relight))
    {
        return;
    }
    std::string names;
    for (const std::string& n : r.changeGiven)
    {
        names += (names.empty() ? "{" : ", {") + n + "}";
    }
    throw ParameterError("{look} applies a look of {config} as it is: " +
                         (names.empty() ? std::string("{src}, {dst}, {method} and the plates")
                                        : names) +
                         " do not apply to it (give the look, or the change of light)");
}

}  // namespace bandlight::jobs
