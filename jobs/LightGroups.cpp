// SPDX-License-Identifier: BSD-3-Clause
#include "bandlight/jobs/LightGroups.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "bandlight/spectral/Exception.h"
#include "bandlight/spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{

bool StartsWith(const std::string& s, const std::string& prefix)
{
    return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

/// The layers of an image that hold R, G and B ("" for plain R, G, B), with
/// their channel indices.
std::map<std::string, std::array<int, 3>> RgbLayers(const std::vector<std::string>& names)
{
    std::map<std::string, std::array<int, 3>> layers;
    std::map<std::string, int> index;
    for (size_t i = 0; i < names.size(); ++i)
    {
        index[names[i]] = int(i);
    }
    for (const std::string& n : names)
    {
        std::string layer;
        if (n == "R")
        {
            layer = "";
        }
        else if (n.size() > 2 && n.compare(n.size() - 2, 2, ".R") == 0)
        {
            layer = n.substr(0, n.size() - 2);
        }
        else
        {
            continue;
        }
        const std::string prefix = layer.empty() ? "" : layer + ".";
        const auto g = index.find(prefix + "G");
        const auto b = index.find(prefix + "B");
        if (g != index.end() && b != index.end())
        {
            layers[layer] = {index[prefix + "R"], g->second, b->second};
        }
    }
    return layers;
}

/// The view layer of a Blender layer name ("ViewLayer.Combined_key" →
/// "ViewLayer."), and the pass after it.
void SplitViewLayer(const std::string& layer, std::string& view, std::string& pass)
{
    const size_t dot = layer.rfind('.');
    view = dot == std::string::npos ? "" : layer.substr(0, dot + 1);
    pass = dot == std::string::npos ? layer : layer.substr(dot + 1);
}

std::string Quoted(const std::string& s)
{
    return "'" + OneLine(s, 80) + "'";
}

}  // namespace

const char* LightGroupNamingName(LightGroupNaming naming)
{
    switch (naming)
    {
        case LightGroupNaming::BLENDER:
            return "Blender/Cycles";
        case LightGroupNaming::ARNOLD:
            return "Arnold";
        case LightGroupNaming::BANDLIGHT:
            return "bandlight";
        case LightGroupNaming::MAPPED:
            return "mapped";
    }
    return "";
}

const LightGroupLayer* LightGroupLayout::find(const std::string& name) const
{
    for (const LightGroupLayer& g : groups)
    {
        if (g.name == name)
        {
            return &g;
        }
    }
    return nullptr;
}

std::string LightGroupLayout::describe() const
{
    std::string names;
    std::set<std::string> namings;
    for (const LightGroupLayer& g : groups)
    {
        names += (names.empty() ? "" : ", ") + g.name;
        namings.insert(LightGroupNamingName(g.naming));
    }
    std::string naming;
    for (const std::string& n : namings)
    {
        naming += (naming.empty() ? "" : " and ") + n;
    }
    return std::to_string(groups.size()) + " light group" + (groups.size() == 1 ? "" : "s") + " (" +
           names + "), " + naming + " naming, beauty " +
           (beautyLayer.empty() ? std::string("R, G, B") : beautyLayer);
}

LightGroupLayout FindLightGroups(const std::string& file,
                                 const std::vector<std::string>& channelNames,
                                 const std::map<std::string, std::string>& attributes,
                                 const std::map<std::string, std::string>& mapped)
{
    const std::map<std::string, std::array<int, 3>> layers = RgbLayers(channelNames);
    LightGroupLayout out;
    // bandlight's own groups, as its header lists them.
    std::set<std::string> listed;
    if (const auto a = attributes.find(LIGHT_GROUPS_ATTRIBUTE); a != attributes.end())
    {
        std::string item;
        for (size_t i = 0; i <= a->second.size(); ++i)
        {
            if (i == a->second.size() || a->second[i] == ',')
            {
                if (!item.empty())
                {
                    listed.insert(item);
                }
                item.clear();
            }
            else if (a->second[i] != ' ')
            {
                item += a->second[i];
            }
        }
    }
    std::set<std::string> views;  // Blender view layers holding groups
    for (const auto& [layer, rgb] : layers)
    {
        std::string view, pass;
        SplitViewLayer(layer, view, pass);
        LightGroupLayer g;
        g.layer = layer;
        std::copy(rgb.begin(), rgb.end(), g.rgb);
        if (StartsWith(pass, "Combined_") && pass.size() > 9)
        {
            g.name = pass.substr(9);
            g.naming = LightGroupNaming::BLENDER;
            views.insert(view);
        }
        else if (view.empty() && StartsWith(pass, "RGBA_") && pass.size() > 5)
        {
            g.name = pass.substr(5);
            g.naming = LightGroupNaming::ARNOLD;
        }
        else if (listed.count(layer))
        {
            g.name = layer;
            g.naming = LightGroupNaming::BANDLIGHT;
        }
        else
        {
            continue;
        }
        if (!mapped.count(g.name))
        {
            out.groups.push_back(g);
        }
    }
    // Groups the user maps: a layer prefix, or three channels.
    for (const auto& [name, where] : mapped)
    {
        LightGroupLayer g;
        g.name = name;
        g.layer = where;
        g.naming = LightGroupNaming::MAPPED;
        const size_t c1 = where.find(',');
        if (c1 != std::string::npos)
        {
            const size_t c2 = where.find(',', c1 + 1);
            const std::vector<std::string> three = {
                where.substr(0, c1),
                c2 == std::string::npos ? "" : where.substr(c1 + 1, c2 - c1 - 1),
                c2 == std::string::npos ? "" : where.substr(c2 + 1)};
            if (c2 == std::string::npos || three[2].find(',') != std::string::npos)
            {
                throw Exception(file + ": light group " + Quoted(name) + " is mapped to " +
                                Quoted(where) + ": give a layer prefix or three channels r,g,b");
            }
            for (int c = 0; c < 3; ++c)
            {
                const auto at =
                    std::find(channelNames.begin(), channelNames.end(), three[size_t(c)]);
                if (at == channelNames.end())
                {
                    throw Exception(file + ": light group " + Quoted(name) + ": channel " +
                                    Quoted(three[size_t(c)]) + " is not in the image");
                }
                g.rgb[c] = int(at - channelNames.begin());
            }
        }
        else
        {
            const auto l = layers.find(where);
            if (l == layers.end())
            {
                throw Exception(file + ": light group " + Quoted(name) +
                                ": the image has no layer " + Quoted(where) + " (no channels " +
                                where + ".R, " + where + ".G, " + where + ".B)");
            }
            std::copy(l->second.begin(), l->second.end(), g.rgb);
        }
        out.groups.push_back(g);
    }
    // bandlight's groups in the order its header lists them (the scene's).
    std::vector<std::string> order;
    if (const auto a = attributes.find(LIGHT_GROUPS_ATTRIBUTE); a != attributes.end())
    {
        for (size_t at = 0; at <= a->second.size();)
        {
            const size_t comma = std::min(a->second.find(',', at), a->second.size());
            order.push_back(a->second.substr(at, comma - at));
            at = comma + 1;
        }
    }
    const auto rank = [&](const LightGroupLayer& g)
    {
        const auto i = std::find(order.begin(), order.end(), g.name);
        return g.naming == LightGroupNaming::BANDLIGHT ? size_t(i - order.begin()) : order.size();
    };
    std::stable_sort(out.groups.begin(), out.groups.end(),
                     [&](const LightGroupLayer& a, const LightGroupLayer& b)
                     { return rank(a) < rank(b); });
    if (out.groups.empty())
    {
        throw Exception(file +
                        ": holds no light groups (looked for Blender/Cycles "
                        "'<ViewLayer>.Combined_<group>', Arnold 'RGBA_<group>' and bandlight's "
                        "own layers; other namings are mapped to a group by their layer)");
    }
    if (views.size() > 1)
    {
        std::string list;
        for (const std::string& v : views)
        {
            list += (list.empty() ? "" : ", ") +
                    (v.empty() ? std::string("(none)") : v.substr(0, v.size() - 1));
        }
        throw Exception(file + ": holds light groups of several view layers (" + list +
                        "); relight one view layer's file at a time");
    }
    // Two groups on the same channels, or one name twice.
    for (size_t i = 0; i < out.groups.size(); ++i)
    {
        for (size_t j = 0; j < i; ++j)
        {
            const LightGroupLayer& a = out.groups[j];
            const LightGroupLayer& b = out.groups[i];
            if (a.name == b.name)
            {
                throw Exception(file + ": light group " + Quoted(a.name) + " is named twice (" +
                                Quoted(a.layer) + " and " + Quoted(b.layer) + ")");
            }
            for (int c = 0; c < 3; ++c)
            {
                for (int d = 0; d < 3; ++d)
                {
                    if (a.rgb[c] == b.rgb[d])
                    {
                        throw Exception(file + ": light groups " + Quoted(a.name) + " and " +
                                        Quoted(b.name) + " resolve to the same channel " +
                                        Quoted(channelNames[size_t(a.rgb[c])]));
                    }
                }
            }
        }
    }
    // The beauty: the view layer's Combined, Arnold's RGBA, or R, G, B.
    std::vector<std::string> candidates;
    const bool blender =
        std::any_of(out.groups.begin(), out.groups.end(),
                    [](const auto& g) { return g.naming == LightGroupNaming::BLENDER; });
    const bool arnold =
        std::any_of(out.groups.begin(), out.groups.end(),
                    [](const auto& g) { return g.naming == LightGroupNaming::ARNOLD; });
    if (blender)
    {
        candidates.push_back(*views.begin() + "Combined");
    }
    if (arnold)
    {
        candidates.push_back("");  // Arnold's beauty: R, G, B, A
        candidates.push_back("RGBA");
    }
    if (!blender && !arnold)
    {
        candidates = {"", "Combined", "RGBA"};
    }
    for (const std::string& c : candidates)
    {
        if (const auto l = layers.find(c); l != layers.end())
        {
            out.beautyLayer = c;
            std::copy(l->second.begin(), l->second.end(), out.beauty);
            break;
        }
    }
    if (out.beauty[0] < 0)
    {
        std::string list;
        for (const std::string& c : candidates)
        {
            list +=
                (list.empty() ? "" : ", ") + (c.empty() ? std::string("R, G, B") : c + ".R/G/B");
        }
        throw Exception(file + ": has light groups but no beauty they sum to (looked for " + list +
                        ")");
    }
    for (const LightGroupLayer& g : out.groups)
    {
        for (int c = 0; c < 3; ++c)
        {
            if (std::find(out.beauty, out.beauty + 3, g.rgb[c]) != out.beauty + 3)
            {
                throw Exception(file + ": light group " + Quoted(g.name) +
                                " resolves to the beauty's own channel " +
                                Quoted(channelNames[size_t(g.rgb[c])]));
            }
        }
    }
    return out;
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
    const LightGroupLayer* nonFinite = nullptr;  ///< the first NaN or infinite group
    int channel = -1;  ///< else the first channel whose groups exceed the beauty
    float value = 0.0f;
    double sum = 0.0, beauty = 0.0;
    explicit operator bool() const { return nonFinite || channel >= 0; }
};

/// Checks one pixel: finite groups that do not sum past the beauty,
/// channel by channel, in double. A non-finite beauty is carried: the
/// groups say nothing about it. The sum alone decides most pixels (it is
/// finite exactly when every group is; the tolerance only matters when it
/// exceeds the beauty), so the culprit and the level are looked for only
/// then.
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
        if (std::isfinite(sum) && !(sum > beauty))
        {
            continue;
        }
        double partial = 0.0, level = std::abs(beauty);
        for (const LightGroupLayer& g : layout.groups)
        {
            const float x = v[g.rgb[c]];
            if (!std::isfinite(x))
            {
                fault.nonFinite = &g;
                fault.value = x;
                return fault;
            }
            partial += x;
            level = std::max(level, std::abs(partial));
        }
        if (std::isfinite(beauty) && sum - beauty > PartitionTolerance(level, peak, layout.half))
        {
            fault.channel = c;
            fault.sum = sum;
            fault.beauty = beauty;
            return fault;
        }
    }
    return fault;
}

/// The one line naming a pixel's fault, `file` and the pixel (x, y).
std::string FaultMessage(const PixelFault& f, const std::string& file, size_t x, size_t y)
{
    const std::string at = " at pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
    if (f.nonFinite)
    {
        return file + ": light group '" + OneLine(f.nonFinite->name, 80) + "' is " +
               (std::isnan(f.value) ? "NaN" : "infinite") + at + " (layer " +
               OneLine(f.nonFinite->layer, 80) + ")";
    }
    return file + ": the light groups sum to more than the beauty" + at + " (" +
           std::to_string(f.sum) + " against " + std::to_string(f.beauty) + " in " +
           "RGB"[f.channel] +
           "): they are not a partition of it (a group twice, or a layer that is not a light "
           "group)";
}
}  // namespace

void RelightLightGroups(const LightGroupLayout& layout,
                        const std::map<std::string, LightGroupWork>& works, float* pixels,
                        long width, long height, int channels, const std::string& file)
{
    const size_t w = size_t(std::max(width, 0L)), h = size_t(std::max(height, 0L));
    const size_t n = size_t(channels);
    const double peak = BeautyPeak(layout, pixels, w * h, n);
    // Every pixel checked before any changes; the first at fault is named,
    // whichever thread found it.
    size_t bad = w * h;
    std::mutex mu;
    ParallelFor(w * h, 0,
                [&](size_t a, size_t b)
                {
                    for (size_t p = a; p < b; ++p)
                    {
                        if (CheckPixel(layout, pixels + p * n, peak))
                        {
                            std::lock_guard<std::mutex> lock(mu);
                            bad = std::min(bad, p);
                            return;
                        }
                    }
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
                            const float* v = block + p * n;
                            for (int c = 0; c < 3; ++c)
                            {
                                double sum = 0.0;
                                for (const LightGroupLayer& g : layout.groups)
                                {
                                    sum += v[g.rgb[c]];
                                }
                                residual[3 * p + size_t(c)] = double(v[layout.beauty[c]]) - sum;
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
}

}  // namespace bandlight::jobs
