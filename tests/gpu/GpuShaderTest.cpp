// SPDX-License-Identifier: BSD-3-Clause
// Every transform bandlight emits, as OpenColorIO 2.1 writes it for the GPU:
// the shader compiles in every language OCIO offers that a Debian compiler
// exists for, and on Mesa's llvmpipe it computes what OCIO's CPU processor
// computes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include <catch2/catch.hpp>

#include "gpu/GpuRunner.h"
#include "luts/LutWriter.h"
#include "plugin/ConfigBuilder.h"
#include "robustness/HardValues.h"
#include "spectral/CameraFile.h"
#include "spectral/Illuminants.h"

using namespace bandlight;
using namespace bandlight::test;

namespace
{

// ---------------------------------------------------------------------------
// Languages.

/// The languages glslangValidator checks (GLSL 1.2/1.3/4.0, GLSL ES 1.0/3.0
/// as fragment shaders; HLSL DX11 translated to SPIR-V).
const std::vector<OCIO::GpuLanguage>& ValidatedLanguages()
{
    static const std::vector<OCIO::GpuLanguage> languages = {
        OCIO::GPU_LANGUAGE_GLSL_1_2,    OCIO::GPU_LANGUAGE_GLSL_1_3,
        OCIO::GPU_LANGUAGE_GLSL_4_0,    OCIO::GPU_LANGUAGE_GLSL_ES_1_0,
        OCIO::GPU_LANGUAGE_GLSL_ES_3_0, OCIO::GPU_LANGUAGE_HLSL_DX11};
    return languages;
}

/// The languages OCIO 2.1 also writes but Debian 12 packages no compiler for:
/// Cg (NVIDIA's toolkit is not packaged), Metal 2.0 (Apple only) and OSL 1
/// (a renderer's language, not a GPU one). For these the test only checks
/// that OCIO generates the shader function without throwing.
const std::vector<OCIO::GpuLanguage>& GeneratedOnlyLanguages()
{
    static const std::vector<OCIO::GpuLanguage> languages = {
        OCIO::GPU_LANGUAGE_CG, OCIO::GPU_LANGUAGE_MSL_2_0, OCIO::LANGUAGE_OSL_1};
    return languages;
}

/// The languages run on llvmpipe and compared with the CPU: all five
/// OpenGL ones. Two GLSL ES quirks of OCIO 2.1 on llvmpipe do not reach
/// bandlight's transforms, which have no 1D LUT (their LUTs are 3D, with
/// analytic shapers) and no dynamic property: a one-row single-channel 1D
/// LUT is sampled .g/.b in ES (wrong by up to 1), and in ES 1.0 a dynamic
/// ExposureContrast comes out at about half precision (5e-4). Should a
/// transform ever gain either, the comparison here is where it shows.
const std::vector<OCIO::GpuLanguage>& RunLanguages()
{
    static const std::vector<OCIO::GpuLanguage> languages = {
        OCIO::GPU_LANGUAGE_GLSL_1_2, OCIO::GPU_LANGUAGE_GLSL_1_3, OCIO::GPU_LANGUAGE_GLSL_4_0,
        OCIO::GPU_LANGUAGE_GLSL_ES_1_0, OCIO::GPU_LANGUAGE_GLSL_ES_3_0};
    return languages;
}

// ---------------------------------------------------------------------------
// Transforms and what they are made of.

/// What a processor's ops are, which decides the tolerance.
enum class Kind
{
    MATRIX,  ///< ranges and matrices only: the same float arithmetic on both sides
    CURVE,   ///< analytic curves too (the sRGB encoding's pow): GPU pow differs in the last bits
    LUT,     ///< 1D or 3D LUTs: texture fetches and interpolation
};

const char* KindName(Kind k)
{
    switch (k)
    {
        case Kind::MATRIX:
            return "matrix";
        case Kind::CURVE:
            return "curve";
        case Kind::LUT:
            return "LUT";
    }
    return "?";
}

Kind KindOf(const OCIO::ConstProcessorRcPtr& processor)
{
    const OCIO::GroupTransformRcPtr ops = processor->createGroupTransform();
    Kind kind = Kind::MATRIX;
    for (int i = 0; i < ops->getNumTransforms(); ++i)
    {
        switch (ops->getTransform(i)->getTransformType())
        {
            case OCIO::TRANSFORM_TYPE_MATRIX:
            case OCIO::TRANSFORM_TYPE_RANGE:
                break;
            case OCIO::TRANSFORM_TYPE_LUT1D:
            case OCIO::TRANSFORM_TYPE_LUT3D:
                return Kind::LUT;
            default:
                kind = Kind::CURVE;
        }
    }
    return kind;
}

/// GPU vs CPU agreement required of each kind:
/// |gpu − cpu| ≤ relative · scale + absolute, per channel, where scale is
/// the largest |channel| of the CPU's output pixel. A pixel's scale rather
/// than the channel's own value because a 3×3 with negative entries
/// cancels: a channel near zero carries the rounding of its large
/// neighbours, on either processor.
struct Tolerance
{
    double relative;
    double absolute;
};

Tolerance ToleranceOf(Kind kind)
{
    switch (kind)
    {
        case Kind::MATRIX:
            return {1e-5, 1e-7};
        case Kind::CURVE:
            // The sRGB curve's pow: llvmpipe's exp2/log2 against OCIO's SSE
            // approximations; measured 1.9e-6 of the pixel.
            return {1e-5, 1e-7};
        case Kind::LUT:
            // Both use the same LUT and tetrahedral interpolation, but the
            // inverse shaper's exp2 multiplies the float rounding of the
            // encoded value (6e-8 near 1) by ln 2 × the shaper's 25–32
            // stops: measured 2.8e-6 (upsample) and 5.3e-6 (LUT files).
            return {1e-4, 1e-6};
    }
    return {0.0, 0.0};
}

struct Case
{
    std::string name;  ///< "look bradford_A_to_D65", "colour space sRGB -> scene_linear"
    OCIO::ConstProcessorRcPtr processor;
    Kind kind = Kind::MATRIX;
};

Case MakeCase(std::string name, const OCIO::ConstProcessorRcPtr& processor)
{
    return {std::move(name), processor, KindOf(processor)};
}

/// Every transform a config offers: each look (scene_linear in and out),
/// each named transform, each colour space to and from scene_linear, each
/// display/view from scene_linear.
std::vector<Case> ConfigCases(const OCIO::ConstConfigRcPtr& config)
{
    std::vector<Case> cases;
    const std::string linear = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName();
    for (int i = 0; i < config->getNumLooks(); ++i)
    {
        const std::string look = config->getLookNameByIndex(i);
        OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
        t->setSrc(linear.c_str());
        t->setDst(linear.c_str());
        t->setLooks(look.c_str());
        cases.push_back(MakeCase("look " + look, config->getProcessor(t)));
    }
    for (int i = 0; i < config->getNumNamedTransforms(); ++i)
    {
        const OCIO::ConstNamedTransformRcPtr nt =
            config->getNamedTransform(config->getNamedTransformNameByIndex(i));
        OCIO::ConstTransformRcPtr t = nt->getTransform(OCIO::TRANSFORM_DIR_FORWARD);
        REQUIRE(t);
        cases.push_back(
            MakeCase("named transform " + std::string(nt->getName()), config->getProcessor(t)));
    }
    for (int i = 0;
         i < config->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL); ++i)
    {
        const std::string cs = config->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL,
                                                                OCIO::COLORSPACE_ALL, i);
        cases.push_back(MakeCase("colour space " + cs + " -> " + linear,
                                 config->getProcessor(cs.c_str(), linear.c_str())));
        cases.push_back(MakeCase("colour space " + linear + " -> " + cs,
                                 config->getProcessor(linear.c_str(), cs.c_str())));
    }
    for (int d = 0; d < config->getNumDisplays(); ++d)
    {
        const std::string display = config->getDisplay(d);
        for (int v = 0; v < config->getNumViews(display.c_str()); ++v)
        {
            const std::string view = config->getView(display.c_str(), v);
            OCIO::DisplayViewTransformRcPtr t = OCIO::DisplayViewTransform::Create();
            t->setSrc(linear.c_str());
            t->setDisplay(display.c_str());
            t->setView(view.c_str());
            cases.push_back(
                MakeCase("display " + display + " / view " + view, config->getProcessor(t)));
        }
    }
    return cases;
}

Light L(const std::string& name)
{
    return {name, BuiltinIlluminant(name)};
}

/// The default package config (`bandlight package`), built once.
const OCIO::ConstConfigRcPtr& PackageConfig()
{
    static const OCIO::ConstConfigRcPtr config = []
    {
        ConfigOptions options;
        options.lights = LectureLights();
        options.methods = LinearMethodNames();
        return OCIO::ConstConfigRcPtr(BuildConfig(options).config);
    }();
    return config;
}

/// A fresh folder under $TMPDIR, removed with what it holds.
class TempDir
{
public:
    explicit TempDir(const std::string& tag)
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern =
            std::string(tmp && *tmp ? tmp : "/tmp") + "/bandlight_gpu_" + tag + "_XXXXXX";
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        m_path = pattern;
    }
    ~TempDir()
    {
        std::error_code ignored;
        std::filesystem::remove_all(m_path, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::string& path() const { return m_path; }

private:
    std::string m_path;
};

// ---------------------------------------------------------------------------
// The test image.

constexpr int kWidth = 64;
constexpr int kHeight = 64;

/// 64×64 RGBA: greys 2^-10 … 2^16 in 1/10-stop steps, saturated colours
/// (12 hues, fully saturated and at 50 %, over the same range), negatives
/// (single channels, whole pixels, out-of-gamut mixes), then random
/// colours of random brightness; alpha varies and must come through.
const std::vector<float>& TestImage()
{
    static const std::vector<float> image = []
    {
        std::vector<float> px;
        px.reserve(size_t(kWidth) * kHeight * 4);
        auto add = [&px](float r, float g, float b)
        {
            const size_t i = px.size() / 4;
            px.insert(px.end(), {r, g, b, float(i % 5) * 0.25f});
        };
        for (int i = 0; i <= 260; ++i)
        {
            const float v = std::exp2(-10.0f + 0.1f * float(i));
            add(v, v, v);
        }
        for (int hue = 0; hue < 12; ++hue)
        {
            // A hexcone hue: one channel 1, one 0, one ramping.
            const float h = float(hue) / 2.0f;  // 0 … 6
            const int sector = int(h);
            const float f = h - float(sector);
            float rgb[3] = {};
            const int full[6] = {0, 1, 1, 2, 2, 0};
            const int zero[6] = {2, 2, 0, 0, 1, 1};
            const int ramp[6] = {1, 0, 2, 1, 0, 2};
            rgb[full[sector]] = 1.0f;
            rgb[zero[sector]] = 0.0f;
            rgb[ramp[sector]] = sector % 2 == 0 ? f : 1.0f - f;
            for (float saturation : {1.0f, 0.5f})
            {
                for (int e = -10; e <= 16; e += 1)
                {
                    const float s = std::exp2(float(e));
                    add(s * (1.0f - saturation + saturation * rgb[0]),
                        s * (1.0f - saturation + saturation * rgb[1]),
                        s * (1.0f - saturation + saturation * rgb[2]));
                }
            }
        }
        std::mt19937 rng(20240601);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        std::uniform_real_distribution<float> stops(-10.0f, 16.0f);
        for (const float v : {-0.05f, -0.001f, -1e-5f, -1.0f, -100.0f, -65504.0f})
        {
            add(v, 0.18f, 0.18f);
            add(0.18f, v, 0.18f);
            add(0.18f, 0.18f, v);
            add(v, v, v);
        }
        for (int i = 0; i < 200; ++i)
        {
            const float s = std::exp2(stops(rng));
            add(s * (unit(rng) * 1.2f - 0.2f), s * (unit(rng) * 1.2f - 0.2f),
                s * (unit(rng) * 1.2f - 0.2f));
        }
        while (px.size() < size_t(kWidth) * kHeight * 4)
        {
            const float s = std::exp2(stops(rng));
            add(s * unit(rng), s * unit(rng), s * unit(rng));
        }
        return px;
    }();
    return image;
}

std::vector<float> ApplyCpu(const OCIO::ConstProcessorRcPtr& processor,
                            const std::vector<float>& rgba, int width, int height)
{
    std::vector<float> out = rgba;
    OCIO::PackedImageDesc desc(out.data(), width, height, 4);
    processor->getDefaultCPUProcessor()->apply(desc);
    return out;
}

// ---------------------------------------------------------------------------
// Measurements.

using Clock = std::chrono::steady_clock;

/// The worst disagreement of one comparison: absolute, and relative to the
/// pixel's scale (see Tolerance).
struct Difference
{
    double absolute = 0.0;
    double relative = 0.0;
    bool pass = true;
    std::string worst;  ///< the pixel that needed the most of its tolerance
};

Difference Compare(const std::vector<float>& input, const std::vector<float>& cpu,
                   const std::vector<float>& gpu, const Tolerance& tol,
                   const std::vector<bool>* denormal = nullptr)
{
    Difference d;
    double worstUse = -1.0;
    for (size_t p = 0; p < cpu.size() / 4; ++p)
    {
        double scale = 0.0;
        for (int c = 0; c < 3; ++c)
        {
            scale = std::max(scale, double(std::fabs(cpu[p * 4 + c])));
        }
        for (int c = 0; c < 4; ++c)
        {
            const double e = cpu[p * 4 + c], g = gpu[p * 4 + c];
            // The GPU flushes denormals to zero (GLSL allows it; llvmpipe
            // does): a zero for a denormal input is the right answer there.
            if (denormal && (*denormal)[p] && g == 0.0)
            {
                continue;
            }
            const double diff = std::fabs(g - e);
            const double allowed = tol.relative * scale + tol.absolute;
            const double use = std::isfinite(diff) ? diff / allowed : HUGE_VAL;
            if (!(use <= 1.0))
            {
                d.pass = false;
            }
            d.absolute = std::max(d.absolute, diff);
            if (scale > 0.0)
            {
                d.relative = std::max(d.relative, diff / scale);
            }
            if (use > worstUse)
            {
                worstUse = use;
                std::ostringstream s;
                s << std::setprecision(9) << "pixel " << p << " in (" << input[p * 4] << ", "
                  << input[p * 4 + 1] << ", " << input[p * 4 + 2] << ", " << input[p * 4 + 3]
                  << ") channel " << c << ": cpu " << e << " gpu " << g << " (|diff| " << diff
                  << ", allowed " << allowed << ")";
                d.worst = s.str();
            }
        }
    }
    return d;
}

/// The largest differences seen, by kind and language, printed per test case.
class Report
{
public:
    void add(Kind kind, OCIO::GpuLanguage language, const Difference& d)
    {
        Difference& m = m_max[{kind, language}];
        m.absolute = std::max(m.absolute, d.absolute);
        m.relative = std::max(m.relative, d.relative);
        ++m_count[{kind, language}];
    }
    /// Notes how long a phase took, for the printout.
    void time(const std::string& phase, Clock::time_point since)
    {
        std::ostringstream s;
        s << std::fixed << std::setprecision(1)
          << std::chrono::duration<double>(Clock::now() - since).count();
        m_times += (m_times.empty() ? "" : ", ") + phase + " " + s.str() + " s";
    }
    void print(const std::string& title) const
    {
        std::ostringstream s;
        s << "[gpu] " << title << " (" << m_times << "): max |gpu - cpu| on llvmpipe"
          << (m_max.empty() ? ": no GPU runs\n" : "\n");
        s << std::defaultfloat << std::setprecision(3);
        for (const auto& [key, m] : m_max)
        {
            s << "  " << std::left << std::setw(7) << KindName(key.first) << std::setw(12)
              << GpuLanguageName(key.second) << std::right << std::setw(4) << m_count.at(key)
              << " transforms: absolute " << m.absolute << ", relative to the pixel " << m.relative
              << "\n";
        }
        std::cout << s.str() << std::flush;
    }

private:
    std::map<std::pair<Kind, OCIO::GpuLanguage>, Difference> m_max;
    std::map<std::pair<Kind, OCIO::GpuLanguage>, int> m_count;
    std::string m_times;
};

// ---------------------------------------------------------------------------
// The checks.

/// Whether the GPU can run `language`. Without a context the tests warn and
/// skip, or fail when BANDLIGHT_REQUIRE_GPU=1.
bool GpuFor(OCIO::GpuLanguage language)
{
    std::string why;
    if (GpuRunner::Available(language, &why))
    {
        return true;
    }
    const char* require = std::getenv("BANDLIGHT_REQUIRE_GPU");
    const std::string message =
        std::string("no GPU context for ") + GpuLanguageName(language) + ": " + why;
    if (require && std::string(require) == "1")
    {
        FAIL_CHECK(message << " (BANDLIGHT_REQUIRE_GPU=1)");
    }
    else
    {
        WARN("SKIPPED: " << message << "; set BANDLIGHT_REQUIRE_GPU=1 to fail instead");
    }
    return false;
}

/// Validator results, by language and complete shader text, for the whole
/// run: transforms that differ only in their LUT values share a text.
std::map<std::pair<OCIO::GpuLanguage, std::string>, std::string>& CompileCache()
{
    static std::map<std::pair<OCIO::GpuLanguage, std::string>, std::string> cache;
    return cache;
}

/// Every case's shader is generated in every language OCIO 2.1 offers, and
/// compiles where a compiler exists.
void CheckShadersCompile(const std::vector<Case>& cases)
{
    for (OCIO::GpuLanguage language : GeneratedOnlyLanguages())
    {
        for (const Case& c : cases)
        {
            INFO(c.name << " in " << GpuLanguageName(language) << " (generated, not compiled)");
            const auto generate = [&c, language] {
                return GpuRunner::Extract(c.processor->getDefaultGPUProcessor(), language).ocioText;
            };
            if (language == OCIO::LANGUAGE_OSL_1 && c.kind == Kind::LUT)
            {
                // OCIO 2.1 LIMITATION, not a bandlight bug: its OSL writer
                // has no LUTs ("The Lut3DOp is not yet supported by the 'Open
                // Shading language (OSL)' translation"), so the upsample
                // looks and the lattice LUT files have no OSL form. Checked
                // so that an OCIO that lifts it shows here.
                CHECK_THROWS_WITH(
                    generate(), Catch::Matchers::Contains("not yet supported by the 'Open Shading "
                                                          "language (OSL)' translation"));
                continue;
            }
            std::string text;
            CHECK_NOTHROW(text = generate());
            CHECK(text.find("OCIOMain") != std::string::npos);
        }
    }
    if (!GpuRunner::HasValidator())
    {
        WARN(
            "SKIPPED: glslangValidator was not found when the tests were configured "
            "(Debian: glslang-tools); shaders are generated but not compiled");
    }
    for (OCIO::GpuLanguage language : ValidatedLanguages())
    {
        std::vector<std::string> texts(cases.size());
        std::vector<std::string> pending;
        std::set<std::string> seen;
        for (size_t i = 0; i < cases.size(); ++i)
        {
            INFO(cases[i].name << " in " << GpuLanguageName(language));
            REQUIRE_NOTHROW(texts[i] = GpuRunner::Extract(
                                           cases[i].processor->getDefaultGPUProcessor(), language)
                                           .fragmentText);
            if (!CompileCache().count({language, texts[i]}) && seen.insert(texts[i]).second)
            {
                pending.push_back(texts[i]);
            }
        }
        if (!GpuRunner::HasValidator())
        {
            continue;
        }
        const std::vector<std::string> results = GpuRunner::Compile(pending, language);
        for (size_t i = 0; i < pending.size(); ++i)
        {
            CompileCache()[{language, pending[i]}] = results[i];
        }
        for (size_t i = 0; i < cases.size(); ++i)
        {
            INFO(cases[i].name << " in " << GpuLanguageName(language) << ":\n" << texts[i]);
            CHECK(CompileCache().at({language, texts[i]}).empty());
        }
    }
}

/// Every case on llvmpipe in each runnable language against the CPU.
void CheckGpuMatchesCpu(const std::vector<Case>& cases, Report& report)
{
    const std::vector<float>& image = TestImage();
    for (OCIO::GpuLanguage language : RunLanguages())
    {
        if (!GpuFor(language))
        {
            continue;
        }
        for (const Case& c : cases)
        {
            INFO(c.name << " (" << KindName(c.kind) << ") in " << GpuLanguageName(language)
                        << " on " << GpuRunner::Renderer(language));
            const std::vector<float> cpu = ApplyCpu(c.processor, image, kWidth, kHeight);
            std::vector<float> gpu;
            try
            {
                gpu = GpuRunner::Run(c.processor->getDefaultGPUProcessor(), language, image, kWidth,
                                     kHeight);
            }
            catch (const std::exception& e)
            {
                FAIL_CHECK(e.what());
                continue;
            }
            const Tolerance tol = ToleranceOf(c.kind);
            const Difference d = Compare(image, cpu, gpu, tol);
            report.add(c.kind, language, d);
            INFO("worst: " << d.worst);
            CHECK(d.pass);
        }
    }
}

}  // namespace

TEST_CASE("Every transform of the default package config compiles and runs on the GPU", "[gpu]")
{
    Report report;
    Clock::time_point t = Clock::now();
    const std::vector<Case> cases = ConfigCases(PackageConfig());
    // 120 looks, 120 named transforms, the colour spaces both ways, 2 views.
    REQUIRE(cases.size() > 240);
    report.time("config", t);
    t = Clock::now();
    CheckShadersCompile(cases);
    report.time("shaders", t);
    t = Clock::now();
    CheckGpuMatchesCpu(cases, report);
    report.time("GPU runs", t);
    report.print("default package config, " + std::to_string(cases.size()) + " transforms");
}

namespace
{
/// Writes the config `options` describe, reads it back from its file (so
/// that the looks' FileTransforms find luts/), and runs every transform's
/// shaders: compiled in every language, run on llvmpipe against the CPU.
/// Returns how many of them are LUTs.
long CheckConfigOnGpu(const ConfigOptions& options, const std::string& name)
{
    Report report;
    Clock::time_point t = Clock::now();
    const TempDir dir(name);
    WriteConfigPackage(BuildConfig(options), dir.path());
    const OCIO::ConstConfigRcPtr config =
        OCIO::Config::CreateFromFile((dir.path() + "/config.ocio").c_str());
    const std::vector<Case> cases = ConfigCases(config);
    report.time("config", t);
    t = Clock::now();
    CheckShadersCompile(cases);
    report.time("shaders", t);
    t = Clock::now();
    CheckGpuMatchesCpu(cases, report);
    report.time("GPU runs", t);
    report.print(name + " config, " + std::to_string(cases.size()) + " transforms");
    return std::count_if(cases.begin(), cases.end(),
                         [](const Case& c) { return c.kind == Kind::LUT; });
}
}  // namespace

TEST_CASE("upsample looks (CLF files of a package) compile and run on the GPU", "[gpu]")
{
    ConfigOptions options;
    options.lights = {L("A"), L("D65")};
    options.methods = {"upsample", "bradford"};
    // upsample A→D65 and D65→A, as looks and as named transforms.
    CHECK(CheckConfigOnGpu(options, "upsample") == 4);
}

TEST_CASE("Looks for lit and balanced plates, rootpoly-camera included, compile and run on the GPU",
          "[gpu]")
{
    // A camera of three Gaussian channels: rootpoly-camera's looks need one.
    std::ostringstream csv;
    csv << "nm,R,G,B\n";
    for (int l = 380; l <= 780; l += 5)
    {
        const auto g = [&](double peak) { return std::exp(-0.5 * std::pow((l - peak) / 32.0, 2)); };
        csv << l << "," << g(605) << "," << g(535) << "," << g(450) << "\n";
    }
    for (const Plates plates : {Plates{PlateConvention::LIT, AdaptationMethod::CAT02},
                                Plates{PlateConvention::BALANCED, AdaptationMethod::BRADFORD}})
    {
        ConfigOptions options;
        options.lights = {L("A"), L("D65")};
        options.methods = {"band3", "rootpoly", "rootpoly-camera"};
        options.plates = plates;
        options.camera =
            std::make_shared<const SpectralCamera>(ReadCameraText(csv.str(), "gaussian.csv"));
        options.lutSize = 33;
        // rootpoly and rootpoly-camera, A→D65 and D65→A, looks and named transforms.
        CHECK(CheckConfigOnGpu(options, "plates_" + plates.key()) == 8);
    }
}

TEST_CASE("LUT files bandlight writes compile and run on the GPU", "[gpu]")
{
    Report report;
    Clock::time_point t = Clock::now();
    const OCIO::ConstTransformRcPtr exact = IlluminantChangeTransform(
        L("A"), L("D65"), ParseMethod("bradford"), FindRgbSpace("acescg"));
    const TempDir dir("luts");
    struct File
    {
        const char* name;
        LutFormat format;
        bool forceLattice;
    };
    std::vector<Case> cases;
    for (const File f : {File{"bradford_matrix.clf", LutFormat::CLF, false},
                         File{"bradford_lattice.clf", LutFormat::CLF, true},
                         File{"bradford.cube", LutFormat::CUBE, false},
                         File{"bradford.spi3d", LutFormat::SPI3D, false},
                         File{"bradford.3dl", LutFormat::THREE_DL, false}})
    {
        LutOptions o;
        o.format = f.format;
        o.size = 33;
        o.forceLattice = f.forceLattice;
        const LutFiles files = WriteLut(exact, true, o, dir.path() + "/" + f.name);
        CHECK(files.lattice == (f.forceLattice || f.format != LutFormat::CLF));
        // The companion shaper (3D-only formats), the LUT, the inverse shaper.
        cases.push_back(MakeCase(std::string("LUT file ") + f.name,
                                 OCIO::Config::CreateRaw()->getProcessor(ReadLutFiles(files))));
    }
    CHECK(cases[0].kind == Kind::MATRIX);
    for (size_t i = 1; i < cases.size(); ++i)
    {
        CHECK(cases[i].kind == Kind::LUT);
    }
    report.time("files", t);
    t = Clock::now();
    CheckShadersCompile(cases);
    report.time("shaders", t);
    t = Clock::now();
    CheckGpuMatchesCpu(cases, report);
    report.time("GPU runs", t);
    report.print("LUT files");
}

TEST_CASE("Hard pixels come out finite on the GPU and as on the CPU", "[gpu]")
{
    Report report;
    const Clock::time_point t = Clock::now();
    const OCIO::ConstConfigRcPtr& config = PackageConfig();
    const std::string linear = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName();
    OCIO::LookTransformRcPtr look = OCIO::LookTransform::Create();
    look->setSrc(linear.c_str());
    look->setDst(linear.c_str());
    look->setLooks("bradford_A_to_D65");
    const std::vector<Case> cases = {
        MakeCase("look bradford_A_to_D65", config->getProcessor(look)),
        MakeCase("named transform relight_band3_A_to_D65",
                 config->getProcessor(config->getNamedTransform("relight_band3_A_to_D65")
                                          ->getTransform(OCIO::TRANSFORM_DIR_FORWARD)))};

    // NaN, ±Inf, negatives, a denormal, zero, 65504, 1e6, 1e30: one row.
    const std::vector<HardPixel>& hard = HardPixels();
    const int width = int(hard.size());
    std::vector<float> image;
    std::vector<bool> denormal;
    for (const HardPixel& p : hard)
    {
        image.insert(image.end(), {p.rgb.x(), p.rgb.y(), p.rgb.z(), 1.0f});
        denormal.push_back(p.denormal);
    }
    CheckShadersCompile(cases);
    for (OCIO::GpuLanguage language : RunLanguages())
    {
        if (!GpuFor(language))
        {
            continue;
        }
        for (const Case& c : cases)
        {
            const std::vector<float> cpu = ApplyCpu(c.processor, image, width, 1);
            std::vector<float> gpu;
            INFO(c.name << " in " << GpuLanguageName(language));
            REQUIRE_NOTHROW(gpu = GpuRunner::Run(c.processor->getDefaultGPUProcessor(), language,
                                                 image, width, 1));
            for (size_t i = 0; i < hard.size(); ++i)
            {
                INFO(hard[i].label << ": cpu (" << cpu[i * 4] << ", " << cpu[i * 4 + 1] << ", "
                                   << cpu[i * 4 + 2] << ") gpu (" << gpu[i * 4] << ", "
                                   << gpu[i * 4 + 1] << ", " << gpu[i * 4 + 2] << ")");
                CHECK(std::isfinite(gpu[i * 4]));
                CHECK(std::isfinite(gpu[i * 4 + 1]));
                CHECK(std::isfinite(gpu[i * 4 + 2]));
            }
            // NaN: OCIO's clamp is max(lower, x) then min(upper, x); GLSL
            // leaves max/min of a NaN undefined, and llvmpipe returns the
            // other operand, so NaN becomes −1e16 as on the CPU (a GPU that
            // returned the NaN would fail the finiteness checks above).
            // ±Inf and 1e30 become ±1e16 on both. Denormals: a GPU may flush
            // them to zero (llvmpipe does), so zero is accepted for them.
            // Everything else must agree to 1e-5 of the pixel; measured: 0,
            // bit for bit, in every language.
            const Difference d = Compare(image, cpu, gpu, ToleranceOf(Kind::MATRIX), &denormal);
            report.add(c.kind, language, d);
            INFO("worst: " << d.worst);
            CHECK(d.pass);
        }
    }
    report.time("all", t);
    report.print("hard pixels");
}

TEST_CASE("The checks catch the literal OCIO 2.1 writes for a 1e30 clamp", "[gpu]")
{
    // Why PIXEL_GUARD is 1e16: OCIO 2.1 prints a RangeTransform's bounds as
    // "%.17g" and appends "." to whole numbers, so ±1e30 became "1e+30.", a
    // syntax error in every shading language. This is the bug the suite
    // exists to catch: the validator and the GPU must both reject it.
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    OCIO::RangeTransformRcPtr range = OCIO::RangeTransform::Create();
    range->setStyle(OCIO::RANGE_CLAMP);
    range->setMinInValue(-1e30);
    range->setMinOutValue(-1e30);
    range->setMaxInValue(1e30);
    range->setMaxOutValue(1e30);
    g->appendTransform(range);
    g->appendTransform(MakeMatrixTransform(Mat3::Identity() * 2.0));
    const OCIO::ConstGPUProcessorRcPtr gpu =
        OCIO::Config::CreateRaw()->getProcessor(g)->getDefaultGPUProcessor();
    for (OCIO::GpuLanguage language : ValidatedLanguages())
    {
        INFO(GpuLanguageName(language));
        const GpuShader shader = GpuRunner::Extract(gpu, language);
        if (shader.ocioText.find("1e+30.") == std::string::npos)
        {
            WARN("OCIO no longer writes '1e+30.' in " << GpuLanguageName(language)
                                                      << ": PIXEL_GUARD's limit may be lifted");
            continue;
        }
        if (GpuRunner::HasValidator())
        {
            CHECK_FALSE(GpuRunner::Compile(shader.fragmentText, language).empty());
        }
        if (IsRunnable(language) && GpuFor(language))
        {
            const std::vector<float> pixel = {0.5f, 0.5f, 0.5f, 1.0f};
            CHECK_THROWS_WITH(GpuRunner::Run(gpu, language, pixel, 1, 1),
                              Catch::Matchers::Contains("does not compile on the GPU"));
        }
    }
}
