// SPDX-License-Identifier: BSD-3-Clause
#include "measure/SpectralAccuracy.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include <Eigen/LU>

#include "report/DeltaEMap.h"
#include "spectral/AtomicFile.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/SpectrumIO.h"
#include "transforms/Accuracy.h"
#include "transforms/Methods.h"
#include "transforms/Plates.h"

namespace bandlight::jobs
{

namespace
{

/// Emissive images: 1 / the 99.9th percentile of Y relative to a white
/// reflector under `from`; reflective images: 1.
double EmissiveScale(const std::string& path, const SpectralImage& image, const SpectralOptions& o)
{
    if (image.layout.kind == SpectralKind::REFLECTIVE)
    {
        return 1.0;
    }
    const Observer observer = ParseObserver(o.observer);
    const Eigen::RowVectorXd y = SpectralXyzWeights(image.layout, observer, {}).row(1);
    const std::vector<double> white = LightOnLayout(image.layout, o.from.spectrum);
    double whiteY = 0.0;
    for (size_t i = 0; i < white.size(); ++i)
    {
        whiteY += y(Eigen::Index(i)) * white[i];
    }
    const std::vector<float> spectra = image.spectra();
    const size_t n = image.layout.wavelengths.size();
    std::vector<double> lum;
    for (size_t p = 0; p * n < spectra.size(); ++p)
    {
        double v = 0.0;
        for (size_t i = 0; i < n; ++i)
        {
            v += y(Eigen::Index(i)) * double(spectra[p * n + i]);
        }
        if (v > 0.0)
        {
            lum.push_back(v / whiteY);
        }
    }
    const double top = Percentile(lum, 0.999);
    if (!(top > 0.0) || !(whiteY > 0.0))
    {
        throw Exception(path +
                        ": the spectral image is black under the eye's sensitivity: nothing to "
                        "measure");
    }
    return 1.0 / top;
}

void RequireLights(const SpectralImage& image, const SpectralOptions& o, bool needTo)
{
    if (image.layout.kind == SpectralKind::EMISSIVE && o.from.spectrum.empty())
    {
        throw ParameterError(
            "an emissive spectral image is measured as lit by a known light: "
            "give {src=}LIGHT");
    }
    if (needTo && (o.from.spectrum.empty() || o.to.spectrum.empty()))
    {
        throw ParameterError(
            "the heat maps compare a change of light: give {src=}S1 and "
            "{dst=}S2");
    }
}

std::string FileStem(const std::string& path)
{
    return std::filesystem::path(path).stem().string();
}

/// A file-name-safe form of a method name.
std::string Safe(const std::string& s)
{
    std::string o;
    for (const char c : s)
    {
        o += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    }
    return o;
}

}  // namespace

ReflectanceSet ReflectanceSetFromSpectralImage(const std::string& path,
                                               const SpectralOptions& options, size_t maxSamples,
                                               Reporter& reporter)
{
    const SpectralImage image = ReadSpectralImage(path, options);
    RequireLights(image, options, false);
    const SpectralLayout& layout = image.layout;
    const size_t n = layout.wavelengths.size();
    const bool emissive = layout.kind == SpectralKind::EMISSIVE;
    const double scale = EmissiveScale(path, image, options);
    const std::vector<double> light =
        emissive ? LightOnLayout(layout, options.from.spectrum) : std::vector<double>(n, 1.0);
    const size_t count = size_t(image.width) * size_t(image.height);
    const size_t step = std::max<size_t>(
        1, size_t(std::ceil(std::sqrt(double(count) / double(std::max<size_t>(1, maxSamples))))));
    ReflectanceSet set;
    set.name = path;
    std::set<std::vector<float>> seen;
    const std::vector<float> spectra = image.spectra();
    int lost = 0;
    for (size_t y = 0; y < size_t(image.height) && set.samples.size() < maxSamples; y += step)
    {
        for (size_t x = 0; x < size_t(image.width) && set.samples.size() < maxSamples; x += step)
        {
            const size_t p = y * size_t(image.width) + x;
            std::vector<float> s(spectra.begin() + long(p * n),
                                 spectra.begin() + long((p + 1) * n));
            if (std::all_of(s.begin(), s.end(), [](float v) { return v == 0.0f; }) ||
                !seen.insert(s).second)
            {
                continue;
            }
            std::vector<double> beta(n);
            for (size_t i = 0; i < n; ++i)
            {
                beta[i] = light[i] > 0.0 ? double(s[i]) / light[i] * scale : 0.0;
                lost += light[i] > 0.0 || s[i] == 0.0f ? 0 : 1;
            }
            set.samples.push_back({std::to_string(x) + "," + std::to_string(y),
                                   SpectrumFromSamples(layout.wavelengths, beta, path)});
        }
    }
    if (set.samples.empty())
    {
        throw Exception(path + ": every pixel is black: nothing to measure");
    }
    std::ostringstream note;
    note << path << ": " << set.samples.size() << " distinct pixels (every " << step
         << (step == 1 ? "" : "th") << " pixel in each direction) as remittances";
    if (emissive)
    {
        note << ", radiance divided by " << options.from.name
             << " and scaled so the brightest pixel has Y = 1";
    }
    reporter.note(note.str());
    if (lost > 0)
    {
        reporter.note(path + ": " + std::to_string(lost) +
                      " samples where the source light has no power were set to 0");
    }
    return set;
}

std::vector<HeatmapSummary> WriteAccuracyHeatmaps(const std::string& path, const SpectralOptions& o,
                                                  const std::vector<std::string>& methods,
                                                  const std::string& dir, const std::string& stem,
                                                  OutputSet& outputs, Reporter& reporter)
{
    const SpectralImage image = ReadSpectralImage(path, o);
    RequireLights(image, o, true);
    const SpectralLayout& layout = image.layout;
    const Observer observer = ParseObserver(o.observer);
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    const Plates plates = o.plates.parsed();
    const bool balanced = plates.convention == PlateConvention::BALANCED;
    const bool reflective = layout.kind == SpectralKind::REFLECTIVE;
    const double scale = EmissiveScale(path, image, o);
    // Every pixel as a remittance (emissive ones divided by S1, as the
    // accuracy set takes them), seen under S1 (the plate) and under S2 (the
    // exact answer), each light's white reflector at Y = 1.
    SpectralLayout asRemittance = layout;
    asRemittance.kind = SpectralKind::REFLECTIVE;
    const Eigen::Matrix<double, 3, Eigen::Dynamic> w1 =
        SpectralXyzWeights(asRemittance, observer, {Spectrum(), o.from.spectrum});
    const Eigen::Matrix<double, 3, Eigen::Dynamic> w2 =
        SpectralXyzWeights(asRemittance, observer, {Spectrum(), o.to.spectrum});
    const size_t n = layout.wavelengths.size();
    const std::vector<double> light =
        reflective ? std::vector<double>(n, 1.0) : LightOnLayout(layout, o.from.spectrum);
    const Mat3 toXyz = RgbToXyzMatrix(working.chromaticities);
    const Mat3 toRgb = toXyz.inverse();
    const Mat3 in =
        balanced
            ? Mat3(BalanceMatrix(o.from.spectrum, working, plates.adaptation, observer) * toRgb)
            : toRgb;
    const Mat3 out =
        balanced ? Mat3(BalanceMatrix(o.to.spectrum, working, plates.adaptation, observer) * toRgb)
                 : toRgb;
    // L*a*b* as the accuracy report takes it: relative to the working white
    // for balanced plates, to S2's white for lit ones.
    const Vec3 white =
        balanced ? WorkingWhiteXyz(working) : Vec3(w2 * Eigen::VectorXd::Ones(Eigen::Index(n)));
    const size_t count = size_t(image.width) * size_t(image.height);
    const std::vector<float> spectra = image.spectra();
    std::vector<float> plate(3 * count);
    std::vector<Vec3> reference(count);
    std::vector<char> lit(count, 0);
    Eigen::VectorXd beta = Eigen::VectorXd::Zero(Eigen::Index(n));
    for (size_t p = 0; p < count; ++p)
    {
        bool any = false;
        for (size_t i = 0; i < n; ++i)
        {
            const double v = spectra[p * n + i];
            any = any || v != 0.0;
            beta(Eigen::Index(i)) = light[i] > 0.0 ? v / light[i] * scale : 0.0;
        }
        const Vec3 rgb = in * (w1 * beta);
        plate[3 * p] = float(rgb.x());
        plate[3 * p + 1] = float(rgb.y());
        plate[3 * p + 2] = float(rgb.z());
        // The exact answer, in the working space the look's result is in.
        reference[p] = XyzToLab(toXyz * (out * (w2 * beta)), white);
        lit[p] = any ? 1 : 0;
    }
    std::filesystem::create_directories(dir);
    std::vector<HeatmapSummary> summaries;
    for (const std::string& name : methods)
    {
        const MethodSpec parsed = ParseMethod(name);
        if (parsed.entry().isReference() || parsed.entry().needsCamera)
        {
            continue;  // the reference itself; camera methods need the camera's plates
        }
        RelightRequest relight;
        relight.src = o.from;
        relight.dst = o.to;
        relight.method = name;
        relight.workingSpace = o.workingSpace;
        relight.observer = o.observer;
        relight.plates = o.plates;
        const Relighter relighter = relight.relighter(reporter);
        std::vector<float> result = plate;
        relighter.apply(result.data(), count, 0);
        DeltaEMap map(image.width, image.height);
        for (size_t p = 0; p < count; ++p)
        {
            if (lit[p])
            {
                const Vec3 rgb(result[3 * p], result[3 * p + 1], result[3 * p + 2]);
                map.set(p, DeltaE2000(XyzToLab(toXyz * rgb, white), reference[p]));
            }
        }
        const DeltaESummary summary = map.summary();
        HeatmapSummary h;
        h.method = name;
        h.mean = summary.mean;
        h.p95 = summary.p95;
        h.max = summary.max;
        const std::string base = dir + "/" + stem + "_" + Safe(name) + "_dE00";
        h.exr = base + ".exr";
        h.png = base + ".png";
        std::ostringstream title;
        title << "CIEDE2000 of " << name << ", " << o.from.name << " -> " << o.to.name << " ("
              << (balanced ? "balanced" : "lit") << " plates): mean " << Fixed(h.mean, 2)
              << ", p95 " << Fixed(h.p95, 2) << ", max " << Fixed(h.max, 2);
        WriteDeltaEMap(
            map, h.exr, h.png, title.str(),
            {{"bandlight:transform", "CIEDE2000 of " + name + ", " + o.from.name + " -> " +
                                         o.to.name + " against the exact relight"}},
            outputs);
        summaries.push_back(h);
    }
    return summaries;
}

std::vector<std::string> HeatmapStems(const std::vector<std::string>& images)
{
    const auto folderOf = [](const std::string& path)
    {
        const std::filesystem::path parent =
            std::filesystem::absolute(std::filesystem::path(path)).lexically_normal().parent_path();
        const std::string name = parent.filename().string();
        return Safe(name.empty() ? std::string("root") : name);
    };
    std::vector<std::string> stems;
    for (const std::string& image : images)
    {
        stems.push_back(FileStem(image));
    }
    const auto shared = [](const std::vector<std::string>& names, size_t i)
    { return std::count(names.begin(), names.end(), names[i]) > 1; };
    std::vector<std::string> named = stems;
    for (size_t i = 0; i < images.size(); ++i)
    {
        if (shared(stems, i))
        {
            named[i] = folderOf(images[i]) + "_" + stems[i];
        }
    }
    std::vector<std::string> result = named;
    for (size_t i = 0; i < images.size(); ++i)
    {
        if (shared(named, i))
        {
            result[i] = named[i] + "_" + std::to_string(i + 1);
        }
    }
    return result;
}

}  // namespace bandlight::jobs
