// SPDX-License-Identifier: BSD-3-Clause
// Covers, through the entry points it calls: render/SceneColour.cpp.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/SceneRenderer.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/RgbSpaces.h"
#include "transforms/BandModel.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
SceneSpectrum Bands(const std::vector<double>& v)
{
    return {"bands", StepSpectrum(BandSet::Lecture(), v), {}};
}

/// A plane at z = 0 facing +z, a camera looking straight at it, one material.
Scene FlatScene(const SceneMaterial& m)
{
    Scene s;
    s.camera.position = Vec3(0, 0, 3);
    s.camera.lookAt = Vec3::Zero();
    s.camera.width = 8;
    s.camera.height = 6;
    s.materials = {m};
    s.planes = {{Vec3::Zero(), Vec3(0, 0, 1), 0}};
    return s;
}

SceneLight Directional(const SceneSpectrum& spectrum, const Vec3& travel, double intensity = 1.0)
{
    SceneLight l;
    l.kind = SceneLight::Kind::DIRECTIONAL;
    l.spectrum = spectrum;
    l.direction = travel;
    l.intensity = intensity;
    return l;
}

const float* Pixel(const RenderedImage& img, int x, int y)
{
    return &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels)];
}
}  // namespace

TEST_CASE("The lecture's counter-example: spectral black, band (0, 0.2, 0)", "[render][scene]")
{
    // docs/science.md §1.4: light 1 on VB, VR and 500–549 nm; surface 0.8 on 550–599 nm only.
    std::vector<double> light(471), surface(471);
    for (int i = 0; i < 471; ++i)
    {
        const int l = 360 + i;
        light[size_t(i)] = (l >= 400 && l < 550) || (l >= 600 && l < 700) ? 1.0 : 0.0;
        surface[size_t(i)] = l >= 550 && l < 600 ? 0.8 : 0.0;
    }
    SceneMaterial m;
    m.diffuse = {"half green", Spectrum(360.0, 1.0, surface), {}};
    m.ambient = m.specular = {"0", ConstantRemittance(0.0), {}};
    Scene s = FlatScene(m);
    s.lights = {Directional({"half light", Spectrum(360.0, 1.0, light), {}}, Vec3(0, 0, -1))};
    CHECK(IlluminantBands(s.lights[0].spectrum.continuous, BandSet::Lecture())[1] == Approx(0.5));
    s.settings.output = "bands";
    const RenderedImage band = RenderScene(s, PlanScene(s));
    const float* p = Pixel(band, 4, 3);
    CHECK(p[0] == Approx(0.0).margin(1e-7));
    CHECK(p[1] == Approx(0.2).margin(1e-6));
    CHECK(p[2] == Approx(0.0).margin(1e-7));

    s.settings.mode = RenderSettings::Mode::SPECTRAL;
    s.settings.output = "acescg";
    const RenderedImage spectral = RenderScene(s, PlanScene(s));
    for (float v : spectral.pixels)
    {
        CHECK(v == 0.0f);
    }
    CHECK_THROWS_WITH((
                          [&]
                          {
                              Scene t = s;
                              t.settings.output = "bands";
                              PlanScene(t);
                          })(),
                      Contains("needs band mode"));
}

TEST_CASE("One light, no specular, no attenuation: R_amb* + R_diff cos α in closed form",
          "[render][scene]")
{
    SceneMaterial m;
    m.diffuse = Bands({0.4, 0.5, 1.0});  // copper's R_diff
    m.ambientStar = Bands({0.1, 0.05, 0.2});
    m.ambient = m.specular = {"0", ConstantRemittance(0.0), {}};
    Scene s = FlatScene(m);
    const double theta = 0.6;  // the light arrives 0.6 rad off the normal
    const std::vector<double> i = {1.0, 0.9747, 0.7880};  // a D65-like band light
    s.lights = {Directional(Bands(i), Vec3(std::sin(theta), 0.0, -std::cos(theta)), 2.0)};
    s.settings.output = "bands";
    const RenderedImage img = RenderScene(s, PlanScene(s));
    const RenderedImage slow = RenderSceneUnplanned(s);
    const double diff[3] = {0.4, 0.5, 1.0}, star[3] = {0.1, 0.05, 0.2};
    for (int b = 0; b < 3; ++b)
    {
        // I_0 = 2 × I (the band model's max-normalised band light).
        const double expected = 2.0 * i[size_t(b)] * (star[b] + diff[b] * std::cos(theta));
        CHECK(Pixel(img, 3, 2)[b] == Approx(expected).margin(1e-6));
        CHECK(Pixel(slow, 3, 2)[b] == Approx(expected).margin(1e-6));
    }
}

TEST_CASE("Spectral mode agrees with the spectral core on a flat-lit plane", "[render][scene]")
{
    for (const char* tcs : {"TCS01", "TCS09", "TCS12"})
    {
        const Spectrum r = [&]
        {
            for (const NamedSpectrum& t : TestColourSamples())
            {
                if (t.name == tcs)
                {
                    return t.spectrum;
                }
            }
            return Spectrum();
        }();
        SceneMaterial m;
        m.diffuse = {tcs, r, {}};
        m.ambient = m.specular = {"0", ConstantRemittance(0.0), {}};
        Scene s = FlatScene(m);
        const Spectrum d65 = BuiltinIlluminant("D65");
        s.lights = {Directional({"D65", d65, {}}, Vec3(0, 0, -1))};
        s.settings.mode = RenderSettings::Mode::SPECTRAL;
        s.settings.stepNm = 5.0;
        s.settings.output = "rec709";
        const RenderedImage img = RenderScene(s, PlanScene(s));
        const Mat3 toXyz = RgbToXyzMatrix(FindRgbSpace("rec709").chromaticities);
        const float* p = Pixel(img, 4, 3);
        const Vec3 xyz = toXyz * Vec3(p[0], p[1], p[2]);
        const Vec3 core = SurfaceXyz(r, d65, Observer::CIE1931_2DEG);
        INFO(tcs);
        CHECK(XyzToxyY(xyz).x() == Approx(XyzToxyY(core).x()).margin(2e-4));
        CHECK(XyzToxyY(xyz).y() == Approx(XyzToxyY(core).y()).margin(2e-4));
    }
}

TEST_CASE("The planner: a term switched off gives the full pipeline's image, without the work",
          "[render][scene]")
{
    SceneMaterial m = LectureMaterial("gold");
    m.specular = {"0", ConstantRemittance(0.0), {}};  // specular coefficient zero
    Scene s;
    s.camera.width = 48;
    s.camera.height = 32;
    s.materials = {m, LectureMaterial("tin")};
    s.materials[1].specular = {"0", ConstantRemittance(0.0), {}};
    s.spheres = {{Vec3(-0.6, 0, 0), 0.5, 0}, {Vec3(0.6, 0, 0), 0.5, 1}};
    s.planes = {{Vec3(0, -0.5, 0), Vec3(0, 1, 0), 1}};
    SceneLight a = Directional({"D65", BuiltinIlluminant("D65"), {}}, Vec3(-1, -1, -1));
    SceneLight b = a;
    b.direction = Vec3(1, -1, -0.5);
    SceneLight amb;
    amb.kind = SceneLight::Kind::AMBIENT;
    amb.spectrum = {"D65", BuiltinIlluminant("D65"), {}};
    amb.intensity = 0.1;
    s.lights = {a, b, amb};
    for (RenderSettings::Mode mode : {RenderSettings::Mode::BAND, RenderSettings::Mode::SPECTRAL})
    {
        s.settings.mode = mode;
        const ScenePlan planned = PlanScene(s);
        const ScenePlan full = PlanScene(s, PlanOptions{false});
        CHECK_FALSE(planned.specular);
        CHECK(full.specular);
        CHECK(planned.groups.size() == 1);  // two D65 lights, one term
        CHECK(full.groups.size() == 2);
        CHECK_THAT(ExplainPlan(s, planned), Contains("specular: skipped"));
        CHECK_THAT(ExplainPlan(s, planned), Contains("lights sharing a spectrum summed"));
        RenderCounters cp, cf;
        const RenderedImage a1 = RenderScene(s, planned, 0, &cp);
        const RenderedImage a2 = RenderScene(s, full, 0, &cf);
        double worst = 0.0;
        for (size_t i = 0; i < a1.pixels.size(); ++i)
        {
            worst = std::max(worst, double(std::abs(a1.pixels[i] - a2.pixels[i])));
        }
        CHECK(worst < 1e-6);
        CHECK(cp.specularTerms == 0);
        CHECK(cf.specularTerms > 0);
        // And the literal per-sample path agrees with both.
        RenderCounters cu;
        const RenderedImage a3 = RenderSceneUnplanned(s, 0, &cu);
        for (size_t i = 0; i < a1.pixels.size(); ++i)
        {
            CHECK(a3.pixels[i] == Approx(a1.pixels[i]).margin(1e-5));
        }
        CHECK(cu.spectralSamples > 0);
        CHECK(cp.spectralSamples == 0);
    }
}

TEST_CASE("Attenuation is only evaluated when a light attenuates, and is capped at 1",
          "[render][scene]")
{
    SceneMaterial m = LectureMaterial("silver");
    Scene s = FlatScene(m);
    SceneLight p;
    p.kind = SceneLight::Kind::POINT;
    p.spectrum = {"A", BuiltinIlluminant("A"), {}};
    p.position = Vec3(0, 0, 1);
    s.lights = {p};
    RenderCounters c;
    const RenderedImage none = RenderScene(s, PlanScene(s), 0, &c);
    CHECK(c.attenuationTerms == 0);
    s.lights[0].attenuation = Vec3(0.5, 0.0, 0.0);  // 1/0.5 = 2, capped at 1
    const RenderedImage capped = RenderScene(s, PlanScene(s), 0, &c);
    CHECK(c.attenuationTerms > 0);
    CHECK(capped.pixels == none.pixels);
    s.lights[0].attenuation = Vec3(1.0, 0.0, 1.0);  // d ≈ 1: about half
    const RenderedImage dim = RenderScene(s, PlanScene(s));
    CHECK(Pixel(dim, 4, 3)[1] < 0.6 * Pixel(none, 4, 3)[1]);
}

TEST_CASE("Emission lines are integrated exactly in spectral mode", "[render][scene]")
{
    SceneMaterial m;
    m.diffuse = {"white", ConstantRemittance(1.0), {}};
    m.ambient = m.specular = {"0", ConstantRemittance(0.0), {}};
    Scene s = FlatScene(m);
    s.lights = {Directional({"laser", {}, LineSpectrum({{632.8, 1.0}})}, Vec3(0, 0, -1))};
    s.settings.mode = RenderSettings::Mode::SPECTRAL;
    const ScenePlan plan = PlanScene(s);
    CHECK(plan.lineCount == 1);
    const RenderedImage img = RenderScene(s, plan);
    const RenderedImage slow = RenderSceneUnplanned(s);
    const float* p = Pixel(img, 4, 3);
    CHECK(p[0] > 0.0f);
    CHECK(Pixel(slow, 4, 3)[0] == Approx(p[0]).epsilon(1e-6));
}

TEST_CASE("An orthographic camera sees a sphere the same size from any distance", "[render][scene]")
{
    // size 4 over 40 pixels: 0.1 scene units a pixel, so a sphere of radius 1
    // covers the 20 pixels whose centres lie within 1 of its centre.
    SceneMaterial m;
    m.diffuse = {"white", ConstantRemittance(1.0), {}};
    m.ambient = m.specular = {"0", ConstantRemittance(0.0), {}};
    Scene s;
    s.materials = {m};
    s.spheres = {{Vec3::Zero(), 1.0, 0}};
    s.lights = {Directional({"D65", BuiltinIlluminant("D65"), {}}, Vec3(0, 0, -1))};
    s.camera.projection = Camera::Projection::ORTHOGRAPHIC;
    s.camera.size = 4.0;
    s.camera.width = 40;
    s.camera.height = 40;
    auto covered = [&](double distance)
    {
        s.camera.position = Vec3(0, 0, distance);
        const RenderedImage img = RenderScene(s, PlanScene(s), 1);
        int n = 0;
        for (int x = 0; x < img.width; ++x)
        {
            n += Pixel(img, x, 20)[1] > 0.0f;
        }
        return n;
    };
    CHECK(covered(3.0) == 20);
    CHECK(covered(30.0) == 20);
    // Parallel rays in both render paths alike.
    s.camera.position = Vec3(0, 0, 3);
    const RenderedImage img = RenderScene(s, PlanScene(s), 1);
    const RenderedImage slow = RenderSceneUnplanned(s, 1);
    for (size_t i = 0; i < img.pixels.size(); ++i)
    {
        CHECK(slow.pixels[i] == Approx(img.pixels[i]).margin(1e-6));
    }
    s.camera.size = 0.0;
    CHECK_THROWS_WITH(PlanScene(s),
                      "an orthographic camera's size must be positive and at most 1e9");
}

TEST_CASE("The spectral range bounds the samples and the lines", "[render][scene]")
{
    SceneMaterial m;
    m.diffuse = {"white", ConstantRemittance(1.0), {}};
    m.ambient = m.specular = {"0", ConstantRemittance(0.0), {}};
    Scene s = FlatScene(m);
    s.settings.mode = RenderSettings::Mode::SPECTRAL;
    s.settings.stepNm = 5.0;
    s.settings.output = "lin-rec709";
    // A line at 790 nm counts over 360-830 nm and not over 380-780 nm (the default).
    s.lights = {
        Directional({"lines", {}, LineSpectrum({{550.0, 1.0}, {790.0, 1.0}})}, Vec3(0, 0, -1))};
    const ScenePlan plan = PlanScene(s);
    CHECK(plan.lineCount == 1);
    CHECK(plan.samples == 81);
    CHECK_THAT(ExplainPlan(s, plan),
               Contains("spectral range: 81 samples at 5 nm over 380-780 nm (the default, as "
                        "docs/science.md §1.1 sums)") &&
                   Contains("1 emission lines outside the integration range: not counted"));
    const RenderedImage narrow = RenderScene(s, plan, 1);
    const RenderedImage slow = RenderSceneUnplanned(s, 1);
    CHECK(Pixel(slow, 4, 3)[0] == Approx(Pixel(narrow, 4, 3)[0]).epsilon(1e-6));
    s.settings.rangeMinNm = 360.0;
    s.settings.rangeMaxNm = 830.0;
    const ScenePlan widePlan = PlanScene(s);
    CHECK(widePlan.lineCount == 2);
    CHECK_THAT(ExplainPlan(s, widePlan),
               Contains("spectral range: 95 samples at 5 nm over 360-830 nm (as the scene sets)"));
    const RenderedImage wide = RenderScene(s, widePlan, 1);
    CHECK(Pixel(wide, 4, 3)[0] > Pixel(narrow, 4, 3)[0]);
    CHECK(Pixel(RenderSceneUnplanned(s, 1), 4, 3)[0] == Approx(Pixel(wide, 4, 3)[0]).epsilon(1e-6));
    // D65 on white: the matching functions beyond 380-780 nm add little.
    s.lights = {Directional({"D65", BuiltinIlluminant("D65"), {}}, Vec3(0, 0, -1))};
    const float y360 = Pixel(RenderScene(s, PlanScene(s), 1), 4, 3)[1];
    s.settings.rangeMinNm = 380.0;
    s.settings.rangeMaxNm = 780.0;
    const float y380 = Pixel(RenderScene(s, PlanScene(s), 1), 4, 3)[1];
    CHECK(y360 != y380);
    CHECK(y360 == Approx(y380).epsilon(1e-3));
}

TEST_CASE("The grid message names the product that needs 1 nm", "[render][scene]")
{
    // A band-valued remittance jumps at 500 and 600 nm; a grid of step h
    // moves a jump by up to h/2, on samples or between them, so only the
    // reference grid reproduces it.
    SceneMaterial m = LectureMaterial("gold");
    Scene s = FlatScene(m);
    s.lights = {Directional({"D65", BuiltinIlluminant("D65"), {}}, Vec3(0, 0, -1))};
    s.settings.mode = RenderSettings::Mode::SPECTRAL;
    const ScenePlan plan = PlanScene(s);
    CHECK(plan.stepNm == 1.0);
    CHECK_THAT(ExplainPlan(s, plan),
               Contains("spectral grid: 1 nm, the reference grid: at 2 nm light 'D65' on "
                        "remittance 'gold R_"));
    // Spectra without jumps get a coarser grid (D65 on TCS09: 2 nm).
    SceneMaterial smooth;
    smooth.diffuse = {"TCS09", TestColourSamples()[8].spectrum, {}};
    smooth.ambient = smooth.specular = {"0", ConstantRemittance(0.0), {}};
    s.materials = {smooth};
    const ScenePlan coarse = PlanScene(s);
    CHECK(coarse.stepNm > 1.0);
    CHECK_THAT(ExplainPlan(s, coarse), Contains("nm reproduces every light x remittance product"));
}

TEST_CASE("The literal path says what it does", "[render][scene]")
{
    SceneMaterial m = LectureMaterial("tin");
    Scene s = FlatScene(m);
    s.lights = {Directional({"D65", BuiltinIlluminant("D65"), {}}, Vec3(0, 0, -1)),
                Directional({"D65", BuiltinIlluminant("D65"), {}}, Vec3(0, -1, -1))};
    const std::string text = ExplainUnplanned(s);
    CHECK_THAT(text, Contains("the literal path: no plan") &&
                         Contains("every light on its own: 2 direct lights") &&
                         Contains("per light, per band") && !Contains("summed"));
    s.settings.mode = RenderSettings::Mode::SPECTRAL;
    s.settings.stepNm = 5.0;
    CHECK_THAT(ExplainUnplanned(s), Contains("per light, per wavelength sample") &&
                                        Contains("81 samples at 5 nm over 380-780 nm"));
}
