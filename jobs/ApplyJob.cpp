// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/ApplyJob.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "farm/Frames.h"
#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"
#include "plugin/NativeKernels.h"
#include "plugin/OcioTransforms.h"
#include "plugin/SceneLinearEvidence.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{

/// The frame set's counts into the result.
void Counted(const FrameRun& run, ApplyResult& result)
{
    result.frames = run.frames;
    result.skipped = run.skipped;
    result.failed = run.failed;
    result.seconds = run.seconds;
    result.sequence = run.sequence;
}

/// The frames of a request; an image may be relit in place (the result
/// keeps its other channels, metadata and parts).
FrameSetRequest FrameSet(const ApplyRequest& r)
{
    FrameSetRequest f{r.input, r.output, r.frames, r.skipExisting, r.keepGoing};
    f.mayReplaceInput = true;
    return f;
}
/// The first input of a request that is there: the image, or the first
/// frame whose input exists ("" when none is).
std::string FirstExistingInput(const FrameSetRequest& f)
{
    std::error_code ec;
    if (f.frames.empty())
    {
        return std::filesystem::is_regular_file(f.input, ec) ? f.input : "";
    }
    for (const int frame : ParseFrameRange(f.frames))
    {
        const std::string in = ExpandFramePattern(f.input, frame);
        if (std::filesystem::is_regular_file(in, ec))
        {
            return in;
        }
    }
    return "";
}

/// A change of light as the pixels get it: natively (rootpoly, the
/// guarded 3×3 of the linear methods) or through its OCIO processor.
struct RelightForm
{
    OCIO::ConstProcessorRcPtr processor;
    std::function<void(float*, size_t)> native;
    std::optional<ClampMatrixKernel> kernel;
    std::string applied;

    BufferWork work(int threads) const
    {
        return kernel   ? KernelWork(*kernel, threads)
               : native ? RgbWork(native, threads)
                        : ProcessorWork(processor->getOptimizedCPUProcessor(
                                            OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                            OCIO::OPTIMIZATION_DEFAULT),
                                        threads);
    }
};

RelightForm MakeRelightForm(const RelightRequest& relight, Reporter& reporter)
{
    RelightForm f;
    const MethodSpec method = relight.methodSpec(reporter);
    const Observer observer = ParseObserver(relight.observer);
    if (method.entry().appliesNatively())
    {
        const auto relighter = std::make_shared<Relighter>(relight.src, relight.dst, method,
                                                           relight.working(), observer);
        f.native = [relighter](float* rgb, size_t n) { relighter->apply(rgb, n, 1); };
        f.applied = LookName(method.name, relight.src.name, relight.dst.name) + " (native)";
    }
    else
    {
        OCIO::GroupTransformRcPtr t = IlluminantChangeTransform(relight.src, relight.dst, method,
                                                                relight.working(), observer);
        f.processor = OCIO::Config::CreateRaw()->getProcessor(t);
        f.applied = t->getFormatMetadata().getName();
        // The linear methods: their guarded 3×3, natively.
        f.kernel = NativeClampMatrix(f.processor);
    }
    return f;
}

/// The colour space of `config` a look is applied in: {colorspace}, or
/// scene_linear. Throws Exception when the config has no such space.
std::string LookSpace(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config)
{
    const std::string space =
        r.colorspace.empty() ? std::string(OCIO::ROLE_SCENE_LINEAR) : r.colorspace;
    if (!config->getColorSpace(space.c_str()))
    {
        throw Exception("colour space '" + space + "' is not in " + r.config);
    }
    return space;
}

/// A look of the request's config as the pixels get it, as `apply --look`
/// applies it: from LookSpace to itself through the config's own
/// processor; natively when that optimises to a clamp and a matrix (any
/// config's, read back from OCIO). Throws Exception when the config has no
/// such look (checked first) or colour space.
RelightForm MakeLookForm(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config,
                         const std::string& look)
{
    if (!config->getLook(look.c_str()))
    {
        throw Exception("look '" + look + "' is not in " + r.config);
    }
    const std::string space = LookSpace(r, config);
    OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
    t->setSrc(space.c_str());
    t->setDst(space.c_str());
    t->setLooks(look.c_str());
    RelightForm f;
    f.processor = config->getProcessor(t);
    f.kernel = NativeClampMatrix(f.processor);
    f.applied = "look " + look;
    return f;
}

/// The linear space an image is converted to for a config's looks: the
/// config's scene_linear, whose primaries the config shows; nullptr (the
/// pixels go to the looks as they are) when the user named the image's
/// colour space in the config, or when scene_linear's primaries are
/// unknown (`unknown` then says why).
const RgbSpace* LookWorkingSpace(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config,
                                 std::string& unknown)
{
    if (!r.colorspace.empty())
    {
        return nullptr;
    }
    try
    {
        return IdentifySceneLinear(config).space;
    }
    catch (const Exception& e)
    {
        unknown = "the primaries of " + r.config +
                  "'s scene_linear are unknown, so the image goes to the look as it is; name its "
                  "colour space in the config with {colorspace} (" +
                  std::string(e.what()) + ")";
        return nullptr;
    }
}

/// Each note once for a sequence, the frame's names given as the patterns.
class FrameNotes
{
public:
    FrameNotes(const ApplyRequest& r, Reporter& reporter) : m_r(r), m_reporter(reporter) {}
    void add(const std::vector<std::string>& notes, const std::string& in, const std::string& out)
    {
        std::lock_guard<std::mutex> lock(m_mu);
        for (std::string n : notes)
        {
            for (const auto& [name, pattern] :
                 {std::pair{in, m_r.input}, std::pair{out, m_r.output}})
            {
                for (size_t at = n.find(name); !name.empty() && at != std::string::npos;
                     at = n.find(name, at + pattern.size()))
                {
                    n.replace(at, name.size(), pattern);
                }
            }
            if (m_noted.insert(n).second)
            {
                m_reporter.note(n);
            }
        }
    }

private:
    const ApplyRequest& m_r;
    Reporter& m_reporter;
    std::set<std::string> m_noted;
    std::mutex m_mu;
};

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
    result.applied = "light groups (" + applied + ")";
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
    FrameNotes notes(r, reporter);
    const FrameRun run = RunFrameSet(
        FrameSet(r), reporter,
        [&](const std::string& in, const std::string& out)
        { notes.add(ApplyLightGroupsToImage(apply, in, out, result.applied, colour), in, out); });
    Counted(run, result);
    return result;
}
/// A matte's channel as weights in 0..1, one per pixel.
struct Matte
{
    std::string path;
    std::string channel;
    ImageData image;
    std::vector<float> weights;
};

Matte ReadMatte(const std::string& given, Reporter& reporter)
{
    Matte m;
    m.path = given;
    // MATTE.exr:channel, unless the whole text names a file.
    const size_t colon = given.rfind(':');
    std::error_code ec;
    if (colon != std::string::npos && !std::filesystem::exists(given, ec) &&
        given.find('/', colon) == std::string::npos)
    {
        m.path = given.substr(0, colon);
        m.channel = given.substr(colon + 1);
    }
    CheckImageInput(m.path);
    ThrowIfFailed(ImageFiles().read(m.path, m.image, true));
    const std::vector<std::string>& names = m.image.channelNames;
    int index = -1;
    if (!m.channel.empty())
    {
        const auto at = std::find(names.begin(), names.end(), m.channel);
        if (at == names.end())
        {
            throw Exception(m.path + ": the matte has no channel '" + OneLine(m.channel, 80) + "'");
        }
        index = int(at - names.begin());
    }
    else
    {
        for (const char* name : {"A", "Y"})
        {
            const auto at = std::find(names.begin(), names.end(), name);
            if (at != names.end())
            {
                index = int(at - names.begin());
                break;
            }
        }
        if (index < 0 && names.size() == 1)
        {
            index = 0;
        }
        if (index < 0)
        {
            throw Exception(m.path + ": the matte has no channel A or Y and " +
                            std::to_string(names.size()) +
                            " channels: name the one to use, {matte=}MATTE.exr:CHANNEL");
        }
        m.channel = names[size_t(index)];
    }
    const size_t count = size_t(m.image.width) * size_t(m.image.height);
    m.weights.resize(count);
    size_t clamped = 0;
    for (size_t p = 0; p < count; ++p)
    {
        const float v = m.image.pixels[p * size_t(m.image.channels) + size_t(index)];
        if (!std::isfinite(v))
        {
            throw Exception(m.path + ": matte channel '" + m.channel + "' is " +
                            (std::isnan(v) ? "NaN" : "infinite") + " at pixel (" +
                            std::to_string(p % size_t(m.image.width)) + ", " +
                            std::to_string(p / size_t(m.image.width)) + ")");
        }
        m.weights[p] = std::clamp(v, 0.0f, 1.0f);
        clamped += m.weights[p] != v ? 1 : 0;
    }
    if (clamped > 0)
    {
        reporter.note(m.path + ": " + std::to_string(clamped) + " matte values outside 0-1 " +
                      "taken as 0 or 1");
    }
    m.image.pixels.clear();
    return m;
}

/// Throws Exception when the matte does not cover `in`'s data window exactly.
void CheckMatteFits(const Matte& m, const std::string& in, const ImageData& header)
{
    const auto window = [](const ImageData& d)
    {
        return std::to_string(d.width) + "x" + std::to_string(d.height) + " at (" +
               std::to_string(d.x) + ", " + std::to_string(d.y) + ")";
    };
    if (m.image.width != header.width || m.image.height != header.height || m.image.x != header.x ||
        m.image.y != header.y)
    {
        throw Exception(m.path + ": the matte's data window is " + window(m.image) + ", " +
                        PathInMessage(in) + "'s " + window(header) +
                        ": a matte must cover the image pixel for pixel");
    }
}

/// One side of a matte as the pixels get it: a change of light or a look
/// of the config, in the space the image is converted to for the matte.
struct MatteSide
{
    RelightForm form;
    /// A change of light beside a look: the processors that take the looks'
    /// pixels to the change's working space, in order, and those back.
    std::vector<OCIO::ConstCPUProcessorRcPtr> into, back;

    BufferWork work(int threads) const
    {
        BufferWork w = form.work(threads);
        if (into.empty() && back.empty())
        {
            return w;
        }
        return [w, into = into, back = back, threads](float* px, long width, long height,
                                                      int channels, const int* rgb)
        {
            for (const OCIO::ConstCPUProcessorRcPtr& p : into)
            {
                ApplyToBuffer(p, px, width, height, channels, rgb, threads);
            }
            w(px, width, height, channels, rgb);
            for (const OCIO::ConstCPUProcessorRcPtr& p : back)
            {
                ApplyToBuffer(p, px, width, height, channels, rgb, threads);
            }
        };
    }
};

/// The matte's options checked against each other, before any file is read.
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

/// A change of light beside a look: it is defined on linear light of known
/// primaries, so it gets the looks' pixels through the config's
/// scene_linear, whose primaries the config shows, and gives them back.
void ConvertForLooks(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config,
                     const RgbSpace* working, const RelightRequest& relight, MatteSide& s)
{
    const RgbSpace* sceneLinear = working;
    std::string why;
    if (!sceneLinear)
    {
        try
        {
            sceneLinear = IdentifySceneLinear(config).space;
        }
        catch (const Exception& e)
        {
            why = e.what();
        }
    }
    if (!sceneLinear)
    {
        throw ParameterError("{matte}: the change of light " + relight.src.name + " to " +
                             relight.dst.name + " works in linear " +
                             SpaceLabel(relight.working()) +
                             ", and it would get the looks' pixels through " + r.config +
                             "'s scene_linear, whose primaries are unknown (" + why +
                             "): give both sides as looks of the config");
    }
    const std::string space = LookSpace(r, config);
    ImageEncoding linear;
    linear.space = *sceneLinear;
    if (!r.colorspace.empty())
    {
        s.into.push_back(
            config->getProcessor(space.c_str(), OCIO::ROLE_SCENE_LINEAR)->getDefaultCPUProcessor());
    }
    if (const OCIO::ConstCPUProcessorRcPtr p = EncodingToLinear(linear, relight.working()))
    {
        s.into.push_back(p);
    }
    if (const OCIO::ConstCPUProcessorRcPtr p = LinearToEncoding(relight.working(), linear))
    {
        s.back.push_back(p);
    }
    if (!r.colorspace.empty())
    {
        s.back.push_back(
            config->getProcessor(OCIO::ROLE_SCENE_LINEAR, space.c_str())->getDefaultCPUProcessor());
    }
}

/// out = m·inside(pixel) + (1 − m)·outside(pixel), R, G, B only.
BufferWork MixByMatte(const Matte& matte, const BufferWork& in, const BufferWork& out)
{
    return [&matte, in, out](float* px, long w, long h, int n, const int* rgb)
    {
        const std::vector<float>& m = matte.weights;
        if (size_t(w) * size_t(h) != m.size())
        {
            throw Exception(matte.path + ": the matte is " + std::to_string(matte.image.width) +
                            "x" + std::to_string(matte.image.height) + ", the image " +
                            std::to_string(w) + "x" + std::to_string(h));
        }
        std::vector<float> lit(px, px + size_t(w) * size_t(h) * size_t(n));
        in(lit.data(), w, h, n, rgb);
        out(px, w, h, n, rgb);
        for (size_t p = 0; p < m.size(); ++p)
        {
            for (int c = 0; c < 3; ++c)
            {
                float& v = px[p * size_t(n) + size_t(rgb[c])];
                v = m[p] * lit[p * size_t(n) + size_t(rgb[c])] + (1.0f - m[p]) * v;
            }
        }
    };
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
    FrameNotes notes(r, reporter);
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
    // Frames run on several threads at once (RunFrameSet).
    FrameNotes notes(r, reporter);
    const auto applyOne = [&](const std::string& in, const std::string& out)
    { notes.add(ApplyToImage(work, in, out, result.applied, colour), in, out); };

    result.native = form.kernel || form.native;
    const FrameRun run = RunFrameSet(FrameSet(r), reporter, applyOne);
    Counted(run, result);
    return result;
}

}  // namespace bandlight::jobs
