// SPDX-License-Identifier: BSD-3-Clause
// What users get wrong, tried as they would: each mistake gets one line on
// stderr and exit code 2 before any work, and nothing of theirs is lost.
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "cli/RunCommand.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::Result;
using test::Sh;
using test::Slurp;
using test::TempPath;

namespace fs = std::filesystem;

namespace
{
/// A fresh folder for one test.
std::string Folder(const std::string& name)
{
    const std::string dir = TempPath("mistakes_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// One line on stderr: the mistake is named, nothing else is printed.
void CheckOneLine(const Result& r, const std::string& mentions)
{
    CHECK(r.code == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Contains(mentions));
}

/// A small spectral render (Fichet layout) to work on.
std::string SpectralShot(const std::string& dir)
{
    const std::string scene = dir + "/scene.yaml";
    std::ofstream(scene) << "camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, "
                            "width: 24, height: 16}\n"
                            "render: {mode: spectral, output: acescg, step: 10}\n"
                            "lights:\n  - {type: directional, direction: [0, 0, -1], "
                            "spectrum: F11}\n"
                            "materials:\n  red: {diffuse: TCS01}\n"
                            "objects:\n  - {sphere: {center: [0, 0, 0], radius: 1}, material: "
                            "red}\n";
    const std::string shot = dir + "/shot.exr";
    REQUIRE(Bandlight("render '" + scene + "' --spectra -o '" + shot + "'").code == 0);
    return shot;
}
}  // namespace

TEST_CASE("spectral IN IN is refused and the spectral render is kept", "[cli][mistakes]")
{
    const std::string dir = Folder("spectral_in_place");
    const std::string shot = SpectralShot(dir);
    const std::string before = Slurp(shot);
    const Result r = Bandlight("spectral '" + shot + "' '" + shot + "' --from F11 --to D65");
    CheckOneLine(r, "is the input");
    CHECK(Slurp(shot) == before);
    // The same file by another name is the same file.
    const Result again =
        Bandlight("spectral '" + shot + "' '" + dir + "/./shot.exr' --from F11 --to D65");
    CHECK(again.code == 2);
    CHECK(Slurp(shot) == before);
}

TEST_CASE("config --base into the base's own folder is refused and the studio config is kept",
          "[cli][mistakes]")
{
    const std::string studio = Folder("studio");
    REQUIRE(
        Bandlight("config --out '" + studio + "' --illuminants A,D65 --methods bradford").code ==
        0);
    const std::string before = Slurp(studio + "/config.ocio");
    const Result r = Bandlight("config --base '" + studio + "/config.ocio' --out '" + studio +
                               "' --illuminants A,F11 --methods cat02");
    CheckOneLine(r, "the folder of --base");
    CHECK(Slurp(studio + "/config.ocio") == before);
    // Its own folder named another way ("studio/.") is the same folder.
    CHECK(Bandlight("config --base '" + studio + "/config.ocio' --out '" + studio +
                    "/.' --illuminants A,F11 --methods cat02")
              .code == 2);
    CHECK(Slurp(studio + "/config.ocio") == before);
}

TEST_CASE("Empty output paths are refused, never reported as written", "[cli][mistakes]")
{
    const std::string dir = Folder("empty");
    for (const std::string& args :
         {std::string("config --out '' --illuminants A,D65 --methods bradford"),
          std::string("lut --from A --to D65 -o ''"),
          std::string("accuracy --illuminants A,D65 --methods bradford --ideal-only --no-cost "
                      "--json ''"),
          std::string("accuracy --illuminants A,D65 --methods bradford --ideal-only --no-cost "
                      "--plot ''")})
    {
        INFO(args);
        const Result r = Sh("cd '" + dir + "' && '" + BANDLIGHT_EXE + "' " + args);
        CheckOneLine(r, "'' (an empty path)");
        CHECK_THAT(r.out, !Contains("Wrote"));
    }
    CHECK(fs::is_empty(dir));
}

TEST_CASE("Options that do not apply are refused, naming them", "[cli][mistakes]")
{
    const std::string dir = Folder("options");
    REQUIRE(
        Bandlight("config --out '" + dir + "/pkg' --illuminants A,D65 --methods bradford").code ==
        0);
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/materials_A.yaml' -o '" + dir +
                      "/plate.exr'")
                .code == 0);
    SECTION("apply --look with the options of a change of light")
    {
        const Result r =
            Bandlight("apply '" + dir + "/plate.exr' '" + dir +
                      "/out.exr' --look bradford_A_to_D65 --config '" + dir +
                      "/pkg' --from F11 --to A --method band3 --camera '" + dir + "/missing.csv'");
        CheckOneLine(r, "--look");
        CHECK_THAT(r.err, Contains("--from") && Contains("--method") && Contains("--camera"));
        CHECK(!fs::exists(dir + "/out.exr"));
    }
    SECTION("config --base-paths without --base")
    {
        CheckOneLine(Bandlight("config --out '" + dir + "/x' --base-paths absolute"),
                     "--base-paths");
        CHECK(!fs::exists(dir + "/x"));
    }
    SECTION("empty lists")
    {
        CheckOneLine(Bandlight("config --out '" + dir + "/y' --illuminants ''"),
                     "--illuminants is empty");
        CheckOneLine(Bandlight("config --out '" + dir + "/y' --methods ' , '"),
                     "--methods is empty");
        CHECK(!fs::exists(dir + "/y"));
    }
}

TEST_CASE(
    "lut: the format follows the extension, and a format its extension contradicts is refused",
    "[cli][mistakes]")
{
    const std::string dir = Folder("lut_format");
    REQUIRE(Bandlight("lut --from A --to D65 --method bradford --size 9 -o '" + dir + "/x.cube'")
                .code == 0);
    // A .cube file holds a cube, not CLF's XML.
    const std::string cube = Slurp(dir + "/x.cube");
    CHECK_THAT(cube, Contains("LUT_3D_SIZE 9"));
    CHECK_THAT(cube, !Contains("<?xml"));
    // It says, in the file, that it is the middle of a chain.
    CHECK_THAT(cube, Contains("Shaper-encoded in and out: apply x.shaper.clf before this LUT"));
    CHECK(fs::is_regular_file(dir + "/x.shaper.clf"));
    CheckOneLine(Bandlight("lut --from A --to D65 --format clf -o '" + dir + "/y.cube'"),
                 "is named .clf");
    CheckOneLine(Bandlight("lut --from A --to D65 -o '" + dir + "/y.txt'"), ".txt");
    CheckOneLine(Bandlight("lut --from A --to D65 -o '" + dir + "/y.icc'"), ".icc");
    CHECK(!fs::exists(dir + "/y.cube"));
    CHECK(!fs::exists(dir + "/y.txt"));
}

TEST_CASE("Output paths are checked before any work", "[cli][mistakes]")
{
    const std::string dir = Folder("before_work");
    SECTION("accuracy --json into a missing folder fails at once")
    {
        const auto t0 = std::chrono::steady_clock::now();
        const Result r = Bandlight("accuracy --json '" + dir + "/nodir/x.json'");
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains("nodir/x.json: cannot write there: the folder") &&
                              Contains("does not exist"));
        CHECK(s < 5.0);  // the full run takes minutes; the check is immediate
    }
    SECTION("a plot that is neither .png nor .svg")
    {
        CheckOneLine(Bandlight("accuracy --plot '" + dir + "/x.jpg'"), ".png or .svg");
    }
    SECTION("a folder where a file is written")
    {
        fs::create_directories(dir + "/a.cube");
        CheckOneLine(Bandlight("lut --from A --to D65 -o '" + dir + "/a.cube'"), "is a folder");
    }
}

TEST_CASE("Images are read from regular files: a device or a FIFO is refused at once",
          "[cli][mistakes]")
{
    const std::string dir = Folder("devices");
    CheckOneLine(Bandlight("apply /dev/zero '" + dir + "/out.exr' --from A --to D65"), "a device");
    CheckOneLine(Bandlight("spectral /dev/zero '" + dir + "/out.exr'"), "a device");
    const std::string fifo = dir + "/x.exr";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CheckOneLine(Bandlight("apply '" + fifo + "' '" + dir + "/out.exr' --from A --to D65"),
                 "a FIFO");
    CHECK(!fs::exists(dir + "/out.exr"));
}

TEST_CASE("Every file a request names is refused at once when it is a FIFO", "[cli][mistakes]")
{
    // Opening a FIFO waits for a writer: each input is asked what it is
    // before anything opens it. `timeout` turns a hang into a failure.
    const std::string dir = Folder("fifos");
    const std::string camera =
        std::string(BANDLIGHT_TEST_DATA_ROOT) + "/rawtoaces/arri_d21_380_780_5.json";
    for (const char* name : {"light.csv", "config.ocio", "cfg/config.ocio", "cam.json"})
    {
        fs::create_directories(fs::path(dir + "/" + name).parent_path());
        REQUIRE(::mkfifo((dir + "/" + name).c_str(), 0600) == 0);
    }
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/materials_A.yaml' -o '" + dir +
                      "/in.exr'")
                .code == 0);
    const std::string in = "'" + dir + "/in.exr' '" + dir + "/out.exr' ";
    const struct
    {
        std::string args;
        const char* says;
    } cases[] = {
        {"idt --camera '" + camera + "' --lights '" + dir + "/light.csv'", "not a regular file"},
        {"idt --camera '" + camera + "' --lights A --training '" + dir + "/light.csv'",
         "not a regular file"},
        {"idt --camera '" + dir + "/cam.json' --lights A", "not a regular file"},
        {"apply " + in + "--look x --config '" + dir + "/cfg'", "not a regular file"},
        {"apply " + in + "--look x --config '" + dir + "/config.ocio'", "not a regular file"},
        {"config --base '" + dir + "/config.ocio' --out '" + dir + "/extended'",
         "not a regular file"},
        {"apply " + in + "--from '" + dir + "/light.csv' --to D65", "not a regular file"},
        {"apply " + in + "--light-group-file '" + dir + "/light.csv'", "not a regular file"},
    };
    for (const auto& c : cases)
    {
        INFO(c.args);
        const Result r = Sh("timeout 20 '" + std::string(BANDLIGHT_EXE) + "' " + c.args);
        CHECK(r.code != 124);  // not hung
        CheckOneLine(r, c.says);
    }
    CHECK(!fs::exists(dir + "/out.exr"));
    CHECK(!fs::exists(dir + "/extended"));
}

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

TEST_CASE("Skipping existing frames counts only regular files as finished", "[cli][mistakes]")
{
    const std::string dir = Folder("skip_dir");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/materials_A.yaml' -o '" + dir +
                      "/in.1001.exr'")
                .code == 0);
    fs::copy_file(dir + "/in.1001.exr", dir + "/in.1002.exr");
    fs::create_directories(dir + "/out.1002.exr");  // named like a frame, not one
    const Result r = Bandlight("apply '" + dir + "/in.####.exr' '" + dir +
                               "/out.####.exr' --frames 1001-1002 --from A --to D65 "
                               "--skip-existing");
    CheckOneLine(r, "out.1002.exr' is a folder");
    CHECK(!fs::exists(dir + "/out.1001.exr"));  // refused before any frame
}

TEST_CASE("OUT patterns with two frame fields expand both", "[cli][mistakes]")
{
    const std::string dir = Folder("two_fields");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/materials_A.yaml' -o '" + dir +
                      "/in.7.exr'")
                .code == 0);
    const Result r = Bandlight("apply '" + dir + "/in.#.exr' '" + dir +
                               "/out.##.%04d.exr' --frames 7 --from A --to D65");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(fs::is_regular_file(dir + "/out.07.0007.exr"));
}

TEST_CASE("A PNG's code values are not written into an EXR read as linear", "[cli][mistakes]")
{
    const std::string dir = Folder("png_to_exr");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/materials_A.yaml' -o '" + dir +
                      "/chart.exr'")
                .code == 0);
    REQUIRE(Sh("oiiotool '" + dir + "/chart.exr' --colorconvert linear sRGB -d uint8 -o '" + dir +
               "/chart.png'")
                .code == 0);
    CheckOneLine(Bandlight("apply '" + dir + "/chart.png' '" + dir + "/out.exr' --from A --to D65"),
                 "every host would read as linear");
    CHECK(!fs::exists(dir + "/out.exr"));
    // PNG to PNG stays as it was: decoded, relit, encoded again.
    CHECK(Bandlight("apply '" + dir + "/chart.png' '" + dir + "/out.png' --from A --to D65").code ==
          0);
}

TEST_CASE("Names are case-insensitive in every option that takes one", "[cli][mistakes]")
{
    const std::string dir = Folder("case");
    const std::string shot = SpectralShot(dir);
    const Result r = Bandlight("spectral '" + shot + "' '" + dir +
                               "/out.exr' --from F11 --to D65 --plates LIT --adaptation CAT02 "
                               "--sampling Auto");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(fs::is_regular_file(dir + "/out.exr"));
}

TEST_CASE("A missing spectrum file is called missing, not an unknown light", "[cli][mistakes]")
{
    const std::string dir = Folder("missing_light");
    CheckOneLine(Bandlight("xyz --illuminant '" + dir + "/missing.csv'"), "no such spectrum file");
    CheckOneLine(Bandlight("xyz --illuminant lamp.csv"), "lamp.csv: no such spectrum file");
    // A name that is neither lists the built-in lights.
    CheckOneLine(Bandlight("xyz --illuminant D66x"), "unknown illuminant");
}

TEST_CASE("Messages name what is wrong and where", "[cli][mistakes]")
{
    const std::string dir = Folder("messages");
    // A mistyped command is named, with the command it was likely meant to be.
    CheckOneLine(Bandlight("applyy"), "unknown command 'applyy' (did you mean apply?)");
    CheckOneLine(Bandlight(""), "give a command: tables, xyz");
    // A command without an option it requires is not an unknown command.
    Result noIlluminant = Bandlight("xyz");
    CheckOneLine(noIlluminant, "--illuminant is required");
    CHECK_THAT(noIlluminant.err, !Contains("unknown command"));
    // An empty scene is a missing file, not an option the command lacks.
    Result r = Bandlight("render ''");
    CheckOneLine(r, "'' (an empty path): no scene file to render");
    CHECK_THAT(r.err, !Contains("--text"));
    // A channel list whose one row has a wrong wavelength is not a header.
    const std::string shot = SpectralShot(dir);
    std::ofstream(dir + "/one.csv") << "band_00,abc\n";
    CheckOneLine(Bandlight("spectral '" + shot + "' '" + dir + "/o.exr' --channel-wavelengths '" +
                           dir + "/one.csv'"),
                 "one.csv:1: expected 'channel,wavelength_nm', got 'band_00,abc'");
    // An infinite wavelength is not called "not positive".
    CheckOneLine(
        Bandlight("spectral '" + shot + "' '" + dir + "/o.exr' --channel S0.400,000000nm=1e400"),
        "is given a wavelength that is not a finite number");
    CHECK_FALSE(fs::exists(dir + "/o.exr"));
}

TEST_CASE("An image that needs more memory than the process may have is named", "[cli][mistakes]")
{
#ifdef BANDLIGHT_SANITIZED_TESTS
    WARN(
        "skipped: AddressSanitizer reserves terabytes of address space; ulimit -v cannot be "
        "set under it");
    return;
#endif
    // OpenEXR reserves its scanline buffers itself: a 200000x1 image under a
    // limit on address space once failed with a bare "std::bad_alloc".
    const std::string dir = Folder("memory");
    const Result w =
        Sh("/usr/bin/python3 -c \"import numpy as np, OpenImageIO as oiio; "
           "s = oiio.ImageSpec(200000, 1, 3, 'float'); "
           "o = oiio.ImageOutput.create('" +
           dir + "/wide.exr'); o.open('" + dir +
           "/wide.exr', s); o.write_image(np.ones((1, 200000, 3), np.float32)); "
           "o.close()\"");
    REQUIRE(w.code == 0);
    const Result r = Sh("ulimit -v 1500000 && '" + std::string(BANDLIGHT_EXE) + "' apply '" + dir +
                        "/wide.exr' '" + dir + "/out.exr' --from A --to D65");
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("wide.exr: "));
    CHECK_THAT(r.err, !Contains("bad_alloc"));
    CHECK_FALSE(fs::exists(dir + "/out.exr"));
}

TEST_CASE("Commands say what they did and name lights after their files", "[cli][mistakes]")
{
    const std::string dir = Folder("said");
    REQUIRE(Bandlight("render '" + std::string(SCENES_DIR) + "/materials_A.yaml' -o '" + dir +
                      "/plate.exr'")
                .code == 0);
    // apply on one image prints one line on success.
    Result r = Bandlight("apply '" + dir + "/plate.exr' '" + dir +
                         "/out.exr' --from A --to D65 --method bradford");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.out ==
          "Applied bradford_A_to_D65 to " + dir + "/plate.exr; wrote " + dir + "/out.exr\n");
    // A lamp whose one column is headed "value" is the file's light.
    std::ofstream lamp(dir + "/tungsten3200.csv");
    lamp << "wavelength_nm,value\n";
    for (int nm = 380; nm <= 780; nm += 5)
    {
        lamp << nm << "," << 0.2 + 0.002 * (nm - 380) << "\n";
    }
    lamp.close();
    r = Bandlight("config --out '" + dir + "/cfg' --illuminants 'A," + dir +
                  "/tungsten3200.csv' --methods bradford");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(Slurp(dir + "/cfg/config.ocio"), Contains("bradford_A_to_tungsten3200"));
    CHECK_THAT(Slurp(dir + "/cfg/config.ocio"), !Contains("_to_value"));
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

TEST_CASE("idt: bad cameras, lights, charts and options are one line, exit 2, nothing written",
          "[cli][mistakes][idt]")
{
    const std::string dir = Folder("idt");
    const std::string d21 =
        std::string(BANDLIGHT_TEST_DATA_ROOT) + "/rawtoaces/arri_d21_380_780_5.json";
    const std::string out = " --json '" + dir + "/idt.json' --config '" + dir + "/cfg'";
    // A camera whose blue channel is dead.
    {
        std::ofstream f(dir + "/dead.csv");
        f << "nm,R,G,B\n";
        for (int l = 380; l <= 780; l += 5)
        {
            f << l << "," << std::exp(-0.5 * std::pow((l - 600) / 30.0, 2)) << ","
              << std::exp(-0.5 * std::pow((l - 540) / 30.0, 2)) << ",0\n";
        }
    }
    // A camera whose blue sees only 400–450 nm, and a light with no power there.
    {
        std::ofstream cam(dir + "/narrow.csv"), light(dir + "/orange.csv");
        cam << "nm,R,G,B\n";
        light << "nm,orange\n";
        for (int l = 380; l <= 780; l += 5)
        {
            cam << l << "," << std::exp(-0.5 * std::pow((l - 600) / 30.0, 2)) << ","
                << std::exp(-0.5 * std::pow((l - 540) / 30.0, 2)) << ","
                << (l >= 400 && l <= 450 ? 1.0 : 0.0) << "\n";
            light << l << "," << (l >= 500 ? 1.0 : 0.0) << "\n";
        }
    }
    // Chart RGB: too few patches for TCS (15), and a NaN.
    {
        std::ofstream few(dir + "/few.csv"), nan(dir + "/nan.csv");
        few << "name,R,G,B\n";
        nan << "name,R,G,B\n";
        for (int i = 1; i <= 15; ++i)
        {
            if (i <= 5)
            {
                few << "TCS" << i << ",0.2,0.3,0.4\n";
            }
            nan << "TCS" << i << "," << (i == 7 ? "nan" : "0.2") << ",0.3,0.4\n";
        }
    }
    const std::pair<std::string, std::string> mistakes[] = {
        {"--camera '" + dir + "/dead.csv' --lights D55", "no response"},
        {"--camera '" + dir + "/narrow.csv' --lights '" + dir + "/orange.csv'",
         "blue channel records nothing"},
        {"--chart-rgb '" + dir + "/few.csv' --chart TCS --light D55", "5 patches"},
        {"--chart-rgb '" + dir + "/nan.csv' --chart TCS --light D55", "nan.csv:8"},
        {"--camera '" + d21 + "' --lights 32OOK", "'32OOK' is not a colour temperature"},
        {"--camera '" + d21 + "' --as-shot-neutral 0.5,0,0.8", "--as-shot-neutral"},
        {"--camera '" + d21 + "' --interpolate 3200K", "--interpolate takes two lights"},
        {"--camera '" + d21 + "' --lights D55 --base '" + dir + "/x.ocio'", "--out"},
        {"--camera '" + d21 + "' --lights D55 --chart TCS", "--chart-rgb"},
        {"--camera '" + d21 + "'", "--lights"},
        {"--lights D55", "--camera"},
        {"--camera '" + d21 + "' --lights D55 --base-space rec709", "--base-space"},
        {"--camera '" + d21 + "' --lights 3200K,D55 --interpolate 3200k,5600K", "named twice"},
        {"--chart-rgb '" + dir + "/nan.csv' --chart TCS --light D55 --rootpoly 4", "--rootpoly"},
        {"--camera '" + d21 + "' --lights D55 --rootpoly 2", "--rootpoly"},
        {"--chart-rgb '" + dir + "/nan.csv' --chart TCS --light D55 --test-set TCS", "--test-set"},
    };
    for (const auto& [args, mentions] : mistakes)
    {
        INFO(args);
        const Result r = Bandlight("idt " + args + out);
        CheckOneLine(r, mentions);
        CHECK(r.out.empty());
    }
    // The base with an --out but a --config too.
    CheckOneLine(Bandlight("idt --camera '" + d21 + "' --lights D55 --base '" + dir +
                           "/x.ocio' --out '" + dir + "/o'" + out),
                 "give one of them");
    CHECK(!fs::exists(dir + "/idt.json"));
    CHECK(!fs::exists(dir + "/cfg"));
    CHECK(!fs::exists(dir + "/o"));
}

TEST_CASE("apply --look with the options of a change of light names each, as Python does",
          "[cli][mistakes]")
{
    const std::string dir = Folder("look_with_change");
    REQUIRE(Bandlight("config --out '" + dir + "/config' --illuminants A,D65 --methods bradford")
                .code == 0);
    // --method at its default value is still given, and still does not apply.
    const Result r = Bandlight("apply '" + dir + "/in.exr' '" + dir +
                               "/out.exr' --look bradford_A_to_D65 --config '" + dir +
                               "/config' --from A --method bradford --working-space acescg");
    CheckOneLine(r, "--look applies a look of --config as it is: --from, --method, "
                    "--working-space do not apply to it (give the look, or the change of light)");
    CHECK_FALSE(fs::exists(dir + "/out.exr"));
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
