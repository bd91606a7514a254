// SPDX-License-Identifier: BSD-3-Clause
// Every transform bandlight emits, as OpenColorIO 2.1 writes it for the GPU:
// the shader compiles in every language OCIO offers that a Debian compiler
// exists for, and on Mesa's llvmpipe it computes what OCIO's CPU processor
// computes.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>

#include "gpu/GpuChecks.h"
#include "jobs/WallJob.h"
#include "luts/LutWriter.h"
#include "plugin/WallConfig.h"
#include "robustness/HardValues.h"
#include "spectral/CameraFile.h"
#include "spectral/Illuminants.h"
#include "transforms/Idt.h"

using namespace bandlight;
using namespace bandlight::test;

TEST_CASE("Every transform of the default package config compiles and runs on the GPU", "[gpu]")
{
    Report report;
    const Clock::time_point t = Clock::now();
    const std::vector<Case> cases = ConfigCases(PackageConfig());
    // 120 looks, 120 named transforms, the colour spaces both ways, 2 views.
    REQUIRE(cases.size() > 240);
    report.time("config", t);
    CheckCasesOnGpu(cases, "default package config", report);
}

TEST_CASE("upsample looks (CLF files of a package) compile and run on the GPU", "[gpu]")
{
    ConfigOptions options;
    options.lights = {L("A"), L("D65")};
    options.methods = {"upsample", "bradford"};
    // upsample A→D65 and D65→A, as looks and as named transforms.
    CHECK(CheckConfigOnGpu(options, "upsample") == 4);
}

TEST_CASE("hueplane looks (a method in a file of its own) compile and run on the GPU", "[gpu]")
{
    ConfigOptions options;
    options.lights = {L("A"), L("D65")};
    options.methods = {"hueplane", "bradford"};
    // hueplane A→D65 and D65→A, as looks and as named transforms.
    CHECK(CheckConfigOnGpu(options, "hueplane") == 4);
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

TEST_CASE("Camera input colour spaces (idt --config) compile and run on the GPU", "[gpu][idt]")
{
    // rawtoaces' ARRI D21 (tests/data/rawtoaces), IDTs for A and D55.
    const SpectralCamera camera(
        ReadCameraFile(BANDLIGHT_TEST_DATA_ROOT "/rawtoaces/arri_d21_380_780_5.json"));
    ConfigOptions options;
    options.workingSpace = "aces2065-1";
    for (const char* light : {"A", "D55"})
    {
        const IdtFit fit = FitIdtOptimal(IdtProblem(camera, BuiltinIlluminant(light),
                                                    FindRgbSpace("aces2065-1"),
                                                    AdaptationMethod::CAT02));
        options.inputSpaces.push_back({std::string("Input - arri d21 - ") + light, "IDT",
                                       fit.rawToWorking(), "aces2065-1"});
    }
    // Matrices only: no LUT among the config's transforms.
    CHECK(CheckConfigOnGpu(options, "idt") == 0);
}

TEST_CASE("An LED wall's config (bandlight wall) compiles and runs on the GPU for each white balance",
          "[gpu][wall]")
{
    // The config `wall` writes for an RGBW wall (Gaussian emitters: R
    // 630/20 nm, G 530/30, B 460/20 (centre / FWHM), W a 450/20 pump plus a
    // 570/110 phosphor at 0.55) and rawtoaces' ARRI D21: drive spaces with
    // the fourth drive in alpha, the IDT and both post-camera looks (3×3
    // and root-polynomial LUT), each reached through ${WALL_WB}.
    const TempDir dir("wall");
    const auto emitter = [&](const std::string& name, const std::vector<std::array<double, 3>>& g)
    {
        const std::string path = dir.path() + "/" + name + ".csv";
        std::ofstream o(path);
        o << "wavelength," << name << "\n";
        for (int l = 380; l <= 780; ++l)
        {
            double v = 0.0;
            for (const auto& [centre, fwhm, peak] : g)
            {
                const double sigma = fwhm / (2.0 * std::sqrt(2.0 * std::log(2.0)));
                v += peak * std::exp(-0.5 * (l - centre) * (l - centre) / (sigma * sigma));
            }
            o << l << "," << v << "\n";
        }
        return path;
    };
    jobs::WallRequest r;
    r.emitters = {{"R", emitter("red", {{630, 20, 1}})},
                  {"G", emitter("green", {{530, 30, 1}})},
                  {"B", emitter("blue", {{460, 20, 1}})},
                  {"W", emitter("white", {{450, 20, 1}, {570, 110, 0.55}})}};
    r.camera = BANDLIGHT_TEST_DATA_ROOT "/rawtoaces/arri_d21_380_780_5.json";
    r.whiteBalances = {"5600K", "3200K"};
    r.contentSpace = "rec709";
    r.out = dir.path() + "/wall";
    const jobs::WallResult result = jobs::MakeWall(r);
    REQUIRE(result.drives == "RGBA");
    const OCIO::ConstConfigRcPtr written =
        OCIO::Config::CreateFromFile((r.out + "/config.ocio").c_str());
    std::vector<std::string> ids;
    for (const char* key : {"5600K", "3200K"})
    {
        INFO("WALL_WB=" << key);
        // As a host that sets the variable would see the config.
        OCIO::ConfigRcPtr config = written->createEditableCopy();
        config->addEnvironmentVar("WALL_WB", key);
        // The drive spaces map content RGB to four drives: one way only
        // (OCIO refuses the inverse of the singular 4×4, as docs/wall.md says).
        CHECK_THROWS_WITH(config->getProcessor(kWallDriveSpace, "ACES2065-1"),
                          Catch::Contains("Singular"));
        const std::vector<Case> cases =
            ConfigCases(config, {kWallDriveSpace, kWallLightingSpace});
        long luts = 0;
        for (const Case& c : cases)
        {
            luts += c.kind == Kind::LUT ? 1 : 0;
            if (c.name == std::string("look ") + kWallPostRootPolyLook)
            {
                ids.push_back(c.processor->getCacheID());
            }
        }
        // The root-polynomial look is a LUT; the drive spaces, the IDT and
        // the 3×3 look are matrices.
        CHECK(luts >= 1);
        Report report;
        CheckCasesOnGpu(cases, std::string("wall WALL_WB=") + key, report);
    }
    // The variable selects different files.
    REQUIRE(ids.size() == 2);
    CHECK(ids[0] != ids[1]);
}
