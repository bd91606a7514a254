// SPDX-License-Identifier: BSD-3-Clause
// Light groups (jobs/LightGroups): found in every naming, relit per group
// with the beauty rebuilt as Σ groups + residual, and refused when they are
// no partition of the beauty.
// Covers, through the entry points it calls: imaging/LightGroupRelight.cpp.
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <limits>

#include "imaging/LightGroups.h"

using namespace bandlight::jobs;
using Catch::Matchers::Contains;

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
    // Groups summing past the beauty are refused before anything changes.
    std::vector<float> over = in;
    over[3] = 0.9f;
    CHECK_THROWS_WITH(
        RelightLightGroups(l, {{"a", twice}}, over.data(), 2, 1, 9, "x.exr"),
        Contains("x.exr: the light groups sum to more than the beauty at pixel (0, 0)"));
    CHECK(over[4] == in[4]);
    // NaN and infinity, in a group or the beauty, go through the guard of
    // every pixel path (NaN to -1e16, Inf to +1e16): every value written is
    // finite, the pixels met are counted, the other pixel is as before.
    for (const float odd : {std::nanf(""), std::numeric_limits<float>::infinity()})
    {
        for (const size_t at : {size_t(16), size_t(9)})  // (1, 0): b's G, then the beauty's R
        {
            std::vector<float> px = in;
            px[at] = odd;
            CHECK(RelightLightGroups(l, {{"a", twice}}, px.data(), 2, 1, 9, "x.exr") == 1);
            for (const float v : px)
            {
                CHECK(std::isfinite(v));
            }
            std::vector<float> clean = in;
            CHECK(RelightLightGroups(l, {{"a", twice}}, clean.data(), 2, 1, 9, "x.exr") == 0);
            for (size_t i = 0; i < 9; ++i)
            {
                CHECK(px[i] == clean[i]);  // pixel (0, 0) untouched by its neighbour
            }
        }
    }
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
    // The NaN alone is no fault: guarded, counted, and written finite.
    CHECK(RelightLightGroups(l, {{"a", square}}, bad.data(), w, h, 9, "x.exr") == 1);
    CHECK(std::all_of(bad.begin(), bad.end(), [](float v) { return std::isfinite(v); }));
}
