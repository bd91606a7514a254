// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/SpectralGroups.h"

#include <algorithm>
#include <cmath>

#include "imaging/LightGroups.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"
#include "transforms/IlluminantChange.h"
#include "transforms/PixelKernels.h"

namespace bandlight::jobs
{

namespace
{

/// Every integrated pixel through the guard of every pixel path
/// (GuardPixel: NaN to -1e16, ±Inf to ±1e16), so that a NaN or an infinity
/// in a group's spectrum relights as it does in an RGB light group.
void GuardIntegrated(std::vector<float>& rgb)
{
    for (size_t k = 0; k + 2 < rgb.size(); k += 3)
    {
        const Vec3 g = GuardPixel(Vec3(rgb[k], rgb[k + 1], rgb[k + 2]));
        rgb[k] = float(g.x());
        rgb[k + 1] = float(g.y());
        rgb[k + 2] = float(g.z());
    }
}

/// Marks the pixels whose spectral channels in `layout` hold NaN or ±Inf.
void MarkNonFinite(const SpectralLayout& layout, const SpectralImage& image,
                   std::vector<char>& held)
{
    for (size_t p = 0; p < held.size(); ++p)
    {
        const float* v = image.pixels.data() + p * size_t(image.channels);
        for (const int c : layout.channels)
        {
            held[p] = char(held[p] | !std::isfinite(v[c]));
        }
    }
}

/// The spectral groups of an image: the prefixes P of channels
/// "P.S0.<λ>" (or "P.T.<λ>"), in channel order.
std::vector<std::string> SpectralGroupPrefixes(const std::vector<std::string>& names)
{
    std::vector<std::string> groups;
    for (const std::string& n : names)
    {
        for (const char* kind : {".S0.", ".T."})
        {
            const size_t at = n.find(kind);
            if (at != std::string::npos && at > 0 && n.find('.') == at)
            {
                const std::string g = n.substr(0, at);
                if (std::find(groups.begin(), groups.end(), g) == groups.end())
                {
                    groups.push_back(g);
                }
            }
        }
    }
    return groups;
}

/// The layout of group `group`'s spectral channels: the image's channel
/// names with the prefix taken off and every other name hidden.
SpectralLayout GroupLayout(const std::string& file, const std::vector<std::string>& names,
                           const std::map<std::string, std::string>& attributes,
                           const std::string& group, const SpectralOptions& options)
{
    const std::string prefix = group + ".";
    std::vector<std::string> own(names.size());
    for (size_t i = 0; i < names.size(); ++i)
    {
        own[i] = names[i].compare(0, prefix.size(), prefix) == 0 ? names[i].substr(prefix.size())
                                                                 : "-";  // not a spectral name
    }
    SpectralLayoutOptions o = options.layoutOptions();
    o.namedWavelengths.clear();
    return FindSpectralLayout(file + " (light group '" + group + "')", own, attributes, o);
}

}  // namespace

GroupConversion ConvertLightGroups(const std::string& in, const SpectralImage& image,
                                   const std::map<std::string, std::string>& attributes,
                                   const SpectralOptions& options, int threads)
{
    GroupConversion out;
    out.groups = SpectralGroupPrefixes(image.channelNames);
    for (const SpectralLightGroup& g : options.lightGroups)
    {
        if (std::find(out.groups.begin(), out.groups.end(), g.group) == out.groups.end())
        {
            std::string have;
            for (const std::string& h : out.groups)
            {
                have += (have.empty() ? "" : ", ") + h;
            }
            throw Exception(in + ": has no spectral light group '" + OneLine(g.group, 80) + "' (" +
                            (have.empty() ? std::string("it has no <group>.S0.<nm> channels: "
                                                        "render with --spectra --light-groups")
                                          : "it has " + have) +
                            ")");
        }
    }
    const size_t count = size_t(image.width) * size_t(image.height);
    SpectralOptions plain = options;
    plain.from = Light();
    plain.to = Light();
    // The beauty integrated as it is; the groups', relit or as they are.
    const SpectralConversion beauty = MakeSpectralConversion(image.layout, image.channels, plain);
    std::vector<float> residual(3 * count);
    IntegrateSpectralPixels(beauty, image.pixels.data(), count, image.channels, residual.data(),
                            threads);
    GuardIntegrated(residual);
    // Pixels with NaN or infinity in the beauty or a group: guarded, left
    // out of the partition check, and counted in a note.
    std::vector<char> held(count, 0);
    MarkNonFinite(image.layout, image, held);
    std::vector<double> sum(image.layout.channels.size() * count, 0.0);
    for (const std::string& name : out.groups)
    {
        const SpectralLayout layout =
            GroupLayout(in, image.channelNames, attributes, name, options);
        if (layout.wavelengths != image.layout.wavelengths || layout.kind != image.layout.kind)
        {
            throw Exception(in + ": light group '" + OneLine(name, 80) +
                            "' is sampled otherwise than the beauty (" + layout.describe() +
                            " against " + image.layout.describe() + ")");
        }
        CheckSpectralPixels(layout, in, image.channelNames, image.pixels.data(), count,
                            image.channels, image.width, NonFiniteSpectra::GUARD);
        MarkNonFinite(layout, image, held);
        for (size_t p = 0; p < count; ++p)
        {
            for (size_t i = 0; i < layout.channels.size(); ++i)
            {
                sum[p * layout.channels.size() + i] +=
                    image.pixels[p * size_t(image.channels) + size_t(layout.channels[i])];
            }
        }
        SpectralOptions o = plain;
        const auto g = std::find_if(options.lightGroups.begin(), options.lightGroups.end(),
                                    [&](const SpectralLightGroup& x) { return x.group == name; });
        if (g != options.lightGroups.end())
        {
            o.from = g->from;
            o.to = g->to;
        }
        const SpectralConversion asIs = MakeSpectralConversion(layout, image.channels, plain);
        const SpectralConversion relit = MakeSpectralConversion(layout, image.channels, o);
        std::vector<float> before(3 * count);
        out.rgb.emplace_back(3 * count);
        IntegrateSpectralPixels(asIs, image.pixels.data(), count, image.channels, before.data(),
                                threads);
        IntegrateSpectralPixels(relit, image.pixels.data(), count, image.channels,
                                out.rgb.back().data(), threads);
        GuardIntegrated(before);
        GuardIntegrated(out.rgb.back());
        for (size_t k = 0; k < 3 * count; ++k)
        {
            residual[k] -= before[k];
        }
        out.applied += (out.applied.empty() ? "" : "; ") + name + ": " + relit.applied;
        for (const std::string& n : relit.notes)
        {
            out.notes.push_back(name + ": " + n);
        }
    }
    // The groups partition the beauty, wavelength by wavelength.
    double peak = 0.0;
    for (size_t p = 0; p < count; ++p)
    {
        if (held[p])
        {
            continue;
        }
        for (const int c : image.layout.channels)
        {
            peak = std::max(peak, double(image.pixels[p * size_t(image.channels) + size_t(c)]));
        }
    }
    for (size_t p = 0; p < count; ++p)
    {
        if (held[p])
        {
            continue;
        }
        for (size_t i = 0; i < image.layout.channels.size(); ++i)
        {
            const double b =
                image.pixels[p * size_t(image.channels) + size_t(image.layout.channels[i])];
            const double s = sum[p * image.layout.channels.size() + i];
            if (s - b > PartitionTolerance(std::max(b, s), peak, false))
            {
                throw Exception(in +
                                ": the spectral light groups sum to more than the beauty at "
                                "pixel (" +
                                std::to_string(p % size_t(image.width)) + ", " +
                                std::to_string(p / size_t(image.width)) + ") at " +
                                Fixed(image.layout.wavelengths[i], 1) +
                                " nm: they are not a partition of it");
            }
        }
    }
    out.beauty.resize(3 * count);
    // The beauty as Σ groups + residual summed in double.
    for (size_t k = 0; k < 3 * count; ++k)
    {
        double b = residual[k];
        for (const std::vector<float>& g : out.rgb)
        {
            b += g[k];
        }
        out.beauty[k] = float(b);
    }
    const size_t guarded = size_t(std::count(held.begin(), held.end(), char(1)));
    if (guarded > 0)
    {
        out.notes.push_back(std::to_string(guarded) +
                            " pixels held NaN or infinite values in the beauty or a group: NaN "
                            "taken as -1e16 and infinity as +-1e16 after integration, as every "
                            "pixel path takes them, so every value written is finite");
    }
    return out;
}

}  // namespace bandlight::jobs
