// SPDX-License-Identifier: BSD-3-Clause
#include "cli/ImageApply.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <thread>

#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"

namespace bandlight::cli
{

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
    const std::string error = ImageFiles().transform(
        in, out,
        [&](float* pixels, long width, long height, int channels, const int* rgb)
        { ApplyToBuffer(cpu, pixels, width, height, channels, rgb, threads); },
        note);
    if (!error.empty())
    {
        throw Exception(error);
    }
}

void WriteImage(const std::string& path, const float* pixels, int width, int height, int channels,
                const std::vector<std::string>& channelNames, const std::string& colorSpace,
                PixelType type)
{
    const std::string error =
        ImageFiles().write(path, pixels, width, height, channels, channelNames, colorSpace, type);
    if (!error.empty())
    {
        throw Exception(error);
    }
}

const ImageFilesApi& ImageFiles()
{
    static const ImageFilesApi* api = []
    {
        // The module sits beside the executable in a build tree, in
        // ../lib/bandlight when installed, or where the environment says.
        std::vector<std::string> places;
        if (const char* env = std::getenv("BANDLIGHT_IMAGE_MODULE"))
        {
            places.push_back(env);
        }
        char exe[4096];
        const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0)
        {
            exe[n] = '\0';
            std::string dir(exe);
            dir = dir.substr(0, dir.find_last_of('/'));
            places.push_back(dir + "/libbandlight_images.so");
            places.push_back(dir + "/../lib/bandlight/libbandlight_images.so");
        }
        std::string tried;
        for (const std::string& p : places)
        {
            if (void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL))
            {
                using Entry = const ImageFilesApi* (*)();
                auto entry = reinterpret_cast<Entry>(::dlsym(h, "bandlight_image_files_api"));
                if (entry && entry()->version == kImageFilesApiVersion)
                {
                    AlsoOnInterrupt(entry()->removeTemporaryFiles);
                    return entry();
                }
            }
            const char* err = ::dlerror();
            tried += (tried.empty() ? "" : "; ") + std::string(err ? err : p.c_str());
        }
        throw Exception("cannot load the image module libbandlight_images.so (" + tried + ")");
    }();
    return *api;
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
