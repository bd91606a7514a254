// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/ApplyJob.h"

#include <set>
#include <string>
#include <vector>

#include "farm/Frames.h"
#include "imageio/ImageColour.h"
#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"
#include "imaging/Mattes.h"
#include "imaging/RelightForms.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{

/// The request's rule for a light-group file's beauty.
LightGroupBeauty BeautyOf(const ApplyRequest& r)
{
    return r.lightGroupBeauty.empty() ? LightGroupBeauty::RESIDUAL
                                      : ParseLightGroupBeauty(r.lightGroupBeauty);
}

/// The frames of a light-group apply, each file relit by `apply`, its notes
/// said once for the set.
ApplyResult RunLightGroups(const ApplyRequest& r, const LightGroupApply& apply,
                           const ImageColourRequest& colour, Reporter& reporter,
                           ApplyResult result)
{
    FrameNotes notes(r.input, r.output, reporter);
    const FrameRun run = RunFrameSet(
        FrameSet(r), reporter,
        [&](const std::string& in, const std::string& out)
        { notes.add(ApplyLightGroupsToImage(apply, in, out, result.applied, colour), in, out); });
    Counted(run, result);
    return result;
}

ApplyResult ApplyLightGroups(const ApplyRequest& r, Reporter& reporter)
{
    if (r.relight)
    {
        throw ParameterError(
            "{light_group} gives each group its own change of light: {src} and "
            "{dst} do not apply to it (give NAME=FROM:TO per group)");
    }
    ApplyResult result;
    LightGroupApply apply;
    apply.mapped = r.lightGroupLayers;
    ImageColourRequest colour;
    std::set<std::string> names;
    std::string applied;
    bool allNative = true;
    for (const LightGroupRelight& g : r.lightGroups)
    {
        if (g.group.empty())
        {
            throw ParameterError("{light_group} takes NAME=FROM:TO: the group's name is empty");
        }
        if (!names.insert(g.group).second)
        {
            throw ParameterError("{light_group} names the group '" + OneLine(g.group, 80) +
                                 "' twice");
        }
        if (colour.working && colour.working != &g.relight.working())
        {
            throw ParameterError("{light_group}: every group is relit in one working space");
        }
        colour.working = &g.relight.working();
        const Spectrum& a = g.relight.src.spectrum;
        const Spectrum& b = g.relight.dst.spectrum;
        if (a.sameGrid(b) && a.values() == b.values())
        {
            // The same light: nothing changes, exactly (a fitted method's
            // identity is only as exact as its fit).
            (void)g.relight.methodSpec(reporter);
            applied += (applied.empty() ? "" : ", ") + g.group + ": unchanged (" +
                       g.relight.src.name + " to " + g.relight.dst.name + ")";
            apply.works[g.group] = nullptr;  // named, so it must be there; carried
            continue;
        }
        const RelightForm form = MakeRelightForm(g.relight, reporter);
        allNative = allNative && (form.kernel || form.native);
        apply.works[g.group] = form.work(r.threads);
        applied += (applied.empty() ? "" : ", ") + g.group + ": " + form.applied;
    }
    if (!r.colorspace.empty())
    {
        colour.declared = NamedEncoding(r.colorspace);
    }
    apply.beauty = BeautyOf(r);
    result.applied = "light groups (" + applied + ")" + LightGroupBeautyNote(apply.beauty);
    result.native = allNative;
    // The groups checked in the first input's header before any frame: a
    // group that is not there fails at once (a file of one part; the parts
    // of a multi-part file are looked at as each frame is read).
    const std::string first = FirstExistingInput(FrameSet(r));
    if (!first.empty())
    {
        ImageData header;
        ThrowIfFailed(ImageFiles().read(first, header, false));
        if (header.parts == 1)
        {
            (void)CheckedLightGroups(apply, first, header);
        }
    }
    return RunLightGroups(r, apply, colour, reporter, result);
}

ApplyResult ApplyMatte(const ApplyRequest& r, Reporter& reporter)
{
    CheckMatteRequest(r);
    // What the image is to the sides: to looks, as `apply --look` takes it;
    // to two changes of light, as plain `apply --from --to` does.
    ImageColourRequest colour;
    OCIO::ConstConfigRcPtr config;
    std::string unknown;
    if (!r.insideLook.empty() || !r.outsideLook.empty())
    {
        config = LoadConfig(r.config);
        colour.working = LookWorkingSpace(r, config, unknown);
    }
    else
    {
        colour.working = &r.insideRelight->working();
        if (!r.colorspace.empty())
        {
            colour.declared = NamedEncoding(r.colorspace);
        }
    }
    const auto side = [&](const std::optional<RelightRequest>& relight, const std::string& look)
    {
        MatteSide s;
        if (!look.empty())
        {
            s.form = MakeLookForm(r, config, look);
            return s;
        }
        s.form = MakeRelightForm(*relight, reporter);
        if (config)
        {
            ConvertForLooks(r, config, colour.working, *relight, s);
        }
        return s;
    };
    const MatteSide inside = side(r.insideRelight, r.insideLook);
    const MatteSide outside = side(r.outsideRelight, r.outsideLook);
    if (!unknown.empty())
    {
        reporter.note(unknown);
    }
    const Matte matte = ReadMatte(r.matte, reporter);
    const std::string first = FirstExistingInput(FrameSet(r));
    if (!first.empty())
    {
        ImageData header;
        ThrowIfFailed(ImageFiles().read(first, header, false));
        CheckMatteFits(matte, first, header);
    }
    const BufferWork mixed = MixByMatte(matte, inside.work(r.threads), outside.work(r.threads));
    ApplyResult result;
    result.applied = "matte " + matte.path + ":" + matte.channel +
                     " (inside: " + inside.form.applied + ", outside: " + outside.form.applied +
                     ")";
    result.native =
        (inside.form.kernel || inside.form.native) && (outside.form.kernel || outside.form.native);
    FrameNotes notes(r.input, r.output, reporter);
    const FrameRun run =
        RunFrameSet(FrameSet(r), reporter,
                    [&](const std::string& i, const std::string& o)
                    {
                        ImageData header;
                        ThrowIfFailed(ImageFiles().read(i, header, false));
                        CheckMatteFits(matte, i, header);
                        notes.add(ApplyToImage(mixed, i, o, result.applied, colour), i, o);
                    });
    Counted(run, result);
    return result;
}

}  // namespace

ApplyResult ApplyImages(const ApplyRequest& r, Reporter& reporter)
{
    if (r.threads < 0 || r.threads > kMaxThreads)
    {
        throw ParameterError("{threads} must be 0 (all cores) to " + std::to_string(kMaxThreads) +
                             ", got " + std::to_string(r.threads));
    }
    if (!r.look.empty() && !r.lightGroups.empty())
    {
        throw ParameterError(
            "{look} applies one look to the whole image: {light_group} does not "
            "apply to it (give the change of light per group)");
    }
    CheckLookAlone(r);
    if (r.look.empty() && !r.config.empty() && r.matte.empty() && r.insideLook.empty() &&
        r.outsideLook.empty())
    {
        throw ParameterError("{config} holds the looks {look} names: give {look=}NAME with it");
    }
    // Every path before any work: a run that cannot write fails at once.
    CheckFrameSetPaths(FrameSet(r));
    if (!r.lightGroups.empty())
    {
        RequireNamedChannels(r.output, "light groups");
    }
    if (!r.matte.empty() || r.insideRelight || r.outsideRelight || !r.insideLook.empty() ||
        !r.outsideLook.empty())
    {
        return ApplyMatte(r, reporter);
    }
    if (!r.lightGroups.empty())
    {
        return ApplyLightGroups(r, reporter);
    }
    ApplyResult result;
    RelightForm form;
    ImageColourRequest colour;
    if (!r.look.empty())
    {
        if (r.config.empty())
        {
            throw ParameterError("{look} needs {config=}DIR (or use {src}/{dst}/{method})");
        }
        const OCIO::ConstConfigRcPtr config = LoadConfig(r.config);
        form = MakeLookForm(r, config, r.look);
        // The image's pixels in the look's space: as they are when the user
        // named the space; else converted from what the file says to
        // scene_linear, whose primaries the config shows.
        std::string unknown;
        colour.working = LookWorkingSpace(r, config, unknown);
        if (!unknown.empty())
        {
            reporter.note(unknown);
        }
    }
    else
    {
        if (!r.relight)
        {
            throw ParameterError(
                "give {look=}NAME {config=}DIR, or {src=}S1 {dst=}S2 [{method=}M]");
        }
        const RelightRequest& relight = *r.relight;
        colour.working = &relight.working();
        if (!r.colorspace.empty())
        {
            colour.declared = NamedEncoding(r.colorspace);
        }
        // rootpoly without a config is applied natively: a few ns a pixel,
        // no LUT between the fit and the pixels.
        form = MakeRelightForm(relight, reporter);
    }
    result.applied = form.applied;
    const BufferWork work = form.work(r.threads);
    if (!r.lightGroupBeauty.empty() && r.lightGroups.empty() &&
        !HoldsLightGroups(FirstExistingInput(FrameSet(r))))
    {
        throw ParameterError("{light_group_beauty} says what a light-group file's beauty is "
                             "made of: " + r.input + " has no light groups");
    }
    if (r.look.empty() && HoldsLightGroups(FirstExistingInput(FrameSet(r))))
    {
        // A change of light on a file with light groups: every group and the
        // residual get it, so the beauty stays their sum.
        LightGroupApply apply;
        apply.everyGroup = work;
        apply.beauty = BeautyOf(r);
        result.applied += LightGroupBeautyNote(apply.beauty);
        result.native = form.kernel || form.native;
        return RunLightGroups(r, apply, colour, reporter, result);
    }
    // Frames run on several threads at once (RunFrameSet).
    FrameNotes notes(r.input, r.output, reporter);
    const auto applyOne = [&](const std::string& in, const std::string& out)
    { notes.add(ApplyToImage(work, in, out, result.applied, colour), in, out); };

    result.native = form.kernel || form.native;
    const FrameRun run = RunFrameSet(FrameSet(r), reporter, applyOne);
    Counted(run, result);
    return result;
}

}  // namespace bandlight::jobs
