// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/SpectralJob.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>
#include <optional>
#include <set>

#include <Eigen/LU>

#include "imageio/ImageColour.h"
#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"
#include "imaging/SpectralGroups.h"
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
    ImageDescription d = LinearImageDescription(Rec709Space(), "sRGB");
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
    if (!r.options.lightGroups.empty())
    {
        RequireNamedChannels(r.files.output, "light groups");
    }
    SpectralRun run(r, reporter);
    const bool groups = !r.options.lightGroups.empty();
    const auto one = [&](const std::string& in, const std::string& out)
    {
        const SpectralImage image = ReadSpectralImage(
            in, r.options, groups ? NonFiniteSpectra::GUARD : NonFiniteSpectra::REFUSE);
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

}  // namespace bandlight::jobs
