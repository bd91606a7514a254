// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/RenderJob.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <sstream>

#include "imaging/ImageApply.h"
#include "jobs/Inputs.h"
#include "imaging/LightGroups.h"
#include "farm/OutputPaths.h"
#include "jobs/SpectralJob.h"
#include "plugin/ConfigBuilder.h"
#include "plugin/OcioTransforms.h"
#include "render/SceneColour.h"
#include "render/SceneFile.h"
#include "spectral/AtomicFile.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/SpectralImage.h"

namespace bandlight::jobs
{

namespace
{

/// `path` without its extension ("shots/a.exr" → "shots/a").
std::string Stem(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    return dot != std::string::npos && (slash == std::string::npos || dot > slash)
               ? path.substr(0, dot)
               : path;
}

/// The preview beside the render: its stem + ".png".
std::string PreviewPath(const std::string& out)
{
    return Stem(out) + ".png";
}

/// The comparison's map beside the render: its stem + "_dE00" + `extension`.
std::string MapPath(const std::string& out, const std::string& extension)
{
    return Stem(out) + "_dE00" + extension;
}

bool BandOutput(const Scene& scene)
{
    return scene.settings.output == "bands";
}

/// The sRGB preview of a working-space image through OCIO: the working
/// space to Rec.709 as a config's colour spaces convert it (Bradford
/// between the whites), then the sRGB curve.
std::vector<float> SrgbPreview(const RenderedImage& img, const RgbSpace& working)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(MakeMatrixTransform(SpaceToSpace(working, FindRgbSpace("rec709"))));
    OCIO::TransformRcPtr encode = SrgbDecode();
    encode->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
    g->appendTransform(encode);
    std::vector<float> px = img.pixels;
    const int rgb[3] = {0, 1, 2};
    ApplyToBuffer(OCIO::Config::CreateRaw()->getProcessor(g)->getDefaultCPUProcessor(), px.data(),
                  img.width, img.height, 3, rgb, 0);
    return px;
}

std::string Size(const RenderedImage& img)
{
    return std::to_string(img.width) + "x" + std::to_string(img.height);
}

/// How band values are described: not RGB.
ImageDescription BandDescription(const BandSet& bands)
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
        list +=
            (list.empty() ? "" : ",") + b.name + " " + Fixed(b.minNm, 3) + "-" + Fixed(b.maxNm, 3);
    }
    d.attributes.push_back({"bandlight:bands", list});
    d.attributes.push_back({"colorInteropID", "data"});
    return d;
}

/// Band values, tagged as what they are: not RGB.
RenderFile WriteBandValues(const RenderedImage& img, const std::string& out, const BandSet& bands,
                           OutputSet& outputs)
{
    WriteImage(out, img.pixels.data(), img.width, img.height, img.channels, img.channelNames,
               BandDescription(bands), PixelType::FLOAT, &outputs);
    return {out, Size(img) + ", " + std::to_string(img.channels) + " band channels"};
}

/// A render by light groups: each group's image (and its spectral
/// radiance), and the beauty, their sum.
struct GroupRender
{
    std::vector<std::string> names;
    std::vector<RenderedImage> images;
    std::vector<RenderedImage> spectra;  ///< empty without spectra
};

/// `parts` summed in double, each value rounded once: the beauty of a
/// light-group render is Σ groups to float precision.
RenderedImage SumImages(const std::vector<RenderedImage>& parts)
{
    RenderedImage sum = parts.front();
    for (size_t i = 0; i < sum.pixels.size(); ++i)
    {
        double v = 0.0;
        for (const RenderedImage& p : parts)
        {
            v += p.pixels[i];
        }
        sum.pixels[i] = float(v);
    }
    return sum;
}

/// The render with one layer per light group: the beauty's channels, its
/// spectral radiance (when given), then for each group "<group>.<channel>"
/// for both; the groups listed in bandlight:lightGroups.
RenderFile WriteLightGroups(const RenderedImage& beauty, const RenderedImage* beautySpectra,
                            const GroupRender& groups, const std::string& out, ImageDescription d,
                            OutputSet& outputs)
{
    std::vector<const RenderedImage*> layers = {&beauty};
    std::vector<std::string> prefixes = {""};
    if (beautySpectra)
    {
        layers.push_back(beautySpectra);
        prefixes.push_back("");
    }
    for (size_t g = 0; g < groups.names.size(); ++g)
    {
        layers.push_back(&groups.images[g]);
        prefixes.push_back(groups.names[g] + ".");
        if (beautySpectra)
        {
            layers.push_back(&groups.spectra[g]);
            prefixes.push_back(groups.names[g] + ".");
        }
    }
    std::vector<std::string> names;
    int channels = 0;
    for (size_t l = 0; l < layers.size(); ++l)
    {
        for (const std::string& n : layers[l]->channelNames)
        {
            names.push_back(prefixes[l] + n);
        }
        channels += layers[l]->channels;
    }
    const size_t count = size_t(beauty.width) * size_t(beauty.height);
    std::vector<float> pixels(count * size_t(channels));
    for (size_t p = 0; p < count; ++p)
    {
        float* dst = &pixels[p * size_t(channels)];
        for (const RenderedImage* l : layers)
        {
            dst = std::copy_n(&l->pixels[p * size_t(l->channels)], l->channels, dst);
        }
    }
    std::string list;
    for (const std::string& n : groups.names)
    {
        list += (list.empty() ? "" : ",") + n;
    }
    d.attributes.push_back({LIGHT_GROUPS_ATTRIBUTE, list});
    if (beautySpectra)
    {
        d.attributes.push_back({"spectralLayoutVersion", "1.0"});
        d.attributes.push_back({"emissiveUnits", "W.m^-2.sr^-1"});
    }
    WriteImage(out, pixels.data(), beauty.width, beauty.height, channels, names, d,
               PixelType::FLOAT, &outputs);
    return {out, Size(beauty) + ", " + std::to_string(groups.names.size()) + " light groups (" +
                     list + ") beside the beauty, " + std::to_string(channels) + " channels" +
                     (beautySpectra ? ", spectral radiance per group (Fichet 2021 layout)" : "")};
}

/// Linear RGB, with the spectral radiance beside it when `spectra`.
RenderFile WriteRgb(const RenderedImage& img, const std::string& out, const RgbSpace& space,
                    const RenderedImage* spectra, OutputSet& outputs)
{
    const ImageDescription linear = LinearImageDescription(space, ColorSpaceName(space));
    if (!spectra)
    {
        WriteImage(out, img.pixels.data(), img.width, img.height, img.channels, img.channelNames,
                   linear, PixelType::FLOAT, &outputs);
        return {out, Size(img) + ", " + std::to_string(img.channels) + " channels, " +
                         ColorSpaceName(space)};
    }
    std::vector<double> wavelengths;
    for (const std::string& name : spectra->channelNames)
    {
        wavelengths.push_back(ParseSpectralChannel(name)->wavelengthNm);
    }
    WriteSpectralImage(out, img.width, img.height, SpectralKind::EMISSIVE, wavelengths,
                       spectra->pixels, img.pixels, linear, &outputs);
    return {out, Size(img) + ", R, G, B in " + ColorSpaceName(space) + " and " +
                     std::to_string(wavelengths.size()) +
                     " spectral radiance channels, Fichet 2021 layout"};
}

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

/// Every file of the set, before the work: a folder that is not there
/// fails now, not after the render, and the scene is never overwritten.
void CheckFiles(const RenderRequest& r, const Scene& scene)
{
    OutputPlan plan;
    if (!r.text)
    {
        plan.input(r.scene);
    }
    plan.file("{out}", r.out);
    if (r.preview && !BandOutput(scene))
    {
        plan.file(r.previewPath.empty() ? "{out}" : "{preview}",
                  r.previewPath.empty() ? PreviewPath(r.out) : r.previewPath);
    }
    if (r.compare)
    {
        plan.file("{out}", MapPath(r.out, ".exr")).file("{out}", MapPath(r.out, ".png"));
    }
    plan.check();
}

/// "band3", "band6" or "spectral": the mode as --mode names it.
std::string ModeName(const RenderSettings& s)
{
    return s.mode == RenderSettings::Mode::SPECTRAL ? "spectral"
                                                    : "band" + std::to_string(s.bands.size());
}

}  // namespace

Scene LoadScene(const std::string& path, const std::optional<std::string>& text,
                const std::string& source, const std::optional<std::string>& mode)
{
    if (!path.empty() && text.has_value())
    {
        throw ParameterError("give a scene file or {text=}YAML, not both");
    }
    if (path.empty() && !text.has_value())
    {
        // The command has no text option: an empty SCENE is a missing file.
        throw FileError(path, ENOENT, "no scene file to render");
    }
    const std::string name = text ? source : path;
    Scene scene = text ? ReadSceneText(*text, source) : ReadSceneFile(path);
    if (mode)
    {
        if (ModeBandCount(*mode) == 0 && scene.settings.output == "bands")
        {
            throw ParameterError("{mode} " + OneLine(*mode, 80) + ": " + name +
                                 " asks for output 'bands' (band values), which only band mode "
                                 "writes; set render: {output: acescg} (or another working "
                                 "space) to render it spectrally");
        }
        SetRenderMode(scene.settings, *mode);
    }
    return scene;
}

std::string DefaultRenderOutput(const std::string& scenePath)
{
    return Stem(scenePath) + ".exr";
}

PreparedRender PrepareRender(const RenderRequest& request)
{
    PreparedRender p;
    p.request = request;
    p.scene = LoadScene(request.scene, request.text, request.source, request.mode);
    // Unplanned, the explanation says what the literal path does, not what
    // a plan would.
    if (!request.unplanned)
    {
        p.plan = PlanScene(p.scene);
    }
    p.explanation = request.unplanned ? ExplainUnplanned(p.scene) : ExplainPlan(p.scene, p.plan);
    return p;
}

void CheckRenderOutputs(const PreparedRender& prepared)
{
    const RenderRequest& r = prepared.request;
    const Scene& scene = prepared.scene;
    if (r.explain)
    {
        return;  // nothing is written
    }
    if (r.spectra)
    {
        if (scene.settings.mode != RenderSettings::Mode::SPECTRAL)
        {
            throw ParameterError(
                "{spectra} needs spectral mode ({mode=}spectral): band mode has no spectrum to "
                "write");
        }
        if (BandOutput(scene))
        {
            throw ParameterError(
                "{spectra} writes R, G, B beside the spectrum: give an RGB output");
        }
    }
    if (r.compare && BandOutput(scene))
    {
        throw ParameterError("{compare} needs an RGB output: the spectral reference has no bands");
    }
    if (r.compare && scene.settings.mode == RenderSettings::Mode::SPECTRAL)
    {
        throw ParameterError(
            "{compare} measures a band render against the spectral one, and this render is "
            "spectral already (its map would be 0 everywhere): give {mode=}band3 or bandN");
    }
    if (!r.previewPath.empty() && r.preview && BandOutput(scene))
    {
        throw ParameterError("{preview} shows RGB: band values (output: bands) have no preview");
    }
    if (r.out.empty())
    {
        if (r.lightGroups)
        {
            throw ParameterError(
                "{light_groups} writes one layer per light group into the render's EXR: give "
                "{out}");
        }
        if (r.spectra)
        {
            throw ParameterError("{spectra} writes the spectrum into the render's EXR: give {out}");
        }
        if (r.compare)
        {
            throw ParameterError("{compare} writes its ΔE00 map beside the render: give {out}");
        }
        if (!r.previewPath.empty() && r.preview)
        {
            throw ParameterError("{preview} is the picture of a render written: give {out}");
        }
    }
}

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
        CheckFiles(r, scene);
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
