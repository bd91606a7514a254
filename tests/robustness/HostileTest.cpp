// SPDX-License-Identifier: BSD-3-Clause
// Hostile input, one class per test case: strings that reach gnuplot, configs
// that refer to themselves, inputs long enough to break recursive parsers,
// numbers that overflow, sizes that would exhaust memory, output sets that
// fail half-way, and results that would not be finite. Each gives a defined
// result or one line "bandlight: ..." with exit code 2 — never a command run,
// a crash, a replaced output or NaN/Inf/null with exit code 0.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "robustness/HardValues.h"

using namespace bandlight::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

#if defined(__SANITIZE_ADDRESS__)
#define BANDLIGHT_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BANDLIGHT_TEST_UNDER_ASAN 1
#endif
#endif

namespace
{

/// A fresh, empty folder for one test.
std::string Folder(const std::string& name)
{
    const std::string dir = TempFile(name);
    Sh("rm -rf '" + dir + "' && mkdir -p '" + dir + "'");
    return dir;
}

void WriteText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

std::string ReadText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool Exists(const std::string& path)
{
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

/// A CSV spectrum file with one column named `name`, 0.5 at 380–780 nm.
std::string Remittance(const std::string& name, double value = 0.5)
{
    std::ostringstream csv;
    csv << "nm," << name << "\n";
    for (int nm = 380; nm <= 780; nm += 5)
    {
        csv << nm << "," << value << "\n";
    }
    return csv.str();
}

/// Quotes a path for the shell (single quotes, ' as '\'').
std::string ShellWord(const std::string& s)
{
    std::string out = "'";
    for (char c : s)
    {
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

/// Strings that would create INJECTED in the working folder if gnuplot (or
/// a shell) evaluated them where a name belongs.
const std::vector<std::string>& GnuplotPayloads()
{
    static const std::vector<std::string> payloads = {
        "a'.system('touch INJECTED').'",
        "a\".system(\"touch INJECTED\").\"",
        "`touch INJECTED`",
        "x' `touch INJECTED` '",
        "@MACRO' . system('touch INJECTED') . '",
        "back\\slash\\' . system('touch INJECTED') . '",
        "quote' ! touch INJECTED '",
        "$DATA' . system('touch INJECTED') . '",
        "EOD",
    };
    return payloads;
}

/// Exactly one line on stderr, starting "bandlight: ".
void CheckOneLineError(const Result& r)
{
    CHECK(r.code == 2);
    CHECK_THAT(r.err, StartsWith("bandlight: "));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

}  // namespace

TEST_CASE("Names and file names never reach gnuplot as code", "[robustness][hostile][plot]")
{
    const std::string dir = Folder("gnuplot");
    // Commands run in `dir`; each payload would create `dir`/INJECTED if
    // gnuplot (or a shell) evaluated it.
    const std::string marker = dir + "/INJECTED";
    const auto plot = [&](const std::string& in, const std::string& out)
    {
        return Sh("cd " + ShellWord(dir) + " && '" + BANDLIGHT_EXE + "' plot --reflectance " +
                  ShellWord(in) + " -o " + ShellWord(out));
    };
    for (const std::string& p : GnuplotPayloads())
    {
        INFO(p);
        // The payload as a spectrum's name (a CSV column header).
        WriteText(dir + "/spectrum.csv", Remittance("\"" + p + "\""));
        for (const char* out : {"plot.png", "plot.svg"})
        {
            std::remove((dir + "/" + out).c_str());  // each run writes its own
            const Result r = plot("spectrum.csv", out);
            CHECK(r.code == 0);
            CHECK(Exists(dir + "/" + out));
            CHECK_FALSE(Exists(marker));
        }
    }
    // Payloads, line breaks and a leading '-' in the input's and output's names.
    const std::string evil =
        "n'`touch INJECTED`@x$(touch INJECTED)\n'; system('touch INJECTED')\n.csv";
    WriteText(dir + "/" + evil, Remittance("plain"));
    const std::string evilOut =
        "-o'.system('touch INJECTED').'`touch INJECTED`\n!touch INJECTED\n.png";
    const Result r = plot(evil, evilOut);
    CHECK(r.code == 0);
    CHECK(Exists(dir + "/" + evilOut));
    CHECK_FALSE(Exists(marker));
    // A CGATS sample name, quoted, with a payload.
    WriteText(dir + "/names.sp",
              "CGATS.17\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_380 SPEC_480 SPEC_580 SPEC_680 "
              "SPEC_780\nEND_DATA_FORMAT\nBEGIN_DATA\n\"x' . system('touch INJECTED') . '\" 0.5 "
              "0.5 0.5 0.5 0.5\nEND_DATA\n");
    CHECK(plot("names.sp", "cg.svg").code == 0);
    CHECK_FALSE(Exists(marker));
    // No gnuplot input is left behind.
    CHECK(Sh("ls -a " + ShellWord(dir) + " | grep -c tmp-").out == "0\n");
}

TEST_CASE("Light names and file names never reach gnuplot as code in quality --plot",
          "[robustness][hostile][plot][quality]")
{
    const std::string dir = Folder("quality_plot");
    const std::string marker = dir + "/INJECTED";
    const auto quality = [&](const std::string& args)
    {
        return Sh("cd " + ShellWord(dir) + " && '" + BANDLIGHT_EXE + "' quality " + args);
    };
    for (const std::string& p : GnuplotPayloads())
    {
        INFO(p);
        // The payload as a light's name (a CSV column header), for the
        // light and for the reference: both are drawn and labelled.
        WriteText(dir + "/light.csv", Remittance("\"" + p + "\""));
        for (const char* out : {"q.png", "q.svg"})
        {
            std::remove((dir + "/" + out).c_str());  // each run writes its own
            const Result r = quality("light.csv D65 --reference light.csv --plot " +
                                     std::string(out));
            CHECK(r.code == 0);
            CHECK(Exists(dir + "/" + out));
            CHECK_FALSE(Exists(marker));
        }
    }
    // Payloads and line breaks in the light's file name and the plot's.
    const std::string evil = "l'`touch INJECTED`$(touch INJECTED)\n'; system('touch INJECTED')\n.csv";
    WriteText(dir + "/" + evil, Remittance("plain"));
    const std::string evilOut = "p'.system('touch INJECTED').'`touch INJECTED`\n!touch INJECTED\n.png";
    const Result r = quality(ShellWord(evil) + " --plot " + ShellWord(evilOut));
    CHECK(r.code == 0);
    CHECK(Exists(dir + "/" + evilOut));
    CHECK_FALSE(Exists(marker));
    // No gnuplot input is left behind.
    CHECK(Sh("ls -a " + ShellWord(dir) + " | grep -c tmp-").out == "0\n");
}

TEST_CASE("Configs that refer to themselves are refused before OCIO recurses",
          "[robustness][hostile][config]")
{
    const std::string dir = Folder("cycles");
    const std::string head =
        "ocio_profile_version: 2\nroles:\n  default: lin\n  scene_linear: lin\n"
        "displays:\n  d:\n    - !<View> {name: v, colorspace: lin}\n";
    struct Case
    {
        const char* name;
        std::string body;
        const char* chain;
    };
    const std::vector<Case> cases = {
        {"space",
         head + "colorspaces:\n  - !<ColorSpace>\n    name: lin\n"
                "  - !<ColorSpace>\n    name: a\n"
                "    to_scene_reference: !<ColorSpaceTransform> {src: a, dst: lin}\n",
         "colour space 'a' -> colour space 'a'"},
        {"two",
         head + "colorspaces:\n  - !<ColorSpace>\n    name: lin\n"
                "  - !<ColorSpace>\n    name: a\n"
                "    to_scene_reference: !<ColorSpaceTransform> {src: b, dst: lin}\n"
                "  - !<ColorSpace>\n    name: b\n"
                "    to_scene_reference: !<ColorSpaceTransform> {src: a, dst: lin}\n",
         "colour space 'a' -> colour space 'b' -> colour space 'a'"},
        {"look",
         head + "colorspaces:\n  - !<ColorSpace>\n    name: lin\n"
                "looks:\n  - !<Look>\n    name: L\n    process_space: lin\n"
                "    transform: !<LookTransform> {src: lin, dst: lin, looks: L}\n",
         "look 'L' -> look 'L'"},
        {"view",
         "ocio_profile_version: 2\nroles:\n  default: lin\n  scene_linear: lin\n"
         "displays:\n  d:\n    - !<View> {name: v, colorspace: out}\n"
         "colorspaces:\n  - !<ColorSpace>\n    name: lin\n  - !<ColorSpace>\n    name: out\n"
         "    from_scene_reference: !<DisplayViewTransform> {src: lin, display: d, view: v}\n",
         "colour space 'out' -> view 'd/v' -> colour space 'out'"},
    };
    for (const Case& c : cases)
    {
        INFO(c.name);
        const std::string file = dir + "/" + c.name + ".ocio";
        WriteText(file, c.body);
        const std::string expected = "bandlight: " + file +
                                     ": the config refers to itself, which OpenColorIO cannot "
                                     "resolve: " +
                                     c.chain + "\n";
        Result r = Bandlight("config --base '" + file + "' --out '" + dir + "/out'");
        CheckOneLineError(r);
        CHECK(r.err == expected);
        r = Bandlight("apply '" + dir + "/in.exr' '" + dir + "/out.exr' --config '" + file +
                      "' --look L");
        CheckOneLineError(r);
        CHECK(r.err == expected);
    }
}

TEST_CASE("Long arguments are parsed without recursion", "[robustness][hostile][cli]")
{
    const std::string dir = Folder("long");
    const std::string spaces(40000, ' ');
    Result r = Bandlight("apply '" + dir + "/in.####.exr' '" + dir + "/out.####.exr' --frames '" +
                         spaces + "1-2' --from A --to D65");
    CheckOneLineError(r);
    CHECK_THAT(r.err, Contains("in.0001.exr: cannot read image"));

    r = Bandlight("apply '" + dir + "/in.%0" + std::string(40000, '4') + "d.exr' '" + dir +
                  "/o.%04d.exr' --frames 1-2 --from A --to D65");
    CheckOneLineError(r);
    CHECK_THAT(r.err, Contains("the frame number's width is at most 9 digits"));
    CHECK_THAT(r.err, Contains("more bytes)"));  // the echo of the pattern is cut short

    r = Bandlight("config --base '" + dir + "/" + std::string(60000, 'a') + "' --out '" + dir +
                  "/o'");
    CheckOneLineError(r);
    CHECK(r.err.size() < 5000);
}

TEST_CASE("Thread counts are bounded", "[robustness][hostile][cli]")
{
    const Result r =
        Bandlight("render '" + std::string(SCENES_DIR) +
                  "/materials_D65.yaml' --threads 100000 -o '" + TempFile("threads.exr") + "'");
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: --threads: Value 100000 not in range 0 to 256\n");
}

TEST_CASE("Numbers that overflow an int are errors, not internal errors",
          "[robustness][hostile][cli]")
{
    const std::string dir = Folder("overflow");
    // Run inside the folder: a message shortens a long path, and the
    // build folder's temporary path may be long.
    Result r = Sh("cd '" + dir + "' && '" + BANDLIGHT_EXE +
                  "' apply 'in.%099999999999d.exr' 'o.%04d.exr' --frames 1-2 --from A --to D65");
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: frame pattern 'in.%099999999999d.exr': the frame number's width "
                   "is at most 9 digits\n");

    // OCIO's message quotes the file name, which holds "line <huge number>".
    const std::string named = dir + "/line 99999999999999999999.ocio";
    WriteText(named, "ocio_profile_version: 2\ncolorspaces: [\n");
    r = Bandlight("config --base '" + named + "' --out '" + dir + "/o'");
    CheckOneLineError(r);
    CHECK_THAT(r.err, StartsWith("bandlight: " + named));

    r = Bandlight("apply '" + dir + "/in.####.exr' '" + dir +
                  "/o.####.exr' --frames 1-99999999999 --from A --to D65");
    CheckOneLineError(r);
    CHECK_THAT(r.err, Contains("frame numbers of at most 9 digits"));
}

TEST_CASE("Sizes are checked against limits before anything is allocated",
          "[robustness][hostile][memory]")
{
    const std::string dir = Folder("limits");
    Result r = Bandlight("apply '" + dir + "/in.####.exr' '" + dir +
                         "/o.####.exr' --frames -999999999-999999999 --from A --to D65");
    CheckOneLineError(r);
    CHECK(r.err ==
          "bandlight: frame range '-999999999-999999999': 1999999999 frames; at most 1000000 per "
          "call (split the range)\n");

    for (const char* step : {"1e-6", "1e-300", "60"})
    {
        const std::string scene = dir + "/step.yaml";
        WriteText(scene,
                  std::string("render: {mode: spectral, step: ") + step +
                      "}\nlights:\n  - {type: ambient, spectrum: D65}\n"
                      "materials:\n  m: {diffuse: 0.5}\n"
                      "objects:\n  - {sphere: {center: [0, 0, 0], radius: 1}, material: m}\n");
        r = Bandlight("render '" + scene + "' -o '" + dir + "/step.exr'");
        CheckOneLineError(r);
        CHECK(r.err ==
              "bandlight: " + scene + ":1: step must be from 0.1 to 50 nm, got " + step + "\n");
    }

    // 30 Mi one-character tokens in a CGATS file under the 64 MiB file limit.
    const std::string many = dir + "/many.sp";
    {
        std::ofstream f(many);
        f << "CGATS.17\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_380 SPEC_390\nEND_DATA_FORMAT\n"
             "BEGIN_DATA\n";
        const std::string chunk(1 << 20, ' ');
        std::string ones = chunk;
        for (size_t i = 0; i < ones.size(); i += 2)
        {
            ones[i] = '1';
        }
        for (int i = 0; i < 60; ++i)
        {
            f << ones;
        }
        f << "\nEND_DATA\n";
    }
    r = Bandlight("xyz --illuminant D65 --reflectance '" + many + "'");
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: " + many +
                       ":6: more than 4194304 values and keywords, the limit for a CGATS file\n");

    // A PNG whose header declares 100000 x 100000 RGB pixels (30 GB as float).
    const std::string png = dir + "/huge.png";
    {
        auto crc = [](const std::string& bytes)
        {
            uint32_t c = 0xFFFFFFFFu;
            for (unsigned char b : bytes)
            {
                c ^= b;
                for (int k = 0; k < 8; ++k)
                {
                    c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
                }
            }
            return c ^ 0xFFFFFFFFu;
        };
        auto be32 = [](uint32_t v) {
            return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
        };
        const std::string ihdr = "IHDR" + be32(100000) + be32(100000) + std::string{8, 2, 0, 0, 0};
        const std::string iend = "IEND";
        const std::string idat = "IDAT" + std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
        WriteText(png, std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + ihdr + be32(crc(ihdr)) +
                           be32(8) + idat + be32(crc(idat)) + be32(0) + iend + be32(crc(iend)));
    }
    r = Bandlight("apply '" + png + "' '" + dir + "/out.png' --from A --to D65");
    CheckOneLineError(r);
    CHECK_THAT(r.err, StartsWith("bandlight: " + png +
                                 ": the header declares 100000x100000 "
                                 "pixels x 3 channels, more than bandlight processes in memory"));
    CHECK_FALSE(Exists(dir + "/out.png"));
}

TEST_CASE("A set of outputs is replaced together or not at all", "[robustness][hostile][atomic]")
{
    const std::string dir = Folder("sets");

    SECTION("a LUT and its shaper")
    {
        const std::string cube = dir + "/o.cube";
        WriteText(cube, "previous LUT\n");
        // The shaper's name is taken by a folder: its rename must fail.
        ::mkdir((dir + "/o.shaper.clf").c_str(), 0755);
        const Result r =
            Bandlight("lut --from A --to D65 --method bradford --format cube -o '" + cube + "'");
        CheckOneLineError(r);
        CHECK_THAT(r.err, Contains("o.shaper.clf: cannot replace output file"));
        CHECK(ReadText(cube) == "previous LUT\n");
    }
    SECTION("a config and its LUTs")
    {
        const std::string out = dir + "/config";
        REQUIRE(
            Bandlight("config --out '" + out + "' --illuminants A,D65 --methods upsample,bradford")
                .code == 0);
        const Result luts = Sh("cd '" + out + "/luts' && ls && cat * | md5sum");
        ::rename((out + "/config.ocio").c_str(), (out + "/config.ocio.keep").c_str());
        ::mkdir((out + "/config.ocio").c_str(), 0755);
        const Result r = Bandlight("config --out '" + out +
                                   "' --illuminants A,D65 --methods upsample,bradford "
                                   "--lut-size 17 --working-space lin-rec709");
        CheckOneLineError(r);
        CHECK(Sh("cd '" + out + "/luts' && ls && cat * | md5sum").out == luts.out);
        CHECK(Sh("ls '" + out + "' '" + out + "/luts' | grep -c tmp-").out == "0\n");
    }
    SECTION("a render and its preview")
    {
        const std::string exr = dir + "/r.exr";
        WriteText(exr, "previous render\n");
        ::mkdir((dir + "/r.png").c_str(), 0755);
        const Result r = Bandlight("render '" + std::string(SCENES_DIR) +
                                   "/materials_D65.yaml' -o '" + exr + "'");
        CheckOneLineError(r);
        CHECK(ReadText(exr) == "previous render\n");
    }
    SECTION("an accuracy report and its plot")
    {
        const std::string json = dir + "/a.json";
        WriteText(json, "{}\n");
        ::mkdir((dir + "/a.png").c_str(), 0755);
        const Result r = Bandlight("accuracy --illuminants A,D65 --methods bradford --json '" +
                                   json + "' --plot '" + dir + "/a.png'");
        CheckOneLineError(r);
        CHECK(ReadText(json) == "{}\n");
    }
}

TEST_CASE("Illuminants without a white are refused and results are finite or an error",
          "[robustness][hostile][finite]")
{
    const std::string dir = Folder("finite");
    struct Case
    {
        const char* name;
        double value;
        const char* message;  ///< "" when the illuminant is usable
    };
    const std::vector<Case> cases = {
        {"huge", 1e308, ""},
        {"denormal", 4.9e-324, ""},
        {"negative", -1e308,
         ": the illuminant has no power where the eye sees (its luminance is "
         "not positive): it has no white"},
        {"zero", 0.0, ": the illuminant has no power (all values are 0): it has no white"},
    };
    for (const Case& c : cases)
    {
        INFO(c.name);
        const std::string file = dir + "/" + c.name + ".csv";
        WriteText(file, Remittance("light", c.value));
        for (const char* command : {"xyz --json --illuminant ", "cri --json --illuminant ",
                                    "xyz --json --reflectance TCS --illuminant "})
        {
            INFO(command);
            const Result r = Bandlight(command + ShellWord(file));
            if (*c.message)
            {
                CheckOneLineError(r);
                CHECK(r.err == "bandlight: " + file + c.message + "\n");
            }
            else
            {
                CHECK(r.code == 0);
                CHECK_THAT(r.out, !Contains("null"));  // what nlohmann::json makes of NaN/Inf
            }
        }
    }
    // Power only beyond the visible range.
    const std::string ir = dir + "/ir.csv";
    WriteText(ir, "nm,ir\n800,1\n805,1\n810,1\n815,1\n820,1\n");
    Result r = Bandlight("cri --illuminant " + ShellWord(ir));
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: " + ir +
                       ": the illuminant has no power where the eye sees (its luminance is below "
                       "1e-6 of an equal-energy light's): it has no white\n");

    // Power only above 650 nm: a white with no Z, nothing L*a*b* can relate to.
    const std::string red = dir + "/red.csv";
    WriteText(red, "nm,red\n680,0\n705,0.25\n730,0.5\n755,0.75\n780,1\n");
    r = Bandlight("xyz --reflectance TCS --illuminant " + ShellWord(red));
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: " + red +
                       ": the illuminant's white has no Z (no power where that matching function "
                       "sees): L*a*b* and chromatic adaptation need a white with X, Y and Z all "
                       "above zero\n");

    // SPECTRAL_NORM 1e-300 turns 1 into 1e300: refused as a remittance.
    const std::string sp = dir + "/norm.sp";
    WriteText(sp,
              "CGATS.17\nSPECTRAL_NORM 1e-300\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_380 SPEC_780\n"
              "END_DATA_FORMAT\nBEGIN_DATA\na 1 1\nEND_DATA\n");
    r = Bandlight("xyz --illuminant D65 --reflectance " + ShellWord(sp) + " --json");
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: " + sp +
                       ": 'a' has a remittance of 1e+300; remittances beyond ±1000 are refused\n");

    // A scene's numbers are bounded, and a render never writes Inf or NaN.
    const std::string scene = dir + "/hot.yaml";
    WriteText(scene,
              "lights:\n  - {type: ambient, spectrum: D65, intensity: 1e308}\n"
              "materials:\n  m: {diffuse: 0.5}\n"
              "objects:\n  - {sphere: {center: [0, 0, 0], radius: 1}, material: m}\n");
    r = Bandlight("render '" + scene + "' -o '" + dir + "/hot.exr'");
    CheckOneLineError(r);
    CHECK(r.err == "bandlight: " + scene +
                       ":2: intensity must be at most 1e12 in magnitude, got "
                       "1e308\n");
    CHECK_FALSE(Exists(dir + "/hot.exr"));
}

TEST_CASE("CGATS fields are unique", "[robustness][hostile][files]")
{
    const std::string dir = Folder("cgats");
    const std::string sp = dir + "/twice.sp";
    WriteText(sp,
              "CGATS.17\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_380 SPEC_380 SPEC_390\n"
              "END_DATA_FORMAT\nBEGIN_DATA\na 0.1 0.2 0.3\nEND_DATA\n");
    const Result r = Bandlight("xyz --illuminant D65 --reflectance " + ShellWord(sp));
    CheckOneLineError(r);
    CHECK(r.err ==
          "bandlight: " + sp +
              ":3: field 'SPEC_380' appears twice in BEGIN_DATA_FORMAT (column 2 and 3)\n");
}

TEST_CASE("A failed run prints one line: notes and library messages are held back",
          "[robustness][hostile][cli]")
{
    const std::string dir = Folder("oneline");
    // An illuminant that gets a coverage note, then a reflectance that fails.
    const std::string light = dir + "/short.csv";
    WriteText(light, "nm,l\n400,1\n475,1\n550,1\n625,1\n700,1\n");
    Result r = Bandlight("xyz --illuminant " + ShellWord(light) + " --reflectance " +
                         ShellWord(dir + "/missing.csv"));
    CheckOneLineError(r);
    CHECK_THAT(r.err, !Contains("note:"));
    // The same note is shown when the run succeeds.
    r = Bandlight("xyz --illuminant " + ShellWord(light));
    CHECK(r.code == 0);
    CHECK_THAT(r.err, Contains("note: "));

    // A newline in a file name is escaped in the message.
    const std::string nl = dir + "/a\nb.csv";
    r = Bandlight("xyz --illuminant D65 --reflectance " + ShellWord(nl));
    CheckOneLineError(r);
    CHECK_THAT(r.err, Contains("a\\nb.csv"));

#ifndef BANDLIGHT_TEST_UNDER_ASAN
    // A PNG that libpng complains about: its own messages are not printed.
    // (Not under AddressSanitizer: OpenImageIO 2.4's PNG reader leaks its
    // error string when libpng longjmps out of PNGInput::PngReadCallback,
    // and LeakSanitizer ends the process over it; the check runs in the
    // normal build.)
    const std::string png = dir + "/bad.png";
    WriteText(png, std::string("\x89PNG\r\n\x1a\n", 8) + "garbage");
    r = Bandlight("apply " + ShellWord(png) + " " + ShellWord(dir + "/o.png") +
                  " --from A --to D65");
    CheckOneLineError(r);
#endif
}
