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

#include "cli/MistakesSupport.h"
#include "cli/RunCommand.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::Result;
using test::Sh;
using test::Slurp;
using test::CheckOneLine;
using test::Folder;
using test::TempPath;

namespace fs = std::filesystem;

namespace
{

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
