// SPDX-License-Identifier: BSD-3-Clause
// Phong at its edges: exponents from 0 to 1e6, cos ψ at rounding distance
// from 0 and 1, lights at the surface and behind it, degenerate geometry.
// One pixel looking straight down the axis at a plane, band mode, output in
// band values: the pixel is I·(R_diff·cos α + R_spek·cosⁿψ), exactly.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/SceneFile.h"
#include "render/SceneRenderer.h"
#include "spectral/Exception.h"

using namespace bandlight;

namespace
{

/// A 1×1 image of the plane z = 0 seen from (0, 0, 3), lit by `light`
/// (YAML flow mapping), material R_diff 0.5, R_spek 0.25, exponent n.
std::vector<float> Pixel(const std::string& light, double n, bool planned = true)
{
    const std::string yaml = R"(
camera: {position: [0, 0, 3], look_at: [0, 0, 0], width: 1, height: 1, fov: 10}
render: {mode: band3, output: bands}
lights:
  - )" + light + R"(
materials:
  m: {diffuse: {bands: [0.5, 0.5, 0.5]}, specular: {bands: [0.25, 0.25, 0.25]}, exponent: )" +
                             std::to_string(n) + R"(}
objects:
  - {plane: {point: [0, 0, 0], normal: [0, 0, 1]}, material: m}
)";
    const Scene scene = ReadSceneText(yaml, "edge.yaml");
    PlanOptions o;
    o.optimise = planned;
    return planned ? RenderScene(scene, PlanScene(scene, o), 1).pixels
                   : RenderSceneUnplanned(scene, 1).pixels;
}

const std::string kOverhead = "{type: directional, direction: [0, 0, -1], spectrum: {bands: [1, 1, 1]}}";
// toLight at 60° from the normal, in the x-z plane: cos α = cos ψ = 0.5.
const std::string kSixty =
    "{type: directional, direction: [-0.8660254037844386, 0, -0.5], spectrum: {bands: [1, 1, 1]}}";

std::string Message(const std::string& yaml)
{
    try
    {
        const Scene s = ReadSceneText(yaml, "bad.yaml");
        PlanScene(s);
    }
    catch (const Exception& e)
    {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("Phong exponent from 0 to 1e6 at the mirror direction and at 60 degrees",
          "[robustness][shading]")
{
    for (bool planned : {true, false})
    {
        for (double n : {0.0, 1.0, 64.0, 1e6})
        {
            INFO("n = " << n << (planned ? " planned" : " literal"));
            // Mirror direction: cos ψ = 1, so cosⁿψ = 1 for every n.
            for (float v : Pixel(kOverhead, n, planned))
            {
                CHECK(v == Approx(0.5 + 0.25).epsilon(1e-6));
            }
            // 60°: 0.5·0.5 + 0.25·0.5ⁿ; n = 0 lights the whole lit side (0.5⁰ = 1),
            // n = 1e6 underflows to exactly 0.
            const double expected = 0.25 + 0.25 * std::pow(0.5, n);
            for (float v : Pixel(kSixty, n, planned))
            {
                CHECK(v == Approx(expected).epsilon(1e-6));
            }
        }
    }
}

TEST_CASE("cos psi a rounding error from 1 or 0 stays in [0, 1]", "[robustness][shading]")
{
    // A tilted plane seen and lit along its normal: cos ψ is 1 up to rounding;
    // with n = 1e6 any excess over 1 would show as a value above R_diff + R_spek.
    const std::string yaml = R"(
camera: {position: [1, 2, 3], look_at: [0, 0, 0], width: 1, height: 1, fov: 10}
render: {mode: band3, output: bands}
lights:
  - {type: point, position: [1, 2, 3], spectrum: {bands: [1, 1, 1]}}
materials:
  m: {diffuse: {bands: [0.5, 0.5, 0.5]}, specular: {bands: [0.25, 0.25, 0.25]}, exponent: 1000000}
objects:
  - {plane: {point: [0, 0, 0], normal: [1, 2, 3]}, material: m}
)";
    const Scene scene = ReadSceneText(yaml, "tilted.yaml");
    for (float v : RenderScene(scene, PlanScene(scene), 1).pixels)
    {
        CHECK(v <= 0.75f);
        CHECK(v == Approx(0.75).epsilon(1e-5));
    }
    // Grazing light: cos α = 0 exactly, nothing reflected, no NaN from 0⁰.
    for (float v : Pixel("{type: directional, direction: [1, 0, 0], spectrum: {bands: [1, 1, 1]}}",
                         0.0))
    {
        CHECK(v == 0.0f);
    }
}

TEST_CASE("Back-facing lights give exactly zero", "[robustness][shading]")
{
    for (float v : Pixel("{type: directional, direction: [0, 0, 1], spectrum: {bands: [1, 1, 1]}}",
                         8.0))
    {
        CHECK(v == 0.0f);
    }
    for (float v : Pixel("{type: point, position: [0, 0, -1], spectrum: {bands: [1, 1, 1]}}", 8.0))
    {
        CHECK(v == 0.0f);
    }
}

TEST_CASE("A point light at the surface contributes nothing, just above it full strength",
          "[robustness][shading]")
{
    // d = 0: no direction to the light; the term is skipped (0), never NaN.
    for (float v : Pixel("{type: point, position: [0, 0, 0], spectrum: {bands: [1, 1, 1]}}", 8.0))
    {
        CHECK(v == 0.0f);
    }
    // d = 1e-9 straight above: cos α = 1; inverse-square attenuation is capped at 1.
    for (const char* att : {"[1, 0, 0]", "[0, 0, 1]", "[0, 1, 0]"})
    {
        INFO("attenuation " << att);
        for (float v :
             Pixel(std::string("{type: point, position: [0, 0, 1.0e-9], attenuation: ") + att +
                       ", spectrum: {bands: [1, 1, 1]}}",
                   8.0))
        {
            CHECK(v == Approx(0.75).epsilon(1e-6));
        }
    }
}

TEST_CASE("Degenerate geometry is refused with the file and line", "[robustness][shading]")
{
    const std::string lights =
        "lights:\n  - {type: directional, direction: [0, 0, -1], spectrum: D65}\n";
    CHECK(Message("camera:\n  position: [0, 0, 3]\n  look_at: [0, 0, 0]\n  up: [0, 0, 1]\n" +
                  lights) == "bad.yaml:4: camera up is zero or parallel to the view direction");
    CHECK(Message("camera:\n  up: [0, 0, 0]\n" + lights) ==
          "bad.yaml:2: camera up is zero or parallel to the view direction");
    CHECK(Message(lights + "materials: {m: {diffuse: TCS01}}\nobjects:\n"
                           "  - {plane: {normal: [0, 0, 0]}, material: m}\n") ==
          "bad.yaml:5: plane normal must not be zero");
    CHECK(Message(lights + "materials: {m: {diffuse: TCS01}}\nobjects:\n"
                           "  - {sphere: {radius: 0}, material: m}\n") ==
          "bad.yaml:5: sphere radius must be positive, got 0");
    CHECK(Message(lights + "materials: {m: {diffuse: TCS01}}\nobjects:\n"
                           "  - {sphere: {center: [1e300, 0, 0]}, material: m}\n") ==
          "bad.yaml:5: sphere center must lie within ±1e9 (got a coordinate of " +
              std::to_string(1e300) + ")");
    CHECK(Message("camera: {width: 1e300}\n" + lights) ==
          "bad.yaml:1: width must be a whole number of pixels from 1 to 16384, got 1e300");
    CHECK(Message(lights.substr(0, lights.size() - 1) + "\nmaterials: {m: {diffuse: TCS01, exponent: -1}}\n") ==
          "bad.yaml:3: material 'm': the Phong exponent must not be negative");

    // Through the API, without the reader: the planner refuses the same scenes.
    Scene s = ReadSceneText(lights, "ok.yaml");
    s.camera.up = Vec3(0, 0, 5);
    s.camera.position = Vec3(0, 0, 1);
    CHECK_THROWS_WITH(PlanScene(s),
                      "the camera's up vector is zero or parallel to its view direction");
    s = ReadSceneText(lights, "ok.yaml");
    s.materials.push_back({});
    s.planes.push_back({Vec3::Zero(), Vec3::Zero(), 0});
    CHECK_THROWS_WITH(PlanScene(s), Catch::StartsWith("a plane needs a finite point and a unit normal"));
}
