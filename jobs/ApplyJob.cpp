// SPDX-License-Identifier: BSD-3-Clause
#include "bandlight/jobs/ApplyJob.h"

#include <functional>
#include <memory>
#include <mutex>
#include <set>

#include "bandlight/jobs/Frames.h"
#include "bandlight/jobs/ImageApply.h"
#include "bandlight/plugin/OcioTransforms.h"
#include "bandlight/plugin/SceneLinearEvidence.h"
#include "bandlight/spectral/Exception.h"
#include "bandlight/spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{
/// The frames of a request; an image may be relit in place (the result
/// keeps its other channels, metadata and parts).
FrameSetRequest FrameSet(const ApplyRequest& r)
{
    FrameSetRequest f{r.input, r.output, r.frames, r.skipExisting, r.keepGoing};
    f.mayReplaceInput = true;
    return f;
}
}  // namespace

ApplyResult ApplyImages(const ApplyRequest& r, Reporter& reporter)
{
    if (r.threads < 0 || r.threads > kMaxThreads)
    {
        throw ParameterError("{threads} must be 0 (all cores) to " + std::to_string(kMaxThreads) +
                             ", got " + std::to_string(r.threads));
    }
    if (!r.look.empty() && r.relight)
    {
        throw ParameterError("{look} applies a look of {config} as it is: {src}, {dst}, {method} "
                             "and the plates do not apply to it (give the look, or the change "
                             "of light)");
    }
    if (r.look.empty() && !r.config.empty())
    {
        throw ParameterError("{config} holds the looks {look} names: give {look=}NAME with it");
    }
    // Every path before any work: a run that cannot write fails at once.
    CheckFrameSetPaths(FrameSet(r));
    ApplyResult result;
    OCIO::ConstProcessorRcPtr processor;
    // rootpoly without a config is applied natively: a few ns a pixel, no
    // LUT between the fit and the pixels.
    std::function<void(float*, size_t)> native;
    std::optional<ClampMatrixKernel> kernel;
    ImageColourRequest colour;
    if (!r.look.empty())
    {
        if (r.config.empty())
        {
            throw ParameterError("{look} needs {config=}DIR (or use {src}/{dst}/{method})");
        }
        OCIO::ConstConfigRcPtr config = LoadConfig(r.config);
        if (!config->getLook(r.look.c_str()))
        {
            throw Exception("look '" + r.look + "' is not in " + r.config);
        }
        const std::string space =
            r.colorspace.empty() ? std::string(OCIO::ROLE_SCENE_LINEAR) : r.colorspace;
        if (!config->getColorSpace(space.c_str()))
        {
            throw Exception("colour space '" + space + "' is not in " + r.config);
        }
        OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
        t->setSrc(space.c_str());
        t->setDst(space.c_str());
        t->setLooks(r.look.c_str());
        processor = config->getProcessor(t);
        result.applied = "look " + r.look;
        // The image's pixels in the look's space: as they are when the user
        // named the space; else converted from what the file says to
        // scene_linear, whose primaries the config shows.
        if (r.colorspace.empty())
        {
            try
            {
                colour.working = IdentifySceneLinear(config).space;
            }
            catch (const Exception& e)
            {
                reporter.note("the primaries of " + r.config +
                              "'s scene_linear are unknown, so the image goes to the look as it "
                              "is; name its colour space in the config with {colorspace} (" +
                              std::string(e.what()) + ")");
            }
        }
        // A look whose optimised processor is a clamp and a matrix (any
        // config's, read back from OCIO) runs on the native kernel.
        if (const std::optional<ClampMatrixKernel> k = NativeClampMatrix(processor))
        {
            kernel = *k;
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
        const MethodSpec method = relight.methodSpec(reporter);
        const Observer observer = ParseObserver(relight.observer);
        if (method.entry().appliesNatively())
        {
            const auto relighter = std::make_shared<Relighter>(relight.src, relight.dst, method,
                                                               relight.working(), observer);
            native = [relighter](float* rgb, size_t n) { relighter->apply(rgb, n, 1); };
            result.applied =
                LookName(method.name, relight.src.name, relight.dst.name) + " (native)";
        }
        else
        {
            OCIO::GroupTransformRcPtr t = IlluminantChangeTransform(
                relight.src, relight.dst, method, relight.working(), observer);
            processor = OCIO::Config::CreateRaw()->getProcessor(t);
            result.applied = t->getFormatMetadata().getName();
            // The linear methods: their guarded 3×3, natively.
            kernel = NativeClampMatrix(processor);
        }
    }
    const BufferWork work = kernel   ? KernelWork(*kernel, r.threads)
                            : native ? RgbWork(native, r.threads)
                                     : ProcessorWork(processor->getOptimizedCPUProcessor(
                                                         OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                                         OCIO::OPTIMIZATION_DEFAULT),
                                                     r.threads);
    // Each note once for a sequence: the frame's name as the pattern.
    // Frames run on several threads at once (RunFrameSet).
    std::set<std::string> noted;
    std::mutex mu;
    const auto applyOne = [&](const std::string& in, const std::string& out)
    {
        const std::vector<std::string> notes = ApplyToImage(work, in, out, result.applied, colour);
        std::lock_guard<std::mutex> lock(mu);
        for (std::string n : notes)
        {
            for (const auto& [name, pattern] : {std::pair{in, r.input}, std::pair{out, r.output}})
            {
                for (size_t at = n.find(name); !name.empty() && at != std::string::npos;
                     at = n.find(name, at + pattern.size()))
                {
                    n.replace(at, name.size(), pattern);
                }
            }
            if (noted.insert(n).second)
            {
                reporter.note(n);
            }
        }
    };

    result.native = kernel.has_value() || bool(native);
    const FrameRun run = RunFrameSet(FrameSet(r), reporter, applyOne);
    result.frames = run.frames;
    result.skipped = run.skipped;
    result.failed = run.failed;
    result.seconds = run.seconds;
    result.sequence = run.sequence;
    return result;
}

}  // namespace bandlight::jobs
