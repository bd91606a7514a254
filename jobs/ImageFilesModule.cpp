// SPDX-License-Identifier: BSD-3-Clause
// The image-file module (see jobs/ImageFiles.h): OpenImageIO reading and
// writing, loaded on demand by the bandlight command.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

#include <OpenImageIO/imageio.h>

#include "bandlight/jobs/ImageFiles.h"
#include "bandlight/spectral/AtomicFile.h"
#include "bandlight/spectral/Exception.h"
#include "bandlight/spectral/TextFile.h"

namespace bandlight::jobs
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

/// Writes `path` atomically, or straight to `writeAs` when the caller's
/// OutputSet owns the temporary name.
void Write(const std::string& path, const OIIO::ImageSpec& spec, const float* pixels,
           const std::string& writeAs = "")
{
    std::unique_ptr<AtomicFile> file;
    if (writeAs.empty())
    {
        file = std::make_unique<AtomicFile>(path);
        file->stream().close();  // OIIO writes by name
    }
    const std::string target = writeAs.empty() ? file->tempPath() : writeAs;
    auto output = OIIO::ImageOutput::create(path);
    if (!output)
    {
        throw Exception(PathInMessage(path) +
                        ": no image writer for this file type: " + OIIO::geterror());
    }
    // The file itself was created above (or by the caller's OutputSet): what
    // fails here is the format refusing the image, not the file system.
    if (!output->open(target, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, pixels) ||
        !output->close())
    {
        throw Exception(PathInMessage(path) + ": cannot write image: " + output->geterror());
    }
    if (file)
    {
        file->commit();
    }
}

/// Checks, before anything is allocated, that an image of this size fits:
/// at most half the machine's memory, and dimensions OIIO can address.
void CheckImageSize(const std::string& file, const OIIO::ImageSpec& spec)
{
    const double pages = double(::sysconf(_SC_PHYS_PAGES));
    const double pageSize = double(::sysconf(_SC_PAGESIZE));
    const double limit = pages > 0 && pageSize > 0 ? 0.5 * pages * pageSize : 8.0 * (1 << 30);
    const double bytes = double(spec.width) * double(spec.height) *
                         double(std::max(1, spec.depth)) * double(spec.nchannels) * 4.0;
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || !(bytes <= limit))
    {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.1f GiB", limit / double(1 << 30));
        throw Exception(file + ": the header declares " + std::to_string(spec.width) + "x" +
                        std::to_string(spec.height) + " pixels x " +
                        std::to_string(spec.nchannels) +
                        " channels, more than bandlight processes in memory (the limit is half "
                        "this machine's memory, " +
                        buf + ")");
    }
}

/// Opens an image for reading. A file that cannot be opened is a FileError
/// with the errno that says why (OpenImageIO's message does not); a file
/// that opens but is no image OpenImageIO reads is an Exception.
std::unique_ptr<OIIO::ImageInput> OpenImage(const std::string& path)
{
    const int error = InputFileError(path);
    if (error == EISDIR)
    {
        throw FileError(path, error, "is a directory, not an image file");
    }
    auto input = OIIO::ImageInput::open(path);
    if (!input)
    {
        const std::string what = "cannot read image: " + OIIO::geterror();
        if (error != 0)
        {
            throw FileError(path, error, what);
        }
        throw Exception(PathInMessage(path) + ": " + what);
    }
    return input;
}

/// Runs a module call on the image `path`: what it throws is reported as
/// plain data (ImageFilesStatus), since this module's exception types are
/// its own.
template <typename Call>
ImageFilesStatus Reported(const std::string& path, Call&& call)
{
    try
    {
        call();
        return {};
    }
    catch (const FileError& e)
    {
        return {e.what(), true, e.path(), e.error()};
    }
    catch (const std::bad_alloc&)
    {
        // OpenEXR reserves its line buffers itself (a 200000x1 image under
        // a limit on address space): name the image, not std::bad_alloc.
        ImageFilesStatus status;
        status.message = PathInMessage(path) +
                         ": out of memory reading or writing the image (it asks for more "
                         "memory than this process may have)";
        return status;
    }
    catch (const std::exception& e)
    {
        ImageFilesStatus status;
        status.message = e.what();
        return status;
    }
}

/// The header of an open image as ImageData (no pixels).
ImageData Header(const OIIO::ImageInput& input, const OIIO::ImageSpec& spec)
{
    ImageData image;
    image.width = spec.width;
    image.height = spec.height * std::max(1, spec.depth);
    image.channels = spec.nchannels;
    image.channelNames = spec.channelnames;
    for (int c = 0; c < spec.nchannels; ++c)
    {
        image.channelTypes.push_back(spec.channelformat(c).c_str());
    }
    for (const OIIO::ParamValue& p : spec.extra_attribs)
    {
        image.attributes[p.name().string()] = p.type() == OIIO::TypeDesc::STRING
                                                  ? std::string(p.get_string())
                                                  : spec.metadata_val(p, false);
    }
    image.format = input.format_name();
    return image;
}

ImageFilesStatus Transform(const std::string& in, const std::string& out,
                           const PixelProcess& process, const std::string& note)
{
    return Reported(
        in,
        [&]
        {
            auto input = OpenImage(in);
            const OIIO::ImageSpec spec = input->spec();
            if (spec.nchannels < 3)
            {
                throw Exception(in + ": has " + std::to_string(spec.nchannels) +
                                " channels; a colour transform needs R, G and B");
            }
            CheckImageSize(in, spec);
            std::vector<float> pixels(spec.image_pixels() * size_t(spec.nchannels));
            if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
            {
                throw Exception(in + ": cannot read pixels: " + input->geterror());
            }
            input->close();
            int rgb[3];
            FindRgb(spec, rgb);
            process(pixels.data(), spec.width, long(spec.height) * std::max(1, spec.depth),
                    spec.nchannels, rgb, Header(*input, spec));
            OIIO::ImageSpec outSpec = spec;  // pixel type, channel names, metadata
            if (!note.empty())
            {
                outSpec.attribute("bandlight:transform", note);
            }
            Write(out, outSpec, pixels.data());
        });
}

ImageFilesStatus WriteImage(const std::string& path, const float* pixels, int width, int height,
                            int channels, const std::vector<std::string>& channelNames,
                            const ImageDescription& description, PixelType type)
{
    return Reported(
        path,
        [&]
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
            spec.attribute("oiio:ColorSpace", description.colorSpace);
            if (description.chromaticities.size() == 8)
            {
                // OpenEXR's standard attribute (OIIO passes it to other formats
                // that can carry it): the primaries and white of the pixels.
                spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8),
                               description.chromaticities.data());
            }
            for (const auto& [name, value] : description.attributes)
            {
                spec.attribute(name, value);
            }
            spec.attribute("Software", "bandlight");
            Write(path, spec, pixels, description.writeAs);
        });
}

ImageFilesStatus Read(const std::string& path, ImageData& image, bool pixels)
{
    return Reported(
        path,
        [&]
        {
            auto input = OpenImage(path);
            const OIIO::ImageSpec spec = input->spec();
            CheckImageSize(path, spec);
            image = Header(*input, spec);
            image.pixels.clear();
            if (pixels)
            {
                image.pixels.resize(spec.image_pixels() * size_t(spec.nchannels));
                if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                                       image.pixels.data()))
                {
                    throw Exception(path + ": cannot read pixels: " + input->geterror());
                }
            }
            input->close();
        });
}

const ImageFilesApi kApi = {kImageFilesApiVersion, &Transform, &WriteImage, &Read,
                            &RemoveTemporaryFiles};

}  // namespace
}  // namespace bandlight::jobs

extern "C" const bandlight::jobs::ImageFilesApi* bandlight_image_files_api()
{
    return &bandlight::jobs::kApi;
}
