// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/RenderFiles.h"

#include <algorithm>
#include <sstream>

#include "imageio/ImageColour.h"
#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"
#include "imaging/SpectralImages.h"
#include "plugin/ConfigBuilder.h"
#include "plugin/OcioTransforms.h"
#include "render/SceneColour.h"
#include "requests/Inputs.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/SpectralImage.h"

namespace bandlight::jobs
{

std::vector<float> SrgbPreview(const RenderedImage& img, const RgbSpace& working)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(MakeMatrixTransform(SpaceToSpace(working, Rec709Space())));
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

RenderFile WriteBandValues(const RenderedImage& img, const std::string& out, const BandSet& bands,
                           OutputSet& outputs)
{
    WriteImage(out, img.pixels.data(), img.width, img.height, img.channels, img.channelNames,
               BandDescription(bands), PixelType::FLOAT, &outputs);
    return {out, Size(img) + ", " + std::to_string(img.channels) + " band channels"};
}

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

}  // namespace bandlight::jobs
