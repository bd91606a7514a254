// SPDX-License-Identifier: BSD-3-Clause
#include "cli/ImageApply.h"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <thread>

#include <OpenImageIO/imageio.h>

#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{

namespace
{

/// Channel indices of R, G, B by name ("R", "G", "B", or a layer's "*.R"),
/// falling back to the first three channels.
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

}  // namespace

void ApplyToBuffer(const OCIO::ConstCPUProcessorRcPtr& cpu, float* pixels, long width, long height,
                   int channels, const int rgb[3], int threads)
{
    if (threads <= 0)
    {
        threads = int(std::max(1u, std::thread::hardware_concurrency()));
    }
    threads = int(std::min<long>(threads, std::max<long>(1, height)));
    const bool packed = rgb[0] == 0 && rgb[1] == 1 && rgb[2] == 2 && channels >= 3;
    const ptrdiff_t xStride = ptrdiff_t(channels) * ptrdiff_t(sizeof(float));
    const ptrdiff_t yStride = xStride * width;
    auto run = [&](long y0, long y1)
    {
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
    if (threads == 1)
    {
        run(0, height);
        return;
    }
    std::vector<std::thread> pool;
    const long rows = (height + threads - 1) / threads;
    for (int t = 0; t < threads; ++t)
    {
        const long y0 = rows * t;
        const long y1 = std::min(height, y0 + rows);
        if (y0 < y1)
        {
            pool.emplace_back(run, y0, y1);
        }
    }
    for (std::thread& th : pool)
    {
        th.join();
    }
}

void ApplyToImage(const OCIO::ConstCPUProcessorRcPtr& cpu, const std::string& in,
                  const std::string& out, int threads, const std::string& note)
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
    ApplyToBuffer(cpu, pixels.data(), spec.width, spec.height * std::max(1, spec.depth),
                  spec.nchannels, rgb, threads);

    OIIO::ImageSpec outSpec = spec;  // pixel type, channel names, metadata
    if (!note.empty())
    {
        outSpec.attribute("bandlight:transform", note);
    }
    AtomicFile file(out);
    file.stream().close();  // OIIO writes by name
    auto output = OIIO::ImageOutput::create(out);
    if (!output)
    {
        throw Exception(out + ": no image writer for this file type: " + OIIO::geterror());
    }
    if (!output->open(file.tempPath(), outSpec))
    {
        throw Exception(out + ": cannot write image: " + output->geterror());
    }
    if (!output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !output->close())
    {
        throw Exception(out + ": cannot write image: " + output->geterror());
    }
    file.commit();
}

void WriteImage(const std::string& path, const float* pixels, int width, int height, int channels,
                const std::vector<std::string>& channelNames, const std::string& colorSpace,
                OIIO::TypeDesc type)
{
    OIIO::ImageSpec spec(width, height, channels, type);
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
    AtomicFile file(path);
    file.stream().close();  // OIIO writes by name
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
    {
        throw Exception(path + ": no image writer for this file type: " + OIIO::geterror());
    }
    if (!out->open(file.tempPath(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels) ||
        !out->close())
    {
        throw Exception(path + ": cannot write image: " + out->geterror());
    }
    file.commit();
}

bool HasFramePattern(const std::string& pattern)
{
    return pattern.find('#') != std::string::npos ||
           std::regex_search(pattern, std::regex("%0?[0-9]*d"));
}

std::string ExpandFramePattern(const std::string& pattern, int frame)
{
    const size_t hash = pattern.find('#');
    if (hash != std::string::npos)
    {
        size_t end = hash;
        while (end < pattern.size() && pattern[end] == '#')
        {
            ++end;
        }
        char buf[32];
        std::snprintf(buf, sizeof buf, "%0*d", int(end - hash), frame);
        return pattern.substr(0, hash) + buf + pattern.substr(end);
    }
    std::smatch m;
    if (std::regex_search(pattern, m, std::regex("%0?([0-9]*)d")))
    {
        const int width = m[1].str().empty() ? 1 : std::stoi(m[1].str());
        char buf[32];
        std::snprintf(buf, sizeof buf, "%0*d", width, frame);
        return m.prefix().str() + buf + m.suffix().str();
    }
    return pattern;
}

std::vector<int> ParseFrameRange(const std::string& text)
{
    std::smatch m;
    if (!std::regex_match(text, m,
                          std::regex("\\s*(-?[0-9]{1,9})\\s*(?:-\\s*(-?[0-9]{1,9}))?\\s*")))
    {
        throw Exception("frame range '" + text + "': expected FIRST-LAST, e.g. 1001-1100");
    }
    const int first = std::stoi(m[1].str());
    const int last = m[2].matched ? std::stoi(m[2].str()) : first;
    if (last < first)
    {
        throw Exception("frame range '" + text + "': the last frame comes before the first");
    }
    std::vector<int> frames;
    for (int f = first; f <= last; ++f)
    {
        frames.push_back(f);
    }
    return frames;
}

}  // namespace bandlight::cli
