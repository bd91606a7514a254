// SPDX-License-Identifier: BSD-3-Clause
// `bandlight render`: Phong with coloured lights in band or spectral mode,
// planned so only the effects the scene calls for are simulated.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include <Eigen/LU>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/ImageApply.h"
#include "jobs/RenderJob.h"
#include "jobs/SpectralJob.h"
#include "plugin/ConfigBuilder.h"
#include "render/SceneColour.h"
#include "render/SceneRenderer.h"
#include "spectral/AtomicFile.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"
#include "spectral/SpectralImage.h"
#include "transforms/Accuracy.h"

namespace bandlight::cli
{

namespace
{
using jobs::ApplyToBuffer;
using jobs::ImageDescription;
using jobs::LinearImageDescription;
using jobs::PixelType;
using jobs::WriteImage;

struct RenderOptions
{
    std::string scene;
    std::string out;
    std::string mode;
    bool explain = false;
    bool compare = false;
    bool unplanned = false;
    bool spectra = false;
    int threads = 0;
};

std::string Stem(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    return dot != std::string::npos && (slash == std::string::npos || dot > slash)
               ? path.substr(0, dot)
               : path;
}

/// An sRGB preview of a working-space image through OCIO: Bradford to
/// Rec.709, then the sRGB curve.
std::vector<float> SrgbPreview(const RenderedImage& img, const RgbSpace& working)
{
    const RgbSpace& rec709 = FindRgbSpace("rec709");
    const Vec3 ws = WhiteXyz(working.chromaticities.wx, working.chromaticities.wy);
    const Vec3 wd = WhiteXyz(rec709.chromaticities.wx, rec709.chromaticities.wy);
    const Mat3 m = RgbToXyzMatrix(rec709.chromaticities).inverse() *
                   AdaptationMatrix(ws, wd, AdaptationMethod::BRADFORD) *
                   RgbToXyzMatrix(working.chromaticities);
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    // clang-format off
    const double m44[16] = {m(0, 0), m(0, 1), m(0, 2), 0, m(1, 0), m(1, 1), m(1, 2), 0,
                            m(2, 0), m(2, 1), m(2, 2), 0, 0, 0, 0, 1};
    // clang-format on
    OCIO::MatrixTransformRcPtr mt = OCIO::MatrixTransform::Create();
    mt->setMatrix(m44);
    g->appendTransform(mt);
    OCIO::ExponentWithLinearTransformRcPtr srgb = OCIO::ExponentWithLinearTransform::Create();
    const double gamma[4] = {2.4, 2.4, 2.4, 1.0};
    const double offset[4] = {0.055, 0.055, 0.055, 0.0};
    srgb->setGamma(gamma);
    srgb->setOffset(offset);
    srgb->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
    g->appendTransform(srgb);
    std::vector<float> px = img.pixels;
    const int rgb[3] = {0, 1, 2};
    ApplyToBuffer(OCIO::Config::CreateRaw()->getProcessor(g)->getDefaultCPUProcessor(), px.data(),
                  img.width, img.height, 3, rgb, 0);
    return px;
}

/// Adds the render (and its sRGB preview) to `outputs`; returns what to
/// report once the set is written.
std::string Write(const RenderedImage& img, const std::string& out, const std::string& space,
                  const BandSet& bands, const RenderedImage* spectra, OutputSet& outputs)
{
    std::ostringstream report;
    if (space == "bands")
    {
        ImageDescription d;
        d.colorSpace = "bands";
        d.attributes.push_back(
            {"bandlight:channels", "band values (radiometric), not RGB: " + bands.describe()});
        d.attributes.push_back({"bandlight:colorSpace", "bands"});
        // Each channel's band, for readers (bandlight spectral reads them as buckets).
        std::string list;
        for (const Band& b : bands)
        {
            list += (list.empty() ? "" : ",") + b.name + " " + Fixed(b.minNm, 3) + "-" +
                    Fixed(b.maxNm, 3);
        }
        d.attributes.push_back({"bandlight:bands", list});
        d.attributes.push_back({"colorInteropID", "data"});
        WriteImage(out, img.pixels.data(), img.width, img.height, img.channels, img.channelNames, d,
                   PixelType::FLOAT, &outputs);
        report << "Wrote " << out << " (" << img.width << "x" << img.height << ", " << img.channels
               << " band channels)\n";
        return report.str();
    }
    const RgbSpace& rgb = FindRgbSpace(space);
    const ImageDescription linear = LinearImageDescription(rgb, ColorSpaceName(rgb));
    if (spectra)
    {
        std::vector<double> wavelengths;
        for (const std::string& name : spectra->channelNames)
        {
            wavelengths.push_back(ParseSpectralChannel(name)->wavelengthNm);
        }
        jobs::WriteSpectralImage(out, img.width, img.height, SpectralKind::EMISSIVE, wavelengths,
                                 spectra->pixels, img.pixels, linear, &outputs);
        report << "Wrote " << out << " (" << img.width << "x" << img.height << ", R, G, B in "
               << ColorSpaceName(rgb) << " and " << wavelengths.size()
               << " spectral radiance channels, Fichet 2021 layout)\n";
    }
    else
    {
        WriteImage(out, img.pixels.data(), img.width, img.height, img.channels, img.channelNames,
                   linear, PixelType::FLOAT, &outputs);
        report << "Wrote " << out << " (" << img.width << "x" << img.height << ", " << img.channels
               << " channels, " << ColorSpaceName(rgb) << ")\n";
    }
    const std::string png = Stem(out) + ".png";
    const std::vector<float> preview = SrgbPreview(img, rgb);
    ImageDescription srgb;
    srgb.colorSpace = "sRGB";
    WriteImage(png, preview.data(), img.width, img.height, 3, img.channelNames, srgb,
               PixelType::UINT8, &outputs);
    report << "Wrote " << png << " (sRGB preview)\n";
    return report.str();
}

void RunRender(const RenderOptions& o)
{
    const Scene scene =
        jobs::LoadScene(o.scene, std::nullopt, o.scene,
                        o.mode.empty() ? std::nullopt : std::optional<std::string>(o.mode));
    // --unplanned says what the literal path does, not what a plan would.
    const ScenePlan plan = o.unplanned ? ScenePlan{} : PlanScene(scene);
    std::cout << (o.unplanned ? ExplainUnplanned(scene) : ExplainPlan(scene, plan));
    if (o.explain)
    {
        return;
    }
    const std::string out = o.out.empty() ? Stem(o.scene) + ".exr" : o.out;
    RenderCounters counters;
    const auto t0 = std::chrono::steady_clock::now();
    const RenderedImage img = o.unplanned ? RenderSceneUnplanned(scene, o.threads, &counters)
                                          : RenderScene(scene, plan, o.threads, &counters);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "rendered " << counters.pixels << " pixels (" << counters.hits << " hits) in "
              << Fixed(seconds * 1e3, 1) << " ms: " << counters.lightTerms << " light terms, "
              << counters.specularTerms << " specular, " << counters.attenuationTerms
              << " attenuation, " << counters.spectralSamples << " per-pixel spectral samples\n";
    // The render, its preview and (with --compare) the heat maps are one set.
    OutputSet outputs;
    std::optional<RenderedImage> spectra;
    if (o.spectra)
    {
        if (scene.settings.mode != RenderSettings::Mode::SPECTRAL)
        {
            throw Exception(
                "--spectra needs spectral mode (--mode spectral): band mode has no "
                "spectrum to write");
        }
        if (scene.settings.output == "bands")
        {
            throw Exception("--spectra writes R, G, B beside the spectrum: give an RGB output");
        }
        Scene radiance = scene;
        radiance.settings.output = detail::SPECTRUM_OUTPUT;
        spectra = RenderScene(radiance, PlanScene(radiance), o.threads);
    }
    std::string report = Write(img, out, scene.settings.output, scene.settings.bands,
                               spectra ? &*spectra : nullptr, outputs);

    if (!o.compare)
    {
        outputs.commit();
        std::cout << report;
        return;
    }
    if (scene.settings.output == "bands")
    {
        throw Exception("--compare needs an RGB output: the spectral reference has no bands");
    }
    Scene reference = scene;
    reference.settings.mode = RenderSettings::Mode::SPECTRAL;
    const RenderedImage ref = RenderScene(reference, PlanScene(reference), o.threads);
    const Mat3 toXyz = RgbToXyzMatrix(FindRgbSpace(scene.settings.output).chromaticities);
    // L*a*b* relative to the equal-energy white at the brightest light's level.
    double level = 0.0;
    for (const SceneLight& l : scene.lights)
    {
        level += l.intensity;
    }
    const Vec3 white = Vec3::Ones() * std::max(level, 1e-6);
    RenderedImage heat;
    heat.width = img.width;
    heat.height = img.height;
    heat.channels = 1;
    heat.channelNames = {"dE00"};
    heat.pixels.assign(size_t(img.width) * size_t(img.height), 0.0f);
    std::vector<double> de;
    for (size_t i = 0; i < heat.pixels.size(); ++i)
    {
        const float* a = &img.pixels[3 * i];
        const float* b = &ref.pixels[3 * i];
        const Vec3 xa = toXyz * Vec3(a[0], a[1], a[2]);
        const Vec3 xb = toXyz * Vec3(b[0], b[1], b[2]);
        if (xa.isZero(0.0) && xb.isZero(0.0))
        {
            continue;  // background
        }
        const double e = DeltaE2000(XyzToLab(xa, white), XyzToLab(xb, white));
        heat.pixels[i] = float(e);
        de.push_back(e);
    }
    const std::string heatPath = Stem(out) + "_dE00.exr";
    ImageDescription data;
    data.colorSpace = "data";
    WriteImage(heatPath, heat.pixels.data(), heat.width, heat.height, 1, heat.channelNames, data,
               PixelType::FLOAT, &outputs);
    // A viewable heat map: 0 → black, 10 ΔE00 or more → white.
    std::vector<float> grey(heat.pixels.size());
    for (size_t i = 0; i < grey.size(); ++i)
    {
        grey[i] = std::min(1.0f, heat.pixels[i] / 10.0f);
    }
    WriteImage(Stem(out) + "_dE00.png", grey.data(), heat.width, heat.height, 1, {"Y"}, data,
               PixelType::UINT8, &outputs);
    outputs.commit();
    std::cout << report;
    double sum = 0.0;
    for (double e : de)
    {
        sum += e;
    }
    std::cout << "compare with spectral: " << de.size() << " pixels, ΔE00 mean "
              << Fixed(de.empty() ? 0.0 : sum / double(de.size()), 3) << ", p95 "
              << Fixed(Percentile(de, 0.95), 3) << ", max " << Fixed(Percentile(de, 1.0), 3) << " ("
              << heatPath << ", _dE00.png: black 0, white >= 10)\n";
}

}  // namespace

void AddRenderCommand(CLI::App& app)
{
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a YAML scene (Phong, coloured lights) in band or spectral mode");
    cmd->add_option("SCENE", o->scene, "Scene file (see docs/scenes.md)")->required();
    cmd->add_option("-o,--out", o->out, "Output EXR (default: SCENE.exr); an sRGB PNG goes beside");
    cmd->add_option("--mode", o->mode, "Override the scene's mode: band3, bandN or spectral");
    cmd->add_flag("--explain", o->explain,
                  "Print the plan (with --unplanned: what the literal path does) and stop");
    cmd->add_flag("--compare", o->compare,
                  "Also render the spectral reference; write a ΔE00 heat map and a summary");
    cmd->add_flag("--unplanned", o->unplanned,
                  "Evaluate every term per pixel and sample (the reference for the planner)");
    cmd->add_flag("--spectra", o->spectra,
                  "Spectral mode: write the spectral radiance into the EXR too, as S0.<nm> "
                  "channels beside R, G, B (Fichet 2021 layout; read by bandlight spectral)");
    cmd->add_option("--threads", o->threads, "Threads (0: all cores; at most 256)")
        ->check(CLI::Range(0, kMaxThreads))
        ->capture_default_str();
    cmd->callback([o] { RunRender(*o); });
}

}  // namespace bandlight::cli
