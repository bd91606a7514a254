// SPDX-License-Identifier: BSD-3-Clause
// The scene reader says no to what it would ignore: every key is used or an
// error "FILE:LINE: what" at the offending key's line. And every form it
// accepts reads as docs/scenes.md says, defaults included.
// Covers, through the entry points it calls: render/Scene.cpp, render/SceneLights.cpp,
// render/SceneMaterials.cpp, render/YamlReader.cpp.
#include <catch2/catch.hpp>

#include "render/SceneFile.h"
#include "render/SceneRenderer.h"
#include "spectral/CieData.h"
#include "spectral/Exception.h"

using namespace bandlight;

namespace
{

const std::string kLight =
    "lights:\n  - {type: directional, direction: [0, 0, -1], spectrum: D65}\n";

/// The reader's (or, for a scene it accepts, the planner's) message.
std::string Message(const std::string& yaml)
{
    try
    {
        PlanScene(ReadSceneText(yaml, "s.yaml"));
    }
    catch (const Exception& e)
    {
        return e.what();
    }
    return "(no error)";
}

std::string WithMaterial(const std::string& material)
{
    return kLight + "materials:\n  m: " + material + "\n";
}

/// The value of a step remittance in each of the band model's bands (VB, VG,
/// VR), taken at the band's middle.
std::vector<double> Bands(const SceneSpectrum& s)
{
    return {s.continuous(450.0), s.continuous(550.0), s.continuous(650.0)};
}

}  // namespace

TEST_CASE("The compact form's exponent is 'exponent': 'n' there is an error", "[render][file]")
{
    CHECK(Message(WithMaterial("{diffuse: 0.5, specular: 0.5, n: 20}")) ==
          "s.yaml:4: key 'n' in material 'm' belongs to the full form (k_a, k_d, k_s, O_a, O_d, "
          "O_s, n), but 'diffuse' makes it the compact form: write 'exponent'");
    CHECK(Message(WithMaterial("{k_s: 0.5, exponent: 20}")) ==
          "s.yaml:4: key 'exponent' in material 'm' belongs to the compact form (ambient, diffuse, "
          "specular, exponent), but 'k_s' makes it the full form: write 'n'");
}

TEST_CASE("The two Phong forms do not mix: the first key decides", "[render][file]")
{
    CHECK(Message(WithMaterial("{k_d: 0.8, O_d: TCS01, specular: 0.2}")) ==
          "s.yaml:4: key 'specular' in material 'm' belongs to the compact form (ambient, "
          "diffuse, specular, exponent), but 'k_d' makes it the full form");
}

TEST_CASE("A lecture material takes nothing beside its name", "[render][file]")
{
    CHECK(Message(WithMaterial("{lecture: gold, exponent: 5, diffuse: 0.9}")) ==
          "s.yaml:4: key 'exponent' in material 'm' is unused beside 'lecture': a lecture "
          "material takes every value from the table; write the compact or the full form to "
          "change one");
    CHECK(Message(WithMaterial("copper")) ==
          "s.yaml:4: material 'm' must be 'lecture' or a mapping (the compact or the full Phong "
          "form, or {lecture: NAME}), got 'copper'");
    CHECK(Message(WithMaterial("{lecture: brass}")) ==
          "s.yaml:4: unknown lecture material 'brass' (copper, gold, silver, aluminium, tin, "
          "matte lacquer, gloss lacquer)");
}

TEST_CASE("An O_* without its k_* is an error, not a silent zero", "[render][file]")
{
    CHECK(Message(WithMaterial("{k_d: 0.8, O_s: TCS01}")) ==
          "s.yaml:4: key 'O_s' in material 'm' is unused without 'k_s' (R_spek = k_s·O_s)");
}

TEST_CASE("An exponent without a specular part is an error", "[render][file]")
{
    CHECK(Message(WithMaterial("{diffuse: TCS01, exponent: 20}")) ==
          "s.yaml:4: key 'exponent' in material 'm' is unused: the material has no specular part "
          "(give 'specular')");
    CHECK(Message(WithMaterial("{k_d: 0.5, n: 20}")) ==
          "s.yaml:4: key 'n' in material 'm' is unused: the material has no specular part (give "
          "'k_s')");
}

TEST_CASE("A negative exponent is reported at the exponent's line", "[render][file]")
{
    CHECK(Message(kLight +
                  "materials:\n  m:\n    diffuse: TCS01\n    specular: 0.5\n    exponent: -1\n") ==
          "s.yaml:7: material 'm': the Phong exponent must not be negative");
    CHECK(Message(kLight + "materials:\n  m:\n    k_s: 0.5\n    n: -2\n") ==
          "s.yaml:6: material 'm': the Phong exponent must not be negative");
}

TEST_CASE("A light's keys must be ones its kind uses", "[render][file]")
{
    CHECK(Message("lights:\n  - {type: point, direction: [0, 0, -1], spectrum: D65}\n") ==
          "s.yaml:2: key 'direction' is unused by a point light: a point light shines from its "
          "position in every direction");
    CHECK(Message("lights:\n  - {type: directional,\n     position: [0, 0, 1], spectrum: D65}\n") ==
          "s.yaml:3: key 'position' is unused by a directional light: a directional light is "
          "infinitely far: it has a direction, and no position or attenuation");
    CHECK(Message(
              "lights:\n  - type: directional\n    spectrum: D65\n    attenuation: [1, 0, 1]\n") ==
          "s.yaml:4: key 'attenuation' is unused by a directional light: a directional light is "
          "infinitely far: it has a direction, and no position or attenuation");
    CHECK(Message("lights:\n  - {type: ambient, position: [0, 0, 1], spectrum: D65}\n") ==
          "s.yaml:2: key 'position' is unused by an ambient light: it lights every surface alike "
          "(spectrum and intensity only)");
}

TEST_CASE("A light spectrum is one form, not two", "[render][file]")
{
    CHECK(Message("lights:\n  - spectrum:\n      cct: 5000\n      blackbody: 3000\n") ==
          "s.yaml:4: a light spectrum has exactly one of cct, blackbody, lines, bands, file; "
          "'blackbody' follows 'cct'");
}

TEST_CASE("A remittance is bands or a file, and a sample needs the file", "[render][file]")
{
    CHECK(Message(WithMaterial("{diffuse: {bands: [0, 0.5, 0], file: x.csv}}")) ==
          "s.yaml:4: key 'file' is unused beside 'bands': a remittance is either {bands: [...]} "
          "or {file: path, sample: id}");
    CHECK(Message(WithMaterial("{diffuse: {sample: TCS01}}")) ==
          "s.yaml:4: key 'sample' needs 'file': the sample is an id in that file");
}

TEST_CASE("A camera's keys must be ones its projection uses", "[render][file]")
{
    CHECK(Message("camera:\n  type: orthographic\n  fov: 30\n" + kLight) ==
          "s.yaml:3: key 'fov' is unused by an orthographic camera: its view is 'size' scene units "
          "high");
    CHECK(Message("camera:\n  size: 4\n" + kLight) ==
          "s.yaml:2: key 'size' is unused by a pinhole camera: its view is 'fov' degrees high "
          "(type: orthographic has a size)");
    CHECK(Message("camera: {type: fisheye}\n" + kLight) ==
          "s.yaml:1: camera type must be pinhole or orthographic, got 'fisheye'");
    CHECK(Message("camera: {type: orthographic, size: 0}\n" + kLight) ==
          "s.yaml:1: camera size must be positive, got 0");
}

TEST_CASE("A mode's band count must agree with explicit bands", "[render][file]")
{
    CHECK(Message("render:\n  bands: [400, 500, 600, 700]\n  mode: band6\n" + kLight) ==
          "s.yaml:3: mode band6 names 6 bands, but render bands gives 3");
    CHECK(Message("render: {mode: band3-wp}\n" + kLight) ==
          "s.yaml:1: mode must be band3, bandN (3 <= N <= 300) or spectral, got 'band3-wp'");
}

TEST_CASE("Band output in spectral mode is refused at its line", "[render][file]")
{
    CHECK(Message("render:\n  mode: spectral\n  output: bands\n" + kLight) ==
          "s.yaml:3: output 'bands' needs band mode: spectral mode has no bands to write");
}

TEST_CASE("The spectral range lies within 360-830 nm", "[render][file]")
{
    CHECK(Message("render:\n  range: [350, 780]\n" + kLight) ==
          "s.yaml:2: range must lie within 360-830 nm and span at least 50 nm, got [350, 780]");
    CHECK(Message("render:\n  range: [500, 520]\n" + kLight) ==
          "s.yaml:2: range must lie within 360-830 nm and span at least 50 nm, got [500, 520]");
    CHECK(Message("render:\n  range: 380\n" + kLight) ==
          "s.yaml:2: range must be [start_nm, end_nm]");
}

TEST_CASE("An object is a sphere or a plane, not both", "[render][file]")
{
    CHECK(Message(WithMaterial("{diffuse: 0.5}") +
                  "objects:\n  - sphere: {radius: 1}\n    plane: {normal: [0, 1, 0]}\n"
                  "    material: m\n") ==
          "s.yaml:7: an object is one sphere or one plane, not both");
}

TEST_CASE("A key or a material given twice is an error, not the first one's", "[render][file]")
{
    CHECK(Message(WithMaterial("{diffuse: 0.5, diffuse: 0.7}")) ==
          "s.yaml:4: key 'diffuse' appears twice in material 'm'");
    CHECK(Message(WithMaterial("{diffuse: 0.5}") + "  m: {diffuse: 0.7}\n") ==
          "s.yaml:5: material 'm' is defined twice");
}

TEST_CASE("ambient_star needs exactly one direct light, said at its line", "[render][file]")
{
    CHECK(Message(kLight + "  - {type: point, position: [0, 1, 1], spectrum: A}\n" +
                  "materials:\n  m: {diffuse: 0.5,\n      ambient_star: 0.1}\n") ==
          "s.yaml:6: ambient_star (R_amb*) needs exactly one direct light, the scene has 2");
}

TEST_CASE("Every accepted form reads with the documented defaults", "[render][file]")
{
    const Scene s = ReadSceneText(R"(
lights:
  - {spectrum: D65}
  - {type: ambient, spectrum: {bands: [1, 0.5, 0.25]}}
materials:
  gold: lecture
  shiny: {lecture: silver}
  compact: {diffuse: TCS09, specular: 0.04}
  full: {k_a: 0.1, k_d: 0.8, O_d: TCS01, k_s: 0.2}
  star: {diffuse: 0.5, ambient_star: {bands: [0.1, 0.2, 0.3]}}
)",
                                  "forms.yaml");
    // A light is a point light of intensity 1 unless it says otherwise.
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].kind == SceneLight::Kind::POINT);
    CHECK(s.lights[0].intensity == 1.0);
    CHECK_FALSE(s.lights[0].attenuates());
    CHECK(s.lights[1].kind == SceneLight::Kind::AMBIENT);
    REQUIRE(s.materials.size() == 5);
    // Lecture materials (both forms): the table's values, R_amb = R_diff.
    const SceneMaterial& gold = s.materials[0];
    CHECK(gold.name == "gold");
    CHECK(gold.exponent == 32.0);
    CHECK(Bands(gold.diffuse) == std::vector<double>{0.0, 0.5, 0.5});
    CHECK(Bands(gold.ambient) == Bands(gold.diffuse));
    CHECK(Bands(gold.specular) == std::vector<double>{0.0, 1.0, 1.0});
    const SceneMaterial& silver = s.materials[1];
    CHECK(silver.name == "shiny");
    CHECK(silver.exponent == 32.0);
    CHECK(Bands(silver.ambient) == Bands(silver.diffuse));
    // The compact form: exponent 1, no ambient unless given.
    const SceneMaterial& compact = s.materials[2];
    CHECK(compact.exponent == 1.0);
    CHECK(compact.ambient.isZero());
    CHECK(Bands(compact.specular) == std::vector<double>{0.04, 0.04, 0.04});
    // The full form: O_* = 1 unless given, n = 1, R = k·O.
    const SceneMaterial& full = s.materials[3];
    CHECK(full.exponent == 1.0);
    CHECK(Bands(full.ambient) == std::vector<double>{0.1, 0.1, 0.1});
    CHECK(Bands(full.specular) == std::vector<double>{0.2, 0.2, 0.2});
    const Spectrum& tcs01 = TestColourSamples()[0].spectrum;
    CHECK(full.diffuse.continuous(550.0) == Approx(0.8 * tcs01(550.0)).epsilon(1e-12));
    CHECK(s.materials[4].ambientStar.continuous(450.0) == Approx(0.1));
    // Camera defaults: a pinhole.
    CHECK(s.camera.projection == Camera::Projection::PINHOLE);
    // The spectral range: docs/science.md §1.1's 380-780 nm.
    CHECK(s.settings.rangeMinNm == 380.0);
    CHECK(s.settings.rangeMaxNm == 780.0);
}

TEST_CASE("Orthographic cameras and the spectral range read as written", "[render][file]")
{
    const Scene s = ReadSceneText(R"(
camera: {type: orthographic, size: 3.5, position: [0, 0, 5], look_at: [0, 0, 0]}
render: {mode: spectral, range: [360, 830], step: 5}
)" + kLight,
                                  "ortho.yaml");
    CHECK(s.camera.projection == Camera::Projection::ORTHOGRAPHIC);
    CHECK(s.camera.size == 3.5);
    CHECK(s.settings.rangeMinNm == 360.0);
    CHECK(s.settings.rangeMaxNm == 830.0);
}

TEST_CASE("Lights have names and light groups: unnamed ones light1, light2, ... in file order",
          "[render][file][lightgroups]")
{
    const Scene s = ReadSceneText(R"(
lights:
  - {type: point, position: [0, 2, 2], spectrum: A}
  - {name: window, group: daylight, type: directional, direction: [0, 0, -1], spectrum: D65}
  - {name: bounce, group: daylight, type: ambient, spectrum: D65, intensity: 0.1}
  - {type: ambient, spectrum: F11, intensity: 0.05}
)",
                                  "s.yaml");
    REQUIRE(s.lights.size() == 4);
    CHECK(s.lights[0].name == "light1");
    CHECK(s.lights[0].group == "light1");
    CHECK(s.lights[1].name == "window");
    CHECK(s.lights[1].group == "daylight");
    CHECK(s.lights[3].name == "light4");
    CHECK(LightGroupNames(s) == std::vector<std::string>{"light1", "daylight", "light4"});
    const Scene daylight = SceneOfLightGroup(s, "daylight");
    REQUIRE(daylight.lights.size() == 2);
    CHECK(daylight.lights[1].name == "bounce");
    CHECK_THROWS_WITH(SceneOfLightGroup(s, "sun"), "the scene has no light group 'sun'");
}

TEST_CASE("Light names that cannot name a layer, and a name twice, are errors",
          "[render][file][lightgroups]")
{
    const std::string m = "materials:\n  m: {diffuse: 0.5}\n";
    CHECK(Message("lights:\n  - {name: 'key light', spectrum: A}\n" + m) ==
          "s.yaml:2: a light's name or group must be letters, digits, '_' and '-' (it names "
          "the layer <group>.R, <group>.G, <group>.B), got 'key light'");
    CHECK(Message("lights:\n  - {group: S0, spectrum: A}\n" + m) ==
          "s.yaml:2: a light group cannot be called 'S0': it is a channel name of the render "
          "itself");
    CHECK(Message("lights:\n  - {name: key, spectrum: A}\n  - {name: key, spectrum: D65}\n" +
                  m) ==
          "s.yaml:3: two lights are named 'key': a light's name is its own (lights share a "
          "layer through group:)");
    CHECK(Message("lights:\n  - {spectrum: A}\n  - {name: light1, spectrum: D65}\n" + m) ==
          "s.yaml:3: two lights are named 'light1': a light's name is its own (lights share a "
          "layer through group:)");
}
