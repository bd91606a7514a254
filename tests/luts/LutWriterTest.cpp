// SPDX-License-Identifier: BSD-3-Clause
// Covers, through the entry points it calls: luts/Shaper.cpp.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>

#include <catch2/catch.hpp>

#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
std::string Temp(const std::string& name)
{
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir ? dir : "/tmp") + "/bandlight_lut_test_" + name;
}

OCIO::GroupTransformRcPtr Relight(const char* from, const char* to, const char* method)
{
    return IlluminantChangeTransform({from, BuiltinIlluminant(from)}, {to, BuiltinIlluminant(to)},
                                     ParseMethod(method), FindRgbSpace("acescg"));
}

OCIO::ConstCPUProcessorRcPtr Cpu(const OCIO::ConstTransformRcPtr& t)
{
    return OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
}

OCIO::ConstCPUProcessorRcPtr FileCpu(const std::string& path)
{
    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
    f->setSrc(path.c_str());
    f->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    return Cpu(f);
}

Vec3 Run(const OCIO::ConstCPUProcessorRcPtr& cpu, const Vec3& v)
{
    float rgb[3] = {float(v.x()), float(v.y()), float(v.z())};
    cpu->applyRGB(rgb);
    return Vec3(rgb[0], rgb[1], rgb[2]);
}

/// Worst relative error max|a - e| / max|e| over a grey ramp 1e-4 … 65504.
double WorstGreyError(const OCIO::ConstCPUProcessorRcPtr& approx,
                      const OCIO::ConstCPUProcessorRcPtr& exact)
{
    double worst = 0.0;
    for (double x = 1e-4; x <= 65504.0; x *= 1.07)
    {
        const Vec3 e = Run(exact, Vec3(x, x, x));
        const Vec3 a = Run(approx, Vec3(x, x, x));
        worst = std::max(worst, (a - e).cwiseAbs().maxCoeff() / e.cwiseAbs().maxCoeff());
    }
    return worst;
}
}  // namespace

TEST_CASE("A CLF of a linear method is its matrix and loads back through OCIO", "[luts]")
{
    for (LutFormat format : {LutFormat::CLF, LutFormat::CTF})
    {
        const auto exact = Relight("A", "D65", "bradford");
        const std::string path = Temp(std::string("bradford.") + LutExtension(format));
        LutOptions o;
        o.format = format;
        const LutFiles files = WriteLut(exact, true, o, path);
        CHECK_FALSE(files.lattice);
        const Mat3 a = MeasureMatrix(OCIO::Config::CreateRaw()->getProcessor(exact));
        OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
        f->setSrc(path.c_str());
        const Mat3 b = MeasureMatrix(OCIO::Config::CreateRaw()->getProcessor(f));
        CHECK((a - b).cwiseAbs().maxCoeff() < 1e-6);
        std::ifstream in(path);
        std::string text((std::istreambuf_iterator<char>(in)), {});
        CHECK_THAT(text, Contains("<Matrix"));
        CHECK_THAT(text, Contains("Relight from A to D65"));
    }
}

TEST_CASE("A 33^3 LUT with the log2 shaper reproduces HDR greys within 2e-3", "[luts]")
{
    for (const char* method : {"bradford", "band3", "band3-wp"})
    {
        for (const auto& [from, to] : {std::pair{"A", "D65"}, std::pair{"F11", "D65"}})
        {
            const auto exact = Relight(from, to, method);
            LutOptions o;
            o.forceLattice = true;
            // A path per case: OCIO caches files by path.
            const std::string path = Temp(std::string("lattice_") + method + "_" + from + ".clf");
            WriteLut(exact, true, o, path);
            const double worst = WorstGreyError(FileCpu(path), Cpu(exact));
            INFO(method << " " << from << " → " << to << ": worst grey error " << worst);
            CHECK(worst < 2e-3);
        }
    }
}

TEST_CASE("Small negatives survive the shaper LUT", "[luts]")
{
    const auto exact = Relight("A", "D65", "band3");
    const auto lattice = Cpu(LatticeTransform(exact, ShaperSpec(), 33));
    const auto cpu = Cpu(exact);
    std::mt19937 rng(7);
    // Negative and tiny values down to the shaper's floor come through with a
    // defined, close result (not clamped to zero, never NaN).
    std::uniform_real_distribution<double> u(-0.0005, 3e-5);
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i)
    {
        const Vec3 v(u(rng), u(rng), u(rng));
        const Vec3 e = Run(cpu, v);
        if (e.minCoeff() > -0.0005)  // inside the LUT's range
        {
            const Vec3 a = Run(lattice, v);
            REQUIRE(a.allFinite());
            worst = std::max(worst, (a - e).cwiseAbs().maxCoeff());
        }
    }
    INFO("worst absolute error " << worst);
    CHECK(worst < 5e-5);  // cells that straddle the shaper's break at 3e-5
}

TEST_CASE("cube, spi3d and 3dl load back through OCIO and match the lattice", "[luts]")
{
    const auto exact = Relight("F11", "D65", "band3");
    const ShaperSpec shaper;
    const auto cpu = Cpu(exact);
    struct Case
    {
        LutFormat format;
        double tolerance;  // relative, from each format's number precision
    };
    // cube prints 6 decimals and spi3d 9 significant digits of the encoded
    // value; Flame 3dl holds 12-bit integers: 1/4095 of the shaper's 57-stop
    // range is 0.014 stop (1 %) per code value.
    for (const Case c : {Case{LutFormat::CUBE, 2e-3}, Case{LutFormat::SPI3D, 2e-3},
                         Case{LutFormat::THREE_DL, 5e-2}})
    {
        const std::string path = Temp(std::string("lut.") + LutExtension(c.format));
        LutOptions o;
        o.format = c.format;
        o.size = 33;
        const LutFiles files = WriteLut(exact, true, o, path);
        REQUIRE(files.lattice);
        REQUIRE_FALSE(files.shaper.empty());
        // The companion shaper, then the LUT, then the inverse shaper.
        const auto loaded = Cpu(ReadLutFiles(files));
        double worst = 0.0;
        for (double x = 0.02; x <= 60000.0; x *= 1.5)
        {
            const Vec3 e = Run(cpu, Vec3(x, x, x));
            worst = std::max(worst, (Run(loaded, Vec3(x, x, x)) - e).cwiseAbs().maxCoeff() /
                                        e.cwiseAbs().maxCoeff());
        }
        INFO(LutExtension(c.format) << ": worst grey error " << worst);
        CHECK(worst < c.tolerance);
    }
}

TEST_CASE("Hosts' formats: resolve_cube, csp and houdini for [0, 1] data", "[luts]")
{
    const auto exact = Relight("A", "D65", "bradford");
    const auto cpu = Cpu(exact);
    ShaperSpec none;
    none.kind = ShaperSpec::Kind::NONE;
    // resolve_cube and csp print 6 decimals, houdini too: 33 points a side
    // interpolate a 3x3 exactly inside the cube (tetrahedral), so only the
    // printing is left. Values stay inside [0, 1] for the comparison.
    for (const LutFormat f : {LutFormat::RESOLVE_CUBE, LutFormat::CINESPACE, LutFormat::HOUDINI})
    {
        const std::string path = Temp(std::string("hostlut.") + LutExtension(f));
        LutOptions o;
        o.format = f;
        o.shaper = none;
        const LutFiles files = WriteLut(exact, true, o, path);
        REQUIRE(files.shaper.empty());
        const auto loaded = Cpu(ReadLutFiles(files));
        double worst = 0.0;
        for (const Vec3& v : {Vec3(0.18, 0.18, 0.18), Vec3(0.5, 0.3, 0.2), Vec3(0.1, 0.4, 0.6),
                              Vec3(0.02, 0.02, 0.05), Vec3(0.6, 0.55, 0.5)})
        {
            worst = std::max(worst, (Run(loaded, v) - Run(cpu, v)).cwiseAbs().maxCoeff());
        }
        INFO(LutExtension(f) << ": worst absolute error " << worst);
        CHECK(worst < 2e-6);
        // A log shaper cannot be carried by these files' pre-LUT: refused.
        o.shaper = ShaperSpec();
        CHECK_THROWS_WITH(WriteLut(exact, true, o, path),
                          Contains("samples too coarsely for scene-linear HDR"));
    }
}

TEST_CASE("The shaper's curve is continuous and invertible", "[luts]")
{
    const ShaperSpec s;
    CHECK(s.encode(s.minLinear) == Approx(0.0).margin(1e-12));
    CHECK(s.encode(s.maxLinear) == Approx(1.0).epsilon(1e-12));
    CHECK(s.encode(s.breakLinear * (1 + 1e-9)) == Approx(s.encode(s.breakLinear * (1 - 1e-9))));
    for (double x : {-0.01, -0.001, 0.0, 1e-4, 0.015625, 0.18, 1.0, 100.0, 65504.0})
    {
        CHECK(s.decode(s.encode(x)) == Approx(x).epsilon(1e-12).margin(1e-15));
    }
    // The OCIO transform is the same curve.
    const auto cpu = Cpu(s.transform());
    for (double x : {-0.005, 0.001, 0.18, 1000.0})
    {
        CHECK(Run(cpu, Vec3(x, x, x)).x() == Approx(s.encode(x)).epsilon(1e-6));
    }
}

TEST_CASE("LUT errors", "[luts]")
{
    CHECK_THROWS_WITH(ParseLutFormat("icc"), Contains("unknown LUT format 'icc'"));
    CHECK(ParseLutFormat("CUBE") == LutFormat::CUBE);
    CHECK_THROWS_WITH(ShaperSpec::Parse("gamma"), Contains("unknown shaper 'gamma'"));
    CHECK_THROWS_WITH(
        BakeLattice(PixelFunctionOf(Relight("A", "D65", "none")), ShaperSpec(), 1, false),
        Contains("size must be 2 to 129"));
    LutOptions o;
    o.forceLattice = true;
    CHECK_THROWS_WITH(WriteLut(Relight("A", "D65", "none"), true, o, "/nonexistent/dir/x.clf"),
                      Contains("/nonexistent/dir/x.clf: cannot create output file"));
}

TEST_CASE("Every LUT format's entry names a writer OpenColorIO has, its shaper rule and hosts",
          "[luts]")
{
    std::set<std::string> bakerFormats, groupFormats;
    for (int i = 0; i < OCIO::Baker::getNumFormats(); ++i)
    {
        bakerFormats.insert(OCIO::Baker::getFormatNameByIndex(i));
    }
    for (int i = 0; i < OCIO::GroupTransform::GetNumWriteFormats(); ++i)
    {
        groupFormats.insert(OCIO::GroupTransform::GetFormatNameByIndex(i));
    }
    for (const LutFormatEntry& e : LutFormats())
    {
        INFO(e.name);
        CHECK(&FindLutFormat(e.format) == &e);
        CHECK(std::string(e.hosts).size() > 3);
        switch (e.writer)
        {
            case LutWriterKind::BAKER:
                CHECK(bakerFormats.count(e.ocioFormat) == 1);
                break;
            case LutWriterKind::GROUP:
                CHECK(groupFormats.count(e.ocioFormat) == 1);
                // A group carries its own shaper; nothing else does.
                CHECK(e.shaper == LutShaperRule::IN_FILE);
                break;
            case LutWriterKind::OWN_SPI3D:
                CHECK(std::string(e.ocioFormat).empty());
                break;
        }
        if (e.shaper == LutShaperRule::IN_FILE)
        {
            CHECK(e.writer == LutWriterKind::GROUP);
        }
    }
}
