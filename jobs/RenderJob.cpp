// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/RenderJob.h"

#include <chrono>
#include <optional>
#include <sstream>

#include "imageio/ImageColour.h"
#include "plugin/ConfigBuilder.h"
#include "render/SceneColour.h"
#include "render/SceneFile.h"
#include "spectral/Colorimetry.h"
#include "requests/Inputs.h"
#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::jobs
{

std::vector<std::string> RenderResult::written() const
{
    std::vector<std::string> all;
    for (const RenderFile& f : files)
    {
        all.push_back(f.path);
    }
    if (comparison)
    {
        all.push_back(comparison->exr);
        all.push_back(comparison->png);
    }
    return all;
}

namespace
{

/// ΔE00 of `img` against the spectral reference `ref`, per pixel hit:
/// L*a*b* relative to the equal-energy white at the lights' summed level.
DeltaEMap CompareWithReference(const Scene& scene, const RenderedImage& img,
                               const RenderedImage& ref)
{
    const Mat3 toXyz = RgbToXyzMatrix(FindRgbSpace(scene.settings.output).chromaticities);
    double level = 0.0;
    for (const SceneLight& l : scene.lights)
    {
        level += l.intensity;
    }
    const Vec3 white = Vec3::Ones() * std::max(level, 1e-6);
    DeltaEMap map(img.width, img.height);
    const size_t count = size_t(img.width) * size_t(img.height);
    for (size_t i = 0; i < count; ++i)
    {
        const float* a = &img.pixels[3 * i];
        const float* b = &ref.pixels[3 * i];
        const Vec3 xa = toXyz * Vec3(a[0], a[1], a[2]);
        const Vec3 xb = toXyz * Vec3(b[0], b[1], b[2]);
        if (xa.isZero(0.0) && xb.isZero(0.0))
        {
            continue;  // background
        }
        map.set(i, DeltaE2000(XyzToLab(xa, white), XyzToLab(xb, white)));
    }
    return map;
}

/// The render itself, timed: one image, or with light groups one render
/// per group, each planned on its own (lights sharing a spectrum share a
/// term only inside a group), the beauty their sum.
void RenderImages(const PreparedRender& prepared, GroupRender& groups, RenderResult& result)
{
    const RenderRequest& r = prepared.request;
    const Scene& scene = prepared.scene;
    const auto t0 = std::chrono::steady_clock::now();
    const auto render = [&](const Scene& s, const ScenePlan* plan, RenderCounters* counters)
    {
        return r.unplanned ? RenderSceneUnplanned(s, r.threads, counters)
                           : RenderScene(s, plan ? *plan : PlanScene(s), r.threads, counters);
    };
    if (r.lightGroups)
    {
        groups.names = LightGroupNames(scene);
        for (const std::string& g : groups.names)
        {
            RenderCounters c;
            groups.images.push_back(render(SceneOfLightGroup(scene, g), nullptr, &c));
            result.counters.pixels = c.pixels;
            result.counters.hits = c.hits;
            result.counters.lightTerms += c.lightTerms;
            result.counters.specularTerms += c.specularTerms;
            result.counters.attenuationTerms += c.attenuationTerms;
            result.counters.spectralSamples += c.spectralSamples;
        }
        result.image = SumImages(groups.images);
    }
    else
    {
        result.image = render(scene, &prepared.plan, &result.counters);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// --spectra: the scene's spectral radiance (per group with light groups;
/// the groups' spectra kept in `groups`), rendered after the timed render.
RenderedImage RenderSpectra(const PreparedRender& prepared, GroupRender& groups)
{
    const RenderRequest& r = prepared.request;
    const auto radiance = [](Scene s)
    {
        s.settings.output = detail::SPECTRUM_OUTPUT;
        return s;
    };
    if (r.lightGroups)
    {
        for (const std::string& g : groups.names)
        {
            const Scene s = radiance(SceneOfLightGroup(prepared.scene, g));
            groups.spectra.push_back(RenderScene(s, PlanScene(s), r.threads));
        }
        return SumImages(groups.spectra);
    }
    const Scene s = radiance(prepared.scene);
    return RenderScene(s, PlanScene(s), r.threads);
}

/// The RGB render (with its spectra and group layers when asked) and its
/// sRGB preview, joining `outputs`.
void WriteRgbRender(const PreparedRender& prepared, GroupRender& groups, RenderResult& result,
                    OutputSet& outputs)
{
    const RenderRequest& r = prepared.request;
    const RenderedImage& img = result.image;
    const RgbSpace& space = FindRgbSpace(prepared.scene.settings.output);
    std::optional<RenderedImage> spectra;
    if (r.spectra)
    {
        spectra = RenderSpectra(prepared, groups);
    }
    if (r.lightGroups)
    {
        result.files.push_back(
            WriteLightGroups(img, spectra ? &*spectra : nullptr, groups, r.out,
                             LinearImageDescription(space, ColorSpaceName(space)), outputs));
    }
    else
    {
        result.files.push_back(WriteRgb(img, r.out, space, spectra ? &*spectra : nullptr, outputs));
    }
    if (r.preview)
    {
        const std::string png = r.previewPath.empty() ? PreviewPath(r.out) : r.previewPath;
        const std::vector<float> preview = SrgbPreview(img, space);
        ImageDescription srgb;
        srgb.colorSpace = "sRGB";
        WriteImage(png, preview.data(), img.width, img.height, 3, img.channelNames, srgb,
                   PixelType::UINT8, &outputs);
        result.files.push_back({png, "sRGB preview"});
    }
}

/// --compare: the render against a spectral render of the same scene, as a
/// ΔE00 map (EXR, and PNG with its scale) joining `outputs`.
RenderComparison WriteComparison(const PreparedRender& prepared, const RenderedImage& img,
                                 OutputSet& outputs)
{
    const RenderRequest& r = prepared.request;
    const Scene& scene = prepared.scene;
    Scene reference = scene;
    reference.settings.mode = RenderSettings::Mode::SPECTRAL;
    const RenderedImage ref = RenderScene(reference, PlanScene(reference), r.threads);
    const DeltaEMap map = CompareWithReference(scene, img, ref);
    RenderComparison c;
    c.summary = map.summary();
    c.exr = MapPath(r.out, ".exr");
    c.png = MapPath(r.out, ".png");
    std::ostringstream title;
    title << "CIEDE2000 of the " << ModeName(scene.settings)
          << " render against the spectral reference: mean " << Fixed(c.summary.mean, 2)
          << ", p95 " << Fixed(c.summary.p95, 2) << ", max " << Fixed(c.summary.max, 2);
    WriteDeltaEMap(map, c.exr, c.png, title.str(), {}, outputs);
    return c;
}

}  // namespace

RenderResult MakeRender(const PreparedRender& prepared, Reporter& reporter)
{
    (void)reporter;  // the render has nothing to note; the parameter keeps the jobs' shape
    const RenderRequest& r = prepared.request;
    const Scene& scene = prepared.scene;
    RenderResult result;
    result.explanation = prepared.explanation;
    if (r.explain)
    {
        return result;
    }
    CheckRenderOutputs(prepared);
    if (!r.out.empty())
    {
        CheckRenderFiles(r, scene);
    }
    GroupRender groups;
    RenderImages(prepared, groups, result);
    if (r.out.empty())
    {
        return result;
    }
    // The render, its preview and the comparison's map are one set.
    OutputSet outputs;
    if (BandOutput(scene))
    {
        result.files.push_back(
            r.lightGroups ? WriteLightGroups(result.image, nullptr, groups, r.out,
                                             BandDescription(scene.settings.bands), outputs)
                          : WriteBandValues(result.image, r.out, scene.settings.bands, outputs));
    }
    else
    {
        WriteRgbRender(prepared, groups, result, outputs);
    }
    if (r.compare)
    {
        result.comparison = WriteComparison(prepared, result.image, outputs);
    }
    outputs.commit();
    return result;
}

RenderResult MakeRender(const RenderRequest& request, Reporter& reporter)
{
    return MakeRender(PrepareRender(request), reporter);
}

}  // namespace bandlight::jobs
