// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `apply`'s request and result, and the checks of a request that need no
// file, shared by every face.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "farm/Frames.h"
#include "requests/Inputs.h"

namespace bandlight::jobs
{

/// `apply`: a look of a config, or an illuminant change, applied to an
/// image file or a frame sequence through OpenImageIO.
/// One light group's change of light (`apply --light-group NAME=FROM:TO`).
struct LightGroupRelight
{
    std::string group;       ///< the group's name, as the file's naming gives it
    RelightRequest relight;  ///< its lights, method, working space and plates
};

struct ApplyRequest
{
    std::string input;   ///< an image, or a pattern such as plate.####.exr
    std::string output;  ///< an image, or a pattern
    std::string frames;  ///< with patterns: the frames, "1001-1100"
    /// A look of a config (folder or .ocio file), applied in `colorspace`
    /// (empty: the config's scene_linear role, the image converted to it from
    /// what the file says when the config shows scene_linear's primaries).
    std::string look;
    std::string config;
    /// With a look: the image's colour space in the config, taken as given.
    /// Without: what the file holds, instead of what its tags say: a
    /// built-in RGB space (linear) or "srgb" (docs/images.md).
    std::string colorspace;
    /// Without a look: the illuminant change (rootpoly applies natively,
    /// the other methods through their OCIO transform).
    std::optional<RelightRequest> relight;
    /// Light groups (docs/lightgroups.md): each named group relit on its
    /// own, the beauty written as Σ relit groups + residual, every other
    /// channel, part and the metadata kept; groups not named are carried.
    /// Not with `look` or `relight`.
    std::vector<LightGroupRelight> lightGroups;
    /// A matte for a plate lit by two lights (docs/lightgroups.md): out =
    /// m·inside(in) + (1−m)·outside(in), m the matte's channel (clamped to
    /// 0..1). Each side is a change of light (insideRelight) or a look of
    /// `config` (insideLook), applied as `look` is: in `colorspace` of the
    /// config, or its scene_linear with the image converted from what the
    /// file says. A change of light beside a look gets the pixels in its
    /// working space, converted from the look's space (whose primaries
    /// must be known). The matte's size and data window must be the
    /// image's. Not with `look`, `relight` or light groups.
    std::string matte;  ///< MATTE.exr, or MATTE.exr:channel (default A, Y, or its only channel)
    std::optional<RelightRequest> insideRelight;
    std::optional<RelightRequest> outsideRelight;
    std::string insideLook;  ///< a look of `config` instead of insideRelight
    std::string outsideLook;
    /// Groups the file names otherwise: group → layer prefix, or "r,g,b".
    std::map<std::string, std::string> lightGroupLayers;
    /// What a relit light-group file's beauty is made of: "" or "residual"
    /// (Σ relit groups + beauty − Σ groups, the groups a partition of the
    /// beauty), "rebuild" (Σ relit groups: a denoised beauty) or
    /// "difference" (the denoised beauty's difference carried as it is).
    std::string lightGroupBeauty;
    /// The parameters of a change of light the caller was given, by their
    /// ParameterError names ("src", "method", "working_space", ...), in the
    /// order a face lists them: with a look, each is refused by name
    /// (CheckLookAlone), whichever face collected them. A face fills it;
    /// a C++ host may leave it empty and set `relight` instead.
    std::vector<std::string> changeGiven;
    int threads = 0;  ///< 0: all cores
    /// Frames whose output exists are skipped (outputs are written
    /// atomically, so an existing file is a complete one): a re-queued
    /// chunk redoes only what is missing.
    bool skipExisting = false;
    /// A frame that fails does not stop the others; the result lists it.
    bool keepGoing = false;
};

struct ApplyResult
{
    std::string applied;               ///< what was applied: "look band3_A_to_D65", a look name
    size_t frames = 0;                 ///< frames written (1 for a single image)
    size_t skipped = 0;                ///< frames whose output existed (skipExisting)
    std::vector<FrameFailure> failed;  ///< keepGoing: the frames that failed, in order
    double seconds = 0.0;              ///< wall time of the frames
    /// Applied by bandlight's own kernel (a clamp-and-matrix processor,
    /// rootpoly) rather than by OpenColorIO's CPU processor.
    bool native = false;
    bool sequence = false;
};

/// The rule every face shares: a look is applied as its config holds it, so
/// with `look` nothing of a change of light may be given (`changeGiven`,
/// `relight`). Throws ParameterError naming what was given; ApplyImages
/// calls it, and a face may call it first to report this mistake before
/// others.
void CheckLookAlone(const ApplyRequest& request);

/// The frames of a request; an image may be relit in place (the result
/// keeps its other channels, metadata and parts).
FrameSetRequest FrameSet(const ApplyRequest& request);

/// A frame set's counts into the result.
void Counted(const FrameRun& run, ApplyResult& result);

/// The matte's options checked against each other, before any file is read.
void CheckMatteRequest(const ApplyRequest& request);

}  // namespace bandlight::jobs
