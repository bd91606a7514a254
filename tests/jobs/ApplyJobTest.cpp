// SPDX-License-Identifier: BSD-3-Clause
// The apply job (jobs/ApplyJob) run in process, as a C++ host runs it:
// the command's pixels for a change of light, OCIO's for a look of any
// config; light groups relit with the rest of the file kept, every part of a
// multi-part EXR carried, a matte mixing two changes, frame sets.
// Covers, through the entry points it calls: imaging/ImageApply.cpp, imaging/RelightForms.cpp,
// imaging/Mattes.cpp, imageio/ImageFiles.cpp, requests/Apply.cpp, plugin/NativeKernels.cpp.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "jobs/ApplyJob.h"
#include "imaging/ImageApply.h"
#include "requests/Inputs.h"
#include "spectral/Exception.h"
#include "jobs/JobsTestSupport.h"
#include "jobs/LightGroupsTestSupport.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Change;
using test::Exr;
using test::ReadExr;
using test::WriteExr;
namespace fs = std::filesystem;

namespace
{
/// The image module is found beside the bandlight executable; this test
/// program lives elsewhere, so it says where.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

std::vector<float> ReadPixels(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> px(size_t(spec.image_pixels()) * size_t(spec.nchannels));
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

/// A key and a fill group in Arnold's naming, a residual (emission) in the
/// beauty, alpha, a normal AOV and a string attribute: 6x4 pixels.
void WriteArnoldShot(const std::string& path, float fillScale = 1.0f)
{
    const std::vector<std::string> names = {
        "R",          "G",          "B",           "A",           "RGBA_key.R",
        "RGBA_key.G", "RGBA_key.B", "RGBA_fill.R", "RGBA_fill.G", "RGBA_fill.B",
        "N.X",        "N.Y",        "N.Z"};
    const auto key = [](size_t p, size_t c)
    { return 0.2f + 0.05f * float(p % 6) + 0.1f * float(c); };
    const auto fill = [](size_t p, size_t c)
    { return 0.1f + 0.03f * float(p / 6) + 0.05f * float(2 - c); };
    const auto emission = [](size_t p, size_t c) { return p == 7 ? 0.5f + 0.1f * float(c) : 0.0f; };
    WriteExr(path, 6, 4,
             {{names,
               [&](size_t p, size_t c) -> float
               {
                   if (c < 3)
                   {
                       return key(p, c) + fill(p, c) + emission(p, c);
                   }
                   if (c == 3)
                   {
                       return 1.0f;
                   }
                   if (c < 7)
                   {
                       return key(p, c - 4);
                   }
                   if (c < 10)
                   {
                       return fillScale * fill(p, c - 7);
                   }
                   return float(c) * 0.1f - float(p) * 0.01f;
               },
               "",
               {{"studio:shot", "sq010_sh020"}}}});
}
}  // namespace

TEST_CASE("the apply job writes the command's image, and names its parameters", "[jobs]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = test::Fresh("apply");
    fs::create_directories(dir);
    std::vector<float> px(16 * 8 * 4);
    for (size_t i = 0; i < px.size(); ++i)
    {
        px[i] = (i % 4 == 3) ? 1.0f : 0.01f * float(i % 97);
    }
    WriteImage(dir + "/plate.exr", px.data(), 16, 8, 4, {"R", "G", "B", "A"},
               LinearImageDescription(FindRgbSpace("acescg"), "ACEScg"), PixelType::FLOAT);
    jobs::ApplyRequest request;
    request.input = dir + "/plate.exr";
    request.output = dir + "/lib.exr";
    jobs::RelightRequest relight;
    relight.src = jobs::ResolveIlluminant("A");
    relight.dst = jobs::ResolveIlluminant("D65");
    request.relight = relight;
    const jobs::ApplyResult result = jobs::ApplyImages(request);
    CHECK(result.frames == 1);
    CHECK(result.applied == "bradford_A_to_D65");
    REQUIRE(test::Bandlight("apply '" + dir + "/plate.exr' '" + dir + "/cli.exr' --from A --to D65")
                .code == 0);
    const std::vector<float> lib = ReadPixels(dir + "/lib.exr");
    REQUIRE(lib.size() == px.size());
    CHECK(lib == ReadPixels(dir + "/cli.exr"));
    CHECK(lib[3] == 1.0f);     // alpha passes through
    CHECK(lib[40] != px[40]);  // and the colour changed

    jobs::ApplyRequest none;
    none.input = request.input;
    none.output = dir + "/none.exr";
    try
    {
        jobs::ApplyImages(none);
        FAIL("accepted");
    }
    catch (const ParameterError& e)
    {
        CHECK(e.spelled(Face::COMMAND) ==
              "give --look NAME --config DIR, or --from S1 --to S2 [--method M]");
        CHECK(e.spelled(Face::PYTHON) == "give look=NAME config=DIR, or src=S1 dst=S2 [method=M]");
    }
    CHECK_FALSE(fs::exists(none.output));
}

TEST_CASE("apply --look runs a matrix look of any config natively, with OCIO's pixels", "[jobs]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = test::Fresh("apply_look");
    fs::create_directories(dir);
    // A config that is not bandlight's: a look that clamps and grades by a
    // matrix with an offset, the same matrix without the clamp, and an
    // exponent (not a matrix). Only the first is a clamp and a matrix.
    OCIO::ConfigRcPtr config = OCIO::Config::CreateRaw()->createEditableCopy();
    OCIO::RangeTransformRcPtr clamp = OCIO::RangeTransform::Create();
    clamp->setMinInValue(-100.0);
    clamp->setMinOutValue(-100.0);
    clamp->setMaxInValue(1000.0);
    clamp->setMaxOutValue(1000.0);
    OCIO::MatrixTransformRcPtr grade = OCIO::MatrixTransform::Create();
    const double m44[16] = {1.1, 0.05, 0, 0, 0.02, 0.9, 0.01, 0, 0, 0.1, 1.2, 0, 0, 0, 0, 1};
    const double offset[4] = {0.01, -0.02, 0.0, 0.0};
    grade->setMatrix(m44);
    grade->setOffset(offset);
    OCIO::GroupTransformRcPtr clamped = OCIO::GroupTransform::Create();
    clamped->appendTransform(clamp);
    clamped->appendTransform(grade);
    OCIO::LookRcPtr look = OCIO::Look::Create();
    look->setName("grade");
    look->setProcessSpace("raw");
    look->setTransform(clamped);
    config->addLook(look);
    OCIO::LookRcPtr plain = OCIO::Look::Create();
    plain->setName("plain");
    plain->setProcessSpace("raw");
    plain->setTransform(grade);
    config->addLook(plain);
    OCIO::ExponentTransformRcPtr gamma = OCIO::ExponentTransform::Create();
    const double g[4] = {1.2, 1.2, 1.2, 1.0};
    gamma->setValue(g);
    OCIO::LookRcPtr curve = OCIO::Look::Create();
    curve->setName("curve");
    curve->setProcessSpace("raw");
    curve->setTransform(gamma);
    config->addLook(curve);
    config->setRole(OCIO::ROLE_SCENE_LINEAR, "raw");
    {
        std::ofstream f(dir + "/config.ocio");
        config->serialize(f);
    }
    std::vector<float> px(64 * 8 * 4);
    for (size_t i = 0; i < px.size(); ++i)
    {
        px[i] = i % 4 == 3 ? 0.5f : std::exp2(float(int(i % 29) - 14));
    }
    px[0] = std::numeric_limits<float>::quiet_NaN();
    px[5] = std::numeric_limits<float>::infinity();
    WriteImage(dir + "/plate.exr", px.data(), 64, 8, 4, {"R", "G", "B", "A"}, ImageDescription{},
               PixelType::FLOAT);
    for (const std::string name : {"grade", "plain", "curve"})
    {
        jobs::ApplyRequest request;
        request.input = dir + "/plate.exr";
        request.output = dir + "/" + name + ".exr";
        request.look = name;
        request.config = dir;
        const jobs::ApplyResult result = jobs::ApplyImages(request);
        CHECK(result.native == (name == "grade"));
        OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
        t->setSrc("raw");
        t->setDst("raw");
        t->setLooks(name.c_str());
        std::vector<float> want = px;
        OCIO::PackedImageDesc desc(want.data(), 64, 8, 4);
        config->getProcessor(t)->getDefaultCPUProcessor()->apply(desc);
        const std::vector<float> got = ReadPixels(request.output);
        REQUIRE(got.size() == want.size());
        for (size_t i = 0; i < got.size(); ++i)
        {
            INFO(name << " value " << i << ": " << got[i] << " against OCIO's " << want[i]);
            if (std::isnan(want[i]))
            {
                CHECK(std::isnan(got[i]));
            }
            else
            {
                CHECK(got[i] == Approx(want[i]).epsilon(1e-6).margin(1e-30));
            }
        }
    }
}

TEST_CASE(
    "apply with light groups writes relit groups, the beauty as their sum plus the "
    "residual, and keeps the rest of the file",
    "[jobs][lightgroups]")
{
    const std::string dir = test::FreshLightGroupDir("apply");
    const std::string in = dir + "/arnold.exr";
    WriteArnoldShot(in);
    const Exr before = ReadExr(in);

    jobs::ApplyRequest r;
    r.input = in;
    r.output = dir + "/out.exr";
    r.lightGroups = {{"key", Change("A", "D65", "bradford")}};
    const jobs::ApplyResult result = jobs::ApplyImages(r);
    CHECK(result.frames == 1);
    CHECK_THAT(result.applied, Contains("key: bradford_A_to_D65"));
    const Exr after = ReadExr(r.output);
    REQUIRE(after.parts.size() == 1);
    const Exr::Part& a = after[0];
    const Exr::Part& b = before[0];
    CHECK(a.spec.channelnames == b.spec.channelnames);
    CHECK(a.spec.get_string_attribute("studio:shot") == "sq010_sh020");

    // The key relit as the same look relights a plain image.
    const Relighter relighter = Change("A", "D65", "bradford").relighter();
    double maxBeauty = 0.0;
    for (size_t p = 0; p < b.count(); ++p)
    {
        maxBeauty = std::max(maxBeauty, double(b.at(p, "R")));
    }
    for (size_t p = 0; p < b.count(); ++p)
    {
        const Vec3 key = relighter.apply(
            Vec3(b.at(p, "RGBA_key.R"), b.at(p, "RGBA_key.G"), b.at(p, "RGBA_key.B")));
        CHECK(a.at(p, "RGBA_key.R") == Approx(key.x()).epsilon(1e-6));
        CHECK(a.at(p, "RGBA_key.B") == Approx(key.z()).epsilon(1e-6));
        // The fill, alpha and the normals unchanged.
        CHECK(a.at(p, "RGBA_fill.G") == b.at(p, "RGBA_fill.G"));
        CHECK(a.at(p, "A") == b.at(p, "A"));
        CHECK(a.at(p, "N.Y") == b.at(p, "N.Y"));
        // Beauty = Σ groups + the residual as read, to 1e-6 relative.
        for (const char* c : {"R", "G", "B"})
        {
            const std::string cs(c);
            const double residual =
                double(b.at(p, cs)) - b.at(p, "RGBA_key." + cs) - b.at(p, "RGBA_fill." + cs);
            const double sum = double(a.at(p, "RGBA_key." + cs)) + a.at(p, "RGBA_fill." + cs);
            CHECK(std::abs(a.at(p, cs) - (sum + residual)) <= 1e-6 * maxBeauty);
        }
    }
    // The emissive pixel keeps its residual.
    CHECK(b.at(7, "R") - b.at(7, "RGBA_key.R") - b.at(7, "RGBA_fill.R") ==
          Approx(0.5).epsilon(1e-6));

    SECTION("identity relight of every group reproduces the beauty")
    {
        for (const std::string method : {"bradford", "rootpoly", "band3"})
        {
            INFO(method);
            jobs::ApplyRequest same = r;
            same.output = dir + "/same_" + method + ".exr";
            same.lightGroups = {{"key", Change("A", "A", method)},
                                {"fill", Change("F11", "F11", method)}};
            jobs::ApplyImages(same);
            const Exr::Part s = ReadExr(same.output)[0];
            for (size_t p = 0; p < b.count(); ++p)
            {
                for (const char* c : {"R", "G", "B"})
                {
                    CHECK(std::abs(s.at(p, c) - b.at(p, c)) <= 1e-6 * maxBeauty);
                }
            }
        }
    }
    SECTION("bad input: one line naming the group or file, nothing written")
    {
        jobs::ApplyRequest bad = r;
        bad.output = dir + "/bad.exr";
        bad.lightGroups = {{"rim", Change("A", "D65", "bradford")}};
        CHECK_THROWS_WITH(jobs::ApplyImages(bad),
                          Contains("arnold.exr: has no light group 'rim' (it has fill, key)"));
        const std::string over = dir + "/over.exr";
        WriteArnoldShot(over, 2.0f);
        bad.input = over;
        bad.lightGroups = {{"key", Change("A", "D65", "bradford")}};
        CHECK_THROWS_WITH(jobs::ApplyImages(bad), Contains("sum to more than the beauty"));
        bad.input = in;
        bad.lightGroupLayers = {{"rim", "RGBA_key"}};
        CHECK_THROWS_WITH(jobs::ApplyImages(bad),
                          Contains("light groups 'key' and 'rim' resolve to the same channel"));
        CHECK_FALSE(fs::exists(bad.output));
    }
}

TEST_CASE("apply carries every part of a multi-part EXR", "[jobs][lightgroups][multipart]")
{
    const std::string dir = test::FreshLightGroupDir("multipart");
    const std::string in = dir + "/stereo.exr";
    const auto grey = [](size_t p, size_t c) { return 0.1f * float(p % 5) + 0.02f * float(c); };
    WriteExr(in, 5, 3,
             {{{"R", "G", "B", "A"}, grey, "left", {{"view", "left"}}},
              {{"R", "G", "B"}, grey, "right", {{"view", "right"}}},
              {{"Z"}, [](size_t p, size_t) { return 10.0f + float(p); }, "depth", {}}});
    jobs::ApplyRequest r;
    r.input = in;
    r.output = dir + "/out.exr";
    r.relight = Change("A", "D65", "bradford");
    jobs::ApplyImages(r);
    const Exr out = ReadExr(r.output);
    REQUIRE(out.parts.size() == 3);
    const Relighter relighter = Change("A", "D65", "bradford").relighter();
    for (size_t part : {0, 1})
    {
        for (size_t p = 0; p < 15; ++p)
        {
            const Vec3 v = relighter.apply(Vec3(grey(p, 0), grey(p, 1), grey(p, 2)));
            CHECK(out[part].at(p, "G") == Approx(v.y()).epsilon(1e-6).margin(1e-7));
        }
    }
    CHECK(out[1].spec.get_string_attribute("view") == "right");
    CHECK(out[0].at(3, "A") == grey(3, 3));
    for (size_t p = 0; p < 15; ++p)
    {
        CHECK(out[2].at(p, "Z") == 10.0f + float(p));
    }
    // A format of one image would lose parts: refused naming them.
    jobs::ApplyRequest png = r;
    png.output = dir + "/out.hdr";
    CHECK_THROWS_WITH(jobs::ApplyImages(png),
                      Contains("this format holds one image, and " + in +
                               " has 3 parts: part 1 ('right'), part 2 ('depth') would be lost"));
    CHECK_FALSE(fs::exists(png.output));
}

TEST_CASE("A matte mixes two changes of light: m inside, 1 - m outside",
          "[jobs][lightgroups][matte]")
{
    const std::string dir = test::FreshLightGroupDir("matte");
    const std::string plate = dir + "/plate.exr";
    const auto colour = [](size_t p, size_t c)
    { return 0.1f + 0.02f * float(p) + 0.1f * float(c); };
    WriteExr(
        plate, 6, 4,
        {{{"R", "G", "B", "A"}, [&](size_t p, size_t c) { return c == 3 ? 1.0f : colour(p, c); }}});
    // A ramp from 0 to 1 across, with one value past 1 (taken as 1).
    const auto m = [](size_t p) { return std::min(1.0f, float(p % 6) / 5.0f); };
    WriteExr(dir + "/matte.exr", 6, 4, {{{"Y", "window"}, [&](size_t p, size_t c) {
                                             return c == 1 ? (p % 6 == 5 ? 1.5f : m(p)) : 0.0f;
                                         }}});
    jobs::ApplyRequest r;
    r.input = plate;
    r.output = dir + "/out.exr";
    r.matte = dir + "/matte.exr:window";
    r.insideRelight = Change("D65", "A", "bradford");
    r.outsideRelight = Change("A", "D65", "bradford");
    const jobs::ApplyResult result = jobs::ApplyImages(r);
    CHECK_THAT(result.applied, Contains("matte.exr:window (inside: bradford_D65_to_A"));
    const Exr::Part out = ReadExr(r.output)[0];
    const Relighter inside = Change("D65", "A", "bradford").relighter();
    const Relighter outside = Change("A", "D65", "bradford").relighter();
    for (size_t p = 0; p < 24; ++p)
    {
        const Vec3 v(colour(p, 0), colour(p, 1), colour(p, 2));
        const Vec3 expected =
            double(m(p)) * inside.apply(v) + (1.0 - double(m(p))) * outside.apply(v);
        CHECK(out.at(p, "R") == Approx(expected.x()).epsilon(1e-5));
        CHECK(out.at(p, "B") == Approx(expected.z()).epsilon(1e-5));
        CHECK(out.at(p, "A") == 1.0f);
    }
    // A matte of another size, and a channel it does not have, are refused.
    WriteExr(dir + "/small.exr", 5, 4, {{{"A"}, [](size_t, size_t) { return 1.0f; }}});
    jobs::ApplyRequest bad = r;
    bad.output = dir + "/bad.exr";
    bad.matte = dir + "/small.exr";
    CHECK_THROWS_WITH(jobs::ApplyImages(bad),
                      Contains("small.exr: the matte's data window is 5x4 at "
                               "(0, 0), " +
                               plate + "'s 6x4 at (0, 0)"));
    bad.matte = dir + "/matte.exr:door";
    CHECK_THROWS_WITH(jobs::ApplyImages(bad), Contains("the matte has no channel 'door'"));
    CHECK_FALSE(fs::exists(bad.output));
}

TEST_CASE("A matte with two looks of a config is the mix of the config's own processors",
          "[jobs][lightgroups][matte]")
{
    const std::string dir = test::FreshLightGroupDir("matte_looks");
    const std::string plate = dir + "/plate.exr";
    // Values past 1 reach the rootpoly look's shaper range, as a bright
    // window does.
    const auto colour = [](size_t p, size_t c)
    { return 0.05f + 0.09f * float(p) + 0.2f * float(c); };
    WriteExr(
        plate, 6, 4,
        {{{"R", "G", "B", "A"}, [&](size_t p, size_t c) { return c == 3 ? 1.0f : colour(p, c); }}});
    const auto m = [](size_t p) { return float(p % 6) / 5.0f; };
    WriteExr(dir + "/matte.exr", 6, 4, {{{"A"}, [&](size_t p, size_t) { return m(p); }}});
    const std::string cfg = dir + "/cfg";
    REQUIRE(test::Bandlight("config --out '" + cfg +
                            "' --illuminants A,D65,F11 --methods rootpoly,bradford")
                .code == 0);
    const std::string apply = "apply '" + plate + "' '" + dir + "/%s.exr' --config '" + cfg +
                              "' --matte '" + dir + "/matte.exr' ";
    const auto run = [&](const std::string& out, const std::string& sides)
    {
        std::string args = apply;
        args.replace(args.find("%s"), 2, out);
        const test::Result r = test::Bandlight(args + sides);
        INFO(r.err);
        REQUIRE(r.code == 0);
        return ReadExr(dir + "/" + out + ".exr")[0];
    };
    const Exr::Part looks =
        run("looks", "--look-inside rootpoly_A_to_D65 --look-outside bradford_F11_to_D65");

    // The looks as OpenColorIO applies them from the written config, in its
    // scene_linear (the plate says nothing, so it is taken as ACEScg, the
    // config's scene_linear: no conversion).
    const OCIO::ConstConfigRcPtr config =
        OCIO::Config::CreateFromFile((cfg + "/config.ocio").c_str());
    const auto byOcio = [&](const std::string& look, size_t p)
    {
        OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
        t->setSrc(OCIO::ROLE_SCENE_LINEAR);
        t->setDst(OCIO::ROLE_SCENE_LINEAR);
        t->setLooks(look.c_str());
        float rgb[3] = {colour(p, 0), colour(p, 1), colour(p, 2)};
        config->getProcessor(t)->getDefaultCPUProcessor()->applyRGB(rgb);
        return std::vector<float>(rgb, rgb + 3);
    };
    const char* channels[3] = {"R", "G", "B"};
    for (size_t p = 0; p < 24; ++p)
    {
        const std::vector<float> in = byOcio("rootpoly_A_to_D65", p);
        const std::vector<float> out = byOcio("bradford_F11_to_D65", p);
        for (int c = 0; c < 3; ++c)
        {
            const double expected =
                double(m(p)) * in[size_t(c)] + (1.0 - double(m(p))) * out[size_t(c)];
            INFO("pixel " << p << " channel " << channels[c]);
            CHECK(looks.at(p, channels[c]) == Approx(expected).margin(1e-6));
        }
        CHECK(looks.at(p, "A") == 1.0f);
    }

    // A look beside a change of light: the change as plain apply makes it.
    const Exr::Part mixed =
        run("mixed", "--look-inside rootpoly_A_to_D65 --look-outside F11:D65 --method bradford");
    const test::Result plain = test::Bandlight("apply '" + plate + "' '" + dir +
                                               "/plain.exr' --from F11 --to D65 --method bradford");
    REQUIRE(plain.code == 0);
    const Exr::Part outside = ReadExr(dir + "/plain.exr")[0];
    for (size_t p = 0; p < 24; ++p)
    {
        const std::vector<float> in = byOcio("rootpoly_A_to_D65", p);
        for (int c = 0; c < 3; ++c)
        {
            const double expected =
                double(m(p)) * in[size_t(c)] + (1.0 - double(m(p))) * outside.at(p, channels[c]);
            INFO("pixel " << p << " channel " << channels[c]);
            CHECK(mixed.at(p, channels[c]) == Approx(expected).margin(1e-6));
        }
    }
}

TEST_CASE("apply --light-group on frame sets: --skip-existing and --keep-going as plain apply",
          "[jobs][lightgroups][frames]")
{
    const std::string dir = test::FreshLightGroupDir("frames");
    WriteArnoldShot(dir + "/shot.1001.exr");
    WriteArnoldShot(dir + "/shot.1002.exr", 2.0f);  // no partition: fails
    WriteArnoldShot(dir + "/shot.1003.exr");
    WriteArnoldShot(dir + "/out.1003.exr");  // already done
    jobs::ApplyRequest r;
    r.input = dir + "/shot.####.exr";
    r.output = dir + "/out.####.exr";
    r.frames = "1001-1003";
    r.skipExisting = true;
    r.keepGoing = true;
    r.lightGroups = {{"key", Change("A", "D65", "bradford")}};
    const jobs::ApplyResult result = jobs::ApplyImages(r);
    CHECK(result.sequence);
    CHECK(result.frames == 1);
    CHECK(result.skipped == 1);
    REQUIRE(result.failed.size() == 1);
    CHECK(result.failed[0].frame == 1002);
    CHECK_THAT(result.failed[0].error, Contains("sum to more than the beauty"));
    CHECK(fs::is_regular_file(dir + "/out.1001.exr"));
    CHECK_FALSE(fs::exists(dir + "/out.1002.exr"));
    // The skipped frame is the file that was there.
    CHECK(ReadExr(dir + "/out.1003.exr")[0].at(0, "RGBA_key.R") ==
          ReadExr(dir + "/shot.1003.exr")[0].at(0, "RGBA_key.R"));
    CHECK(ReadExr(dir + "/out.1001.exr")[0].at(0, "RGBA_key.R") !=
          ReadExr(dir + "/shot.1001.exr")[0].at(0, "RGBA_key.R"));
}
