// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/ApplyJob.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>

#include "jobs/Frames.h"
#include "jobs/ImageApply.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

ApplyResult ApplyImages(const ApplyRequest& r, Reporter& reporter)
{
    if (r.threads < 0 || r.threads > kMaxThreads)
    {
        throw ParameterError("{threads} must be 0 (all cores) to " + std::to_string(kMaxThreads) +
                             ", got " + std::to_string(r.threads));
    }
    ApplyResult result;
    OCIO::ConstProcessorRcPtr processor;
    // rootpoly without a config is applied natively: a few ns a pixel, no
    // LUT between the fit and the pixels.
    std::function<void(float*, size_t)> native;
    std::optional<ClampMatrixKernel> kernel;
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
        const MethodSpec method = relight.methodSpec(reporter);
        const Observer observer = ParseObserver(relight.observer);
        if (method.method == ChangeMethod::ROOTPOLY ||
            method.method == ChangeMethod::ROOTPOLY_CAMERA)
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
    const auto applyOne = [&](const std::string& in, const std::string& out)
    {
        if (kernel)
        {
            ApplyToImage(*kernel, in, out, r.threads, result.applied);
        }
        else if (native)
        {
            ApplyToImage(native, in, out, r.threads, result.applied);
        }
        else
        {
            ApplyToImage(processor->getOptimizedCPUProcessor(
                             OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT),
                         in, out, r.threads, result.applied);
        }
    };

    result.native = kernel.has_value() || bool(native);
    if (r.frames.empty())
    {
        if (HasFramePattern(r.input))
        {
            throw ParameterError("'" + r.input + "' is a frame pattern: give {frames=}FIRST-LAST");
        }
        applyOne(r.input, r.output);
        result.frames = 1;
        return result;
    }
    if (!HasFramePattern(r.input) || !HasFramePattern(r.output))
    {
        throw ParameterError("{frames} needs frame patterns such as plate.####.exr for IN and OUT");
    }
    const std::vector<int> frames = ParseFrameRange(r.frames);
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < frames.size(); ++i)
    {
        const int f = frames[i];
        const std::string out = ExpandFramePattern(r.output, f);
        std::string state = "done";
        if (r.skipExisting && std::filesystem::exists(out))
        {
            ++result.skipped;
            state = "skipped (exists)";
        }
        else
        {
            try
            {
                applyOne(ExpandFramePattern(r.input, f), out);
                ++result.frames;
            }
            catch (const std::exception& e)
            {
                if (!r.keepGoing)
                {
                    throw;
                }
                result.failed.push_back({f, e.what()});
                state = "failed";
            }
        }
        reporter.progress("frame " + std::to_string(f) + " " + state + " (" +
                              std::to_string(i + 1) + " of " + std::to_string(frames.size()) + ")",
                          double(i + 1) / double(frames.size()));
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    result.sequence = true;
    return result;
}

}  // namespace bandlight::jobs
