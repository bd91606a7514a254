// SPDX-License-Identifier: BSD-3-Clause
// Light groups: found in every naming, relit per group with the beauty
// rebuilt as Σ groups + residual, the rest of the file (other channels,
// metadata, other parts) kept; spectral groups relit exactly.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "bandlight/jobs/ApplyJob.h"
#include "bandlight/jobs/ImageApply.h"
#include "bandlight/jobs/LightGroupAccuracy.h"
#include "bandlight/jobs/LightGroups.h"
#include "bandlight/jobs/RenderJob.h"
#include "bandlight/jobs/SpectralJob.h"
#include "bandlight/render/SceneColour.h"
#include "bandlight/spectral/Colorimetry.h"
#include "bandlight/spectral/Exception.h"
#include "bandlight/spectral/RgbSpaces.h"
#include "cli/RunCommand.h"

using namespace bandlight;
using namespace bandlight::jobs;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace
{
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

std::string Fresh(const std::string& name)
{
    const std::string dir = test::TempPath("lightgroups_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// An EXR read back through OpenImageIO: every part, channels by name.
struct Exr
{
    struct Part
    {
        OIIO::ImageSpec spec;
        std::vector<float> pixels;
        float at(size_t p, const std::string& channel) const
        {
            const auto c = std::find(spec.channelnames.begin(), spec.channelnames.end(), channel);
            REQUIRE(c != spec.channelnames.end());
            return pixels[p * size_t(spec.nchannels) + size_t(c - spec.channelnames.begin())];
        }
        size_t count() const { return size_t(spec.width) * size_t(spec.height); }
    };
    std::vector<Part> parts;
    const Part& operator[](size_t i) const { return parts.at(i); }
};

Exr ReadExr(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    Exr exr;
    for (int p = 0; in->seek_subimage(p, 0); ++p)
    {
        Exr::Part part;
        part.spec = in->spec();
        part.pixels.resize(part.spec.image_pixels() * size_t(part.spec.nchannels));
        REQUIRE(in->read_image(p, 0, 0, part.spec.nchannels, OIIO::TypeDesc::FLOAT,
                               part.pixels.data()));
        exr.parts.push_back(std::move(part));
    }
    return exr;
}

/// Writes parts (each: channel names and a function of (pixel, channel)).
struct PartSpec
{
    std::vector<std::string> channels;
    std::function<float(size_t, size_t)> value;
    std::string name = "";
    std::map<std::string, std::string> attributes = {};
};

void WriteExr(const std::string& path, int width, int height, const std::vector<PartSpec>& parts)
{
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    std::vector<OIIO::ImageSpec> specs;
    std::vector<std::vector<float>> pixels;
    for (const PartSpec& p : parts)
    {
        OIIO::ImageSpec spec(width, height, int(p.channels.size()), OIIO::TypeDesc::FLOAT);
        spec.channelnames = p.channels;
        spec.alpha_channel = -1;
        if (!p.name.empty())
        {
            spec.attribute("name", p.name);
        }
        for (const auto& [k, v] : p.attributes)
        {
            spec.attribute(k, v);
        }
        specs.push_back(spec);
        std::vector<float> px(size_t(width) * size_t(height) * p.channels.size());
        for (size_t i = 0; i < size_t(width) * size_t(height); ++i)
        {
            for (size_t c = 0; c < p.channels.size(); ++c)
            {
                px[i * p.channels.size() + c] = p.value(i, c);
            }
        }
        pixels.push_back(std::move(px));
    }
    if (specs.size() == 1)
    {
        REQUIRE(out->open(path, specs[0]));
    }
    else
    {
        REQUIRE(out->open(path, int(specs.size()), specs.data()));
    }
    for (size_t p = 0; p < specs.size(); ++p)
    {
        if (p > 0)
        {
            REQUIRE(out->open(path, specs[p], OIIO::ImageOutput::AppendSubimage));
        }
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels[p].data()));
    }
    REQUIRE(out->close());
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

RelightRequest Change(const std::string& from, const std::string& to, const std::string& method,
                      const std::string& plates = "lit")
{
    RelightRequest r;
    r.src = ResolveIlluminant(from);
    r.dst = ResolveIlluminant(to);
    r.method = method;
    r.plates.plates = plates;
    return r;
}

double MaxAbs(const std::vector<float>& v)
{
    double m = 0.0;
    for (const float x : v)
    {
        m = std::max(m, double(std::abs(x)));
    }
    return m;
}

}  // namespace

TEST_CASE("Light groups are found in Blender, Arnold, bandlight and mapped namings",
          "[jobs][lightgroups]")
{
    SECTION("Blender/Cycles with the view-layer prefix")
    {
        const std::vector<std::string> ch = {
            "ViewLayer.Combined.A",      "ViewLayer.Combined.B",      "ViewLayer.Combined.G",
            "ViewLayer.Combined.R",      "ViewLayer.Combined_key.B",  "ViewLayer.Combined_key.G",
            "ViewLayer.Combined_key.R",  "ViewLayer.Combined_fill.B", "ViewLayer.Combined_fill.G",
            "ViewLayer.Combined_fill.R", "ViewLayer.Depth.Z",         "ViewLayer.DiffCol.R",
            "ViewLayer.DiffCol.G",       "ViewLayer.DiffCol.B"};
        const LightGroupLayout l = FindLightGroups("shot.exr", ch, {});
        REQUIRE(l.groups.size() == 2);
        CHECK(l.beautyLayer == "ViewLayer.Combined");
        CHECK(l.beauty[0] == 3);
        CHECK(l.beauty[1] == 2);
        CHECK(l.beauty[2] == 1);
        const LightGroupLayer* key = l.find("key");
        REQUIRE(key);
        CHECK(key->naming == LightGroupNaming::BLENDER);
        CHECK(key->layer == "ViewLayer.Combined_key");
        CHECK(key->rgb[0] == 6);
        CHECK(key->rgb[2] == 4);
        CHECK(l.find("fill"));
        CHECK_FALSE(l.find("DiffCol"));
        CHECK_THAT(l.describe(), Contains("Blender/Cycles naming, beauty ViewLayer.Combined"));
    }
    SECTION("Blender/Cycles without the view-layer prefix")
    {
        const LightGroupLayout l =
            FindLightGroups("shot.exr",
                            {"Combined.R", "Combined.G", "Combined.B", "Combined_sun.R",
                             "Combined_sun.G", "Combined_sun.B"},
                            {});
        REQUIRE(l.groups.size() == 1);
        CHECK(l.groups[0].name == "sun");
        CHECK(l.beautyLayer == "Combined");
    }
    SECTION("Arnold")
    {
        const LightGroupLayout l =
            FindLightGroups("shot.exr",
                            {"R", "G", "B", "A", "RGBA_key.R", "RGBA_key.G", "RGBA_key.B",
                             "diffuse.R", "diffuse.G", "diffuse.B"},
                            {});
        REQUIRE(l.groups.size() == 1);
        CHECK(l.groups[0].name == "key");
        CHECK(l.groups[0].naming == LightGroupNaming::ARNOLD);
        CHECK(l.beautyLayer.empty());
        CHECK(l.beauty[0] == 0);
    }
    SECTION("bandlight's own, listed in its header; other layers are not groups")
    {
        const std::vector<std::string> ch = {"R",      "G",      "B",      "key.R",
                                             "key.G",  "key.B",  "fill.R", "fill.G",
                                             "fill.B", "spec.R", "spec.G", "spec.B"};
        const LightGroupLayout l =
            FindLightGroups("shot.exr", ch, {{LIGHT_GROUPS_ATTRIBUTE, "key,fill"}});
        REQUIRE(l.groups.size() == 2);
        CHECK(l.find("key"));
        CHECK_FALSE(l.find("spec"));
        CHECK_THROWS_WITH(FindLightGroups("shot.exr", ch, {}), Contains("holds no light groups"));
    }
    SECTION("mapped: a layer prefix or three channels")
    {
        const std::vector<std::string> ch = {"R",         "G",  "B",  "lgt_key.R", "lgt_key.G",
                                             "lgt_key.B", "kr", "kg", "kb"};
        const LightGroupLayout l =
            FindLightGroups("shot.exr", ch, {}, {{"key", "lgt_key"}, {"rim", "kr,kg,kb"}});
        REQUIRE(l.groups.size() == 2);
        CHECK(l.find("key")->rgb[0] == 3);
        CHECK(l.find("rim")->rgb[2] == 8);
        CHECK(l.find("rim")->naming == LightGroupNaming::MAPPED);
        CHECK_THROWS_WITH(FindLightGroups("shot.exr", ch, {}, {{"key", "nope"}}),
                          Contains("shot.exr: light group 'key': the image has no layer 'nope'"));
        CHECK_THROWS_WITH(
            FindLightGroups("shot.exr", ch, {}, {{"key", "lgt_key"}, {"fill", "lgt_key"}}),
            Contains("resolve to the same channel"));
        CHECK_THROWS_WITH(FindLightGroups("shot.exr", ch, {}, {{"key", "R,G,B"}}),
                          Contains("beauty's own channel"));
    }
    SECTION("groups without a beauty")
    {
        CHECK_THROWS_WITH(
            FindLightGroups("shot.exr", {"RGBA_key.R", "RGBA_key.G", "RGBA_key.B"}, {}),
            Contains("no beauty they sum to"));
    }
}

TEST_CASE("RelightLightGroups keeps the residual and refuses groups that are no partition",
          "[jobs][lightgroups]")
{
    const LightGroupLayout l = FindLightGroups(
        "x.exr",
        {"R", "G", "B", "RGBA_a.R", "RGBA_a.G", "RGBA_a.B", "RGBA_b.R", "RGBA_b.G", "RGBA_b.B"},
        {});
    // Two pixels: beauty = a + b + residual (0.25, 0, 0.5 in the second).
    std::vector<float> px = {0.6f,  0.5f, 0.4f, 0.4f, 0.3f,  0.2f, 0.2f, 0.2f,  0.2f,
                             1.25f, 0.5f, 1.5f, 0.5f, 0.25f, 0.5f, 0.5f, 0.25f, 0.5f};
    const std::vector<float> in = px;
    const auto twice = [](float* p, long w, long h, int n, const int* rgb)
    {
        for (long i = 0; i < w * h; ++i)
        {
            for (int c = 0; c < 3; ++c)
            {
                p[i * n + rgb[c]] *= 2.0f;
            }
        }
    };
    RelightLightGroups(l, {{"a", twice}}, px.data(), 2, 1, 9, "x.exr");
    // a doubled, b kept, the residual carried: beauty = 2a + b + residual.
    CHECK(px[3] == 0.8f);
    CHECK(px[6] == 0.2f);
    CHECK(px[0] == Approx(1.0).epsilon(1e-7));
    CHECK(px[9] == Approx(2 * 0.5 + 0.5 + 0.25).epsilon(1e-7));
    CHECK(px[11] == Approx(2 * 0.5 + 0.5 + 0.5).epsilon(1e-7));
    CHECK(px[13] == 0.5f);  // group a's G of pixel 2 doubled: 0.25 -> 0.5
    // The identity (no work) gives the input back.
    std::vector<float> same = in;
    RelightLightGroups(l, {}, same.data(), 2, 1, 9, "x.exr");
    for (size_t i = 0; i < in.size(); ++i)
    {
        CHECK(same[i] == Approx(in[i]).epsilon(1e-6));
    }
    // Groups summing past the beauty, and NaN in a group, are refused
    // before anything changes.
    std::vector<float> over = in;
    over[3] = 0.9f;
    CHECK_THROWS_WITH(
        RelightLightGroups(l, {{"a", twice}}, over.data(), 2, 1, 9, "x.exr"),
        Contains("x.exr: the light groups sum to more than the beauty at pixel (0, 0)"));
    CHECK(over[4] == in[4]);
    std::vector<float> nan = in;
    nan[16] = std::nanf("");
    CHECK_THROWS_WITH(RelightLightGroups(l, {{"a", twice}}, nan.data(), 2, 1, 9, "x.exr"),
                      Contains("x.exr: light group 'b' is NaN at pixel (1, 0)"));
}

TEST_CASE(
    "RelightLightGroups relights a frame of many row blocks as pixel by pixel, and names "
    "the first pixel at fault",
    "[jobs][lightgroups]")
{
    const LightGroupLayout l = FindLightGroups(
        "x.exr",
        {"R", "G", "B", "RGBA_a.R", "RGBA_a.G", "RGBA_a.B", "RGBA_b.R", "RGBA_b.G", "RGBA_b.B"},
        {});
    // 7 x 101 pixels: rows in blocks, the last one partial, split over
    // threads within each block.
    const long w = 7, h = 101;
    const size_t count = size_t(w * h);
    std::vector<float> px(9 * count);
    for (size_t p = 0; p < count; ++p)
    {
        for (int c = 0; c < 3; ++c)
        {
            const float a = 0.01f * float(p % 97) + 0.1f * float(c);
            const float b = 0.02f * float(p % 13);
            px[9 * p + 3 + size_t(c)] = a;
            px[9 * p + 6 + size_t(c)] = b;
            px[9 * p + size_t(c)] = a + b + 0.125f;  // a residual of 0.125
        }
    }
    const std::vector<float> in = px;
    // A work that depends on where the pixel is in its buffer would show a
    // block's offset: this one depends on the value alone.
    const auto square = [](float* p, long bw, long bh, int n, const int* rgb)
    {
        for (long i = 0; i < bw * bh; ++i)
        {
            for (int c = 0; c < 3; ++c)
            {
                p[i * n + rgb[c]] *= p[i * n + rgb[c]];
            }
        }
    };
    RelightLightGroups(l, {{"a", square}}, px.data(), w, h, 9, "x.exr");
    for (size_t p = 0; p < count; ++p)
    {
        for (size_t c = 0; c < 3; ++c)
        {
            const double a = in[9 * p + 3 + c], b = in[9 * p + 6 + c];
            const double residual = double(in[9 * p + c]) - (a + b);
            CHECK(px[9 * p + 3 + c] == float(a * a));
            CHECK(px[9 * p + 6 + c] == float(b));
            CHECK(px[9 * p + c] == float(double(float(a * a)) + b + residual));
        }
    }
    // Faults in two places, far apart (other threads, other blocks): the
    // first in reading order is named, and nothing has changed.
    std::vector<float> bad = in;
    bad[9 * (40 * size_t(w) + 3) + 4] = 5.0f;           // (3, 40): a's G past the beauty
    bad[9 * (90 * size_t(w) + 1) + 8] = std::nanf("");  // (1, 90): b's B NaN
    const std::vector<float> before = bad;
    CHECK_THROWS_WITH(
        RelightLightGroups(l, {{"a", square}}, bad.data(), w, h, 9, "x.exr"),
        Contains("x.exr: the light groups sum to more than the beauty at pixel (3, 40)"));
    // Bit for bit (the NaN compares unequal to itself).
    CHECK(std::memcmp(bad.data(), before.data(), bad.size() * sizeof(float)) == 0);
    bad[9 * (40 * size_t(w) + 3) + 4] = in[9 * (40 * size_t(w) + 3) + 4];
    CHECK_THROWS_WITH(RelightLightGroups(l, {{"a", square}}, bad.data(), w, h, 9, "x.exr"),
                      Contains("x.exr: light group 'b' is NaN at pixel (1, 90) (layer RGBA_b)"));
}

TEST_CASE(
    "apply with light groups writes relit groups, the beauty as their sum plus the "
    "residual, and keeps the rest of the file",
    "[jobs][lightgroups]")
{
    const std::string dir = Fresh("apply");
    const std::string in = dir + "/arnold.exr";
    WriteArnoldShot(in);
    const Exr before = ReadExr(in);

    ApplyRequest r;
    r.input = in;
    r.output = dir + "/out.exr";
    r.lightGroups = {{"key", Change("A", "D65", "bradford")}};
    const ApplyResult result = ApplyImages(r);
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
            ApplyRequest same = r;
            same.output = dir + "/same_" + method + ".exr";
            same.lightGroups = {{"key", Change("A", "A", method)},
                                {"fill", Change("F11", "F11", method)}};
            ApplyImages(same);
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
        ApplyRequest bad = r;
        bad.output = dir + "/bad.exr";
        bad.lightGroups = {{"rim", Change("A", "D65", "bradford")}};
        CHECK_THROWS_WITH(ApplyImages(bad),
                          Contains("arnold.exr: has no light group 'rim' (it has fill, key)"));
        const std::string over = dir + "/over.exr";
        WriteArnoldShot(over, 2.0f);
        bad.input = over;
        bad.lightGroups = {{"key", Change("A", "D65", "bradford")}};
        CHECK_THROWS_WITH(ApplyImages(bad), Contains("sum to more than the beauty"));
        bad.input = in;
        bad.lightGroupLayers = {{"rim", "RGBA_key"}};
        CHECK_THROWS_WITH(ApplyImages(bad),
                          Contains("light groups 'key' and 'rim' resolve to the same channel"));
        CHECK_FALSE(fs::exists(bad.output));
    }
}

TEST_CASE("apply carries every part of a multi-part EXR", "[jobs][lightgroups][multipart]")
{
    const std::string dir = Fresh("multipart");
    const std::string in = dir + "/stereo.exr";
    const auto grey = [](size_t p, size_t c) { return 0.1f * float(p % 5) + 0.02f * float(c); };
    WriteExr(in, 5, 3,
             {{{"R", "G", "B", "A"}, grey, "left", {{"view", "left"}}},
              {{"R", "G", "B"}, grey, "right", {{"view", "right"}}},
              {{"Z"}, [](size_t p, size_t) { return 10.0f + float(p); }, "depth", {}}});
    ApplyRequest r;
    r.input = in;
    r.output = dir + "/out.exr";
    r.relight = Change("A", "D65", "bradford");
    ApplyImages(r);
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
    ApplyRequest png = r;
    png.output = dir + "/out.hdr";
    CHECK_THROWS_WITH(ApplyImages(png),
                      Contains("this format holds one image, and " + in +
                               " has 3 parts: part 1 ('right'), part 2 ('depth') would be lost"));
    CHECK_FALSE(fs::exists(png.output));
}

namespace
{
/// The two-light scene of scenes/two_lights.yaml with other lights: the key
/// and fill replaced, each at the luminance of the light it replaces (as
/// the spectral relight keeps it).
Scene Relit(const Scene& scene, const std::map<std::string, std::string>& to)
{
    Scene s = scene;
    const detail::Grid grid = detail::MakeGrid(s.settings, s.settings.stepNm);
    const detail::Cmf cmf = detail::MakeCmf(grid, s.settings.bands);
    const auto luminance = [&](const SceneSpectrum& sp, double intensity)
    {
        const std::vector<double> v = detail::Sample(sp.continuous, grid);
        double y = 0.0;
        for (size_t i = 0; i < v.size(); ++i)
        {
            y += v[i] * cmf.weight[i].y();
        }
        return intensity * detail::LightScale(sp, s.settings.bands) * y;
    };
    for (SceneLight& l : s.lights)
    {
        const double before = luminance(l.spectrum, l.intensity);
        l.spectrum.name = to.at(l.name);
        l.spectrum.continuous = ResolveIlluminant(to.at(l.name)).spectrum;
        l.intensity *= before / luminance(l.spectrum, l.intensity);
    }
    return s;
}

/// ΔE00 of two acescg images per pixel hit, L*a*b* relative to the
/// equal-energy white at `level` (the lights' summed intensity, as
/// render --compare takes it).
double MeanDeltaE(const std::vector<float>& a, const std::vector<float>& ref, double level)
{
    const Mat3 toXyz = RgbToXyzMatrix(FindRgbSpace("acescg").chromaticities);
    const Vec3 white = Vec3::Ones() * level;
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i + 2 < ref.size(); i += 3)
    {
        const Vec3 r(ref[i], ref[i + 1], ref[i + 2]);
        if (r.isZero(0.0))
        {
            continue;
        }
        sum += DeltaE2000(XyzToLab(toXyz * Vec3(a[i], a[i + 1], a[i + 2]), white),
                          XyzToLab(toXyz * r, white));
        ++n;
    }
    return sum / double(n);
}

std::vector<float> Rgb(const Exr::Part& part, const std::string& prefix = "")
{
    std::vector<float> v(3 * part.count());
    for (size_t p = 0; p < part.count(); ++p)
    {
        v[3 * p] = part.at(p, prefix + "R");
        v[3 * p + 1] = part.at(p, prefix + "G");
        v[3 * p + 2] = part.at(p, prefix + "B");
    }
    return v;
}
}  // namespace

TEST_CASE(
    "Spectral light groups relight a two-light render exactly, RGB groups within the "
    "method's own error",
    "[jobs][lightgroups][spectral]")
{
    const std::string dir = Fresh("spectral");
    const std::string shot = dir + "/shot.exr";
    RenderRequest render;
    render.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
    render.spectra = true;
    render.lightGroups = true;
    render.preview = false;
    render.out = shot;
    const PreparedRender prepared = PrepareRender(render);
    MakeRender(prepared);
    const Exr::Part file = ReadExr(shot)[0];

    // Beauty = Σ groups in the file, RGB and every wavelength, to 1e-6.
    double peak = 0.0;
    for (size_t p = 0; p < file.count(); ++p)
    {
        peak = std::max(peak, double(file.at(p, "R")));
    }
    REQUIRE(peak > 0.0);
    for (const std::string& c :
         {std::string("R"), std::string("B"), SpectralChannelName(SpectralKind::EMISSIVE, 550.0)})
    {
        double worst = 0.0, level = 0.0;
        for (size_t p = 0; p < file.count(); ++p)
        {
            level = std::max(level, double(file.at(p, c)));
            worst = std::max(worst, std::abs(double(file.at(p, c)) - file.at(p, "key." + c) -
                                             file.at(p, "fill." + c)));
        }
        CHECK(worst <= 1e-6 * level);
    }

    // The reference: the same scene lit by D65 and D50.
    RenderRequest refRequest;
    refRequest.scene = render.scene;
    PreparedRender ref = PrepareRender(refRequest);
    ref.scene = Relit(prepared.scene, {{"key", "D65"}, {"fill", "D50"}});
    ref.plan = PlanScene(ref.scene);
    const std::vector<float> reference = MakeRender(ref).image.pixels;
    const double refPeak = MaxAbs(reference);

    SpectralRequest sr;
    sr.files.input = shot;
    sr.files.output = dir + "/relit.exr";
    sr.options.plates.plates = "lit";
    sr.options.lightGroups = {{"key", ResolveIlluminant("A"), ResolveIlluminant("D65")},
                              {"fill", ResolveIlluminant("F11"), ResolveIlluminant("D50")}};
    ConvertSpectralImages(sr);
    const Exr::Part relit = ReadExr(sr.files.output)[0];
    const std::vector<float> spectral = Rgb(relit);
    double worst = 0.0;
    for (size_t i = 0; i < reference.size(); ++i)
    {
        worst = std::max(worst, double(std::abs(spectral[i] - reference[i])));
    }
    std::printf(
        "spectral light groups against the D65/D50 render: max |difference| %.3g of the "
        "brightest value %.4g (%.2g relative)\n",
        worst, refPeak, worst / refPeak);
    CHECK(worst <= 1e-5 * refPeak);
    // Its groups sum to its beauty.
    const std::vector<float> key = Rgb(relit, "key."), fill = Rgb(relit, "fill.");
    for (size_t i = 0; i < spectral.size(); ++i)
    {
        CHECK(std::abs(spectral[i] - key[i] - fill[i]) <= 1e-6 * refPeak);
    }

    SECTION("identity spectral relight of every group reproduces the beauty")
    {
        SpectralRequest same = sr;
        same.files.output = dir + "/same.exr";
        same.options.lightGroups = {{"key", ResolveIlluminant("A"), ResolveIlluminant("A")},
                                    {"fill", ResolveIlluminant("F11"), ResolveIlluminant("F11")}};
        ConvertSpectralImages(same);
        const std::vector<float> s = Rgb(ReadExr(same.files.output)[0]);
        const std::vector<float> beauty = Rgb(file);
        for (size_t i = 0; i < s.size(); ++i)
        {
            CHECK(std::abs(s[i] - beauty[i]) <= 1e-6 * peak);
        }
    }

    SECTION("per-group RGB relighting beats one global look on the beauty")
    {
        // The global look goes from the mix of the scene's lights to the
        // mix of the new ones, each light weighed by its intensity on the
        // band model's scale (what a surface facing both receives).
        const auto mix = [&](const Scene& s, const std::string& name)
        {
            Spectrum sum = Spectrum::Constant(380.0, 5.0, 81, 0.0);
            for (const SceneLight& l : s.lights)
            {
                Spectrum part = l.spectrum.continuous.resampledLike(sum);
                part *= l.intensity * detail::LightScale(l.spectrum, s.settings.bands);
                sum += part;
            }
            return Light{name, sum};
        };
        const Light before = mix(prepared.scene, "key A + fill F11");
        const Light after = mix(ref.scene, "key D65 + fill D50");
        const double level = 1.6;  // the lights' summed intensity
        const double global0 = MeanDeltaE(Rgb(file), reference, level);
        std::printf("no change: mean dE00 %.3f\n", global0);
        // Every method's figures (docs/lightgroups.md) with
        // BANDLIGHT_LIGHT_GROUP_METHODS=all; by default the two checked.
        const char* all = std::getenv("BANDLIGHT_LIGHT_GROUP_METHODS");
        const std::vector<std::string> methods =
            all && std::string(all) == "all"
                ? std::vector<std::string>{"vonkries", "bradford", "cat02",  "band3",
                                           "band3-wp", "band6",    "fit3x3", "prefilter",
                                           "rootpoly", "upsample"}
                : std::vector<std::string>{"bradford", "rootpoly"};
        for (const std::string& method : methods)
        {
            ApplyRequest g;
            g.input = shot;
            g.output = dir + "/global_" + method + ".exr";
            RelightRequest change;
            change.src = before;
            change.dst = after;
            change.method = method;
            change.plates.plates = "lit";
            g.relight = change;
            ApplyImages(g);
            const double global = MeanDeltaE(Rgb(ReadExr(g.output)[0]), reference, level);
            ApplyRequest pg;
            pg.input = shot;
            pg.output = dir + "/groups_" + method + ".exr";
            pg.lightGroups = {{"key", Change("A", "D65", method)},
                              {"fill", Change("F11", "D50", method)}};
            ApplyImages(pg);
            const double groups = MeanDeltaE(Rgb(ReadExr(pg.output)[0]), reference, level);
            std::printf(
                "%-9s global look on the beauty: mean dE00 %.3f; per group: %.3f (%.2f of "
                "global)\n",
                method.c_str(), global, groups, groups / global);
            if (method == "rootpoly" || method == "bradford")
            {
                CHECK(groups <= 0.7 * global);
            }
        }
    }
}

TEST_CASE("render --light-groups in band and N-band mode: beauty = Σ groups in the file",
          "[jobs][lightgroups][render]")
{
    const std::string dir = Fresh("bandrender");
    for (const std::string mode : {"band3", "band6"})
    {
        INFO(mode);
        RenderRequest r;
        r.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
        r.mode = mode;
        r.lightGroups = true;
        r.preview = false;
        r.out = dir + "/" + mode + ".exr";
        const RenderResult result = MakeRender(r);
        const Exr::Part file = ReadExr(r.out)[0];
        CHECK(file.spec.get_string_attribute(LIGHT_GROUPS_ATTRIBUTE) == "key,fill");
        CHECK(file.spec.nchannels == 9);
        // The beauty is what a render without groups gives, to float rounding.
        RenderRequest plain = r;
        plain.lightGroups = false;
        plain.out.clear();
        const std::vector<float> whole = MakeRender(plain).image.pixels;
        const double peak = MaxAbs(whole);
        REQUIRE(peak > 0.0);
        double worstSum = 0.0, worstWhole = 0.0;
        for (size_t p = 0; p < file.count(); ++p)
        {
            for (int c = 0; c < 3; ++c)
            {
                const std::string ch(1, "RGB"[c]);
                worstSum =
                    std::max(worstSum, std::abs(double(file.at(p, ch)) - file.at(p, "key." + ch) -
                                                file.at(p, "fill." + ch)));
                worstWhole = std::max(worstWhole,
                                      std::abs(double(file.at(p, ch)) - whole[3 * p + size_t(c)]));
                CHECK(result.image.pixels[3 * p + size_t(c)] == file.at(p, ch));
            }
        }
        CHECK(worstSum <= 1e-6 * peak);
        CHECK(worstWhole <= 1e-5 * peak);
        // Each group lights only its part: the key's light is warm (A).
        double keyR = 0.0, keyB = 0.0;
        for (size_t p = 0; p < file.count(); ++p)
        {
            keyR += file.at(p, "key.R");
            keyB += file.at(p, "key.B");
        }
        CHECK(keyR > 1.5 * keyB);
    }
}

TEST_CASE("A matte mixes two changes of light: m inside, 1 - m outside",
          "[jobs][lightgroups][matte]")
{
    const std::string dir = Fresh("matte");
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
    ApplyRequest r;
    r.input = plate;
    r.output = dir + "/out.exr";
    r.matte = dir + "/matte.exr:window";
    r.insideRelight = Change("D65", "A", "bradford");
    r.outsideRelight = Change("A", "D65", "bradford");
    const ApplyResult result = ApplyImages(r);
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
    ApplyRequest bad = r;
    bad.output = dir + "/bad.exr";
    bad.matte = dir + "/small.exr";
    CHECK_THROWS_WITH(ApplyImages(bad), Contains("small.exr: the matte's data window is 5x4 at "
                                                 "(0, 0), " +
                                                 plate + "'s 6x4 at (0, 0)"));
    bad.matte = dir + "/matte.exr:door";
    CHECK_THROWS_WITH(ApplyImages(bad), Contains("the matte has no channel 'door'"));
    CHECK_FALSE(fs::exists(bad.output));
}

TEST_CASE("A matte with two looks of a config is the mix of the config's own processors",
          "[jobs][lightgroups][matte]")
{
    const std::string dir = Fresh("matte_looks");
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
    const std::string dir = Fresh("frames");
    WriteArnoldShot(dir + "/shot.1001.exr");
    WriteArnoldShot(dir + "/shot.1002.exr", 2.0f);  // no partition: fails
    WriteArnoldShot(dir + "/shot.1003.exr");
    WriteArnoldShot(dir + "/out.1003.exr");  // already done
    ApplyRequest r;
    r.input = dir + "/shot.####.exr";
    r.output = dir + "/out.####.exr";
    r.frames = "1001-1003";
    r.skipExisting = true;
    r.keepGoing = true;
    r.lightGroups = {{"key", Change("A", "D65", "bradford")}};
    const ApplyResult result = ApplyImages(r);
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

TEST_CASE(
    "accuracy --light-group: one global look against a look per group, against the exact "
    "spectral groups",
    "[jobs][lightgroups][accuracy]")
{
    const std::string dir = Fresh("accuracy");
    RenderRequest render;
    render.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
    render.spectra = true;
    render.lightGroups = true;
    render.preview = false;
    render.out = dir + "/shot.exr";
    MakeRender(render);
    LightGroupAccuracyRequest r;
    r.image = render.out;
    r.methods = {"bradford"};
    r.changes = {{"key", ResolveIlluminant("A"), ResolveIlluminant("D65")}};
    CHECK_THROWS_WITH(MeasureLightGroups(r), Contains("light group 'fill' has no change"));
    r.changes.push_back({"fill", ResolveIlluminant("F11"), ResolveIlluminant("D50")});
    const LightGroupAccuracyResult result = MeasureLightGroups(r);
    REQUIRE(result.rows.size() == 1);
    CHECK(result.pixels > 10000);
    CHECK(result.noChangeMean > 10.0);
    CHECK(result.rows[0].globalMean > 2.0);
    CHECK(result.rows[0].groupsMean < 0.7 * result.rows[0].globalMean);
    CHECK(result.globalFrom == "key A + fill F11");
    // Nothing of the run is left in the temporary folder.
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
    {
        CHECK(e.path().filename().string().rfind(
                  ".bandlight-lightgroups-" + std::to_string(::getpid()), 0) == std::string::npos);
    }
}
