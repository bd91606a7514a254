// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of config, lut and apply against the hosts' own tools:
// ociocheck and oiiotool.
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
#include "cli/RunCommand.h"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace
{

using bandlight::test::Bandlight;
using bandlight::test::Result;
using bandlight::test::Sh;

std::string Temp(const std::string& name)
{
    return bandlight::test::TempPath("image_" + name);
}

bool Exists(const std::string& path)
{
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

/// A float EXR with HDR colour, an alpha ramp and an extra depth channel.
void WriteTestImage(const std::string& path, int width = 64, int height = 48, unsigned seed = 1)
{
    OIIO::ImageSpec spec(width, height, 5, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A", "Z"};
    spec.alpha_channel = 3;
    spec.z_channel = 4;
    spec.attribute("Copyright", "bandlight test plate");
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-13.0f, 16.0f);
    std::vector<float> px(size_t(width) * height * 5);
    for (size_t i = 0; i < size_t(width) * height; ++i)
    {
        for (int c = 0; c < 3; ++c)
        {
            px[5 * i + c] = std::exp2(u(rng));
        }
        px[5 * i + 3] = float(i % 97) / 96.0f;
        px[5 * i + 4] = float(i);
    }
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    REQUIRE(out->close());
}

OIIO::ImageBuf Read(const std::string& path)
{
    OIIO::ImageBuf buf(path);
    REQUIRE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT));
    return buf;
}

/// Worst |a - b| / max(1, |b|) over channels [c0, c1).
double WorstRelative(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, int c0, int c1)
{
    REQUIRE(a.spec().width == b.spec().width);
    REQUIRE(a.spec().height == b.spec().height);
    double worst = 0.0;
    for (OIIO::ImageBuf::ConstIterator<float> pa(a), pb(b); !pa.done(); ++pa, ++pb)
    {
        for (int c = c0; c < c1; ++c)
        {
            worst = std::max(
                worst, double(std::abs(pa[c] - pb[c])) / std::max(1.0, double(std::abs(pb[c]))));
        }
    }
    return worst;
}

std::string ConfigDir()
{
    static const std::string dir = []
    {
        const std::string d = Temp("config");
        const Result r =
            Bandlight("config --out '" + d + "' --methods none,bradford,band3,band3-wp,band5");
        REQUIRE(r.code == 0);
        return d;
    }();
    return dir;
}

}  // namespace

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

TEST_CASE("apply --from --to on a file with light groups relights every group and the residual",
          "[cli][lightgroups]")
{
    // Relighting only the beauty would leave beauty != Σ groups: the file
    // stays consistent, and says so.
    const std::string shot = Temp("lg_shot.exr");
    const std::string relit = Temp("lg_relit.exr");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/two_lights.yaml' --light-groups "
                      "-o '" + shot + "'")
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
            worst = std::max(worst, std::abs(b[channel(rgb)] - groups) -
                                        std::abs(residualIn) * 2.0);
            moved = std::max(moved, double(std::abs(b[channel("key." + rgb)] -
                                                    a[channel("key." + rgb)])));
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
        spec.channelnames = {"R", "G", "B", "RGBA_key.R", "RGBA_key.G", "RGBA_key.B",
                             "RGBA_fill.R", "RGBA_fill.G", "RGBA_fill.B"};
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
                    const std::string name =
                        std::string(part == 0 ? "" : part == 1 ? "RGBA_key." : "RGBA_fill.") +
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
        px[3 * (1 * w + 2) + 0] = std::nanf("");                          // outside (x < 3)
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
