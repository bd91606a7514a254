// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/SpectralImages.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <optional>
#include <set>

#include <Eigen/LU>

#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"
#include "plugin/ConfigBuilder.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"
#include "spectral/RgbSpaces.h"
#include "transforms/PixelKernels.h"
#include "transforms/Plates.h"

namespace bandlight::jobs
{

namespace
{
/// "a, b or c".
std::string ListChoices(const std::vector<std::string>& keys)
{
    std::string list;
    for (size_t i = 0; i < keys.size(); ++i)
    {
        list += (i == 0 ? "" : i + 1 == keys.size() ? " or " : ", ") + keys[i];
    }
    return list;
}
}  // namespace

std::vector<std::string> SpectralKindKeys()
{
    std::vector<std::string> keys;
    for (const SpectralKindEntry& e : SpectralKinds())
    {
        keys.push_back(e.key);
    }
    return keys;
}

std::vector<std::string> SpectralSamplingKeys()
{
    std::vector<std::string> keys = {SAMPLING_AUTO};
    for (const SpectralSamplingEntry& e : SpectralSamplings())
    {
        keys.push_back(e.key);
    }
    return keys;
}

std::string SpectralKindChoices()
{
    return ListChoices(SpectralKindKeys());
}

std::string SpectralSamplingChoices()
{
    return ListChoices(SpectralSamplingKeys());
}

std::string SpectralSamplingHelp()
{
    std::string help = std::string(SAMPLING_AUTO) + " (as the layout says)";
    const auto& table = SpectralSamplings();
    for (size_t i = 0; i < table.size(); ++i)
    {
        help += std::string(i + 1 == table.size() ? " or " : ", ") + table[i].key + " (" +
                table[i].help + ")";
    }
    return help;
}

SpectralLayoutOptions SpectralOptions::layoutOptions() const
{
    SpectralLayoutOptions o;
    o.namedWavelengths = channelWavelengths;
    if (!channelWavelengthsFile.empty())
    {
        for (const auto& [name, nm] : ReadChannelWavelengths(channelWavelengthsFile))
        {
            o.namedWavelengths[name] = nm;
        }
    }
    // Names are case-insensitive, as everywhere.
    const auto lower = [](std::string t)
    {
        for (char& ch : t)
        {
            ch = char(std::tolower(static_cast<unsigned char>(ch)));
        }
        return t;
    };
    const std::string kindName = lower(kind);
    const std::string samplingName = lower(sampling);
    const auto& kinds = SpectralKinds();
    const auto k = std::find_if(kinds.begin(), kinds.end(),
                                [&](const SpectralKindEntry& e) { return kindName == e.key; });
    if (k == kinds.end())
    {
        throw ParameterError("{kind} must be " + SpectralKindChoices() + ", got '" +
                             OneLine(kind, 40) + "'");
    }
    o.namedKind = k->kind;
    const auto& samplings = SpectralSamplings();
    const auto m =
        std::find_if(samplings.begin(), samplings.end(),
                     [&](const SpectralSamplingEntry& e) { return samplingName == e.key; });
    if (m != samplings.end())
    {
        o.sampling = m->sampling;
    }
    else if (samplingName != SAMPLING_AUTO)
    {
        throw ParameterError("{sampling} must be " + SpectralSamplingChoices() + ", got '" +
                             OneLine(sampling, 40) + "'");
    }
    return o;
}

SpectralConversion MakeSpectralConversion(const SpectralLayout& layout, int channels,
                                          const SpectralOptions& o)
{
    SpectralConversion c;
    c.layout = layout;
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    c.workingSpace = working.name;
    const Observer observer = ParseObserver(o.observer);
    const bool reflective = layout.kind == SpectralKind::REFLECTIVE;
    SpectralLighting lighting;
    lighting.from = reflective ? Spectrum() : o.from.spectrum;
    lighting.to = o.to.spectrum;
    const Eigen::Matrix<double, 3, Eigen::Dynamic> xyz =
        SpectralXyzWeights(layout, observer, lighting, &c.notes);
    Mat3 toRgb = RgbToXyzMatrix(working.chromaticities).inverse();
    // The light the result shows: `to` when relit or rendered, `from` when
    // an emissive image is only integrated, else none known.
    const bool relit = !reflective && !o.from.spectrum.empty() && !o.to.spectrum.empty();
    const bool shown = reflective || !o.from.spectrum.empty();
    const Plates plates = o.plates.parsed();
    if (plates.convention == PlateConvention::BALANCED)
    {
        if (shown)
        {
            // The white the image shows, as this integration sees it (a
            // white reflector under `from`, relit or not; rendered under
            // `to`), onto the working white: white stays exactly (1, 1, 1)
            // on any grid.
            const std::vector<double> one =
                reflective ? std::vector<double>(layout.wavelengths.size(), 1.0)
                           : LightOnLayout(layout, o.from.spectrum);
            const Vec3 white =
                xyz * Eigen::Map<const Eigen::VectorXd>(one.data(), Eigen::Index(one.size()));
            toRgb = toRgb * AdaptationMatrix(white / white.y(), WorkingWhiteXyz(working),
                                             plates.adaptation);
            c.balanced = true;
        }
        else
        {
            c.notes.push_back(
                "the image is only integrated: no light is known to balance (give {src=}S1, "
                "the light it was lit by, and {dst=}S2 to relight); written as lit");
        }
    }
    c.weights.setZero(3, channels);
    const Eigen::Matrix<double, 3, Eigen::Dynamic> rgb = toRgb * xyz;
    for (size_t i = 0; i < layout.channels.size(); ++i)
    {
        c.weights.col(layout.channels[i]) = rgb.col(Eigen::Index(i));
    }
    c.applied = reflective ? "rendered under " + o.to.name
                : relit    ? "relit " + o.from.name + " -> " + o.to.name
                : shown    ? "integrated, lit by " + o.from.name
                           : "integrated";
    c.applied += c.balanced ? ", balanced (" + AdaptationName(plates.adaptation) + ")" : ", lit";
    c.applied += ", " + working.name;
    return c;
}

size_t CheckSpectralPixels(const SpectralLayout& layout, const std::string& file,
                           const std::vector<std::string>& channelNames, const float* pixels,
                           size_t count, int channels, int width, NonFiniteSpectra nonFinite)
{
    size_t held = 0;
    for (size_t p = 0; p < count; ++p)
    {
        const float* v = pixels + p * size_t(channels);
        bool heldHere = false;
        for (const int c : layout.channels)
        {
            const float x = v[c];
            if (std::isfinite(x) && x >= 0.0f)
            {
                continue;
            }
            if (!std::isfinite(x) && nonFinite == NonFiniteSpectra::GUARD)
            {
                heldHere = true;
                continue;
            }
            const std::string what = std::isnan(x)   ? "NaN"
                                     : std::isinf(x) ? "infinite"
                                                     : "negative (" + std::to_string(x) + ")";
            const std::string where = width > 0 ? "(" + std::to_string(p % size_t(width)) + ", " +
                                                      std::to_string(p / size_t(width)) + ")"
                                                : std::to_string(p);
            throw Exception(file + ": channel '" + OneLine(channelNames[size_t(c)], 80) + "' is " +
                            what + " at pixel " + where +
                            (layout.kind == SpectralKind::EMISSIVE
                                 ? "; radiance must be finite and not negative"
                                 : "; a remittance must be finite and not negative"));
        }
        held += heldHere ? 1 : 0;
    }
    return held;
}

void CheckIntegratedPixels(const std::string& file, const float* rgb, size_t count, int width)
{
    // Finite spectra whose integral leaves float's range (values near
    // 3.4e38) would be written as Inf: refused, naming the pixel, as a NaN
    // in a spectrum is.
    for (size_t p = 0; p < count; ++p)
    {
        if (!std::isfinite(rgb[3 * p]) || !std::isfinite(rgb[3 * p + 1]) ||
            !std::isfinite(rgb[3 * p + 2]))
        {
            const std::string where = width > 0 ? "(" + std::to_string(p % size_t(width)) + ", " +
                                                      std::to_string(p / size_t(width)) + ")"
                                                : std::to_string(p);
            throw Exception(file + ": pixel " + where +
                            ": its spectrum integrates beyond float's range (about 3.4e38); "
                            "scale the image down");
        }
    }
}

void IntegrateSpectralPixels(const SpectralConversion& conversion, const float* pixels,
                             size_t count, int channels, float* rgb, int threads)
{
    // The dot products run over the channels from the first spectral one to
    // the last (EXR sorts channels by name, so S0.* are consecutive).
    const auto [lo, hi] =
        std::minmax_element(conversion.layout.channels.begin(), conversion.layout.channels.end());
    const size_t first = size_t(*lo), n = size_t(*hi) - first + 1;
    std::vector<float> w(3 * n);
    for (size_t c = 0; c < 3; ++c)
    {
        for (size_t j = 0; j < n; ++j)
        {
            w[c * n + j] = float(conversion.weights(Eigen::Index(c), Eigen::Index(first + j)));
        }
    }
    // Channels inside that range that are not spectral samples (an AOV
    // named between two bands, "band_07x" beside "band_00".."band_15") have
    // weight 0, but 0 × NaN is NaN: where there are any, each block of
    // pixels is copied with those channels zeroed before its dot products,
    // so that only spectral samples ever enter them.
    std::vector<char> spectral(n, 0);
    for (const int c : conversion.layout.channels)
    {
        spectral[size_t(c) - first] = 1;
    }
    const bool gaps = std::find(spectral.begin(), spectral.end(), 0) != spectral.end();
    ParallelFor(count, threads,
                [&](size_t a, size_t b)
                {
                    if (!gaps)
                    {
                        SpectralDot(w.data(), n, pixels + a * size_t(channels) + first, b - a,
                                    size_t(channels), rgb + 3 * a, 3);
                        return;
                    }
                    constexpr size_t kBlock = 1024;
                    std::vector<float> block(kBlock * n);
                    for (size_t p0 = a; p0 < b; p0 += kBlock)
                    {
                        const size_t m = std::min(kBlock, b - p0);
                        for (size_t p = 0; p < m; ++p)
                        {
                            const float* from = pixels + (p0 + p) * size_t(channels) + first;
                            for (size_t j = 0; j < n; ++j)
                            {
                                block[p * n + j] = spectral[j] ? from[j] : 0.0f;
                            }
                        }
                        SpectralDot(w.data(), n, block.data(), m, n, rgb + 3 * p0, 3);
                    }
                });
}

std::vector<float> SpectralImage::spectra() const
{
    const size_t n = layout.channels.size();
    const size_t count = size_t(width) * size_t(height);
    std::vector<float> s(count * n);
    for (size_t p = 0; p < count; ++p)
    {
        for (size_t i = 0; i < n; ++i)
        {
            s[p * n + i] = pixels[p * size_t(channels) + size_t(layout.channels[i])];
        }
    }
    return s;
}

ImageData ReadImageData(const std::string& path, bool pixels)
{
    ImageData image;
    ThrowIfFailed(ImageFiles().read(path, image, pixels));
    return image;
}

SpectralImage ReadSpectralImage(const std::string& path, const SpectralOptions& options,
                                NonFiniteSpectra nonFinite)
{
    // The header first: a layout that does not parse costs no pixels.
    const ImageData header = ReadImageData(path, false);
    SpectralImage image;
    image.layout =
        FindSpectralLayout(path, header.channelNames, header.attributes, options.layoutOptions());
    ImageData data = ReadImageData(path, true);
    if (data.channelNames != header.channelNames)
    {
        throw Exception(path + ": changed while it was read");
    }
    image.width = data.width;
    image.height = data.height;
    image.channels = data.channels;
    image.channelNames = std::move(data.channelNames);
    image.pixels = std::move(data.pixels);
    CheckSpectralPixels(image.layout, path, image.channelNames, image.pixels.data(),
                        size_t(image.width) * size_t(image.height), image.channels, image.width,
                        nonFinite);
    return image;
}

void WriteSpectralImage(const std::string& path, int width, int height, SpectralKind kind,
                        const std::vector<double>& wavelengths, const std::vector<float>& spectra,
                        const std::vector<float>& rgb, ImageDescription d, OutputSet* outputs)
{
    const size_t n = wavelengths.size();
    const size_t count = size_t(width) * size_t(height);
    const size_t channels = 3 + n;
    std::vector<float> pixels(count * channels);
    for (size_t p = 0; p < count; ++p)
    {
        std::copy_n(&rgb[3 * p], 3, &pixels[p * channels]);
        std::copy_n(&spectra[p * n], n, &pixels[p * channels + 3]);
    }
    std::vector<std::string> names = {"R", "G", "B"};
    for (const double nm : wavelengths)
    {
        names.push_back(SpectralChannelName(kind, nm));
    }
    d.attributes.push_back({"spectralLayoutVersion", "1.0"});
    if (kind == SpectralKind::EMISSIVE)
    {
        d.attributes.push_back({"emissiveUnits", "W.m^-2.sr^-1"});
    }
    WriteImage(path, pixels.data(), width, height, int(channels), names, d, PixelType::FLOAT,
               outputs);
}

}  // namespace bandlight::jobs
