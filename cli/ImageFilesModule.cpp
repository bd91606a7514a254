// SPDX-License-Identifier: BSD-3-Clause
// The image-file module (see cli/ImageFiles.h): OpenImageIO reading and
// writing, loaded on demand by the bandlight command.
#include <exception>

#include <OpenImageIO/imageio.h>

#include "cli/ImageFiles.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{
namespace
{

/// Channel indices of R, G, B by name, falling back to the first three.
void FindRgb(const OIIO::ImageSpec& spec, int rgb[3])
{
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
    {
        rgb[c] = c;
        for (int i = 0; i < spec.nchannels; ++i)
        {
            if (spec.channel_name(i) == names[c])
            {
                rgb[c] = i;
                break;
            }
        }
    }
}

void Write(const std::string& path, const OIIO::ImageSpec& spec, const float* pixels)
{
    AtomicFile file(path);
    file.stream().close();  // OIIO writes by name
    auto output = OIIO::ImageOutput::create(path);
    if (!output)
    {
        throw Exception(path + ": no image writer for this file type: " + OIIO::geterror());
    }
    if (!output->open(file.tempPath(), spec) ||
        !output->write_image(OIIO::TypeDesc::FLOAT, pixels) || !output->close())
    {
        throw Exception(path + ": cannot write image: " + output->geterror());
    }
    file.commit();
}

std::string Transform(const std::string& in, const std::string& out, const PixelProcess& process,
                      const std::string& note)
{
    try
    {
        auto input = OIIO::ImageInput::open(in);
        if (!input)
        {
            throw Exception(in + ": cannot read image: " + OIIO::geterror());
        }
        const OIIO::ImageSpec spec = input->spec();
        if (spec.nchannels < 3)
        {
            throw Exception(in + ": has " + std::to_string(spec.nchannels) +
                            " channels; a colour transform needs R, G and B");
        }
        std::vector<float> pixels(spec.image_pixels() * size_t(spec.nchannels));
        if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        {
            throw Exception(in + ": cannot read pixels: " + input->geterror());
        }
        input->close();
        int rgb[3];
        FindRgb(spec, rgb);
        process(pixels.data(), spec.width, long(spec.height) * std::max(1, spec.depth),
                spec.nchannels, rgb);
        OIIO::ImageSpec outSpec = spec;  // pixel type, channel names, metadata
        if (!note.empty())
        {
            outSpec.attribute("bandlight:transform", note);
        }
        Write(out, outSpec, pixels.data());
        return {};
    }
    catch (const std::exception& e)
    {
        return e.what();
    }
}

std::string WriteImage(const std::string& path, const float* pixels, int width, int height,
                       int channels, const std::vector<std::string>& channelNames,
                       const std::string& colorSpace, PixelType type)
{
    try
    {
        const OIIO::TypeDesc t = type == PixelType::HALF    ? OIIO::TypeDesc::HALF
                                 : type == PixelType::UINT8 ? OIIO::TypeDesc::UINT8
                                                            : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(width, height, channels, t);
        if (int(channelNames.size()) == channels)
        {
            spec.channelnames = channelNames;
        }
        spec.alpha_channel = -1;
        for (int c = 0; c < channels; ++c)
        {
            if (spec.channelnames[size_t(c)] == "A")
            {
                spec.alpha_channel = c;
            }
        }
        spec.attribute("oiio:ColorSpace", colorSpace);
        spec.attribute("Software", "bandlight");
        Write(path, spec, pixels);
        return {};
    }
    catch (const std::exception& e)
    {
        return e.what();
    }
}

const ImageFilesApi kApi = {kImageFilesApiVersion, &Transform, &WriteImage,
                            &RemoveTemporaryFiles};

}  // namespace
}  // namespace bandlight::cli

extern "C" const bandlight::cli::ImageFilesApi* bandlight_image_files_api()
{
    return &bandlight::cli::kApi;
}
