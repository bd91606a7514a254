// SPDX-License-Identifier: BSD-3-Clause
// Light groups and mattes, as users get them wrong: files whose groups are
// no partition of the beauty (a denoised beauty), light-group files, layers
// a format cannot name, matte options that do not fit. Each mistake is one
// line on stderr and exit code 2 before any work, nothing of theirs lost.
// Covers, through the entry points it calls: cli/ApplyInputs.cpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "cli/MistakesSupport.h"
#include "cli/RunCommand.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::CheckOneLine;
using test::Folder;
using test::Result;
using test::Sh;
using test::Slurp;

namespace fs = std::filesystem;

TEST_CASE("Named layers are written only to a format that keeps their names", "[cli][mistakes]")
{
    // A TIFF (or PNG) keeps no channel names: "key.R" would come back as
    // "channel3", the groups anonymous. Refused before any work, naming EXR.
    const std::string dir = Folder("named_layers");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/two_lights.yaml' --spectra "
                      "--light-groups -o '" + dir + "/shot.exr'")
                .code == 0);
    const std::string in = "'" + dir + "/shot.exr' ";
    CheckOneLine(Bandlight("apply " + in + "'" + dir +
                           "/out.tif' --light-group key=A:D65 --light-group fill=F11:F11"),
                 "only an EXR keeps channel names");
    CheckOneLine(Bandlight("spectral " + in + "'" + dir + "/out.tif' --light-group key=A:D65"),
                 "only an EXR keeps channel names");
    CheckOneLine(Bandlight("render '" + std::string(SCENES_DIR) + "/two_lights.yaml' "
                           "--light-groups -o '" + dir + "/render.tif'"),
                 "only an EXR keeps channel names");
    // Whatever writes them: the image module refuses the names it would lose.
    CheckOneLine(Bandlight("apply " + in + "'" + dir + "/out.tif' --from A --to D65"),
                 "would become anonymous channels");
    for (const char* f : {"out.tif", "render.tif", "render.png"})
    {
        CHECK(!fs::exists(dir + "/" + f));
    }
}

TEST_CASE("A light-group file: comments, any line ends, and each mistake at its line",
          "[cli][mistakes]")
{
    const std::string dir = Folder("light_group_file");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/two_lights.yaml' --light-groups "
                      "-o '" + dir + "/shot.exr'")
                .code == 0);
    const std::string in = "'" + dir + "/shot.exr' '" + dir + "/out.exr' ";
    const auto write = [&](const std::string& name, const std::string& text)
    {
        std::ofstream(dir + "/" + name, std::ios::binary) << text;
        return "--light-group-file '" + dir + "/" + name + "'";
    };
    // A trailing comment, and lines ended by CR alone (old Mac editors): the
    // same relight as the plain file.
    REQUIRE(Bandlight("apply " + in + write("plain.txt", "key=A:D65\nfill=F11:F11\n")).code == 0);
    const std::string plain = dir + "/plain.exr";
    fs::rename(dir + "/out.exr", plain);
    for (const std::string text :
         {"key=A:D65  # the key, tungsten\nfill=F11:F11\t# the fill\n", "key=A:D65\rfill=F11:F11\r",
          "# groups\r\nkey=A:D65\r\nfill=F11:F11\r\n"})
    {
        INFO(text);
        const Result r = Bandlight("apply " + in + write("g.txt", text));
        INFO(r.err);
        REQUIRE(r.code == 0);
        CHECK(Sh("oiiotool --no-autopremult '" + plain + "' '" + dir +
                 "/out.exr' --diff --fail 0 --failpercent 0")
                  .code == 0);
        fs::remove(dir + "/out.exr");
    }
    CheckOneLine(Bandlight("apply " + in + write("m.txt", "key=A:D65@nosuch\nfill=F11:F11\n")),
                 "m.txt:1: ");
    CheckOneLine(Bandlight("apply " + in + write("i.txt", "key=A:D65\nfill=F11:XYZ\n")),
                 "i.txt:2: unknown illuminant 'XYZ'");
    CheckOneLine(Bandlight("apply " + in + "--light-group-file ''"), "is an empty path");
    CHECK(!fs::exists(dir + "/out.exr"));
}

namespace
{
/// A light-group render in Arnold's naming: beauty R, G, B, A and groups
/// key and fill, 4x3 pixels; `fill` scales the fill group (2: the groups
/// sum past the beauty), `nan` puts a NaN into the key group.
std::string ArnoldShot(const std::string& path, float fill = 1.0f, bool nan = false)
{
    const std::vector<std::string> names = {
        "R",           "G",           "B",          "A",          "RGBA_fill.B",
        "RGBA_fill.G", "RGBA_fill.R", "RGBA_key.B", "RGBA_key.G", "RGBA_key.R"};
    OIIO::ImageSpec spec(4, 3, int(names.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    std::vector<float> px(12 * names.size());
    for (size_t p = 0; p < 12; ++p)
    {
        float* v = &px[p * names.size()];
        for (int c = 0; c < 3; ++c)
        {
            v[6 - c] = fill * 0.2f;
            v[9 - c] = 0.3f + 0.01f * float(p);
            v[c] = 0.2f + 0.3f + 0.01f * float(p);
        }
        v[3] = 1.0f;
    }
    if (nan)
    {
        px[5 * names.size() + 8] = std::nanf("");
    }
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    REQUIRE(out->close());
    return path;
}
}  // namespace

TEST_CASE("apply --light-group: bad input is one line naming the group or file, nothing written",
          "[cli][mistakes][lightgroups]")
{
    const std::string dir = Folder("lightgroups");
    const std::string shot = ArnoldShot(dir + "/shot.exr");
    const std::string out = dir + "/out.exr";
    const std::string apply = "apply '" + shot + "' '" + out + "' ";
    SECTION("a group the file does not hold")
    {
        CheckOneLine(Bandlight(apply + "--light-group rim=A:D65"),
                     "shot.exr: has no light group 'rim' (it has fill, key)");
    }
    SECTION("two groups resolving to the same layer")
    {
        CheckOneLine(Bandlight(apply + "--light-group key=A:D65 --light-group rim=RGBA_key"),
                     "light groups 'key' and 'rim' resolve to the same channel");
    }
    SECTION("groups that are no partition of the beauty")
    {
        const std::string over = ArnoldShot(dir + "/over.exr", 2.0f);
        CheckOneLine(Bandlight("apply '" + over + "' '" + out + "' --light-group key=A:D65"),
                     "over.exr: the light groups sum to more than the beauty at pixel (0, 0)");
    }
    SECTION("NaN in a group is guarded as every pixel path guards it, and counted")
    {
        const std::string nan = ArnoldShot(dir + "/nan.exr", 1.0f, true);
        const std::string guarded = dir + "/guarded.exr";
        const Result r =
            Bandlight("apply '" + nan + "' '" + guarded + "' --light-group fill=F11:D65");
        INFO(r.err);
        CHECK(r.code == 0);
        CHECK_THAT(r.err, Contains("nan.exr: 1 pixels held NaN or infinite values"));
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(guarded);
        REQUIRE(in);
        const OIIO::ImageSpec& spec = in->spec();
        std::vector<float> px(size_t(spec.image_pixels()) * size_t(spec.nchannels));
        REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
        CHECK(std::all_of(px.begin(), px.end(), [](float v) { return std::isfinite(v); }));
        fs::remove(guarded);
    }
    SECTION("--light-group with --look, or with --from")
    {
        REQUIRE(Bandlight("config --out '" + dir + "/pkg' --illuminants A,D65 --methods bradford")
                    .code == 0);
        CheckOneLine(Bandlight(apply + "--look bradford_A_to_D65 --config '" + dir +
                               "/pkg' --light-group key=A:D65"),
                     "--look applies one look to the whole image: --light-group does not apply");
        CheckOneLine(Bandlight(apply + "--from A --to D65 --light-group key=A:D65"),
                     "--from does not apply with --light-group");
    }
    SECTION("a matte of another size than the plate")
    {
        const std::vector<std::string> names = {"A"};
        OIIO::ImageSpec spec(5, 3, 1, OIIO::TypeDesc::FLOAT);
        spec.channelnames = names;
        const std::vector<float> ones(15, 1.0f);
        auto matte = OIIO::ImageOutput::create(dir + "/matte.exr");
        REQUIRE(matte);
        REQUIRE(matte->open(dir + "/matte.exr", spec));
        REQUIRE(matte->write_image(OIIO::TypeDesc::FLOAT, ones.data()));
        REQUIRE(matte->close());
        CheckOneLine(Bandlight(apply + "--matte '" + dir +
                               "/matte.exr' --look-inside A:D65 --look-outside F11:D65"),
                     "matte.exr: the matte's data window is 5x3 at (0, 0)");
        CheckOneLine(Bandlight(apply + "--matte '" + dir + "/matte.exr' --look-inside A:D65"),
                     "give --matte MATTE.exr[:CHANNEL] with --look-inside FROM:TO and "
                     "--look-outside FROM:TO (or looks of --config DIR)");
    }
    SECTION("a malformed --light-group")
    {
        CheckOneLine(Bandlight(apply + "--light-group key"), "--light-group takes NAME=FROM:TO");
        CheckOneLine(Bandlight(apply + "--light-group key=A:"), "give both lights");
    }
    CHECK_FALSE(fs::exists(out));
    // The good run: relit, the beauty the sum.
    const Result ok = Bandlight(apply + "--light-group key=A:D65 --method rootpoly");
    INFO(ok.err);
    CHECK(ok.code == 0);
    CHECK_THAT(ok.err, Contains("2 light groups (fill, key), Arnold naming, beauty R, G, B"));
    CHECK(fs::is_regular_file(out));
}

TEST_CASE(
    "apply --matte with looks of a config: options that do not fit are one line, nothing "
    "written",
    "[cli][mistakes][lightgroups]")
{
    const std::string dir = Folder("matte_looks");
    const std::string plate = ArnoldShot(dir + "/plate.exr");
    {
        const std::vector<std::string> names = {"A"};
        OIIO::ImageSpec spec(4, 3, 1, OIIO::TypeDesc::FLOAT);
        spec.channelnames = names;
        const std::vector<float> half(12, 0.5f);
        auto matte = OIIO::ImageOutput::create(dir + "/matte.exr");
        REQUIRE(matte);
        REQUIRE(matte->open(dir + "/matte.exr", spec));
        REQUIRE(matte->write_image(OIIO::TypeDesc::FLOAT, half.data()));
        REQUIRE(matte->close());
    }
    REQUIRE(Bandlight("config --out '" + dir + "/cfg' --illuminants A,D65,F11 --methods bradford")
                .code == 0);
    const std::string out = dir + "/out.exr";
    const std::string apply =
        "apply '" + plate + "' '" + out + "' --matte '" + dir + "/matte.exr' ";
    const std::string config = "--config '" + dir + "/cfg' ";
    SECTION("a look's name without --config")
    {
        CheckOneLine(Bandlight(apply + "--look-inside bradford_A_to_D65 --look-outside F11:D65"),
                     "--look-inside takes FROM:TO, or a look of --config DIR, got "
                     "'bradford_A_to_D65'");
    }
    SECTION("a value that is neither a look of the config nor FROM:TO")
    {
        CheckOneLine(
            Bandlight(apply + config + "--look-inside bradford_A_to_D66 --look-outside F11:D65"),
            "--look-inside 'bradford_A_to_D66' is no look of " + dir +
                "/cfg; its looks: bradford_A_to_D65, bradford_A_to_F11, "
                "bradford_D65_to_A, bradford_D65_to_F11, bradford_F11_to_A, "
                "bradford_F11_to_D65");
        CheckOneLine(Bandlight(apply + config +
                               "--look-inside bradford_A_to_D65 --look-outside F11:nowhere"),
                     "--look-outside 'F11:nowhere' is no look of " + dir + "/cfg, nor FROM:TO (");
    }
    SECTION("--look with --matte")
    {
        CheckOneLine(Bandlight(apply + config +
                               "--look bradford_A_to_D65 --look-inside bradford_A_to_D65 "
                               "--look-outside bradford_F11_to_D65"),
                     "--matte relights each side with its own change of light: --look");
    }
    SECTION("--config that neither side uses")
    {
        CheckOneLine(Bandlight(apply + config + "--look-inside A:D65 --look-outside F11:D65"),
                     "--config holds looks, and neither --look-inside nor --look-outside names "
                     "one of them");
    }
    SECTION("a method or the lights beside two looks")
    {
        CheckOneLine(Bandlight(apply + config +
                               "--look-inside bradford_A_to_D65 --look-outside "
                               "bradford_F11_to_D65 --method cat02"),
                     "--look-inside and --look-outside are looks of --config, applied as they "
                     "are: --method do not apply");
        CheckOneLine(Bandlight(apply + "--look-inside A:D65 --look-outside F11:D65 --from A"),
                     "--matte relights each side with its own change of light");
    }
    CHECK_FALSE(fs::exists(out));
    // The good run: both looks by name, and a look beside a change of light.
    const Result ok =
        Bandlight(apply + config + "--look-inside bradford_A_to_D65 --look-outside F11:D65");
    INFO(ok.err);
    CHECK(ok.code == 0);
    CHECK_THAT(ok.out, Contains("(inside: look bradford_A_to_D65, outside: bradford_F11_to_D65"));
    CHECK(fs::is_regular_file(out));
}

TEST_CASE("A denoised beauty: refused by default, rebuilt or its difference carried when asked",
          "[cli][mistakes][lightgroups]")
{
    // A denoiser smooths the beauty and not the groups: here the groups sum
    // to more than the beauty (fill doubled), no partition of it.
    const std::string dir = Folder("denoised");
    const std::string shot = ArnoldShot(dir + "/denoised.exr", 2.0f);
    const std::string apply = "apply '" + shot + "' '" + dir + "/out.exr' --light-group key=A:D65 ";
    CheckOneLine(Bandlight(apply), "sum to more than the beauty");
    CheckOneLine(Bandlight(apply + "--light-group-beauty denoise"), "--light-group-beauty is "
                                                                   "residual");
    // Each channel by its name (EXR orders them as it likes): name -> 12 values.
    const auto read = [&](const std::string& path, std::string* transform = nullptr)
    {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
        REQUIRE(in);
        const OIIO::ImageSpec& spec = in->spec();
        if (transform)
        {
            *transform = spec.get_string_attribute("bandlight:transform");
        }
        std::vector<float> px(size_t(spec.image_pixels()) * size_t(spec.nchannels));
        REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
        std::map<std::string, std::vector<float>> channels;
        for (int c = 0; c < spec.nchannels; ++c)
        {
            for (size_t p = 0; p < 12; ++p)
            {
                channels[spec.channelnames[size_t(c)]].push_back(
                    px[p * size_t(spec.nchannels) + size_t(c)]);
            }
        }
        return channels;
    };
    const auto in = read(shot);
    for (const std::string rule : {"rebuild", "difference"})
    {
        INFO(rule);
        const Result r = Bandlight(apply + "--light-group-beauty " + rule);
        INFO(r.err);
        REQUIRE(r.code == 0);
        std::string transform;
        const auto out = read(dir + "/out.exr", &transform);
        CHECK_THAT(transform, Contains(rule == "rebuild" ? "beauty rebuilt from the relit groups"
                                                         : "the beauty's difference"));
        for (size_t p = 0; p < 12; ++p)
        {
            for (const std::string c : {"R", "G", "B"})
            {
                const auto sum = [&](const std::map<std::string, std::vector<float>>& im)
                { return double(im.at("RGBA_fill." + c)[p]) + im.at("RGBA_key." + c)[p]; };
                const double difference = in.at(c)[p] - sum(in);
                CHECK(out.at(c)[p] ==
                      Approx(rule == "rebuild" ? sum(out) : sum(out) + difference).margin(1e-6));
            }
        }
        fs::remove(dir + "/out.exr");
    }
}
