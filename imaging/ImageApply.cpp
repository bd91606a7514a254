// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/ImageApply.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <thread>

#include "plugin/ConfigBuilder.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"
#include "spectral/SpectralImage.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

void ApplyToBuffer(const OCIO::ConstCPUProcessorRcPtr& cpu, float* pixels, long width, long height,
                   int channels, const int rgb[3], int threads)
{
    const bool packed = rgb[0] == 0 && rgb[1] == 1 && rgb[2] == 2 && channels >= 3;
    const ptrdiff_t xStride = ptrdiff_t(channels) * ptrdiff_t(sizeof(float));
    const ptrdiff_t yStride = xStride * width;
    auto run = [&](size_t r0, size_t r1)
    {
        const long y0 = long(r0), y1 = long(r1);
        float* base = pixels + size_t(y0) * size_t(width) * size_t(channels);
        if (packed)
        {
            // R, G, B (and alpha) leading each pixel: the packed fast path;
            // alpha, when the 4th channel, passes through OCIO unchanged.
            const long n = channels == 4 ? 4 : 3;
            OCIO::PackedImageDesc desc(base, width, y1 - y0, n, OCIO::BIT_DEPTH_F32,
                                       ptrdiff_t(sizeof(float)), xStride, yStride);
            cpu->apply(desc);
        }
        else
        {
            OCIO::PlanarImageDesc desc(base + rgb[0], base + rgb[1], base + rgb[2], nullptr, width,
                                       y1 - y0, OCIO::BIT_DEPTH_F32, xStride, yStride);
            cpu->apply(desc);
        }
    };
    ParallelFor(size_t(std::max(height, 0L)), threads, run);
}

BufferWork ProcessorWork(const OCIO::ConstCPUProcessorRcPtr& cpu, int threads)
{
    return [cpu, threads](float* pixels, long width, long height, int channels, const int* rgb)
    { ApplyToBuffer(cpu, pixels, width, height, channels, rgb, threads); };
}

namespace
{
/// R, G, B of each row gathered into packed triples, `rgbFunction` applied,
/// scattered back; rows split over `threads` threads.
void ApplyRgbRows(const std::function<void(float* rgb, size_t count)>& rgbFunction, float* pixels,
                  long width, long height, int channels, const int* rgb, int threads)
{
    ParallelFor(size_t(std::max(height, 0L)), threads,
                [&](size_t y0, size_t y1)
                {
                    std::vector<float> row(3 * size_t(width));
                    for (size_t y = y0; y < y1; ++y)
                    {
                        float* p = pixels + y * size_t(width) * size_t(channels);
                        for (long x = 0; x < width; ++x)
                        {
                            for (int c = 0; c < 3; ++c)
                            {
                                row[3 * size_t(x) + size_t(c)] =
                                    p[size_t(x) * size_t(channels) + size_t(rgb[c])];
                            }
                        }
                        rgbFunction(row.data(), size_t(width));
                        for (long x = 0; x < width; ++x)
                        {
                            for (int c = 0; c < 3; ++c)
                            {
                                p[size_t(x) * size_t(channels) + size_t(rgb[c])] =
                                    row[3 * size_t(x) + size_t(c)];
                            }
                        }
                    }
                });
}

}  // namespace

BufferWork RgbWork(const std::function<void(float* rgb, size_t count)>& rgbFunction, int threads)
{
    return
        [rgbFunction, threads](float* pixels, long width, long height, int channels, const int* rgb)
    { ApplyRgbRows(rgbFunction, pixels, width, height, channels, rgb, threads); };
}

BufferWork KernelWork(const ClampMatrixKernel& kernel, int threads)
{
    return [kernel, threads](float* pixels, long width, long height, int channels, const int* rgb)
    {
        if (rgb[0] == 0 && rgb[1] == 1 && rgb[2] == 2 && channels >= 3)
        {
            const size_t rowFloats = size_t(width) * size_t(channels);
            ParallelFor(size_t(std::max(height, 0L)), threads,
                        [&](size_t y0, size_t y1) {
                            ClampMatrix(kernel, pixels + y0 * rowFloats, (y1 - y0) * size_t(width),
                                        size_t(channels));
                        });
            return;
        }
        // Channels in another order: gathered as RGB rows, as for any
        // per-pixel function.
        ApplyRgbRows([&](float* p, size_t n) { ClampMatrix(kernel, p, n, 3); }, pixels, width,
                     height, channels, rgb, threads);
    };
}

namespace
{
/// A spectral render's emissive channels, the beauty's ("S0.<λ>") or a
/// group's ("<group>.S0.<λ>"): radiance under the light before the change,
/// which a change of the RGB would leave stale. They are left out of the
/// output (reflective "T.<λ>" channels, remittances, do not depend on the
/// light and are kept).
bool StaleSpectralChannel(const std::string& name)
{
    const size_t dot = name.find('.');
    for (const std::string& n : {name, dot == std::string::npos ? std::string() : name.substr(dot + 1)})
    {
        try
        {
            const std::optional<SpectralChannel> c = ParseSpectralChannel(n);
            if (c && c->kind == SpectralKind::EMISSIVE)
            {
                return true;
            }
        }
        catch (const Exception&)
        {
            // Not a spectral channel bandlight reads: carried as it is.
        }
    }
    return false;
}

/// The note for the emissive spectral channels of `header` left out of
/// `out` ("" when it has none).
std::string DroppedSpectraNote(const ImageData& header, const std::string& where)
{
    const size_t n = size_t(std::count_if(header.channelNames.begin(), header.channelNames.end(),
                                          StaleSpectralChannel));
    if (n == 0)
    {
        return "";
    }
    return where + ": its " + std::to_string(n) +
           " spectral channels (S0.*) are left out of the output: they hold the light before "
           "the change, and would contradict the relit RGB (the spectral command relights "
           "spectra exactly)";
}

/// Reads `in`, runs `process` on its pixels and writes `out` through the
/// image module, without the stale spectral channels. What `process` throws comes back as it was (a
/// ParameterError spells its parameters per face), not as the module's text.
void TransformImage(const std::string& in, const std::string& out, const PixelProcess& process,
                    const std::string& note, bool everyPart, bool joinParts = false)
{
    std::exception_ptr thrown;
    const ImageFilesStatus status = ImageFiles().transform(
        in, out,
        [&](float* pixels, long width, long height, int channels, const int* rgb,
            const ImageData& header)
        {
            try
            {
                process(pixels, width, height, channels, rgb, header);
            }
            catch (...)
            {
                thrown = std::current_exception();
                throw;
            }
        },
        note, everyPart, StaleSpectralChannel, joinParts);
    if (thrown)
    {
        std::rethrow_exception(thrown);
    }
    ThrowIfFailed(status);
}

/// A format that holds no integer code values (OpenEXR: half, float): an
/// integer image written there becomes float values read as linear.
bool IsFloatOnlyFile(const std::string& path)
{
    const std::string ext = std::filesystem::path(path).extension().string();
    return ext.size() == 4 && std::tolower(static_cast<unsigned char>(ext[1])) == 'e' &&
           std::tolower(static_cast<unsigned char>(ext[2])) == 'x' &&
           std::tolower(static_cast<unsigned char>(ext[3])) == 'r';
}
}  // namespace

namespace
{

/// Runs a pixel process over an image: its file read and written
/// (TransformImage), or its pixels in memory.
using PixelRunner = std::function<void(const PixelProcess&)>;

std::vector<std::string> ApplyWith(const BufferWork& work, const std::string& in,
                                   const std::string& out, const ImageColourRequest& colour,
                                   const PixelRunner& run)
{
    std::vector<std::string> notes;
    const auto process = [&](float* pixels, long width, long height, int channels, const int* rgb,
                             const ImageData& header)
    {
        if (const std::string dropped = DroppedSpectraNote(header, in); !dropped.empty())
        {
            notes.push_back(dropped);
        }
        if (!colour.working)
        {
            work(pixels, width, height, channels, rgb);
            return;
        }
        const ImageEncoding encoding =
            colour.declared ? *colour.declared : IdentifyImageEncoding(header, in, *colour.working);
        const bool display = IsDisplayReferred(header);
        if (!display && IsDisplayReferredFile(out))
        {
            throw Exception(out +
                            ": a display-referred format (8- or 16-bit code values) "
                            "cannot hold the scene-linear " +
                            encoding.describe() + " of " + in +
                            ": write an EXR (or convert it afterwards, e.g. oiiotool "
                            "--colorconvert)");
        }
        if (display && IsFloatOnlyFile(out))
        {
            // The result would be display code values in a file every host
            // reads as scene-linear, with nothing to say otherwise.
            throw Exception(out + ": " + in + " holds " + encoding.describe() +
                            " code values, which a float format would carry untagged and "
                            "every host would read as linear: write the same format as " +
                            in +
                            " (or convert it to linear EXR first, e.g. oiiotool "
                            "--colorconvert)");
        }
        const std::string working = SpaceLabel(*colour.working);
        if (encoding.assumed)
        {
            notes.push_back(in + " names no colour space: taken as linear " + working +
                            " (say otherwise with {colorspace})");
        }
        const OCIO::ConstCPUProcessorRcPtr in2work = EncodingToLinear(encoding, *colour.working);
        const OCIO::ConstCPUProcessorRcPtr work2out = LinearToEncoding(*colour.working, encoding);
        if (in2work)
        {
            notes.push_back(in + ": " + encoding.describe() + " (" + encoding.evidence +
                            "), converted to linear " + working + " for the work and back");
            ApplyToBuffer(in2work, pixels, width, height, channels, rgb, 0);
        }
        work(pixels, width, height, channels, rgb);
        if (work2out)
        {
            ApplyToBuffer(work2out, pixels, width, height, channels, rgb, 0);
        }
        if (display)
        {
            size_t clipped = 0;
            const size_t count = size_t(width) * size_t(height);
            for (size_t p = 0; p < count; ++p)
            {
                const float* v = pixels + p * size_t(channels);
                clipped += (v[rgb[0]] > 1.0f || v[rgb[1]] > 1.0f || v[rgb[2]] > 1.0f ||
                            v[rgb[0]] < 0.0f || v[rgb[1]] < 0.0f || v[rgb[2]] < 0.0f)
                               ? 1
                               : 0;
            }
            if (clipped > 0)
            {
                notes.push_back(out + ": " + std::to_string(clipped) + " of " +
                                std::to_string(count) +
                                " pixels left 0-1 and are clipped: the format holds "
                                "display-referred code values (write an EXR to keep them)");
            }
        }
    };
    run(process);
    return notes;
}

}  // namespace

LightGroupLayout CheckedLightGroups(const LightGroupApply& apply, const std::string& file,
                                    const ImageData& header)
{
    const std::string where = header.partName.empty() ? file : file + ", " + header.partName;
    LightGroupLayout layout =
        FindLightGroups(where, header.channelNames, header.attributes, apply.mapped);
    for (const auto& [name, work] : apply.works)
    {
        if (!layout.find(name))
        {
            std::string have;
            for (const LightGroupLayer& g : layout.groups)
            {
                have += (have.empty() ? "" : ", ") + g.name;
            }
            throw Exception(where + ": has no light group '" + OneLine(name, 80) + "' (it has " +
                            have + ")");
        }
    }
    const auto isHalf = [&](int c)
    { return size_t(c) < header.channelTypes.size() && header.channelTypes[size_t(c)] == "half"; };
    for (int c = 0; c < 3; ++c)
    {
        layout.half = layout.half || isHalf(layout.beauty[c]);
        for (const LightGroupLayer& g : layout.groups)
        {
            layout.half = layout.half || isHalf(g.rgb[c]);
        }
    }
    return layout;
}

namespace
{

std::vector<std::string> ApplyLightGroupsWith(const LightGroupApply& apply,
                                              const std::string& in, const std::string& out,
                                              const ImageColourRequest& colour,
                                              const PixelRunner& run)
{
    std::vector<std::string> notes;
    int relitParts = 0;
    std::string firstError;
    const auto process = [&](float* pixels, long width, long height, int channels, const int*,
                             const ImageData& header)
    {
        LightGroupLayout layout;
        try
        {
            layout = CheckedLightGroups(apply, in, header);
        }
        catch (const Exception& e)
        {
            // A part of a multi-part file without light groups is carried.
            if (header.parts == 1)
            {
                throw;
            }
            if (firstError.empty())
            {
                firstError = e.what();
            }
            if (header.part + 1 == header.parts && relitParts == 0)
            {
                throw Exception(firstError);
            }
            return;
        }
        const std::string where = header.partName.empty() ? in : in + ", " + header.partName;
        notes.push_back(where + ": " + layout.describe());
        if (const std::string dropped = DroppedSpectraNote(header, where); !dropped.empty())
        {
            notes.push_back(dropped);
        }
        std::map<std::string, LightGroupWork> works;
        OCIO::ConstCPUProcessorRcPtr in2work, work2out;
        if (colour.working)
        {
            // An untagged file is in the convention of the renderer whose
            // naming was recognised: Blender writes linear Rec.709 unless its
            // colour management says otherwise; else the working space.
            const bool blender = !layout.groups.empty() &&
                                 layout.groups.front().naming == LightGroupNaming::BLENDER;
            const RgbSpace& untagged = blender ? Rec709Space() : *colour.working;
            const ImageEncoding encoding = colour.declared
                                               ? *colour.declared
                                               : IdentifyImageEncoding(header, in, untagged);
            if (IsDisplayReferred(header) || IsDisplayReferredFile(out))
            {
                throw Exception(where +
                                ": light groups are scene-linear layers of a render: "
                                "read and write them as EXR");
            }
            if (encoding.assumed)
            {
                notes.push_back(
                    blender ? in + " names no colour space: its Blender light-group naming says "
                                   "Blender wrote it, taken as Blender's default linear Rec.709 "
                                   "(say otherwise with {colorspace})"
                            : in + " names no colour space: taken as linear " +
                                  SpaceLabel(*colour.working) +
                                  " (say otherwise with {colorspace})");
            }
            in2work = EncodingToLinear(encoding, *colour.working);
            work2out = LinearToEncoding(*colour.working, encoding);
            if (in2work)
            {
                notes.push_back(in + ": " + encoding.describe() + " (" + encoding.evidence +
                                "), converted to linear " + SpaceLabel(*colour.working) +
                                " for the work and back");
            }
        }
        const auto inWorkingSpace = [&](const BufferWork& work) -> LightGroupWork
        {
            return [&, work](float* p, long w, long h, int n, const int* rgb)
            {
                if (in2work)
                {
                    ApplyToBuffer(in2work, p, w, h, n, rgb, 0);
                }
                work(p, w, h, n, rgb);
                if (work2out)
                {
                    ApplyToBuffer(work2out, p, w, h, n, rgb, 0);
                }
            };
        };
        LightGroupWork residual;
        if (apply.everyGroup)
        {
            for (const LightGroupLayer& g : layout.groups)
            {
                works[g.name] = inWorkingSpace(apply.everyGroup);
            }
            residual = inWorkingSpace(apply.everyGroup);
            notes.push_back(where + ": every light group and the residual relit by the same "
                            "change, the beauty rebuilt as their sum (the file stays "
                            "consistent)");
        }
        for (const auto& [name, work] : apply.works)
        {
            if (!work)
            {
                continue;  // the same light: carried
            }
            works[name] = inWorkingSpace(work);
        }
        const size_t unguarded =
            RelightLightGroups(layout, works, pixels, width, height, channels, where, residual,
                               apply.beauty);
        if (unguarded > 0)
        {
            notes.push_back(where + ": " + std::to_string(unguarded) +
                            " pixels held NaN or infinite values in the beauty or a group: "
                            "NaN taken as -1e16 and infinity as +-1e16 before the relight, as "
                            "every pixel path takes them, so every value written is finite");
        }
        ++relitParts;
    };
    run(process);
    return notes;
}

/// The pixels of an image read whole, as one part, given to `process`:
/// R, G, B are the channels so named.
PixelRunner InMemory(ImageData& image, const std::string& source)
{
    return [&image, source](const PixelProcess& process)
    {
        int rgb[3] = {-1, -1, -1};
        for (int c = 0; c < 3; ++c)
        {
            const std::string name(1, "RGB"[c]);
            const auto at = std::find(image.channelNames.begin(), image.channelNames.end(), name);
            rgb[c] = at == image.channelNames.end() ? -1 : int(at - image.channelNames.begin());
        }
        process(image.pixels.data(), image.width, image.height, image.channels, rgb, image);
    };
}

}  // namespace

std::vector<std::string> ApplyToImage(const BufferWork& work, const std::string& in,
                                      const std::string& out, const std::string& note,
                                      const ImageColourRequest& colour)
{
    return ApplyWith(work, in, out, colour, [&](const PixelProcess& p)
                     { TransformImage(in, out, p, note, false); });
}

std::vector<std::string> ApplyLightGroupsToImage(const LightGroupApply& apply,
                                                 const std::string& in, const std::string& out,
                                                 const std::string& note,
                                                 const ImageColourRequest& colour)
{
    try
    {
        return ApplyLightGroupsWith(apply, in, out, colour, [&](const PixelProcess& p)
                                    { TransformImage(in, out, p, note, true); });
    }
    catch (const Exception&)
    {
        // No part holds the groups on its own: in a multi-part file they may
        // be split across parts (an AOV a part), taken together then.
        ImageData header;
        if (!ImageFiles().read(in, header, false).message.empty() || header.parts < 2)
        {
            throw;
        }
        try
        {
            return ApplyLightGroupsWith(apply, in, out, colour, [&](const PixelProcess& p)
                                        { TransformImage(in, out, p, note, true, true); });
        }
        catch (const Exception&)
        {
            // Not that either: the first error says what is wrong.
        }
        throw;
    }
}

std::vector<std::string> ApplyToImageData(const BufferWork& work, ImageData& image,
                                          const std::string& source,
                                          const ImageColourRequest& colour)
{
    return ApplyWith(work, source, "", colour, InMemory(image, source));
}

std::vector<std::string> ApplyLightGroupsToImageData(const LightGroupApply& apply,
                                                     ImageData& image, const std::string& source,
                                                     const ImageColourRequest& colour)
{
    return ApplyLightGroupsWith(apply, source, "", colour, InMemory(image, source));
}

bool HoldsLightGroups(const std::string& file)
{
    if (file.empty())
    {
        return false;
    }
    ImageData header;
    if (!ImageFiles().read(file, header, false).message.empty() || header.parts != 1)
    {
        return false;
    }
    try
    {
        return !FindLightGroups(file, header.channelNames, header.attributes).groups.empty();
    }
    catch (const Exception&)
    {
        return false;
    }
}


}  // namespace bandlight::jobs
