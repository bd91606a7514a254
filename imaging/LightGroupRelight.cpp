// SPDX-License-Identifier: BSD-3-Clause
// Light groups relit in place: each group's work on its layer, the beauty
// rebuilt as Σ relit groups + the residual (beauty − Σ groups as read), in
// blocks of rows on every core, each pixel checked first (a group brighter
// than the beauty, NaN or Inf in a layer) and refused naming the pixel.
#include "imaging/LightGroups.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "spectral/Exception.h"
#include "spectral/Parallel.h"
#include "transforms/IlluminantChange.h"

namespace bandlight::jobs
{

const char* LightGroupBeautyName(LightGroupBeauty beauty)
{
    switch (beauty)
    {
        case LightGroupBeauty::REBUILD:
            return "rebuild";
        case LightGroupBeauty::DIFFERENCE:
            return "difference";
        case LightGroupBeauty::RESIDUAL:
            break;
    }
    return "residual";
}

std::string LightGroupBeautyNote(LightGroupBeauty beauty)
{
    switch (beauty)
    {
        case LightGroupBeauty::REBUILD:
            return "; beauty rebuilt from the relit groups (the residual dropped)";
        case LightGroupBeauty::DIFFERENCE:
            return "; beauty: the relit groups + the beauty's difference from the groups as read";
        case LightGroupBeauty::RESIDUAL:
            break;
    }
    return "";
}

LightGroupBeauty ParseLightGroupBeauty(const std::string& name)
{
    for (const LightGroupBeauty b :
         {LightGroupBeauty::RESIDUAL, LightGroupBeauty::REBUILD, LightGroupBeauty::DIFFERENCE})
    {
        if (name == LightGroupBeautyName(b))
        {
            return b;
        }
    }
    throw ParameterError("{light_group_beauty} is residual (a render's own beauty, the default), "
                         "rebuild (the beauty from the relit groups alone: a denoised beauty) or "
                         "difference (the denoised beauty's difference from the groups carried), "
                         "not '" + OneLine(name, 40) + "'");
}

double PartitionTolerance(double level, double peak, bool half)
{
    // Float sums of a few groups round within a few ulps of the level;
    // half storage (11 significant bits) within 2^-11 of each value. The
    // absolute floor covers values far below the image's brightest.
    return (half ? 4e-3 : 1e-5) * level + 1e-6 * peak;
}

namespace
{
/// Rows relit at a time: a block's pixels (4096 × 32 × 10 channels of float,
/// 5 MB) and its residual stay in cache from the residual to the sum, and
/// the residual is held for one block, not for the frame (212 MB of double
/// at 4096×2160: the largest allocation of a relight after the image).
constexpr size_t kRowsPerBlock = 32;

/// The brightest finite beauty value of an image, on every core.
double BeautyPeak(const LightGroupLayout& layout, const float* pixels, size_t count, size_t n)
{
    double peak = 0.0;
    std::mutex mu;
    ParallelFor(count, 0,
                [&](size_t a, size_t b)
                {
                    double local = 0.0;
                    for (size_t p = a; p < b; ++p)
                    {
                        for (int c = 0; c < 3; ++c)
                        {
                            const double v = pixels[p * n + size_t(layout.beauty[c])];
                            if (std::isfinite(v))
                            {
                                local = std::max(local, std::abs(v));
                            }
                        }
                    }
                    std::lock_guard<std::mutex> lock(mu);
                    peak = std::max(peak, local);
                });
    return peak;
}

/// What is wrong with a pixel of a light-group image, if anything.
struct PixelFault
{
    int channel = -1;  ///< the first channel whose groups exceed the beauty
    double sum = 0.0, beauty = 0.0;
    explicit operator bool() const { return channel >= 0; }
};

/// Checks one pixel: finite groups that do not sum past a finite beauty,
/// channel by channel, in double. Non-finite values are no fault: they are
/// guarded (GuardPixel) before the relight, as every pixel path guards them.
/// The sum alone decides most pixels; the level is looked for only when it
/// exceeds the beauty.
PixelFault CheckPixel(const LightGroupLayout& layout, const float* v, double peak)
{
    PixelFault fault;
    for (int c = 0; c < 3; ++c)
    {
        double sum = 0.0;
        for (const LightGroupLayer& g : layout.groups)
        {
            sum += v[g.rgb[c]];
        }
        const double beauty = v[layout.beauty[c]];
        if (!std::isfinite(sum) || !std::isfinite(beauty) || !(sum > beauty))
        {
            continue;
        }
        double partial = 0.0, level = std::abs(beauty);
        for (const LightGroupLayer& g : layout.groups)
        {
            partial += v[g.rgb[c]];
            level = std::max(level, std::abs(partial));
        }
        if (sum - beauty > PartitionTolerance(level, peak, layout.half))
        {
            fault.channel = c;
            fault.sum = sum;
            fault.beauty = beauty;
            return fault;
        }
    }
    return fault;
}

/// Whether any value of the pixel's beauty or groups is NaN, infinite or
/// beyond the guard (|x| > PIXEL_GUARD).
bool Unguarded(const LightGroupLayout& layout, const float* v)
{
    const auto outside = [](float x) { return !(std::abs(double(x)) <= PIXEL_GUARD); };
    for (int c = 0; c < 3; ++c)
    {
        if (outside(v[layout.beauty[c]]))
        {
            return true;
        }
        for (const LightGroupLayer& g : layout.groups)
        {
            if (outside(v[g.rgb[c]]))
            {
                return true;
            }
        }
    }
    return false;
}

/// The pixel's beauty and groups through GuardPixel, the guard of every
/// pixel path (NaN to −PIXEL_GUARD, ±Inf to ±PIXEL_GUARD).
void GuardLayers(const LightGroupLayout& layout, float* v)
{
    const auto guard = [v](const int* rgb)
    {
        const Vec3 g = GuardPixel(Vec3(v[rgb[0]], v[rgb[1]], v[rgb[2]]));
        for (int c = 0; c < 3; ++c)
        {
            v[rgb[c]] = float(g[c]);
        }
    };
    guard(layout.beauty);
    for (const LightGroupLayer& g : layout.groups)
    {
        guard(g.rgb);
    }
}

/// The one line naming a pixel's fault, `file` and the pixel (x, y).
std::string FaultMessage(const PixelFault& f, const std::string& file, size_t x, size_t y)
{
    const std::string at = " at pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
    return file + ": the light groups sum to more than the beauty" + at + " (" +
           std::to_string(f.sum) + " against " + std::to_string(f.beauty) + " in " +
           "RGB"[f.channel] +
           "): they are not a partition of it (a group twice, or a layer that is not a light "
           "group)";
}
}  // namespace

size_t RelightLightGroups(const LightGroupLayout& layout,
                          const std::map<std::string, LightGroupWork>& works, float* pixels,
                          long width, long height, int channels, const std::string& file,
                          const LightGroupWork& residualWork, LightGroupBeauty rule)
{
    const size_t w = size_t(std::max(width, 0L)), h = size_t(std::max(height, 0L));
    const size_t n = size_t(channels);
    const double peak = BeautyPeak(layout, pixels, w * h, n);
    // Every pixel checked before any changes; the first at fault is named,
    // whichever thread found it.
    size_t bad = w * h;
    size_t unguarded = 0;
    std::mutex mu;
    ParallelFor(w * h, 0,
                [&](size_t a, size_t b)
                {
                    size_t mine = 0;
                    for (size_t p = a; p < b; ++p)
                    {
                        mine += Unguarded(layout, pixels + p * n) ? 1 : 0;
                        if (rule == LightGroupBeauty::RESIDUAL &&
                            CheckPixel(layout, pixels + p * n, peak))
                        {
                            std::lock_guard<std::mutex> lock(mu);
                            bad = std::min(bad, p);
                            unguarded += mine;
                            return;
                        }
                    }
                    std::lock_guard<std::mutex> lock(mu);
                    unguarded += mine;
                });
    if (bad < w * h)
    {
        throw Exception(
            FaultMessage(CheckPixel(layout, pixels + bad * n, peak), file, bad % w, bad / w));
    }
    std::vector<double> residual(3 * w * kRowsPerBlock);
    for (size_t y0 = 0; y0 < h; y0 += kRowsPerBlock)
    {
        const size_t rows = std::min(kRowsPerBlock, h - y0);
        const size_t count = rows * w;
        float* block = pixels + y0 * w * n;
        // The residual of each pixel, before the groups change.
        ParallelFor(count, 0,
                    [&](size_t a, size_t b)
                    {
                        for (size_t p = a; p < b; ++p)
                        {
                            float* v = block + p * n;
                            if (unguarded > 0 && Unguarded(layout, v))
                            {
                                GuardLayers(layout, v);
                            }
                            for (int c = 0; c < 3; ++c)
                            {
                                double sum = 0.0;
                                for (const LightGroupLayer& g : layout.groups)
                                {
                                    sum += v[g.rgb[c]];
                                }
                                residual[3 * p + size_t(c)] =
                                    rule == LightGroupBeauty::REBUILD
                                        ? 0.0
                                        : double(v[layout.beauty[c]]) - sum;
                            }
                        }
                    });
        for (const LightGroupLayer& g : layout.groups)
        {
            if (const auto work = works.find(g.name); work != works.end() && work->second)
            {
                work->second(block, width, long(rows), channels, g.rgb);
            }
        }
        if (residualWork)
        {
            // The residual relit as the groups are: as float RGB, back in double.
            std::vector<float> rgb(residual.begin(), residual.begin() + std::ptrdiff_t(3 * count));
            const int channelsRgb[3] = {0, 1, 2};
            residualWork(rgb.data(), width, long(rows), 3, channelsRgb);
            std::copy(rgb.begin(), rgb.end(), residual.begin());
        }
        ParallelFor(count, 0,
                    [&](size_t a, size_t b)
                    {
                        for (size_t p = a; p < b; ++p)
                        {
                            float* v = block + p * n;
                            for (int c = 0; c < 3; ++c)
                            {
                                double sum = residual[3 * p + size_t(c)];
                                for (const LightGroupLayer& g : layout.groups)
                                {
                                    sum += v[g.rgb[c]];
                                }
                                v[layout.beauty[c]] = float(sum);
                            }
                        }
                    });
    }
    return unguarded;
}

}  // namespace bandlight::jobs
