// SPDX-License-Identifier: BSD-3-Clause
// `bandlight render`: the bundled scenes, the plan, and malformed scenes.
// Covers, through the entry points it calls: cli/CommandRender.cpp, report/DeltaEMap.cpp.
#include <sys/stat.h>

#include <fstream>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "spectral/RgbSpaces.h"

using bandlight::test::Bandlight;
using bandlight::test::Result;
using Catch::Matchers::Contains;

namespace
{
std::string Temp(const std::string& name)
{
    return bandlight::test::TempPath("render_" + name);
}

bool Exists(const std::string& path)
{
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

std::string WriteScene(const std::string& name, const std::string& yaml)
{
    const std::string path = Temp(name);
    std::ofstream(path) << yaml;
    return path;
}

const std::string kGood =
    R"(camera: {position: [0, 0, 3], look_at: [0, 0, 0], width: 16, height: 12}
render: {mode: band3}
lights:
  - {type: directional, direction: [0, 0, -1], spectrum: D65}
materials:
  grey: {diffuse: 0.5}
objects:
  - {plane: {point: [0, 0, 0], normal: [0, 0, 1]}, material: grey}
)";
}  // namespace

TEST_CASE("The bundled scenes render, explain and compare", "[cli][scene]")
{
    const std::string dir = SCENES_DIR;
    for (const char* scene : {"materials_D65", "materials_A", "narrowband", "tcs_grid_F11"})
    {
        const std::string out = Temp(std::string(scene) + ".exr");
        const Result r = Bandlight("render '" + dir + "/" + scene +
                                   ".yaml' --mode band3 --compare -o '" + out + "'");
        INFO(scene << ": " << r.err);
        REQUIRE(r.code == 0);
        CHECK(Exists(out));
        CHECK(Exists(Temp(std::string(scene) + ".png")));
        CHECK(Exists(Temp(std::string(scene) + "_dE00.exr")));
        CHECK_THAT(r.out, Contains("compare with spectral"));
    }
    const Result explain = Bandlight("render '" + dir + "/counterexample.yaml' --explain");
    CHECK(explain.code == 0);
    CHECK_THAT(explain.out, Contains("specular: skipped, no material has a specular part"));
    CHECK_THAT(explain.out, Contains("attenuation: skipped"));
}

TEST_CASE("Malformed scenes: file and line, exit 2, nothing written", "[cli][scene]")
{
    struct Case
    {
        std::string yaml;
        std::string message;
    };
    const std::vector<Case> cases = {
        {kGood + "colour: red\n", ":9: unknown key 'colour' in the scene"},
        {"camera: {width: -4}\n" + kGood.substr(kGood.find('\n') + 1),
         ":1: width must be a whole number of pixels from 1 to 16384, got -4"},
        {"camera: {fov: wide}\n" + kGood.substr(kGood.find('\n') + 1),
         ":1: fov must be a number, got 'wide'"},
        {kGood.substr(0, kGood.find("materials:")) +
             "materials:\n  grey: {diffuse: {file: nope.csv}}\nobjects: []\n",
         ":6: "},
        {kGood.substr(0, kGood.find("materials:")) + "materials:\n  grey: {difuse: 0.5}\n",
         ":6: unknown key 'difuse' in material 'grey'"},
        {kGood.substr(0, kGood.find("objects:")) +
             "objects:\n  - {sphere: {center: [0, 0], radius: 1}, material: grey}\n",
         ":8: sphere center must be a list of three numbers"},
        {kGood.substr(0, kGood.find("objects:")) +
             "objects:\n  - {sphere: {radius: 1}, material: gold}\n",
         ":8: unknown material 'gold'"},
        {kGood + "  - {sphere: {radius: 0}, material: grey}\n",
         ":9: sphere radius must be positive"},
        {"camera: [1, 2\n", ":"},
        {"lights:\n  - {type: laser, spectrum: D65}\n",
         ":2: light type must be ambient, point or directional"},
        {"lights:\n  - {type: point, spectrum: Candle}\n", ":2: unknown illuminant 'Candle'"},
    };
    const std::string out = Temp("bad.exr");
    for (size_t i = 0; i < cases.size(); ++i)
    {
        const std::string scene = WriteScene("bad" + std::to_string(i) + ".yaml", cases[i].yaml);
        std::remove(out.c_str());
        const Result r = Bandlight("render '" + scene + "' -o '" + out + "'");
        INFO(cases[i].yaml << "\n-> " << r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains(scene + cases[i].message));
        CHECK_FALSE(Exists(out));
    }
    const Result missing = Bandlight("render '" + Temp("none.yaml") + "'");
    CHECK(missing.code == 2);
    CHECK_THAT(missing.err, Contains("none.yaml: cannot open scene file"));
}

TEST_CASE("A good scene renders in every mode", "[cli][scene]")
{
    const std::string scene = WriteScene("good.yaml", kGood);
    for (const char* mode : {"band3", "band6", "spectral"})
    {
        const Result r = Bandlight("render '" + scene + "' --mode " + mode + " -o '" +
                                   Temp(std::string("good_") + mode + ".exr") + "'");
        INFO(mode << ": " << r.err);
        CHECK(r.code == 0);
    }
}

TEST_CASE("A rendered EXR says what it holds: colour space and chromaticities", "[cli][scene]")
{
    // OpenImageIO 2.4 reads every EXR as oiio:ColorSpace "Linear", so the
    // name travels as bandlight:colorSpace, with the Color Interop Forum ID.
    struct Case
    {
        const char* output;
        const char* colorSpace;
        const char* interopId;
        const char* space;  ///< its chromaticities; "" for band values
    };
    for (const Case& c : {Case{"acescg", "ACEScg", "lin_ap1_scene", "acescg"},
                          Case{"lin-rec709", "Linear Rec.709 (sRGB)", "lin_rec709_scene", "rec709"},
                          Case{"bands", "bands", "data", ""}})
    {
        INFO(c.output);
        std::string yaml = kGood;
        yaml.replace(yaml.find("{mode: band3}"), 13,
                     std::string("{mode: band3, output: ") + c.output + "}");
        const std::string scene = WriteScene(std::string("meta_") + c.output + ".yaml", yaml);
        const std::string exr = Temp(std::string("meta_") + c.output + ".exr");
        const Result r = Bandlight("render '" + scene + "' -o '" + exr + "'");
        REQUIRE(r.code == 0);
        auto in = OIIO::ImageInput::open(exr);
        REQUIRE(in);
        const OIIO::ImageSpec& spec = in->spec();
        CHECK(spec.get_string_attribute("bandlight:colorSpace") == c.colorSpace);
        CHECK(spec.get_string_attribute("colorInteropID") == c.interopId);
        const OIIO::ParamValue* chroma = spec.find_attribute("chromaticities");
        if (*c.space)
        {
            REQUIRE(chroma);
            REQUIRE(chroma->type() == OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
            const float* v = static_cast<const float*>(chroma->data());
            const bandlight::Chromaticities& e = bandlight::FindRgbSpace(c.space).chromaticities;
            const double expected[8] = {e.rx, e.ry, e.gx, e.gy, e.bx, e.by, e.wx, e.wy};
            for (int i = 0; i < 8; ++i)
            {
                CHECK(v[i] == Approx(expected[i]).margin(1e-7));
            }
            CHECK(spec.nchannels == 3);
        }
        else
        {
            // Band values are not RGB: no chromaticities, and the file says so.
            CHECK(chroma == nullptr);
            CHECK(spec.get_string_attribute("bandlight:channels") ==
                  "band values (radiometric), not RGB: 400,500,600,700");
            CHECK(spec.channelnames == std::vector<std::string>{"VB", "VG", "VR"});
        }
    }
}

TEST_CASE("Band output with --mode spectral is refused, not switched", "[cli][scene]")
{
    std::string yaml = kGood;
    yaml.replace(yaml.find("{mode: band3}"), 13, "{mode: band3, output: bands}");
    const std::string scene = WriteScene("bands_spectral.yaml", yaml);
    const std::string out = Temp("bands_spectral.exr");
    std::remove(out.c_str());
    const Result r = Bandlight("render '" + scene + "' --mode spectral -o '" + out + "'");
    CHECK(r.code == 2);
    CHECK(r.err == "bandlight: --mode spectral: " + scene +
                       " asks for output 'bands' (band values), which only band mode writes; set "
                       "render: {output: acescg} (or another working space) to render it "
                       "spectrally\n");
    CHECK_FALSE(Exists(out));
    // Band modes are fine.
    CHECK(Bandlight("render '" + scene + "' --mode band6 -o '" + out + "'").code == 0);
}

TEST_CASE("The literal path (--unplanned) prints what it does, not the plan", "[cli][scene]")
{
    std::string yaml = kGood;
    yaml.replace(yaml.find("lights:\n"), 8,
                 "lights:\n  - {type: directional, direction: [0, 1, -1], spectrum: D65}\n");
    const std::string scene = WriteScene("unplanned.yaml", yaml);
    const Result planned = Bandlight("render '" + scene + "' --explain");
    CHECK(planned.code == 0);
    CHECK_THAT(planned.out, Contains("light terms: 1 for 2 direct lights (lights sharing a "
                                     "spectrum summed into one term)"));
    const Result literal = Bandlight("render '" + scene + "' --unplanned --explain");
    CHECK(literal.code == 0);
    CHECK(literal.out ==
          "unplanned: band mode, 16x12, output acescg (3 channels), the literal path: no plan\n"
          "  per pixel, every light on its own: 2 direct lights (cos a, cos^n psi and f_att "
          "evaluated for each, whatever the materials and lights), 0 ambient\n"
          "  per light, per band: light x (R_amb, R_diff, R_spek, R_amb*) in 3 bands "
          "(400,500,600,700 nm)\n"
          "  then the band values are converted to acescg\n");
    const Result run =
        Bandlight("render '" + scene + "' --unplanned -o '" + Temp("unplanned.exr") + "'");
    INFO(run.err);
    CHECK(run.code == 0);
    CHECK_THAT(run.out, Contains("the literal path") && !Contains("summed"));
}

TEST_CASE("An orthographic scene renders from the command line", "[cli][scene]")
{
    std::string yaml = kGood;
    yaml.replace(0, yaml.find('\n'),
                 "camera: {type: orthographic, size: 2, position: [0, 0, 3], look_at: [0, 0, 0], "
                 "width: 16, height: 12}");
    const std::string scene = WriteScene("ortho.yaml", yaml);
    const Result r = Bandlight("render '" + scene + "' -o '" + Temp("ortho.exr") + "'");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(Exists(Temp("ortho.exr")));
}
