// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/SpectralJob.h"

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

void CheckSpectralPixels(const SpectralLayout& layout, const std::string& file,
                         const std::vector<std::string>& channelNames, const float* pixels,
                         size_t count, int channels, int width)
{
    for (size_t p = 0; p < count; ++p)
    {
        const float* v = pixels + p * size_t(channels);
        for (const int c : layout.channels)
        {
            const float x = v[c];
            if (std::isfinite(x) && x >= 0.0f)
            {
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
    }
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

namespace
{
ImageData ReadImageData(const std::string& path, bool pixels)
{
    ImageData image;
    ThrowIfFailed(ImageFiles().read(path, image, pixels));
    return image;
}
}  // namespace

SpectralImage ReadSpectralImage(const std::string& path, const SpectralOptions& options)
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
                        size_t(image.width) * size_t(image.height), image.channels, image.width);
    return image;
}

namespace
{

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

/// One spectral light-group image relit: RGB of the beauty (Σ relit groups
/// + the residual, integrated as it is) and of each group, `count` pixels
/// of 3 floats each, on `threads` threads. Throws Exception naming the file
/// and the group for a group that is not there or not spectral, groups that
/// sum to more than the beauty, and NaN or negative values.
struct GroupConversion
{
    std::vector<std::string> groups;
    std::vector<std::vector<float>> rgb;  ///< per group
    std::vector<float> beauty;
    std::string applied;
    std::vector<std::string> notes;
};

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
                            image.channels, image.width);
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
        for (const int c : image.layout.channels)
        {
            peak = std::max(peak, double(image.pixels[p * size_t(image.channels) + size_t(c)]));
        }
    }
    for (size_t p = 0; p < count; ++p)
    {
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
    return out;
}

}  // namespace

namespace
{

/// Every check of a spectral request that needs no file: the threads, the
/// names, the outputs against the inputs, and the light groups' own rules.
void CheckSpectralRequest(const SpectralRequest& r)
{
    if (r.threads < 0 || r.threads > kMaxThreads)
    {
        throw ParameterError("{threads} must be 0 (all cores) to " + std::to_string(kMaxThreads) +
                             ", got " + std::to_string(r.threads));
    }
    (void)FindRgbSpace(r.options.workingSpace);
    (void)r.options.plates.parsed();
    (void)ParseObserver(r.options.observer);
    (void)r.options.layoutOptions();
    CheckFrameSetPaths(r.files);  // an output is never its own spectral input
    if (r.options.lightGroups.empty())
    {
        return;
    }
    if (r.options.plates.parsed().convention == PlateConvention::BALANCED)
    {
        throw ParameterError(
            "{light_group}: the groups show several lights and no one white "
            "to balance from: give {plates=}lit");
    }
    if (IsDisplayReferredFile(r.files.output))
    {
        throw ParameterError("{light_group} writes a layer per group: give an EXR output");
    }
    std::set<std::string> names;
    for (const SpectralLightGroup& g : r.options.lightGroups)
    {
        if (g.group.empty() || !names.insert(g.group).second)
        {
            throw ParameterError("{light_group} names the group '" + OneLine(g.group, 80) +
                                 "' twice (or gives no name)");
        }
        if (g.from.spectrum.empty() || g.to.spectrum.empty())
        {
            throw ParameterError("{light_group} '" + OneLine(g.group, 80) +
                                 "' needs both lights, NAME=FROM:TO");
        }
    }
    if (!r.options.from.spectrum.empty() || !r.options.to.spectrum.empty())
    {
        throw ParameterError(
            "{src} and {dst} do not apply with {light_group}: each group "
            "takes its own, NAME=FROM:TO");
    }
}

/// What the frames of one run share: the request, the result that the
/// first frame describes, and the lock that frames running at once
/// (RunFrameSet) take to report.
struct SpectralRun
{
    const SpectralRequest& request;
    Reporter& reporter;
    const RgbSpace& working;
    SpectralResult result;
    bool first = true;
    std::mutex mu;

    SpectralRun(const SpectralRequest& r, Reporter& rep)
        : request(r), reporter(rep), working(FindRgbSpace(r.options.workingSpace))
    {
    }

    /// The first frame to get here describes the run: its layout, what was
    /// applied, and its notes (said once, not per frame).
    void describe(const SpectralImage& image, const std::string& applied,
                  const std::vector<std::string>& notes)
    {
        const std::lock_guard<std::mutex> lock(mu);
        if (!first)
        {
            return;
        }
        result.layout = image.layout.describe();
        result.applied = applied;
        for (const std::string& n : notes)
        {
            reporter.note(n);
        }
        first = false;
    }

    void note(const std::string& text)
    {
        const std::lock_guard<std::mutex> lock(mu);
        reporter.note(text);
    }
};

/// The index of an image's alpha channel, or nullopt.
std::optional<size_t> AlphaChannel(const SpectralImage& image)
{
    const auto alpha = std::find(image.channelNames.begin(), image.channelNames.end(), "A");
    if (alpha == image.channelNames.end())
    {
        return std::nullopt;
    }
    return size_t(alpha - image.channelNames.begin());
}

/// One frame with light groups: each group relit exactly, written as the
/// beauty (Σ relit groups + residual), the alpha, and a layer per group.
void WriteLightGroupFrame(SpectralRun& run, const std::string& in, const std::string& out,
                          const SpectralImage& image)
{
    const SpectralRequest& r = run.request;
    const ImageData header = ReadImageData(in, false);
    const GroupConversion g =
        ConvertLightGroups(in, image, header.attributes, r.options, r.threads);
    run.describe(image, "light groups (" + g.applied + ")", g.notes);
    const size_t count = size_t(image.width) * size_t(image.height);
    const std::optional<size_t> alpha = AlphaChannel(image);
    std::vector<std::string> names = {"R", "G", "B"};
    if (alpha)
    {
        names.push_back("A");
    }
    for (const std::string& name : g.groups)
    {
        for (const char* c : {".R", ".G", ".B"})
        {
            names.push_back(name + c);
        }
    }
    const size_t n = names.size();
    std::vector<float> pixels(count * n);
    for (size_t p = 0; p < count; ++p)
    {
        float* v = &pixels[p * n];
        v = std::copy_n(&g.beauty[3 * p], 3, v);
        if (alpha)
        {
            *v++ = image.pixels[p * size_t(image.channels) + *alpha];
        }
        for (const std::vector<float>& rgb : g.rgb)
        {
            v = std::copy_n(&rgb[3 * p], 3, v);
        }
    }
    ImageDescription d = LinearImageDescription(run.working, ColorSpaceName(run.working));
    std::string list;
    for (const std::string& name : g.groups)
    {
        list += (list.empty() ? "" : ",") + name;
    }
    d.attributes.push_back({LIGHT_GROUPS_ATTRIBUTE, list});
    d.attributes.push_back({"bandlight:transform", "spectral " + image.layout.describe() +
                                                       ", light groups (" + g.applied + ")"});
    WriteImage(out, pixels.data(), image.width, image.height, int(n), names, d, PixelType::FLOAT);
}

/// Encodes linear RGB(A) in place for a display-referred output: sRGB-encoded
/// Rec.709, the pixels leaving 0-1 clipped and counted in a note. Returns
/// the output's description.
ImageDescription EncodeForDisplay(SpectralRun& run, const std::string& out, float* pixels,
                                  int width, int height, int channels)
{
    const size_t count = size_t(width) * size_t(height);
    const ImageEncoding srgb = NamedEncoding("srgb");
    const int index[3] = {0, 1, 2};
    if (const auto cpu = LinearToEncoding(run.working, srgb))
    {
        ApplyToBuffer(cpu, pixels, width, height, channels, index, run.request.threads);
    }
    size_t clipped = 0;
    for (size_t p = 0; p < count; ++p)
    {
        const float* v = pixels + p * size_t(channels);
        clipped += std::any_of(v, v + 3, [](float x) { return x < 0.0f || x > 1.0f; });
    }
    if (clipped > 0)
    {
        run.note(out + ": " + std::to_string(clipped) + " of " + std::to_string(count) +
                 " pixels left 0-1 and are clipped: the format holds "
                 "display-referred code values (write an EXR to keep them)");
    }
    ImageDescription d = LinearImageDescription(FindRgbSpace("rec709"), "sRGB");
    d.attributes = {{"colorInteropID", "srgb_rec709_scene"}};
    return d;
}

/// One frame without light groups: the spectra integrated to RGB in the
/// working space (with the image's alpha), or sRGB-encoded for a
/// display-referred format.
void WriteConvertedFrame(SpectralRun& run, const std::string& in, const std::string& out,
                         const SpectralImage& image)
{
    const SpectralRequest& r = run.request;
    const SpectralConversion conversion =
        MakeSpectralConversion(image.layout, image.channels, r.options);
    std::vector<std::string> notes;
    for (const std::string& n : image.layout.notes)
    {
        notes.push_back(in + ": " + n);
    }
    notes.insert(notes.end(), conversion.notes.begin(), conversion.notes.end());
    run.describe(image, conversion.applied, notes);
    const size_t count = size_t(image.width) * size_t(image.height);
    const std::optional<size_t> alpha = AlphaChannel(image);
    const int outChannels = alpha ? 4 : 3;
    std::vector<float> rgb(3 * count);
    IntegrateSpectralPixels(conversion, image.pixels.data(), count, image.channels, rgb.data(),
                            r.threads);
    CheckIntegratedPixels(in, rgb.data(), count, image.width);
    std::vector<float> pixels;
    if (alpha)
    {
        pixels.resize(4 * count);
        for (size_t p = 0; p < count; ++p)
        {
            std::copy_n(&rgb[3 * p], 3, &pixels[4 * p]);
            pixels[4 * p + 3] = image.pixels[p * size_t(image.channels) + *alpha];
        }
    }
    float* out3 = alpha ? pixels.data() : rgb.data();
    ImageDescription d = LinearImageDescription(run.working, ColorSpaceName(run.working));
    PixelType type = PixelType::FLOAT;
    if (IsDisplayReferredFile(out))
    {
        d = EncodeForDisplay(run, out, out3, image.width, image.height, outChannels);
        type = PixelType::UINT8;
    }
    d.attributes.push_back(
        {"bandlight:transform", "spectral " + image.layout.describe() + ", " + conversion.applied});
    WriteImage(out, out3, image.width, image.height, outChannels,
               alpha ? std::vector<std::string>{"R", "G", "B", "A"}
                     : std::vector<std::string>{"R", "G", "B"},
               d, type);
}

}  // namespace

SpectralResult ConvertSpectralImages(const SpectralRequest& r, Reporter& reporter)
{
    CheckSpectralRequest(r);  // before any file is read
    SpectralRun run(r, reporter);
    const bool groups = !r.options.lightGroups.empty();
    const auto one = [&](const std::string& in, const std::string& out)
    {
        const SpectralImage image = ReadSpectralImage(in, r.options);
        if (groups)
        {
            WriteLightGroupFrame(run, in, out, image);
        }
        else
        {
            WriteConvertedFrame(run, in, out, image);
        }
    };
    run.result.run = RunFrameSet(r.files, reporter, one);
    return std::move(run.result);
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
