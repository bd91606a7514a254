// SPDX-License-Identifier: BSD-3-Clause
// The image-file module (see imageio/ImageFiles.h): OpenImageIO reading and
// writing, loaded on demand by the bandlight command.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <new>

#include <OpenImageIO/imageio.h>

#include "imageio/ImageFiles.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"
#include "spectral/TextFile.h"

namespace bandlight
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

/// Whether the image has channels named R, G and B.
bool HasRgbNames(const OIIO::ImageSpec& spec)
{
    int found = 0;
    for (const char* name : {"R", "G", "B"})
    {
        found += std::find(spec.channelnames.begin(), spec.channelnames.end(), name) !=
                         spec.channelnames.end()
                     ? 1
                     : 0;
    }
    return found == 3;
}

/// A part of a multi-part file as messages name it: "part 2 ('right')".
std::string PartName(const OIIO::ImageSpec& spec, int part)
{
    std::string name = spec.get_string_attribute("oiio:subimagename");
    if (name.empty())
    {
        name = spec.get_string_attribute("name");
    }
    return "part " + std::to_string(part) + (name.empty() ? "" : " ('" + name + "')");
}

/// A part's own name as a layer prefix ("key"), or "part<N>" when it has
/// none.
std::string PartLayer(const OIIO::ImageSpec& spec, int part)
{
    std::string name = spec.get_string_attribute("oiio:subimagename");
    if (name.empty())
    {
        name = spec.get_string_attribute("name");
    }
    return name.empty() ? "part" + std::to_string(part) : name;
}

/// Writes `path` atomically, or straight to `writeAs` when the caller's
/// OutputSet owns the temporary name: one image per spec (the parts of a
/// multi-part EXR), each from its own float pixels. Throws Exception naming
/// the file when the format holds fewer images than given.
void WriteParts(const std::string& path, const std::vector<OIIO::ImageSpec>& specs,
                const std::vector<const float*>& pixels, const std::string& writeAs = "",
                const std::string& in = "")
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
    if (specs.size() > 1 && !output->supports("multiimage"))
    {
        std::string names;
        for (size_t p = 1; p < specs.size(); ++p)
        {
            names += (names.empty() ? "" : ", ") + PartName(specs[p], int(p));
        }
        throw Exception(PathInMessage(path) + ": this format holds one image, and " +
                        PathInMessage(in) + " has " + std::to_string(specs.size()) +
                        " parts: " + names + " would be lost (write a multi-part EXR)");
    }
    // Only OpenEXR keeps channel names: elsewhere (TIFF, PNG, ...) a layer
    // such as a light group's "key.R" would come back as "channel3".
    if (std::string(output->format_name()) != "openexr")
    {
        std::vector<std::string> named;
        for (const OIIO::ImageSpec& spec : specs)
        {
            for (const std::string& n : spec.channelnames)
            {
                if (n != "R" && n != "G" && n != "B" && n != "A" && n != "Y")
                {
                    named.push_back(n);
                }
            }
        }
        if (!named.empty())
        {
            std::string list;
            for (size_t i = 0; i < named.size() && i < 4; ++i)
            {
                list += (i ? ", " : "") + named[i];
            }
            if (named.size() > 4)
            {
                list += ", ... (" + std::to_string(named.size()) + " channels)";
            }
            throw Exception(PathInMessage(path) + ": a " + output->format_name() +
                            " file keeps no channel names, so " + list +
                            " would become anonymous channels: write an EXR, which keeps them");
        }
    }
    // The file itself was created above (or by the caller's OutputSet): what
    // fails here is the format refusing the image, not the file system.
    const auto failed = [&]
    { throw Exception(PathInMessage(path) + ": cannot write image: " + output->geterror()); };
    if (specs.size() == 1)
    {
        if (!output->open(target, specs[0]))
        {
            failed();
        }
    }
    else if (!output->open(target, int(specs.size()), specs.data()))
    {
        failed();
    }
    for (size_t p = 0; p < specs.size(); ++p)
    {
        if (p > 0 && !output->open(target, specs[p], OIIO::ImageOutput::AppendSubimage))
        {
            failed();
        }
        if (!output->write_image(OIIO::TypeDesc::FLOAT, pixels[p]))
        {
            failed();
        }
    }
    if (!output->close())
    {
        failed();
    }
    if (file)
    {
        file->commit();
    }
}

void Write(const std::string& path, const OIIO::ImageSpec& spec, const float* pixels,
           const std::string& writeAs = "")
{
    WriteParts(path, {spec}, {pixels}, writeAs);
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
    image.x = spec.x;
    image.y = spec.y;
    return image;
}

/// `spec` and `pixels` without the channels `drop` names (alpha and depth
/// indices and per-channel formats kept in step); `kept` receives the
/// compacted pixels. Returns false when nothing is dropped.
bool DropChannels(OIIO::ImageSpec& spec, const std::vector<float>& pixels,
                  const ChannelFilter& drop, std::vector<float>& kept)
{
    std::vector<int> keep;
    for (int c = 0; c < spec.nchannels; ++c)
    {
        if (!drop(spec.channelnames[size_t(c)]))
        {
            keep.push_back(c);
        }
    }
    if (int(keep.size()) == spec.nchannels)
    {
        return false;
    }
    const size_t count = pixels.size() / size_t(spec.nchannels);
    kept.resize(count * keep.size());
    for (size_t p = 0; p < count; ++p)
    {
        for (size_t k = 0; k < keep.size(); ++k)
        {
            kept[p * keep.size() + k] = pixels[p * size_t(spec.nchannels) + size_t(keep[k])];
        }
    }
    std::vector<std::string> names;
    std::vector<OIIO::TypeDesc> formats;
    int alpha = -1, z = -1;
    for (size_t k = 0; k < keep.size(); ++k)
    {
        names.push_back(spec.channelnames[size_t(keep[k])]);
        if (!spec.channelformats.empty())
        {
            formats.push_back(spec.channelformats[size_t(keep[k])]);
        }
        alpha = keep[k] == spec.alpha_channel ? int(k) : alpha;
        z = keep[k] == spec.z_channel ? int(k) : z;
    }
    spec.nchannels = int(keep.size());
    spec.channelnames = names;
    spec.channelformats = formats;
    spec.alpha_channel = alpha;
    spec.z_channel = z;
    return true;
}

/// The parts of a multi-part file as one image for `process` (light groups
/// split across parts): every part the same size, channels side by side, a
/// name that repeats across parts given its part's name before it
/// ("key.R"). Each part gets its channels back and keeps its layout.
void ProcessJoined(OIIO::ImageInput& input, const std::vector<OIIO::ImageSpec>& specs,
                   std::vector<std::vector<float>>& pixels, const PixelProcess& process,
                   const std::string& in)
{
    const OIIO::ImageSpec& first = specs.front();
    std::vector<std::string> names;
    std::map<std::string, int> seen;
    for (const OIIO::ImageSpec& spec : specs)
    {
        if (spec.width != first.width || spec.height != first.height ||
            spec.depth != first.depth || spec.x != first.x || spec.y != first.y)
        {
            throw Exception(in + ": its parts differ in size, so their channels cannot be taken "
                                 "together (light groups split across parts)");
        }
        for (const std::string& n : spec.channelnames)
        {
            ++seen[n];
        }
    }
    for (size_t p = 0; p < specs.size(); ++p)
    {
        for (const std::string& n : specs[p].channelnames)
        {
            names.push_back(p > 0 && seen[n] > 1 ? PartLayer(specs[p], int(p)) + "." + n : n);
        }
    }
    const size_t count = size_t(first.image_pixels());
    const size_t total = names.size();
    std::vector<float> joined(count * total);
    const auto each = [&](const auto& copy)
    {
        size_t offset = 0;
        for (size_t p = 0; p < specs.size(); ++p)
        {
            const size_t n = size_t(specs[p].nchannels);
            for (size_t i = 0; i < count; ++i)
            {
                copy(&joined[i * total + offset], &pixels[p][i * n], n);
            }
            offset += n;
        }
    };
    each([](float* to, const float* from, size_t n) { std::copy_n(from, n, to); });
    OIIO::ImageSpec spec = first;
    spec.nchannels = int(total);
    spec.channelnames = names;
    spec.channelformats.clear();
    int rgb[3];
    FindRgb(spec, rgb);
    ImageData header = Header(input, spec);
    process(joined.data(), spec.width, long(spec.height) * std::max(1, spec.depth), int(total),
            rgb, header);
    each([](const float* to, float* from, size_t n) { std::copy_n(to, n, from); });
}

ImageFilesStatus Transform(const std::string& in, const std::string& out,
                           const PixelProcess& process, const std::string& note, bool everyPart,
                           const ChannelFilter& drop, bool joinParts)
{
    return Reported(
        in,
        [&]
        {
            auto input = OpenImage(in);
            // Every part of a multi-part file (stereo views, AOVs in parts):
            // the parts holding R, G, B are processed, every other part is
            // carried as it is, pixels and header.
            std::vector<OIIO::ImageSpec> specs;
            for (int p = 0; input->seek_subimage(p, 0); ++p)
            {
                specs.push_back(input->spec());
            }
            if (specs.empty())
            {
                throw Exception(in + ": cannot read pixels: " + input->geterror());
            }
            const bool multi = specs.size() > 1;
            bool any = false;
            std::vector<std::vector<float>> pixels(specs.size());
            for (size_t p = 0; p < specs.size(); ++p)
            {
                const OIIO::ImageSpec& spec = specs[p];
                const std::string where = multi ? in + ", " + PartName(spec, int(p)) : in;
                if (spec.deep)
                {
                    throw Exception(where +
                                    ": holds deep pixels, which bandlight does not carry: "
                                    "nothing was written (flatten it first)");
                }
                if (multi && input->spec_dimensions(int(p), 1).width > 0)
                {
                    throw Exception(where +
                                    ": has MIP levels, which bandlight does not carry: "
                                    "nothing was written");
                }
                if (!multi && spec.nchannels < 3)
                {
                    throw Exception(in + ": has " + std::to_string(spec.nchannels) +
                                    " channels; a colour transform needs R, G and B");
                }
                CheckImageSize(where, spec);
                if (!input->seek_subimage(int(p), 0))
                {
                    throw Exception(where + ": cannot read pixels: " + input->geterror());
                }
                pixels[p].resize(spec.image_pixels() * size_t(spec.nchannels));
                if (!input->read_image(int(p), 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                                       pixels[p].data()))
                {
                    throw Exception(where + ": cannot read pixels: " + input->geterror());
                }
            }
            input->close();
            std::vector<OIIO::ImageSpec> outSpecs = specs;  // pixel types, names, metadata
            std::vector<const float*> data;
            std::vector<std::vector<float>> kept(specs.size());
            const bool joined = multi && joinParts;
            if (joined)
            {
                ProcessJoined(*input, specs, pixels, process, in);
                any = true;
            }
            for (size_t p = 0; p < specs.size(); ++p)
            {
                const OIIO::ImageSpec& spec = specs[p];
                data.push_back(pixels[p].data());
                if (joined)
                {
                    if (!note.empty())
                    {
                        outSpecs[p].attribute("bandlight:transform", note);
                    }
                    if (drop && DropChannels(outSpecs[p], pixels[p], drop, kept[p]))
                    {
                        data[p] = kept[p].data();
                    }
                    continue;
                }
                if (multi && !everyPart && !HasRgbNames(spec))
                {
                    continue;  // carried
                }
                int rgb[3];
                FindRgb(spec, rgb);
                ImageData header = Header(*input, spec);
                header.part = int(p);
                header.parts = int(specs.size());
                header.partName = multi ? PartName(spec, int(p)) : "";
                process(pixels[p].data(), spec.width, long(spec.height) * std::max(1, spec.depth),
                        spec.nchannels, rgb, header);
                any = true;
                if (!note.empty())
                {
                    outSpecs[p].attribute("bandlight:transform", note);
                }
                if (drop && DropChannels(outSpecs[p], pixels[p], drop, kept[p]))
                {
                    data[p] = kept[p].data();
                }
            }
            if (!any)
            {
                throw Exception(in + ": none of its " + std::to_string(specs.size()) +
                                " parts has channels named R, G and B: nothing to relight, "
                                "nothing was written");
            }
            WriteParts(out, outSpecs, data, "", in);
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
            // How many parts the file has (this reads the first).
            while (input->seek_subimage(image.parts, 0))
            {
                ++image.parts;
            }
            input->seek_subimage(0, 0);
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
}  // namespace bandlight

extern "C" const bandlight::ImageFilesApi* bandlight_image_files_api()
{
    return &bandlight::kApi;
}
