// SPDX-License-Identifier: BSD-3-Clause
// LUTs for log-encoded input (ACEScct, ACEScc): the curves are OCIO's and the
// published ones, and every format's file, read back through OCIO between
// OCIO's own ACEScct (ACEScc) built-in transforms, reproduces the exact
// transform on HDR greys and colours.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

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
    return std::string(dir ? dir : "/tmp") + "/bandlight_lut_encoding_test_" + name;
}

OCIO::ConstCPUProcessorRcPtr Cpu(const OCIO::ConstTransformRcPtr& t)
{
    return OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
}

Vec3 Run(const OCIO::ConstCPUProcessorRcPtr& cpu, const Vec3& v)
{
    float rgb[3] = {float(v.x()), float(v.y()), float(v.z())};
    cpu->applyRGB(rgb);
    return Vec3(rgb[0], rgb[1], rgb[2]);
}

OCIO::BuiltinTransformRcPtr Builtin(const char* style, bool inverse = false)
{
    OCIO::BuiltinTransformRcPtr t = OCIO::BuiltinTransform::Create();
    t->setStyle(style);
    t->setDirection(inverse ? OCIO::TRANSFORM_DIR_INVERSE : OCIO::TRANSFORM_DIR_FORWARD);
    return t;
}

/// ACEScg linear → ACEScct (ACEScc) → the LUT file → ACEScg linear, with
/// OCIO's colour-space built-ins on both sides, as an ACES config's ACEScct
/// colour space applies them (not the curve bandlight baked the LUT with).
OCIO::GroupTransformRcPtr AroundLut(const char* toAces, const std::string& path)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(Builtin("ACEScg_to_ACES2065-1"));
    g->appendTransform(Builtin(toAces, true));
    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
    f->setSrc(path.c_str());
    f->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    g->appendTransform(f);
    g->appendTransform(Builtin(toAces));
    g->appendTransform(Builtin("ACEScg_to_ACES2065-1", true));
    return g;
}

/// Relative error of a pixel: max |a − e| over the channels, divided by the
/// exact pixel's largest |channel|.
double Relative(const Vec3& a, const Vec3& e)
{
    return (a - e).cwiseAbs().maxCoeff() / e.cwiseAbs().maxCoeff();
}

struct Errors
{
    double greys = 0.0;    ///< worst over greys 0.01 … 16
    double colours = 0.0;  ///< worst over colours of level 0.01 … 16
    double coloursMedian = 0.0;
    std::string worst;  ///< the colour of the largest error
};

/// Greys 0.01 … 16 in 1/8 stops, and 4000 colours: channels 0.05 … 1 of a
/// level 0.01 … 16 (log-uniform), a quarter of them saturated (one channel
/// 1, one 0.05, one between). Colours with a channel below `floor`, the
/// linear value of the encoding's 0 where its 3D LUT clamps, are left out
/// (ACEScc's 0.0012; none for ACEScct, whose 0 is below linear 0).
Errors Measure(const OCIO::ConstCPUProcessorRcPtr& approx,
               const OCIO::ConstCPUProcessorRcPtr& exact, double floor)
{
    Errors e;
    for (double x = 0.01; x <= 16.0 * 1.0001; x *= std::exp2(0.125))
    {
        const Vec3 g(x, x, x);
        e.greys = std::max(e.greys, Relative(Run(approx, g), Run(exact, g)));
    }
    std::mt19937 rng(22);
    std::uniform_real_distribution<double> channel(0.05, 1.0);
    std::uniform_real_distribution<double> stops(std::log2(0.01), 4.0);
    std::vector<double> all;
    for (int i = 0; i < 4000; ++i)
    {
        const double level = std::exp2(stops(rng));
        Vec3 c(channel(rng), channel(rng), channel(rng));
        if (i % 4 == 0)
        {
            // A saturated hue: one channel 1, one 0.05, one anywhere between.
            c = Vec3(1.0, 0.05, channel(rng));
            std::shuffle(c.data(), c.data() + 3, rng);
        }
        c *= level / c.maxCoeff();
        if (c.minCoeff() < floor)
        {
            continue;
        }
        all.push_back(Relative(Run(approx, c), Run(exact, c)));
        if (all.back() >= e.colours)
        {
            e.colours = all.back();
            std::ostringstream w;
            w << "(" << c.transpose() << ") -> (" << Run(exact, c).transpose() << "), LUT ("
              << Run(approx, c).transpose() << ")";
            e.worst = w.str();
        }
    }
    std::sort(all.begin(), all.end());
    e.colours = all.back();
    e.coloursMedian = all[all.size() / 2];
    return e;
}

OCIO::GroupTransformRcPtr Relight(const char* from, const char* to, const char* method)
{
    return IlluminantChangeTransform({from, BuiltinIlluminant(from)}, {to, BuiltinIlluminant(to)},
                                     ParseMethod(method), FindRgbSpace("acescg"));
}

std::string Text(const std::string& path)
{
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}
}  // namespace

TEST_CASE("ACEScct and ACEScc are OCIO's built-ins and the published curves", "[luts]")
{
    // Values from the formulas of Academy S-2016-001 and S-2014-003:
    // mid grey 0.18 encodes to (log2 0.18 + 9.72) / 17.52 in both; ACEScct's
    // toe gives 0.0729055341958355 at 0, ACEScc's floor is (9.72 - 16) / 17.52.
    const double grey = (std::log2(0.18) + 9.72) / 17.52;
    CHECK(EncodeLut(LutEncoding::ACESCCT, 0.18) == Approx(grey).epsilon(1e-12));
    CHECK(EncodeLut(LutEncoding::ACESCC, 0.18) == Approx(grey).epsilon(1e-12));
    CHECK(EncodeLut(LutEncoding::ACESCCT, 0.0) == Approx(0.0729055341958355).epsilon(1e-12));
    CHECK(EncodeLut(LutEncoding::ACESCC, 0.0) == Approx((9.72 - 16.0) / 17.52).epsilon(1e-12));
    // ACEScct's two segments meet at 2^-7 (0.155251141552511 encoded).
    CHECK(EncodeLut(LutEncoding::ACESCCT, 0.0078125) == Approx(0.155251141552511).epsilon(1e-9));
    CHECK(DecodeLut(LutEncoding::ACESCCT, 1.0) == Approx(std::exp2(17.52 - 9.72)).epsilon(1e-12));
    for (const LutEncoding e : {LutEncoding::ACESCCT, LutEncoding::ACESCC})
    {
        const auto encode = Cpu(LutEncodingTransform(e));
        // OCIO's colour-space built-ins, ACEScg → ACES2065-1 → ACEScct (ACEScc).
        OCIO::GroupTransformRcPtr viaAces = OCIO::GroupTransform::Create();
        viaAces->appendTransform(Builtin("ACEScg_to_ACES2065-1"));
        viaAces->appendTransform(Builtin(
            e == LutEncoding::ACESCCT ? "ACEScct_to_ACES2065-1" : "ACEScc_to_ACES2065-1", true));
        const auto builtin = Cpu(viaAces);
        for (double x : {-0.005, 1e-5, 0.001, 0.0078125, 0.01, 0.18, 1.0, 16.0, 222.0, 1000.0})
        {
            if (e == LutEncoding::ACESCC && x <= 0.0)
            {
                continue;  // below ACEScc's floor OCIO clamps after its 4096-point LUT
            }
            INFO(LutEncodingName(e) << " at " << x);
            const double published = EncodeLut(e, x);
            // ACEScc is a 4096-point LUT in OCIO 2.1 (inverted on the CPU):
            // 1e-5 of the encoded value; ACEScct is its analytic log op.
            const double tol = e == LutEncoding::ACESCC ? 2e-5 : 2e-6;
            CHECK(Run(encode, Vec3(x, x, x)).x() == Approx(published).margin(tol));
            CHECK(Run(builtin, Vec3(x, x, x)).x() == Approx(published).margin(tol));
            CHECK(DecodeLut(e, published) == Approx(x).epsilon(1e-12).margin(1e-15));
        }
    }
}

TEST_CASE("Log-encoded LUTs in every format reproduce the exact transform through OCIO's ACEScct",
          "[luts]")
{
    struct Case
    {
        LutFormat format;
        bool describes;  ///< OCIO 2.1's writer has a field for the description
    };
    for (const char* method : {"bradford", "band3"})
    {
        const auto exact = Relight("A", "D65", method);
        const auto exactCpu = Cpu(exact);
        for (const LutEncoding encoding : {LutEncoding::ACESCCT, LutEncoding::ACESCC})
        {
            for (const Case c :
                 {Case{LutFormat::RESOLVE_CUBE, true}, Case{LutFormat::CINESPACE, true},
                  Case{LutFormat::HOUDINI, false}, Case{LutFormat::CUBE, true},
                  Case{LutFormat::SPI3D, false}, Case{LutFormat::THREE_DL, false},
                  Case{LutFormat::CLF, true}, Case{LutFormat::CTF, true}})
            {
                LutOptions o;
                o.format = c.format;
                o.encoding = encoding;
                o.size = 33;
                // A path per case: OCIO caches files by path.
                const std::string path =
                    Temp(std::string(method) + "_" + LutEncodingName(encoding) + "_" +
                         std::to_string(int(c.format)) + "." + LutExtension(c.format));
                const LutFiles files = WriteLut(exact, true, o, path);
                REQUIRE(files.lattice);
                CHECK(files.shaper.empty());
                CHECK(files.encoding == encoding);
                const Errors e =
                    Measure(Cpu(AroundLut(encoding == LutEncoding::ACESCCT ? "ACEScct_to_ACES2065-1"
                                                                           : "ACEScc_to_ACES2065-1",
                                          path)),
                            exactCpu, DecodeLut(encoding, 0.0));
                std::cout << "[luts] " << method << " A->D65 33^3 " << LutEncodingName(encoding)
                          << " " << LutExtension(c.format) << " (" << int(c.format)
                          << "): greys 0.01-16 max " << std::setprecision(2) << e.greys
                          << ", colours median " << e.coloursMedian << " max " << e.colours << "\n";
                INFO(method << " " << LutEncodingName(encoding) << " " << path << ": greys "
                            << e.greys << ", colours " << e.colours << " at " << e.worst);
                // Greys are exact in the log segment (the transform is a
                // shift there) but for the files' printed precision: 12-bit
                // 3dl holds 1/4095 of ACEScct's 17.52 stops. Colours carry
                // the lattice's interpolation error (measured 1.8 % bradford,
                // 2.3 % band3; docs/luts.md), and what the encodings cannot
                // hold: 3dl's integers clamp below encoded 0 (linear -0.0069
                // in ACEScct), ACEScc has no negatives at all (band3's
                // saturated yellows give -0.0024 blue).
                const bool integer = c.format == LutFormat::THREE_DL;
                const bool cct = encoding == LutEncoding::ACESCCT;
                CHECK(e.greys < (integer ? 2e-3 : 1e-4));
                CHECK(e.colours < (cct ? (integer ? 7e-2 : 3e-2) : (integer ? 0.12 : 7e-2)));
                if (c.describes)
                {
                    CHECK_THAT(Text(path), Contains(std::string("Input and output: ") +
                                                    LutEncodingTitle(encoding)));
                }
            }
        }
    }
}

TEST_CASE("A log-encoded LUT of a non-linear method bakes the per-pixel transform", "[luts]")
{
    // Pixel functions (upsample, rootpoly) take the same path: here a
    // non-linear function whose exact answer is known.
    const PixelFunction square = [](float* rgb, size_t n)
    {
        for (size_t i = 0; i < 3 * n; ++i)
        {
            rgb[i] = rgb[i] * std::fabs(rgb[i]);
        }
    };
    LutOptions o;
    o.format = LutFormat::RESOLVE_CUBE;
    o.encoding = LutEncoding::ACESCCT;
    o.description = "x times |x|";
    const std::string path = Temp("square.cube");
    WriteLut(square, o, path);
    const auto lut = Cpu(AroundLut("ACEScct_to_ACES2065-1", path));
    // x² is linear in ACEScct's log segment (twice the stops): greys are exact.
    // (0.1's cell reaches outputs in ACEScct's linear toe, below 2^-7.)
    for (double x : {0.18, 1.0, 4.0, 12.0})
    {
        CHECK(Run(lut, Vec3(x, x, x)).x() == Approx(x * x).epsilon(1e-4));
    }
    CHECK_THAT(Text(path), Contains("x times |x| Input and output: ACEScct"));
}

TEST_CASE("LUT encoding errors", "[luts]")
{
    CHECK(ParseLutEncoding("ACEScct") == LutEncoding::ACESCCT);
    CHECK(ParseLutEncoding("linear") == LutEncoding::LINEAR);
    CHECK_THROWS_WITH(ParseLutEncoding("log"),
                      "unknown LUT encoding 'log' (linear, acescct, acescc)");
    try
    {
        ParseLutEncoding("cineon");
        FAIL("no exception");
    }
    catch (const ParameterError& e)
    {
        CHECK(e.spelled(Face::COMMAND) ==
              "unknown LUT --encoding 'cineon' (linear, acescct, acescc)");
    }
}
