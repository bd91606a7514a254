// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of config, lut and apply against the hosts' own tools:
// ociocheck and oiiotool.
// Covers, through the entry points it calls: cli/CommandApply.cpp, cli/CommandPlot.cpp.
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

TEST_CASE("ociocheck passes on every generated config", "[cli][ocio]")
{
    const std::string base = ConfigDir();
    struct Case
    {
        std::string name;
        std::string args;
    };
    std::vector<Case> cases = {
        {"default", ""},
        {"rec709", "--working-space lin-rec709 --illuminants A,D50,D65,F7"},
        {"rec2020-10deg", "--working-space rec2020 --observer 1964 --methods cat02,band8-wp"},
        {"all-methods",
         "--illuminants A,D65 --methods none,vonkries,bradford,cat02,band3,band3-wp,"
         "band6,fit3x3,prefilter,metamer,upsample,hueplane"},
        {"extended", "--base '" + base + "/config.ocio' --illuminants D50,D75,F12"},
    };
    // Blender's own config, when Blender's data are installed (Debian's
    // blender-data): its scene_linear (Linear Rec.709) is found through its
    // aces_interchange role and its LUT folders stay reachable.
    for (const char* blender : {"/usr/share/blender/datafiles/colormanagement/config.ocio"})
    {
        if (Exists(blender))
        {
            cases.push_back({"blender", std::string("--base '") + blender + "'"});
        }
        else
        {
            WARN("Blender's config is not installed (" << blender << "): not extended here");
        }
    }
    for (const Case& c : cases)
    {
        const std::string dir = Temp("check_" + c.name);
        const Result made = Bandlight("config --out '" + dir + "' " + c.args);
        INFO(c.name << ": " << made.err);
        REQUIRE(made.code == 0);
        const Result check = Sh("ociocheck --iconfig '" + dir + "/config.ocio'");
        INFO(check.out);
        CHECK(check.code == 0);
        CHECK_THAT(check.out, Contains("** Validation **\npassed"));
        CHECK(check.out.find("ERROR") == std::string::npos);
    }
}

TEST_CASE("apply gives oiiotool's pixels for the same look and config", "[cli][oiio]")
{
    const std::string in = Temp("plate.exr");
    WriteTestImage(in);
    for (const char* look :
         {"band3_A_to_D65", "bradford_F11_to_D65", "band3-wp_D65_to_F2", "band5_C_to_A"})
    {
        const std::string ours = Temp(std::string("ours_") + look + ".exr");
        const std::string theirs = Temp(std::string("oiiotool_") + look + ".exr");
        const Result a = Bandlight("apply '" + in + "' '" + ours + "' --look " + look +
                                   " --config '" + ConfigDir() + "'");
        INFO(a.err);
        REQUIRE(a.code == 0);
        const Result b =
            Sh("oiiotool '" + in + "' --colorconfig '" + ConfigDir() +
               "/config.ocio' --ociolook:from=ACEScg:to=ACEScg " + look + " -o '" + theirs + "'");
        INFO(b.err);
        REQUIRE(b.code == 0);
        const OIIO::ImageBuf mine = Read(ours), ref = Read(theirs), orig = Read(in);
        CHECK(WorstRelative(mine, ref, 0, 3) <= 1e-5);
        // Alpha and depth pass through untouched; names and metadata are kept.
        CHECK(WorstRelative(mine, orig, 3, 5) == 0.0);
        CHECK(mine.spec().channelnames == orig.spec().channelnames);
        CHECK(mine.spec().get_string_attribute("Copyright") == "bandlight test plate");
        CHECK_THAT(mine.spec().get_string_attribute("bandlight:transform"), Contains(look));
    }
}

TEST_CASE("apply without a config is the same as the config's look", "[cli][oiio]")
{
    const std::string in = Temp("plate2.exr");
    WriteTestImage(in, 32, 16, 2);
    const std::string a = Temp("direct.exr"), b = Temp("vialook.exr");
    REQUIRE(Bandlight("apply '" + in + "' '" + a + "' --from F11 --to D65 --method band3").code ==
            0);
    REQUIRE(Bandlight("apply '" + in + "' '" + b + "' --look band3_F11_to_D65 --config '" +
                      ConfigDir() + "'")
                .code == 0);
    CHECK(WorstRelative(Read(a), Read(b), 0, 3) <= 1e-6);
}

TEST_CASE("apply --method rootpoly applies natively and agrees with the config LUT look",
          "[cli][oiio]")
{
    // Surface colours (channels 0.3-1 of a level) at exposures 2^-8 ... 2^4:
    // what a plate holds. (WriteTestImage's channels are independent over
    // 29 stops, colours no surface makes, where a LUT clamps to its range.)
    const std::string in = Temp("plate3.exr");
    {
        OIIO::ImageSpec spec(32, 16, 4, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"R", "G", "B", "A"};
        spec.alpha_channel = 3;
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> level(-8.0f, 4.0f), chroma(0.3f, 1.0f);
        std::vector<float> px(32 * 16 * 4);
        for (size_t i = 0; i < 32 * 16; ++i)
        {
            const float k = std::exp2(level(rng));
            for (int c = 0; c < 3; ++c)
            {
                px[4 * i + size_t(c)] = k * chroma(rng);
            }
            px[4 * i + 3] = float(i % 7) / 6.0f;
        }
        auto out = OIIO::ImageOutput::create(in);
        REQUIRE(out);
        REQUIRE(out->open(in, spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        REQUIRE(out->close());
    }
    const std::string config = Temp("rootpoly_config");
    REQUIRE(
        Bandlight("config --out '" + config + "' --illuminants A,D65 --methods rootpoly").code ==
        0);
    const std::string a = Temp("rootpoly_native.exr"), b = Temp("rootpoly_look.exr");
    const Result native =
        Bandlight("apply '" + in + "' '" + a + "' --from A --to D65 --method rootpoly");
    REQUIRE(native.code == 0);
    REQUIRE(Bandlight("apply '" + in + "' '" + b + "' --look rootpoly_A_to_D65 --config '" +
                      config + "'")
                .code == 0);
    // The 65³ LUT look against the native map, relative to each pixel's
    // largest channel (what the eye weighs): the LUT's interpolation error.
    const OIIO::ImageBuf lut = Read(b), exact = Read(a);
    double worst = 0.0;
    for (OIIO::ImageBuf::ConstIterator<float> pl(lut), pe(exact); !pl.done(); ++pl, ++pe)
    {
        const double m = std::max({pe[0], pe[1], pe[2]});
        for (int c = 0; c < 3; ++c)
        {
            worst = std::max(worst, std::abs(double(pl[c]) - pe[c]) / m);
        }
    }
    INFO("worst LUT error relative to the pixel's largest channel: " << worst);
    CHECK(worst <= 0.01);
    // Alpha passes through; the colours did change.
    CHECK(WorstRelative(Read(a), Read(in), 3, 4) == 0.0);
    CHECK(WorstRelative(Read(a), Read(in), 0, 3) > 0.01);
}

TEST_CASE("apply reads and writes any format OIIO does, keeping the pixel type", "[cli][oiio]")
{
    const std::string exr = Temp("typed.exr");
    WriteTestImage(exr, 16, 8, 9);
    for (const char* ext : {"tif", "png"})
    {
        const std::string in = Temp(std::string("typed_in.") + ext);
        const std::string out = Temp(std::string("typed_out.") + ext);
        REQUIRE(
            Sh("oiiotool '" + exr + "' --ch R,G,B,A --clamp:min=0:max=1 -d uint16 -o '" + in + "'")
                .code == 0);
        const Result r =
            Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method none");
        INFO(ext << ": " << r.err);
        REQUIRE(r.code == 0);
        const OIIO::ImageBuf a = Read(in), b = Read(out);
        auto fin = OIIO::ImageInput::open(in);
        auto fout = OIIO::ImageInput::open(out);
        REQUIRE(fin);
        REQUIRE(fout);
        CHECK(fout->spec().format == fin->spec().format);
        CHECK(b.spec().nchannels == 4);
        CHECK(WorstRelative(a, b, 0, 4) <= 1.01 / 65535.0);  // identity: at most one code value
    }
}

TEST_CASE("apply runs over a frame range for farm splits", "[cli][oiio]")
{
    for (int f : {1001, 1002, 1003})
    {
        WriteTestImage(Temp("seq." + std::to_string(f) + ".exr"), 16, 8, unsigned(f));
    }
    const Result r = Bandlight("apply '" + Temp("seq.####.exr") + "' '" + Temp("relit.####.exr") +
                               "' --from A --to D65 --frames 1002-1003");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_FALSE(Exists(Temp("relit.1001.exr")));
    CHECK(Exists(Temp("relit.1002.exr")));
    CHECK(Exists(Temp("relit.1003.exr")));
    const Result missing =
        Bandlight("apply '" + Temp("seq.####.exr") + "' '" + Temp("relit.####.exr") +
                  "' --from A --to D65 --frames 1003-1004");
    CHECK(missing.code == 2);
    CHECK_THAT(missing.err, Contains("seq.1004.exr: cannot read image"));
}

TEST_CASE(
    "apply takes farm frame sets, resumes with --skip-existing, and --keep-going names "
    "the bad frame",
    "[cli][oiio][farm]")
{
    for (int f = 1001; f <= 1006; ++f)
    {
        WriteTestImage(Temp("farm." + std::to_string(f) + ".exr"), 16, 8, unsigned(f));
    }
    const std::string in = "'" + Temp("farm.####.exr") + "'";
    const std::string out = "'" + Temp("farmout.####.exr") + "'";
    for (int f = 1001; f <= 1006; ++f)
    {
        std::remove(Temp("farmout." + std::to_string(f) + ".exr").c_str());
    }
    // A step and a list: 1001, 1003, 1005 and 1006.
    Result r =
        Bandlight("apply " + in + " " + out + " --from A --to D65 --frames 1001-1005x2,1006");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("to 4 frames in "));
    for (int f = 1001; f <= 1006; ++f)
    {
        CHECK(Exists(Temp("farmout." + std::to_string(f) + ".exr")) == (f != 1002 && f != 1004));
    }
    // A re-queued chunk after one output was lost rewrites that frame alone.
    const std::string kept = Temp("farmout.1003.exr");
    std::remove(Temp("farmout.1005.exr").c_str());
    struct stat before
    {
    };
    REQUIRE(::stat(kept.c_str(), &before) == 0);
    r = Bandlight("apply " + in + " " + out +
                  " --from A --to D65 --frames 1001-1005x2,1006 --skip-existing");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("to 1 frame (3 skipped, 0 failed)"));
    CHECK(Exists(Temp("farmout.1005.exr")));
    struct stat after
    {
    };
    REQUIRE(::stat(kept.c_str(), &after) == 0);
    CHECK(after.st_ino == before.st_ino);  // not rewritten
    // A corrupt frame in the middle: every other frame is written, exit 2,
    // one line naming the bad frame.
    {
        std::ofstream bad(Temp("farm.1003.exr"), std::ios::binary | std::ios::trunc);
        bad << "not an image";
    }
    for (int f = 1001; f <= 1006; ++f)
    {
        std::remove(Temp("farmout." + std::to_string(f) + ".exr").c_str());
    }
    {
        // A second bad frame: the message names both.
        std::ofstream bad(Temp("farm.1005.exr"), std::ios::binary | std::ios::trunc);
        bad << "not an image either";
    }
    r = Bandlight("apply " + in + " " + out + " --from A --to D65 --frames 1001-1006 --keep-going");
    CHECK(r.code == 2);
    CHECK_THAT(r.out, Contains("to 4 frames (0 skipped, 2 failed)"));
    CHECK_THAT(r.err,
               StartsWith("bandlight: 2 of 6 frames failed (1003, 1005); the first, frame 1003: "));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    for (int f = 1001; f <= 1006; ++f)
    {
        CHECK(Exists(Temp("farmout." + std::to_string(f) + ".exr")) == (f != 1003 && f != 1005));
    }
    // Without --keep-going the chunk stops at the bad frame.
    r = Bandlight("apply " + in + " " + out + " --from A --to D65 --frames 1001-1006");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("farm.1003.exr"));
    // Frame sets are validated: one line each.
    for (const char* bad : {"1-10x0", "10-1", "1-5,,7", "1-3y2", "x"})
    {
        r = Bandlight("apply " + in + " " + out + " --from A --to D65 --frames '" + bad + "'");
        CHECK(r.code == 2);
        CHECK_THAT(r.err, StartsWith("bandlight: frame range '"));
    }
}

TEST_CASE("lut writes files OCIO reads back", "[cli][ocio]")
{
    for (const char* format : {"clf", "ctf", "cube", "spi3d", "3dl"})
    {
        const std::string path = Temp(std::string("relight.") + format);
        const Result r = Bandlight("lut --from A --to D65 --method band3 --format " +
                                   std::string(format) + " --size 17 -o '" + path + "'");
        INFO(format << ": " << r.err);
        REQUIRE(r.code == 0);
        CHECK(Exists(path));
        const Result check = Sh("ociochecklut '" + path + "' 0.18 0.18 0.18");
        INFO(check.out);
        CHECK(check.code == 0);
    }
}

TEST_CASE("Bad input: one line, exit code 2, nothing half-written", "[cli]")
{
    const std::string in = Temp("plate3.exr");
    WriteTestImage(in, 8, 8, 3);
    const std::string out = Temp("keep.exr");
    REQUIRE(Bandlight("apply '" + in + "' '" + out + "' --from A --to D65").code == 0);
    struct stat before;
    REQUIRE(::stat(out.c_str(), &before) == 0);

    struct Case
    {
        std::string args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"apply '" + in + "' '" + out + "' --from Candle --to D65", "unknown illuminant 'Candle'"},
        {"apply '" + in + "' '" + out + "' --from A --to D65 --method magic",
         "unknown method 'magic'"},
        {"apply '" + Temp("nope.exr") + "' '" + out + "' --from A --to D65",
         "nope.exr: cannot read image"},
        {"apply '" + in + "' '" + out + "' --look sepia --config '" + ConfigDir() + "'",
         "look 'sepia' is not in"},
        {"apply '" + in + "' '" + out + "' --look band3_A_to_D65 --config /nonexistent",
         "/nonexistent/config.ocio: cannot read the config"},
        {"apply '" + in + "' '" + Temp("out.unknownformat") + "' --from A --to D65",
         "no image writer"},
        {"config --out '" + Temp("cfg_bad") + "' --illuminants A,Candle",
         "unknown illuminant 'Candle'"},
        {"config --out '" + Temp("cfg_bad") + "' --methods bradford,magic",
         "unknown method 'magic'"},
        {"config --out '" + Temp("cfg_bad") + "' --base /nonexistent.ocio",
         "/nonexistent.ocio: cannot read the config"},
        {"config --out '" + Temp("cfg_bad") + "' --base '" + ConfigDir() + "/config.ocio'",
         "clashes with a look"},
        {"lut --from A --to D65 --format icc -o '" + Temp("x.icc") + "'",
         "unknown LUT format 'icc'"},
    };
    for (const Case& c : cases)
    {
        const Result r = Bandlight(c.args);
        INFO(c.args << "\n" << r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains(c.message));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK_FALSE(Exists(Temp("cfg_bad") + "/config.ocio"));
    CHECK_FALSE(Exists(Temp("out.unknownformat")));
    struct stat after;
    REQUIRE(::stat(out.c_str(), &after) == 0);
    CHECK(after.st_mtime == before.st_mtime);  // the earlier output is intact
    // No temporary file is left behind in the output directory.
    // (hidden: ".<name>.tmp-<pid>")
    const std::string prefix = Temp("");
    const std::string folder = prefix.substr(0, prefix.find_last_of('/'));
    const std::string hidden = "." + prefix.substr(prefix.find_last_of('/') + 1);
    int left = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
    {
        const std::string name = entry.path().filename().string();
        left += name.rfind(hidden, 0) == 0 && name.find(".tmp-") != std::string::npos;
    }
    CHECK(left == 0);
}

TEST_CASE("accuracy writes the documented JSON and a plot, with progress", "[cli][accuracy]")
{
    const std::string json = Temp("accuracy.json"), png = Temp("accuracy.png");
    const Result r = Bandlight(
        "accuracy --illuminants A,F11,D65 --methods bradford,band3,upsample,rootpoly "
        "--lut-size 17 --json '" +
        json + "' --plot '" + png + "'");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.err, Contains("100% of pairs done"));
    CHECK_THAT(r.out, Contains("bradford"));
    std::ifstream in(json);
    std::stringstream text;
    text << in.rdbuf();
    const std::string j = text.str();
    for (const char* key :
         {"\"rows\"", "\"method\"", "\"from\"", "\"to\"", "\"set\"", "\"mean\"", "\"p95\"",
          "\"max\"", "\"worst_sample\"", "\"cost\"", "\"ns_per_pixel\"", "\"threads\"",
          "\"exposure\": 0.00390625", "\"shipped\": true", "\"shipped\": false",
          "\"cross_validation\"", "\"floor\"", "\"floor-rootpoly\""})
    {
        CHECK_THAT(j, Contains(key));
    }
    std::ifstream img(png, std::ios::binary);
    char magic[4] = {};
    img.read(magic, 4);
    CHECK(std::string(magic + 1, 3) == "PNG");
}

TEST_CASE("plot draws the lecture's pictures", "[cli]")
{
    for (const char* what : {"--cmf", "--illuminant F11", "--reflectance TCS09"})
    {
        const std::string out = Temp("plot.svg");
        std::remove(out.c_str());
        const Result r = Bandlight(std::string("plot ") + what + " -o '" + out + "'");
        INFO(what << ": " << r.err);
        CHECK(r.code == 0);
        CHECK(Exists(out));
    }
    const Result bad = Bandlight("plot --cmf -o '" + Temp("plot.gif") + "'");
    CHECK(bad.code == 2);
    CHECK_THAT(bad.err, Contains("plots are written as .png or .svg"));
}
