// SPDX-License-Identifier: BSD-3-Clause
// `bandlight render`: the bundled scenes, the plan, and malformed scenes.
#include <sys/stat.h>

#include <fstream>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"

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
