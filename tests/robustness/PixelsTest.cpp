// SPDX-License-Identifier: BSD-3-Clause
// Hard pixel values through every transform bandlight emits: each method as
// an OCIO transform, each LUT format read back through OCIO. The expected
// results are the ones docs/robustness.md states.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"

#include "cli/RunCommand.h"
#include "robustness/HardValues.h"

using namespace bandlight;
using namespace bandlight::test;

namespace
{

OCIO::ConstCPUProcessorRcPtr Cpu(const OCIO::ConstTransformRcPtr& t)
{
    return OCIO::Config::CreateRaw()->getProcessor(t)->getDefaultCPUProcessor();
}

Vec3 Run(const OCIO::ConstCPUProcessorRcPtr& cpu, const Vec3f& in)
{
    float q[3] = {in[0], in[1], in[2]};
    cpu->applyRGB(q);
    return Vec3(q[0], q[1], q[2]);
}

/// What the guard does to one channel: ±Inf → ±1e30, NaN → −1e30 (OCIO's
/// clamp sends NaN to its lower bound).
double Guard(float v)
{
    if (std::isnan(v))
    {
        return -INFINITY_GUARD;
    }
    return std::clamp(double(v), -INFINITY_GUARD, INFINITY_GUARD);
}

/// What a LUT's shaper does to one channel: clamp to its range, NaN to its minimum.
float ShaperClamp(float v, const ShaperSpec& s)
{
    if (std::isnan(v))
    {
        return float(s.minLinear);
    }
    return float(std::clamp(double(v), s.minLinear, s.maxLinear));
}

bool Close(const Vec3& a, const Vec3& b, double rel)
{
    for (int c = 0; c < 3; ++c)
    {
        const double scale = std::max({std::abs(a[c]), std::abs(b[c]), 1e-30});
        if (!(std::abs(a[c] - b[c]) <= rel * scale + 1e-37))
        {
            return false;
        }
    }
    return true;
}

const Light& A()
{
    static const Light l{"A", BuiltinIlluminant("A")};
    return l;
}
const Light& D65()
{
    static const Light l{"D65", BuiltinIlluminant("D65")};
    return l;
}

}  // namespace

TEST_CASE("Every linear method: guard, then the exact 3x3, no NaN from Inf or finite input",
          "[robustness][pixels]")
{
    const RgbSpace& working = FindRgbSpace("acescg");
    for (const std::string& name : AllMethodNames())
    {
        const MethodSpec method = ParseMethod(name);
        if (!method.isLinear())
        {
            continue;
        }
        const Mat3 m = IlluminantChangeMatrix(A(), D65(), method, working);
        const auto cpu = Cpu(IlluminantChangeTransform(A(), D65(), method, working));
        for (const HardPixel& p : HardPixels())
        {
            INFO(name << ": " << p.label);
            const Vec3 in(Guard(p.rgb[0]), Guard(p.rgb[1]), Guard(p.rgb[2]));
            const Vec3 expected = m * in;
            const Vec3 out = Run(cpu, p.rgb);
            INFO("out " << out.transpose() << " expected " << expected.transpose());
            CHECK(out.allFinite());
            CHECK(Close(out, expected, 2e-6));
            if (p.finite && !p.denormal && p.rgb.cwiseAbs().maxCoeff() < 1e29f)
            {
                // Finite input, HDR included, is not clamped: exactly M·x.
                CHECK(Close(out, m * p.rgb.cast<double>(), 2e-6));
            }
        }
    }
}

TEST_CASE("Denormals and zero through a matrix stay tiny and signed, never NaN",
          "[robustness][pixels]")
{
    const auto cpu =
        Cpu(IlluminantChangeTransform(A(), D65(), ParseMethod("bradford"), FindRgbSpace("acescg")));
    const Vec3 zero = Run(cpu, Vec3f(0.0f, 0.0f, 0.0f));
    CHECK(zero == Vec3::Zero());
    const float tiny = std::numeric_limits<float>::denorm_min() * 1000.0f;
    const Vec3 out = Run(cpu, Vec3f(tiny, tiny, tiny));
    CHECK(out.allFinite());
    CHECK(out.cwiseAbs().maxCoeff() < 1e-40);  // flushed to 0 or kept denormal
}

TEST_CASE("upsample's LUT: shaper clamps the input, NaN to its minimum, output always finite",
          "[robustness][pixels]")
{
    const ShaperSpec shaper = ShaperSpec::ForNonLinear().alignedTo(33);
    const auto cpu =
        Cpu(IlluminantChangeTransform(A(), D65(), ParseMethod("upsample"), FindRgbSpace("acescg")));
    for (const HardPixel& p : HardPixels())
    {
        INFO(p.label);
        const Vec3f clamped(ShaperClamp(p.rgb[0], shaper), ShaperClamp(p.rgb[1], shaper),
                            ShaperClamp(p.rgb[2], shaper));
        const Vec3 out = Run(cpu, p.rgb);
        INFO("out " << out.transpose() << " clamped " << Run(cpu, clamped).transpose());
        CHECK(out.allFinite());
        CHECK(Close(out, Run(cpu, clamped), 1e-5));
    }
    // And the shaper says so, in the transform's own description.
    CHECK_THAT(shaper.describe(), Catch::Contains("is clamped to it, NaN to"));
}

TEST_CASE("Black stays black through every lattice: 0 lies on a node of the aligned shaper",
          "[robustness][pixels][luts]")
{
    for (int size : {17, 33, 65})
    {
        for (const ShaperSpec& s : {ShaperSpec(), ShaperSpec::ForNonLinear()})
        {
            const ShaperSpec a = s.alignedTo(size);
            INFO("size " << size << ", min " << a.minLinear);
            const double node = a.encode(0.0) * (size - 1);
            CHECK(node == Approx(std::round(node)).margin(1e-9));
            CHECK(node >= 1.0);
            CHECK(a.minLinear < 0.0);
            // A nudge of the toe, not a new range: at most a few thousandths.
            CHECK(a.minLinear > -0.005);
            CHECK(a.alignedTo(size).minLinear == Approx(a.minLinear).epsilon(1e-12));
        }
    }
    for (const char* method : {"bradford", "upsample"})
    {
        INFO(method);
        const auto exact =
            IlluminantChangeTransform(A(), D65(), ParseMethod(method), FindRgbSpace("acescg"));
        const auto cpu =
            ParseMethod(method).isLinear()
                ? Cpu(LatticeTransform(OCIO::ConstTransformRcPtr(exact), ShaperSpec(), 33))
                : Cpu(exact);
        const Vec3 black = Run(cpu, Vec3f(0.0f, 0.0f, 0.0f));
        CHECK(black.cwiseAbs().maxCoeff() < 1e-7);
    }
}

TEST_CASE("Every LUT format read back through OCIO: the shaper's clamp, never NaN",
          "[robustness][pixels][luts]")
{
    const auto exact =
        IlluminantChangeTransform(A(), D65(), ParseMethod("bradford"), FindRgbSpace("acescg"));
    for (const char* ext : {"clf", "ctf", "cube", "spi3d", "3dl"})
    {
        LutOptions o;
        o.format = ParseLutFormat(ext);
        o.size = 17;
        o.forceLattice = true;
        const std::string path = TempFile(std::string("hard.") + ext);
        const LutFiles files = WriteLut(exact, true, o, path);
        const auto cpu = Cpu(ReadLutFiles(files));
        for (const HardPixel& p : HardPixels())
        {
            INFO(ext << ": " << p.label);
            const ShaperSpec shaper = o.shaper.alignedTo(o.size);
            const Vec3f clamped(ShaperClamp(p.rgb[0], shaper), ShaperClamp(p.rgb[1], shaper),
                                ShaperClamp(p.rgb[2], shaper));
            const Vec3 out = Run(cpu, p.rgb);
            CHECK(out.allFinite());
            CHECK(Close(out, Run(cpu, clamped), 1e-5));
        }
    }
}

TEST_CASE("A matrix CLF keeps the guard: Inf in, finite out, after a round trip through the file",
          "[robustness][pixels][luts]")
{
    const auto exact =
        IlluminantChangeTransform(A(), D65(), ParseMethod("band3"), FindRgbSpace("acescg"));
    const std::string path = TempFile("guarded.clf");
    LutOptions o;
    WriteLut(exact, true, o, path);
    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
    f->setSrc(path.c_str());
    const auto cpu = Cpu(f);
    const float inf = std::numeric_limits<float>::infinity();
    CHECK(Run(cpu, Vec3f(inf, inf, inf)).allFinite());
    CHECK(Run(cpu, Vec3f(-inf, inf, 0.5f)).allFinite());
}

TEST_CASE("bandlight apply gives the same defined results on a float EXR of hard values",
          "[robustness][pixels][cli]")
{
    const std::vector<HardPixel>& hard = HardPixels();
    const int width = int(hard.size());
    std::vector<float> pixels;
    for (const HardPixel& p : hard)
    {
        pixels.insert(pixels.end(), {p.rgb[0], p.rgb[1], p.rgb[2]});
    }
    const std::string in = TempFile("hard_in.exr");
    WriteFloatImage(in, pixels, width, 1, 3);
    for (const char* method : {"bradford", "band3", "upsample"})
    {
        const std::string out = TempFile(std::string("hard_out_") + method + ".exr");
        const Result r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method " +
                                   method + " --working-space acescg");
        REQUIRE(r.code == 0);
        const std::vector<float> got = ReadFloatImage(out, width, 1, 3);
        // The command's default plates: white-balanced (CAT02).
        MethodSpec spec = ParseMethod(method);
        spec.plates = ParsePlates("balanced", "cat02");
        const auto cpu = Cpu(IlluminantChangeTransform(A(), D65(), spec, FindRgbSpace("acescg")));
        for (int i = 0; i < width; ++i)
        {
            INFO(method << ": " << hard[size_t(i)].label);
            const Vec3 g(got[size_t(3 * i)], got[size_t(3 * i + 1)], got[size_t(3 * i + 2)]);
            CHECK(g.allFinite());
            CHECK(Close(g, Run(cpu, hard[size_t(i)].rgb), 1e-5));
        }
    }
}

TEST_CASE("The direct path (Relighter) matches the OCIO transforms on hard values",
          "[robustness][pixels]")
{
    const RgbSpace& working = FindRgbSpace("acescg");
    for (const std::string& name : AllMethodNames())
    {
        const MethodSpec method = ParseMethod(name);
        const Relighter relighter(A(), D65(), method, working);
        std::vector<float> buffer;
        for (const HardPixel& p : HardPixels())
        {
            buffer.insert(buffer.end(), {p.rgb[0], p.rgb[1], p.rgb[2]});
        }
        relighter.apply(buffer.data(), HardPixels().size(), 1);
        const auto cpu = method.isLinear()
                             ? Cpu(IlluminantChangeTransform(A(), D65(), method, working))
                             : nullptr;
        for (size_t i = 0; i < HardPixels().size(); ++i)
        {
            const HardPixel& p = HardPixels()[i];
            INFO(name << ": " << p.label);
            const Vec3 one = relighter.apply(p.rgb.cast<double>());
            const Vec3 many(buffer[3 * i], buffer[3 * i + 1], buffer[3 * i + 2]);
            CHECK(one.allFinite());
            CHECK(many.allFinite());
            if (cpu)
            {
                CHECK(Close(one, Run(cpu, p.rgb), 2e-6));
            }
        }
    }
}
