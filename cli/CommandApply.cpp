// SPDX-License-Identifier: BSD-3-Clause
// `bandlight apply`: re-light images (and frame sequences) through OpenImageIO.
#include <functional>
#include <iostream>
#include <memory>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/ImageApply.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::cli
{

namespace
{

struct ApplyOptions
{
    std::string in;
    std::string out;
    std::string look;
    std::string config;
    std::string colorspace;
    RelightOptions relight;
    std::string frames;
    int threads = 0;
};

OCIO::ConstConfigRcPtr LoadConfig(const std::string& path)
{
    const std::string file =
        path.size() > 5 && path.substr(path.size() - 5) == ".ocio" ? path : path + "/config.ocio";
    return ReadConfigFile(file);
}

void RunApply(const ApplyOptions& o)
{
    OCIO::ConstProcessorRcPtr processor;
    std::string note;
    // rootpoly without a config is applied natively: a few ns a pixel, no
    // LUT between the fit and the pixels.
    std::function<void(float*, size_t)> native;
    if (!o.look.empty())
    {
        if (o.config.empty())
        {
            throw Exception("--look needs --config DIR (or use --from/--to/--method)");
        }
        OCIO::ConstConfigRcPtr config = LoadConfig(o.config);
        if (!config->getLook(o.look.c_str()))
        {
            throw Exception("look '" + o.look + "' is not in " + o.config);
        }
        const std::string space =
            o.colorspace.empty() ? std::string(OCIO::ROLE_SCENE_LINEAR) : o.colorspace;
        if (!config->getColorSpace(space.c_str()))
        {
            throw Exception("colour space '" + space + "' is not in " + o.config);
        }
        OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
        t->setSrc(space.c_str());
        t->setDst(space.c_str());
        t->setLooks(o.look.c_str());
        processor = config->getProcessor(t);
        note = "look " + o.look;
    }
    else
    {
        if (o.relight.from.empty() || o.relight.to.empty())
        {
            throw Exception("give --look NAME --config DIR, or --from S1 --to S2 [--method M]");
        }
        const MethodSpec method = o.relight.methodSpec();
        if (method.method == ChangeMethod::ROOTPOLY ||
            method.method == ChangeMethod::ROOTPOLY_CAMERA)
        {
            const NamedSpectrum from = ResolveIlluminant(o.relight.from);
            const NamedSpectrum to = ResolveIlluminant(o.relight.to);
            const auto relighter = std::make_shared<Relighter>(
                Light{from.name, from.spectrum}, Light{to.name, to.spectrum}, method,
                FindRgbSpace(o.relight.workingSpace));
            native = [relighter](float* rgb, size_t n) { relighter->apply(rgb, n, 1); };
            note = LookName(method.name, from.name, to.name) + " (native)";
        }
        else
        {
            OCIO::GroupTransformRcPtr t = RelightTransform(o.relight, nullptr);
            processor = OCIO::Config::CreateRaw()->getProcessor(t);
            note = t->getFormatMetadata().getName();
        }
    }
    const auto applyOne = [&](const std::string& in, const std::string& out)
    {
        if (native)
        {
            ApplyToImage(native, in, out, o.threads, note);
        }
        else
        {
            ApplyToImage(processor->getOptimizedCPUProcessor(
                             OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT),
                         in, out, o.threads, note);
        }
    };

    if (o.frames.empty())
    {
        if (HasFramePattern(o.in))
        {
            throw Exception("'" + o.in + "' is a frame pattern: give --frames FIRST-LAST");
        }
        applyOne(o.in, o.out);
        return;
    }
    if (!HasFramePattern(o.in) || !HasFramePattern(o.out))
    {
        throw Exception("--frames needs frame patterns such as plate.####.exr for IN and OUT");
    }
    const std::vector<int> frames = ParseFrameRange(o.frames);
    for (int f : frames)
    {
        applyOne(ExpandFramePattern(o.in, f), ExpandFramePattern(o.out, f));
    }
    std::cout << "Applied " << note << " to " << frames.size() << " frames\n";
}

}  // namespace

void AddApplyCommand(CLI::App& app)
{
    auto o = std::make_shared<ApplyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "apply", "Re-light an image or a frame sequence through OpenImageIO and OpenColorIO");
    cmd->add_option("IN", o->in, "Input image, or a pattern such as plate.####.exr")->required();
    cmd->add_option("OUT", o->out, "Output image, or a pattern")->required();
    cmd->add_option("--look", o->look, "Look to apply, from --config");
    cmd->add_option("--config", o->config, "Config directory (or .ocio file) holding the look");
    cmd->add_option("--colorspace", o->colorspace,
                    "Colour space of the image in the config (default: its scene_linear role)");
    AddRelightOptions(*cmd, o->relight, false);
    cmd->add_option("--frames", o->frames, "Frame range for patterns, e.g. 1001-1100");
    cmd->add_option("--threads", o->threads, "Threads (0: all cores; at most 256)")
        ->check(CLI::Range(0, kMaxThreads))
        ->capture_default_str();
    cmd->callback([o] { RunApply(*o); });
}

}  // namespace bandlight::cli
