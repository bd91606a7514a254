// SPDX-License-Identifier: BSD-3-Clause
// 3D LUT looks on the GPU as hosts upload them: OCIO 2.1's tetrahedral
// shader against its CPU processor on random saturated HDR pixels, with the
// LUT textures filtered GL_LINEAR (OCIO's own apps, Blender) or nearest, as
// float or half-float (Blender's RGB16F) textures, in a fragment and a
// compute shader.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>

#include "gpu/GpuChecks.h"
#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"

using namespace bandlight;
using namespace bandlight::test;

namespace
{
constexpr int kPixelsWide = 200;
constexpr int kPixelsHigh = 100;

/// The pixel and 19,999 random saturated HDR pixels, RGBA: a hexcone hue at saturation
/// 0.7 … 1 (one channel at most 30 % of the largest), brightness 1e-3 … 200
/// log-uniform, alpha 1.
std::vector<float> SaturatedHdrPixels()
{
    std::mt19937 rng(2022);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> saturation(0.7, 1.0);
    std::uniform_real_distribution<double> stops(std::log2(1e-3), std::log2(200.0));
    // First the example: upsample's 33³ look gave G = 21.1 on the
    // CPU and 8.4 on the GPU.
    std::vector<float> px = {109.8f, 34.9f, 180.4f, 1.0f};
    for (int i = 1; i < kPixelsWide * kPixelsHigh; ++i)
    {
        const double h = 6.0 * unit(rng);
        const int sector = int(h) % 6;
        const double f = h - std::floor(h);
        double rgb[3] = {};
        const int full[6] = {0, 1, 1, 2, 2, 0};
        const int zero[6] = {2, 2, 0, 0, 1, 1};
        const int ramp[6] = {1, 0, 2, 1, 0, 2};
        rgb[full[sector]] = 1.0;
        rgb[zero[sector]] = 0.0;
        rgb[ramp[sector]] = sector % 2 == 0 ? f : 1.0 - f;
        const double s = saturation(rng), level = std::exp2(stops(rng));
        for (double& c : rgb)
        {
            c = level * (1.0 - s + s * c);
        }
        px.insert(px.end(), {float(rgb[0]), float(rgb[1]), float(rgb[2]), 1.0f});
    }
    return px;
}

/// GPU against CPU, relative to each pixel's largest |channel| (CPU).
struct Agreement
{
    double max = 0.0;
    double over1Percent = 0.0;  ///< fraction of pixels off by more than 1 %
    std::string worst;
};

Agreement Compare(const std::vector<float>& in, const std::vector<float>& cpu,
                  const std::vector<float>& gpu)
{
    Agreement a;
    long over = 0;
    const size_t n = cpu.size() / 4;
    for (size_t p = 0; p < n; ++p)
    {
        double scale = 0.0, diff = 0.0;
        for (int c = 0; c < 3; ++c)
        {
            scale = std::max(scale, double(std::fabs(cpu[4 * p + c])));
        }
        int worstChannel = 0;
        for (int c = 0; c < 3; ++c)
        {
            const double d = std::fabs(double(gpu[4 * p + c]) - double(cpu[4 * p + c]));
            if (!(d <= diff))
            {
                diff = d;
                worstChannel = c;
            }
        }
        const double rel = std::isfinite(diff) ? diff / scale : HUGE_VAL;
        over += rel > 0.01;
        if (!(rel <= a.max))
        {
            a.max = rel;
            std::ostringstream s;
            s << std::setprecision(6) << "(" << in[4 * p] << ", " << in[4 * p + 1] << ", "
              << in[4 * p + 2] << ") channel " << worstChannel << ": cpu "
              << cpu[4 * p + worstChannel] << " gpu " << gpu[4 * p + worstChannel];
            a.worst = s.str();
        }
    }
    a.over1Percent = double(over) / double(n);
    return a;
}

struct Look
{
    std::string name;
    OCIO::ConstProcessorRcPtr processor;
};

/// The looks users get: upsample A→D65 as a config's look (the method's
/// own LUT), bradford A→D65 as `lut --format cube` bakes it (shaper + 3D
/// LUT), and as `lut --format resolve_cube --encoding acescct` writes it,
/// read back between OCIO's ACEScct built-ins, at `size`.
std::vector<Look> Looks(int size, const std::string& dir)
{
    const OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateRaw();
    const RgbSpace& acescg = FindRgbSpace("acescg");
    const auto bradford =
        IlluminantChangeTransform(L("A"), L("D65"), ParseMethod("bradford"), acescg);
    LutOptions o;
    o.format = LutFormat::RESOLVE_CUBE;
    o.encoding = LutEncoding::ACESCCT;
    o.size = size;
    const std::string cube = dir + "/bradford_acescct_" + std::to_string(size) + ".cube";
    WriteLut(bradford, true, o, cube);
    OCIO::GroupTransformRcPtr aroundCube = OCIO::GroupTransform::Create();
    const auto builtin = [](const char* style, bool inverse)
    {
        OCIO::BuiltinTransformRcPtr t = OCIO::BuiltinTransform::Create();
        t->setStyle(style);
        t->setDirection(inverse ? OCIO::TRANSFORM_DIR_INVERSE : OCIO::TRANSFORM_DIR_FORWARD);
        return t;
    };
    aroundCube->appendTransform(builtin("ACEScg_to_ACES2065-1", false));
    aroundCube->appendTransform(builtin("ACEScct_to_ACES2065-1", true));
    OCIO::FileTransformRcPtr file = OCIO::FileTransform::Create();
    file->setSrc(cube.c_str());
    file->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    aroundCube->appendTransform(file);
    aroundCube->appendTransform(builtin("ACEScct_to_ACES2065-1", false));
    aroundCube->appendTransform(builtin("ACEScg_to_ACES2065-1", true));
    return {
        {"upsample A->D65",
         raw->getProcessor(IlluminantChangeTransform(L("A"), L("D65"), ParseMethod("upsample"),
                                                     acescg, Observer::CIE1931_2DEG, size))},
        {"bradford A->D65 lattice",
         raw->getProcessor(LatticeTransform(
             IlluminantChangeTransform(L("A"), L("D65"), ParseMethod("bradford"), acescg),
             ShaperSpec(), size))},
        {"bradford A->D65 acescct resolve_cube", raw->getProcessor(aroundCube)},
    };
}

/// How many pixels two GPU results differ in (more than 1e-6 of the pixel).
long Differing(const std::vector<float>& a, const std::vector<float>& b)
{
    long n = 0;
    for (size_t p = 0; p < a.size() / 4; ++p)
    {
        double scale = 0.0, diff = 0.0;
        for (int c = 0; c < 3; ++c)
        {
            scale = std::max(scale, double(std::fabs(a[4 * p + c])));
            diff = std::max(diff, double(std::fabs(a[4 * p + c] - b[4 * p + c])));
        }
        n += !(diff <= 1e-6 * scale);
    }
    return n;
}

bool IsShaperLook(const Look& look)
{
    return look.name.find("acescct") == std::string::npos;
}
}  // namespace

TEST_CASE("3D LUT looks on the GPU as hosts upload them", "[gpu][lutprecision]")
{
    // 20,000 random saturated HDR pixels through each look at 33³ and 65³,
    // with the LUT textures as hosts upload them, in a fragment and a compute
    // shader, against OCIO's CPU processor. Measured on llvmpipe (LLVM 15),
    // max relative to the pixel, the same in both shader stages:
    //                              33³ float     65³ float     half-float
    //   shaper looks, nearest      5.1e-6        7.4e-6        9.6e-3
    //   shaper looks, GL_LINEAR    6.8e-2        7.4e-6        9.6e-3 (65³)
    //   acescct file, nearest      1.8e-6        1.8e-6        3.9e-3
    //   acescct file, GL_LINEAR    9.4e-6        1.8e-6        3.9e-3
    // The 33³ GL_LINEAR disagreement is the next test's subject.
    if (!GpuFor(OCIO::GPU_LANGUAGE_GLSL_4_0))
    {
        return;
    }
    const std::vector<float> in = SaturatedHdrPixels();
    for (const int size : {33, 65})
    {
        const TempDir dir("lutprecision");
        for (const Look& look : Looks(size, dir.path()))
        {
            const std::vector<float> cpu = ApplyCpu(look.processor, in, kPixelsWide, kPixelsHigh);
            const OCIO::ConstGPUProcessorRcPtr gpu = look.processor->getDefaultGPUProcessor();
            for (const LutUpload::Filter filter :
                 {LutUpload::Filter::NEAREST, LutUpload::Filter::LINEAR})
            {
                for (const bool half : {false, true})
                {
                    const LutUpload u{filter, half};
                    const std::vector<float> fragment = GpuRunner::Run(
                        gpu, OCIO::GPU_LANGUAGE_GLSL_4_0, in, kPixelsWide, kPixelsHigh, u);
                    const std::vector<float> compute = GpuRunner::RunCompute(gpu, in, u);
                    const Agreement a = Compare(in, cpu, fragment);
                    std::cout << "[gpu] " << look.name << " " << size << "^3, " << Describe(u)
                              << ": max |gpu - cpu| " << std::setprecision(2) << a.max
                              << " of the pixel, " << 100 * a.over1Percent
                              << " % of pixels over 1 %\n";
                    INFO(look.name << " " << size << "^3, " << Describe(u) << ": worst "
                                   << a.worst);
                    // Both stages run the same code on the same textures.
                    CHECK(Differing(fragment, compute) == 0);
                    if (look.name == "upsample A->D65" && size == 33 && !half)
                    {
                        std::cout << "[gpu] the issue's pixel (109.8, 34.9, 180.4), " << Describe(u)
                                  << ": G " << std::setprecision(3) << cpu[1] << " on the CPU, "
                                  << fragment[1] << " on the GPU\n";
                        // Off by 12.7 with GL_LINEAR, as the issue saw.
                        CHECK((std::fabs(fragment[1] - cpu[1]) > 10.0) ==
                              (filter == LutUpload::Filter::LINEAR));
                    }
                    const bool shaper = IsShaperLook(look);
                    if (half)
                    {
                        // RGB16F keeps 11 bits of each node: 2^-12 of an
                        // encoded value spanning the shaper's 57 stops (ACEScct:
                        // 17.5) is about 1 % (0.3 %) of the pixel, at any size.
                        if (!(shaper && size == 33 && filter == LutUpload::Filter::LINEAR))
                        {
                            CHECK(a.max < (shaper ? 1.2e-2 : 5e-3));
                        }
                    }
                    else if (filter == LutUpload::Filter::NEAREST || size == 65 || !shaper)
                    {
                        // The goal, 1e-4 of the pixel: met by every
                        // float upload except GL_LINEAR at 33³ on shaper looks.
                        CHECK(a.max < 1e-4);
                    }
                    else
                    {
                        // The reproduction: 33³ shaper looks filtered
                        // GL_LINEAR are off by up to 7 % (the issue saw 15 %
                        // with another draw of pixels).
                        CHECK(a.max > 1e-2);
                    }
                }
            }
        }
    }
}

TEST_CASE("GL_LINEAR blends a shaper LUT's nodes with neighbours thousands of units away",
          "[gpu][lutprecision]")
{
    // Why 33³ disagrees. OCIO 2.1's tetrahedral GLSL fetches the four nodes
    // of a tetrahedron at texel centres ((index + 0.5) / N) and weighs them
    // itself. With GL_LINEAR the sampler also interpolates, with weight
    // (index + 0.5) / N · N − 0.5 − index: zero in exact arithmetic, about
    // 1e-6 in llvmpipe's float arithmetic for N = 33 (3e-6 measured, and
    // up to 1e-5 for N = 87 … 129) but exactly zero for N = 2 … 9, 16, 17,
    // 32, 64, 65, 128. That is harmless where neighbouring nodes are
    // close, but a shaper LUT's nodes hold shaper-encoded output, and the
    // shaper's linear toe below -0.0005 has slope 830 per unit: a node whose
    // exact output is -5 holds -4150 (bradford's 33³ lattice goes down to
    // -9e6 at its saturated corners). A 1e-6 blend of -4150 moves a
    // neighbour by 4e-3 encoded, 0.2 stop. Here: the pixels that disagree
    // all sit next to such nodes, and the others agree to 1e-4. (ACEScct
    // LUTs hold bounded values, its toe's slope being 10.5: 9.4e-6 at 33³.)
    if (!GpuFor(OCIO::GPU_LANGUAGE_GLSL_4_0))
    {
        return;
    }
    const int size = 33;
    const OCIO::GroupTransformRcPtr look =
        LatticeTransform(IlluminantChangeTransform(L("A"), L("D65"), ParseMethod("bradford"),
                                                   FindRgbSpace("acescg")),
                         ShaperSpec(), size);
    REQUIRE(look->getNumTransforms() == 3);
    const auto lut = OCIO::DynamicPtrCast<OCIO::Lut3DTransform>(look->getTransform(1));
    REQUIRE(lut);
    const OCIO::ConstProcessorRcPtr processor = OCIO::Config::CreateRaw()->getProcessor(look);
    const OCIO::ConstCPUProcessorRcPtr shaper =
        OCIO::Config::CreateRaw()->getProcessor(look->getTransform(0))->getDefaultCPUProcessor();
    float lowest = 0.0f;
    for (int r = 0; r < size; ++r)
    {
        for (int g = 0; g < size; ++g)
        {
            for (int b = 0; b < size; ++b)
            {
                float v[3];
                lut->getValue(r, g, b, v[0], v[1], v[2]);
                lowest = std::min({lowest, v[0], v[1], v[2]});
            }
        }
    }
    CHECK(lowest < -1000.0f);

    const std::vector<float> in = SaturatedHdrPixels();
    const std::vector<float> cpu = ApplyCpu(processor, in, kPixelsWide, kPixelsHigh);
    const std::vector<float> gpu =
        GpuRunner::Run(processor->getDefaultGPUProcessor(), OCIO::GPU_LANGUAGE_GLSL_4_0, in,
                       kPixelsWide, kPixelsHigh, {LutUpload::Filter::LINEAR, false});
    double worstInRange = 0.0;
    long off = 0, offNearFarNodes = 0, inRange = 0;
    for (size_t p = 0; p < in.size() / 4; ++p)
    {
        // The pixel's cell and the nodes GL_LINEAR can blend into its four
        // fetches: one index either side of the cell, per axis.
        float e[3] = {in[4 * p], in[4 * p + 1], in[4 * p + 2]};
        shaper->applyRGB(e);
        int lo[3];
        for (int c = 0; c < 3; ++c)
        {
            lo[c] = std::clamp(int(std::floor(e[c] * float(size - 1))), 0, size - 2);
        }
        bool far = false;
        for (int r = std::max(lo[0] - 1, 0); r <= std::min(lo[0] + 2, size - 1); ++r)
        {
            for (int g = std::max(lo[1] - 1, 0); g <= std::min(lo[1] + 2, size - 1); ++g)
            {
                for (int b = std::max(lo[2] - 1, 0); b <= std::min(lo[2] + 2, size - 1); ++b)
                {
                    float v[3];
                    lut->getValue(r, g, b, v[0], v[1], v[2]);
                    for (const float x : v)
                    {
                        far = far || x < -1.0f || x > 2.0f;
                    }
                }
            }
        }
        double scale = 0.0, diff = 0.0;
        for (int c = 0; c < 3; ++c)
        {
            scale = std::max(scale, double(std::fabs(cpu[4 * p + c])));
            diff = std::max(diff, double(std::fabs(gpu[4 * p + c] - cpu[4 * p + c])));
        }
        const double rel = diff / scale;
        if (rel > 1e-3)
        {
            ++off;
            offNearFarNodes += far;
        }
        if (!far)
        {
            ++inRange;
            worstInRange = std::max(worstInRange, rel);
        }
    }
    std::cout << "[gpu] bradford A->D65 33^3 shaper LUT, GL_LINEAR: lattice down to " << lowest
              << "; " << off << " pixels off by more than 1e-3, " << offNearFarNodes
              << " of them next to nodes outside [-1, 2]; the " << inRange
              << " pixels away from such nodes agree to " << worstInRange << "\n";
    CHECK(off > 0);
    CHECK(offNearFarNodes == off);
    CHECK(inRange > 2000);
    CHECK(worstInRange < 1e-4);
}
