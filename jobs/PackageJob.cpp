// SPDX-License-Identifier: BSD-3-Clause
// The package job: the default config package, for white-balanced and for
// lit plates, and an example re-lit from A to D65: a chart of the CIE test
// colours rendered spectrally under A, the same re-lit by the band3 and
// Bradford looks, and the spectral truth under D65 to compare with.
#include "jobs/PackageJob.h"

#include <Eigen/LU>

#include "imaging/ImageApply.h"
#include "plugin/ConfigBuilder.h"
#include "spectral/AtomicFile.h"
#include "spectral/Illuminants.h"

namespace bandlight::jobs
{

namespace
{

constexpr int kPatch = 96;  // pixels per patch side
constexpr int kBorder = 8;  // dark border between patches
constexpr int kColumns = 6;
constexpr int kRows = 3;

/// The chart's surfaces: TCS01–TCS15, then a white, a mid grey and a black.
std::vector<Spectrum> ChartSurfaces()
{
    std::vector<Spectrum> s;
    for (const NamedSpectrum& t : TestColourSamples())
    {
        s.push_back(t.spectrum);
    }
    for (double v : {0.9, 0.18, 0.03})
    {
        s.push_back(Spectrum::Constant(360.0, 5.0, 95, v));
    }
    return s;
}

/// The chart lit by `illuminant`, computed spectrally: XYZ (white reflector
/// Y = 1, no adaptation) → working RGB.
std::vector<float> RenderChart(const Spectrum& illuminant, const RgbSpace& working, int& width,
                               int& height)
{
    width = kColumns * (kPatch + kBorder) + kBorder;
    height = kRows * (kPatch + kBorder) + kBorder;
    std::vector<float> px(size_t(width) * size_t(height) * 4, 0.0f);
    const Mat3 toRgb = RgbToXyzMatrix(working.chromaticities).inverse();
    const XyzIntegrator integrate(illuminant, Observer::CIE1931_2DEG);
    const std::vector<Spectrum> surfaces = ChartSurfaces();
    for (size_t i = 0; i < surfaces.size(); ++i)
    {
        const Vec3 rgb = toRgb * (integrate(surfaces[i]) / 100.0);
        const int x0 = kBorder + int(i % kColumns) * (kPatch + kBorder);
        const int y0 = kBorder + int(i / kColumns) * (kPatch + kBorder);
        for (int y = y0; y < y0 + kPatch; ++y)
        {
            for (int x = x0; x < x0 + kPatch; ++x)
            {
                float* p = &px[(size_t(y) * size_t(width) + size_t(x)) * 4];
                p[0] = float(rgb.x());
                p[1] = float(rgb.y());
                p[2] = float(rgb.z());
            }
        }
    }
    for (size_t i = 3; i < px.size(); i += 4)
    {
        px[i] = 1.0f;
    }
    return px;
}

/// The chart balanced to the working white: what an ACES IDT delivers.
std::vector<float> Balanced(std::vector<float> px, const Spectrum& light, const RgbSpace& working)
{
    const Mat3 b = BalanceMatrix(light, working, AdaptationMethod::CAT02);
    for (size_t i = 0; i + 3 < px.size(); i += 4)
    {
        const Vec3 v = b * Vec3(px[i], px[i + 1], px[i + 2]);
        px[i] = float(v.x());
        px[i + 1] = float(v.y());
        px[i + 2] = float(v.z());
    }
    return px;
}

}  // namespace

PackageResult MakePackage(const PackageRequest& request, Reporter&)
{
    const std::string& dir = request.out;
    PackageResult result;
    // The config for white-balanced plates (the ACES convention, the
    // default) in DIR, the one for lit plates in DIR/lit.
    ConfigOptions options;
    options.lights = LectureLights();
    options.methods = LinearMethodNames();
    const ConfigPackage package = BuildConfig(options);
    ConfigOptions litOptions = options;
    litOptions.plates = Plates::Lit();
    const ConfigPackage litPackage = BuildConfig(litOptions);
    // The configs, their LUTs and every image are one set: a failing run
    // leaves the previous package as it was.
    OutputSet files;
    WriteConfigPackage(package, dir, &files);
    WriteConfigPackage(litPackage, dir + "/lit", &files);
    const RgbSpace& working = FindRgbSpace(options.workingSpace);
    const std::string workingName = ColorSpaceName(working);

    int w = 0, h = 0;
    const Spectrum a = BuiltinIlluminant("A"), d65 = BuiltinIlluminant("D65");
    const std::vector<float> underA = RenderChart(a, working, w, h);
    const std::vector<float> underD65 = RenderChart(d65, working, w, h);
    const OCIO::ConstCPUProcessorRcPtr toSrgb =
        package.config->getProcessor(workingName.c_str(), "sRGB")->getDefaultCPUProcessor();
    const int rgb[3] = {0, 1, 2};

    struct Output
    {
        std::string name;
        std::vector<float> pixels;
    };
    std::vector<Output> outputs = {
        {"chart_A", underA},
        {"chart_D65_spectral", underD65},
        {"chart_A_balanced", Balanced(underA, a, working)},
        {"chart_D65_spectral_balanced", Balanced(underD65, d65, working)}};
    for (const bool balanced : {false, true})
    {
        const OCIO::ConstConfigRcPtr config = balanced ? package.config : litPackage.config;
        for (const std::string& method : PackageMethodNames())
        {
            const std::string look = LookName(method, "A", "D65");
            OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
            t->setSrc(workingName.c_str());
            t->setDst(workingName.c_str());
            t->setLooks(look.c_str());
            std::vector<float> px = outputs[balanced ? 2 : 0].pixels;
            ApplyToBuffer(config->getProcessor(t)->getDefaultCPUProcessor(), px.data(), w, h, 4,
                          rgb, 0);
            outputs.push_back({"chart_" + look + (balanced ? "_balanced" : ""), std::move(px)});
        }
    }
    result.looks = package.config->getNumLooks();
    result.lights = options.lights.size();
    result.methods = options.methods.size();
    result.workingSpace = workingName;
    ImageDescription srgb;
    srgb.colorSpace = "sRGB";
    for (const Output& o : outputs)
    {
        WriteImage(dir + "/" + o.name + ".exr", o.pixels.data(), w, h, 4, {"R", "G", "B", "A"},
                   LinearImageDescription(working, workingName), PixelType::HALF, &files);
        std::vector<float> preview = o.pixels;
        ApplyToBuffer(toSrgb, preview.data(), w, h, 4, rgb, 0);
        WriteImage(dir + "/" + o.name + ".png", preview.data(), w, h, 4, {"R", "G", "B", "A"}, srgb,
                   PixelType::UINT8, &files);
        result.charts.push_back(o.name);
    }
    files.commit();
    return result;
}

}  // namespace bandlight::jobs
