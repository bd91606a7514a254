// SPDX-License-Identifier: BSD-3-Clause
#include "measure/LightGroupAccuracy.h"

#include <algorithm>
#include <chrono>

#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"
#include "imaging/RelightForms.h"
#include "imaging/SpectralGroups.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Metrics.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Statistics.h"

namespace bandlight::jobs
{

namespace
{

/// R, G, B of layer `prefix` of an image read whole.
std::vector<Vec3> Layer(const ImageData& image, const std::string& prefix)
{
    int rgb[3] = {-1, -1, -1};
    for (int c = 0; c < 3; ++c)
    {
        const std::string name = prefix + "RGB"[c];
        const auto at = std::find(image.channelNames.begin(), image.channelNames.end(), name);
        if (at == image.channelNames.end())
        {
            throw Exception("the image has no channel '" + name + "'");
        }
        rgb[c] = int(at - image.channelNames.begin());
    }
    const size_t count = size_t(image.width) * size_t(image.height);
    std::vector<Vec3> v(count);
    for (size_t p = 0; p < count; ++p)
    {
        const float* px = &image.pixels[p * size_t(image.channels)];
        v[p] = Vec3(px[rgb[0]], px[rgb[1]], px[rgb[2]]);
    }
    return v;
}

/// Mean and 95th percentile.
std::pair<double, double> Summary(std::vector<double> v)
{
    const Statistics s = Summarise(std::move(v));
    return {s.mean, s.p95};
}

double Seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The methods measured when none are named.
std::vector<std::string> MethodsOf(const LightGroupAccuracyRequest& r)
{
    return r.methods.empty() ? LightGroupMethodNames() : r.methods;
}

/// Throws unless every light group of the image is given its change.
void RequireEveryGroup(const LightGroupAccuracyRequest& r, const LightGroupLayout& layout)
{
    for (const LightGroupLayer& g : layout.groups)
    {
        if (std::none_of(r.changes.begin(), r.changes.end(),
                         [&](const SpectralLightGroup& c) { return c.group == g.name; }))
        {
            throw Exception(r.image + ": light group '" + g.name +
                            "' has no change: the global look and the reference need every "
                            "group's, {light_group=}" +
                            g.name + "=FROM:TO");
        }
    }
}

/// The lights the global look goes between: each group's light at its
/// group's share of the image's luminance, summed.
struct Mixes
{
    Light from;
    Light to;
};

Mixes MixLights(const LightGroupAccuracyRequest& r, const ImageData& input, const Mat3& toXyz,
                LightGroupAccuracyResult& result)
{
    Spectrum from = Spectrum::Constant(360.0, 1.0, 471, 0.0);
    Spectrum to = from;
    for (const SpectralLightGroup& c : r.changes)
    {
        const std::vector<Vec3> rgb = Layer(input, c.group + ".");
        double y = 0.0;
        for (const Vec3& v : rgb)
        {
            y += (toXyz * v).y();
        }
        Spectrum a = c.from.spectrum.resampledLike(from);
        Spectrum b = c.to.spectrum.resampledLike(to);
        a *= y / IntegrateXyz(a, Observer::CIE1931_2DEG).y();
        b *= y / IntegrateXyz(b, Observer::CIE1931_2DEG).y();
        from += a;
        to += b;
        result.globalFrom += (result.globalFrom.empty() ? "" : " + ") + c.group + " " + c.from.name;
        result.globalTo += (result.globalTo.empty() ? "" : " + ") + c.group + " " + c.to.name;
    }
    return {{"mix of " + result.globalFrom, from}, {"mix of " + result.globalTo, to}};
}

/// The reference: each spectral group relit exactly, and judged. L*a*b* is
/// relative to the equal-energy white at the reference's brightest
/// luminance; pixels the reference leaves black (background) are not
/// counted.
struct Reference
{
    std::vector<Vec3> rgb;
    Mat3 toXyz;
    Vec3 whiteXyz;

    /// ΔE00 of each lit pixel of `image` against the reference.
    std::vector<double> deltaE(const std::vector<Vec3>& image) const
    {
        const MetricEntry& metric = Metrics().front();  // ΔE00, the default
        MetricContext context;
        context.rgbToXyz = toXyz;
        context.whiteXyz = whiteXyz;
        std::vector<double> d;
        for (size_t p = 0; p < rgb.size(); ++p)
        {
            if (rgb[p].isZero(0.0))
            {
                continue;  // no light: background
            }
            d.push_back(metric.compute(image[p], rgb[p], context));
        }
        return d;
    }
};

Reference RelightExactly(const LightGroupAccuracyRequest& r, const ImageData& input,
                         const Mat3& toXyz, LightGroupAccuracyResult& result)
{
    SpectralOptions exact;
    exact.workingSpace = r.workingSpace;
    exact.plates.plates = "lit";
    exact.lightGroups = r.changes;
    const auto t0 = std::chrono::steady_clock::now();
    const SpectralImage image = ReadSpectralImage(r.image, exact);
    const GroupConversion relit =
        ConvertLightGroups(r.image, image, input.attributes, exact, r.threads);
    result.spectralSeconds = Seconds(t0);
    std::vector<Vec3> rgb(relit.beauty.size() / 3);
    for (size_t p = 0; p < rgb.size(); ++p)
    {
        rgb[p] = Vec3(relit.beauty[3 * p], relit.beauty[3 * p + 1], relit.beauty[3 * p + 2]);
    }
    Reference ref{std::move(rgb), toXyz, Vec3::Zero()};
    double white = 0.0;
    for (const Vec3& v : ref.rgb)
    {
        white = std::max(white, (toXyz * v).y());
    }
    if (!(white > 0.0))
    {
        throw Exception(r.image + ": the relit image is black: nothing to measure");
    }
    ref.whiteXyz = Vec3::Ones() * white;
    return ref;
}

/// An apply's wall time (in memory: the pixels of the image as read, no
/// files) and its output's ΔE00.
struct ApplyScore
{
    double seconds = 0.0;
    double mean = 0.0;
    double p95 = 0.0;
};

template <class Apply>
ApplyScore TimedApply(const ImageData& input, const Reference& reference, const Apply& apply)
{
    ApplyScore score;
    ImageData image = input;
    const auto t0 = std::chrono::steady_clock::now();
    apply(image);
    score.seconds = Seconds(t0);
    std::tie(score.mean, score.p95) = Summary(reference.deltaE(Layer(image, "")));
    return score;
}

/// One method: one global look on the beauty, then a look per group, as
/// `apply` relights them (the same forms and pixels, imaging/).
LightGroupAccuracyRow MeasureMethod(const LightGroupAccuracyRequest& r, const std::string& method,
                                    const Mixes& mixes, const ImageData& input,
                                    const Reference& reference, Reporter& reporter)
{
    LightGroupAccuracyRow row;
    row.method = method;
    RelightRequest change;
    change.src = mixes.from;
    change.dst = mixes.to;
    change.method = method;
    change.workingSpace = r.workingSpace;
    change.plates.plates = "lit";
    ImageColourRequest colour;
    colour.working = &change.working();
    const BufferWork global = MakeRelightForm(change, reporter).work(r.threads);
    const ApplyScore globalScore = TimedApply(input, reference, [&](ImageData& image)
                                              { ApplyToImageData(global, image, r.image, colour); });
    row.globalSeconds = globalScore.seconds;
    row.globalMean = globalScore.mean;
    row.globalP95 = globalScore.p95;

    LightGroupApply groups;
    for (const SpectralLightGroup& c : r.changes)
    {
        RelightRequest g = change;
        g.src = c.from;
        g.dst = c.to;
        const Spectrum& a = g.src.spectrum;
        const Spectrum& b = g.dst.spectrum;
        // The same light: carried unchanged, as `apply` carries it.
        groups.works[c.group] = a.sameGrid(b) && a.values() == b.values()
                                    ? BufferWork()
                                    : MakeRelightForm(g, reporter).work(r.threads);
    }
    const ApplyScore groupsScore =
        TimedApply(input, reference, [&](ImageData& image)
                   { ApplyLightGroupsToImageData(groups, image, r.image, colour); });
    row.groupsSeconds = groupsScore.seconds;
    row.groupsMean = groupsScore.mean;
    row.groupsP95 = groupsScore.p95;
    return row;
}

}  // namespace

LightGroupAccuracyResult MeasureLightGroups(const LightGroupAccuracyRequest& r, Reporter& reporter)
{
    if (r.changes.empty())
    {
        throw ParameterError(
            "{light_group}: give each group of the image its change, "
            "NAME=FROM:TO");
    }
    const RgbSpace& working = FindRgbSpace(r.workingSpace);
    const std::vector<std::string> methods = MethodsOf(r);
    CheckImageInput(r.image);
    const ImageData input = ReadImageData(r.image, true);
    RequireEveryGroup(r, FindLightGroups(r.image, input.channelNames, input.attributes));
    const Mat3 toXyz = RgbToXyzMatrix(working.chromaticities);
    LightGroupAccuracyResult result;
    const Mixes mixes = MixLights(r, input, toXyz, result);

    const Reference reference = RelightExactly(r, input, toXyz, result);
    const std::vector<double> none = reference.deltaE(Layer(input, ""));
    result.pixels = none.size();
    result.noChangeMean = Summary(none).first;
    for (const std::string& method : methods)
    {
        result.rows.push_back(MeasureMethod(r, method, mixes, input, reference, reporter));
        reporter.progress("light groups: " + method,
                          double(result.rows.size()) / double(methods.size()));
    }
    return result;
}

}  // namespace bandlight::jobs
