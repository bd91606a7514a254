// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of apply on layered files: light groups (in one part or
// across the parts of a multi-part EXR), spectral renders and mattes.
// Covers, through the entry points it calls: cli/CommandSpectral.cpp.
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <catch2/catch.hpp>
#include "cli/ImageCliHelpers.h"
#include "cli/RunCommand.h"

using namespace Catch::Matchers;
using namespace bandlight::test;
using namespace bandlight::test::image;

TEST_CASE("apply --from --to on a file with light groups relights every group and the residual",
          "[cli][lightgroups]")
{
    // Relighting only the beauty would leave beauty != Σ groups: the file
    // stays consistent, and says so.
    const std::string shot = Temp("lg_shot.exr");
    const std::string relit = Temp("lg_relit.exr");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) +
                      "/two_lights.yaml' --light-groups "
                      "-o '" +
                      shot + "'")
                .code == 0);
    const Result r =
        Bandlight("apply '" + shot + "' '" + relit + "' --from A --to D65 --method rootpoly");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.err, Catch::Contains("every light group and the residual relit"));
    const OIIO::ImageBuf in = Read(shot), out = Read(relit);
    const OIIO::ImageSpec& spec = out.spec();
    REQUIRE(spec.channelnames == in.spec().channelnames);
    const auto channel = [&](const std::string& name)
    {
        return int(std::find(spec.channelnames.begin(), spec.channelnames.end(), name) -
                   spec.channelnames.begin());
    };
    double moved = 0.0, worst = 0.0;
    for (OIIO::ImageBuf::ConstIterator<float> a(in), b(out); !b.done(); ++a, ++b)
    {
        for (int c = 0; c < 3; ++c)
        {
            const std::string rgb(1, "RGB"[c]);
            const double groups = b[channel("key." + rgb)] + b[channel("fill." + rgb)];
            const double residualIn =
                a[channel(rgb)] - (a[channel("key." + rgb)] + a[channel("fill." + rgb)]);
            // The render has no emission: its residual is float noise, and
            // so is the relit one.
            worst =
                std::max(worst, std::abs(b[channel(rgb)] - groups) - std::abs(residualIn) * 2.0);
            moved = std::max(moved,
                             double(std::abs(b[channel("key." + rgb)] - a[channel("key." + rgb)])));
        }
    }
    CHECK(worst < 1e-5);
    CHECK(moved > 1e-3);  // the groups were relit, not carried
}

TEST_CASE("apply on a spectral render leaves out the spectra it would leave stale",
          "[cli][spectral]")
{
    // The relit RGB and the old spectra would contradict each other: a later
    // `spectral` on the output must not return the un-relit image.
    const std::string shot = Temp("stale_shot.exr");
    const std::string relit = Temp("stale_relit.exr");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/two_lights.yaml' --spectra -o '" +
                      shot + "'")
                .code == 0);
    const Result r = Bandlight("apply '" + shot + "' '" + relit + "' --from A --to D65");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.err, Catch::Contains("spectral channels (S0.*) are left out of the output"));
    const OIIO::ImageBuf out = Read(relit);
    CHECK(out.spec().channelnames == std::vector<std::string>{"R", "G", "B"});
    const Result again = Bandlight("spectral '" + relit + "' '" + Temp("stale_again.exr") + "'");
    CHECK(again.code == 2);
    CHECK_THAT(again.err, Catch::Contains("has no spectral channels"));
}

TEST_CASE("Light groups split across the parts of a multi-part EXR are found and keep their parts",
          "[cli][lightgroups]")
{
    // Each AOV a part, as Nuke and Arnold write them: "rgba" (the beauty),
    // "RGBA_key" and "RGBA_fill", each R, G, B. Relit as the same groups in
    // one part are, and written back part by part.
    const int w = 4, h = 3;
    const auto value = [](int part, size_t p, int c)
    {
        const float key = 0.3f + 0.01f * float(p) + 0.05f * float(c);
        const float fill = 0.2f - 0.02f * float(c);
        return part == 1 ? key : part == 2 ? fill : key + fill + 0.01f;  // a residual
    };
    const std::string parts = Temp("parts.exr");
    {
        std::vector<OIIO::ImageSpec> specs;
        for (const char* name : {"rgba", "RGBA_key", "RGBA_fill"})
        {
            OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
            spec.channelnames = {"R", "G", "B"};
            spec.attribute("name", name);
            specs.push_back(spec);
        }
        auto out = OIIO::ImageOutput::create(parts);
        REQUIRE(out);
        REQUIRE(out->open(parts, int(specs.size()), specs.data()));
        for (int part = 0; part < 3; ++part)
        {
            if (part > 0)
            {
                REQUIRE(out->open(parts, specs[size_t(part)], OIIO::ImageOutput::AppendSubimage));
            }
            std::vector<float> px(size_t(w * h * 3));
            for (size_t p = 0; p < size_t(w * h); ++p)
            {
                for (int c = 0; c < 3; ++c)
                {
                    px[3 * p + size_t(c)] = value(part, p, c);
                }
            }
            REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        }
        REQUIRE(out->close());
    }
    // The same groups in one part.
    const std::string single = Temp("single.exr");
    {
        OIIO::ImageSpec spec(w, h, 9, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"R",          "G",           "B",           "RGBA_key.R", "RGBA_key.G",
                             "RGBA_key.B", "RGBA_fill.R", "RGBA_fill.G", "RGBA_fill.B"};
        std::vector<float> px(size_t(w * h * 9));
        for (size_t p = 0; p < size_t(w * h); ++p)
        {
            for (int part = 0; part < 3; ++part)
            {
                for (int c = 0; c < 3; ++c)
                {
                    px[9 * p + size_t(3 * part + c)] = value(part, p, c);
                }
            }
        }
        auto out = OIIO::ImageOutput::create(single);
        REQUIRE(out->open(single, spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        REQUIRE(out->close());
    }
    const std::string change = " --light-group key=A:D65 --method rootpoly --colorspace acescg";
    const Result r = Bandlight("apply '" + parts + "' '" + Temp("parts_relit.exr") + "'" + change);
    INFO(r.err);
    REQUIRE(r.code == 0);
    REQUIRE(Bandlight("apply '" + single + "' '" + Temp("single_relit.exr") + "'" + change).code ==
            0);
    OIIO::ImageBuf ref(Temp("single_relit.exr"));
    REQUIRE(ref.read(0, 0, true, OIIO::TypeDesc::FLOAT));
    for (int part = 0; part < 3; ++part)
    {
        OIIO::ImageBuf got(Temp("parts_relit.exr"), part, 0);
        REQUIRE(got.read(part, 0, true, OIIO::TypeDesc::FLOAT));
        REQUIRE(got.nchannels() == 3);  // the parts' layout kept
        for (int y = 0; y < h; ++y)
        {
            for (int x = 0; x < w; ++x)
            {
                for (int c = 0; c < 3; ++c)
                {
                    const std::string name = std::string(part == 0   ? ""
                                                         : part == 1 ? "RGBA_key."
                                                                     : "RGBA_fill.") +
                                             "RGB"[c];
                    const int channel = ref.spec().channelindex(name);
                    CHECK(got.getchannel(x, y, 0, c) == ref.getchannel(x, y, 0, channel));
                }
            }
        }
    }
}

TEST_CASE("A matte's two sides guard NaN and infinity as every pixel path does", "[cli][matte]")
{
    // docs/robustness.md: non-finite inputs give finite outputs (NaN to
    // -1e16, Inf to +1e16 before the matrix), on either side of a matte.
    const int w = 6, h = 4;
    const std::string plate = Temp("nan_plate.exr");
    const std::string matte = Temp("nan_matte.exr");
    {
        OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
        std::vector<float> px(size_t(w * h * 3), 0.5f);
        px[3 * (1 * w + 2) + 0] = std::nanf("");                           // outside (x < 3)
        px[3 * (2 * w + 4) + 1] = std::numeric_limits<float>::infinity();  // inside (x >= 3)
        auto out = OIIO::ImageOutput::create(plate);
        REQUIRE(out->open(plate, spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        REQUIRE(out->close());
        OIIO::ImageSpec m(w, h, 1, OIIO::TypeDesc::FLOAT);
        m.channelnames = {"A"};
        std::vector<float> weights(size_t(w * h));
        for (int y = 0; y < h; ++y)
        {
            for (int x = 0; x < w; ++x)
            {
                weights[size_t(y * w + x)] = x < 3 ? 0.0f : 1.0f;
            }
        }
        auto mo = OIIO::ImageOutput::create(matte);
        REQUIRE(mo->open(matte, m));
        REQUIRE(mo->write_image(OIIO::TypeDesc::FLOAT, weights.data()));
        REQUIRE(mo->close());
    }
    const std::string relit = Temp("nan_relit.exr");
    const Result r = Bandlight("apply '" + plate + "' '" + relit + "' --matte '" + matte +
                               "' --look-inside A:D65 --look-outside F11:D65");
    INFO(r.err);
    REQUIRE(r.code == 0);
    const OIIO::ImageBuf out = Read(relit);
    size_t checked = 0;
    for (OIIO::ImageBuf::ConstIterator<float> it(out); !it.done(); ++it)
    {
        for (int c = 0; c < 3; ++c)
        {
            CHECK(std::isfinite(it[c]));
            ++checked;
        }
    }
    CHECK(checked == size_t(w * h * 3));
}
