// SPDX-License-Identifier: BSD-3-Clause
// The planner's promise: it changes the cost, never the picture. Scenes
// generated at random (every light kind and spectrum form, materials of
// every form, spheres and planes, pinhole and orthographic cameras) render
// the same planned and literally (RenderSceneUnplanned), in band and
// spectral mode, to 1e-6 of each pixel's largest channel.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>

#include "render/SceneFile.h"
#include "render/SceneRenderer.h"

using namespace bandlight;

namespace
{

const std::string kScenes = SCENES_DIR;

std::string Num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

const float* Pixel(const RenderedImage& img, int x, int y)
{
    return &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels)];
}

/// The largest difference between two renders, relative to each pixel's
/// largest channel (plus 1e-9 absolute, for black pixels): ≤ 1e-6 passes.
double WorstRelativeDifference(const RenderedImage& a, const RenderedImage& b)
{
    REQUIRE(a.pixels.size() == b.pixels.size());
    REQUIRE(a.channels == b.channels);
    double worst = 0.0;
    const size_t ch = size_t(a.channels);
    for (size_t p = 0; p < a.pixels.size(); p += ch)
    {
        double scale = 0.0;
        for (size_t k = 0; k < ch; ++k)
        {
            scale = std::max(
                {scale, double(std::abs(a.pixels[p + k])), double(std::abs(b.pixels[p + k]))});
        }
        for (size_t k = 0; k < ch; ++k)
        {
            const double d = std::abs(double(a.pixels[p + k]) - double(b.pixels[p + k]));
            worst = std::max(worst, d / (1e-6 * scale + 1e-9) * 1e-6);
        }
    }
    return worst;
}

/// Renders planned and literally; the worst relative difference.
double PlannedAgainstLiteral(const Scene& s, RenderCounters* counters = nullptr)
{
    const RenderedImage planned = RenderScene(s, PlanScene(s), 1, counters);
    const RenderedImage literal = RenderSceneUnplanned(s, 1);
    return WorstRelativeDifference(planned, literal);
}

/// Random scenes as YAML text, so the reader's every form is exercised too.
class SceneGenerator
{
public:
    explicit SceneGenerator(unsigned seed) : m_rng(seed) {}

    /// A scene; `spectral` picks the mode (band scenes use band3, band6 or
    /// explicit edges, and sometimes band-valued output).
    std::string scene(bool spectral)
    {
        std::ostringstream y;
        const bool explicitBands = !spectral && chance(0.2);
        m_bandCount = explicitBands ? 4 : spectral ? 3 : pick<size_t>({3, 3, 6});
        y << camera();
        y << "render:\n  mode: " << (spectral ? "spectral" : "band" + std::to_string(m_bandCount))
          << "\n";
        if (explicitBands)
        {
            y << "  bands: [400, 460, 530, 610, 700]\n";
        }
        if (spectral && chance(0.5))
        {
            y << "  step: " << pick<int>({1, 2, 5, 10, 20}) << "\n";
        }
        if (spectral && chance(0.4))
        {
            y << "  range: " << pick<std::string>({"[360, 830]", "[380, 780]", "[400, 700]"})
              << "\n";
        }
        y << "  output: "
          << (!spectral && chance(0.3) ? "bands"
                                       : pick<std::string>({"acescg", "lin-rec709", "rec2020"}))
          << "\n";
        y << lights();
        const int materials = uniformInt(1, 4);
        y << "materials:\n";
        for (int m = 0; m < materials; ++m)
        {
            y << material(m);
        }
        y << "objects:\n";
        const int spheres = uniformInt(1, 4);
        for (int i = 0; i < spheres; ++i)
        {
            y << "  - {sphere: {center: " << vec(-1.5, 1.5)
              << ", radius: " << Num(uniform(0.3, 1.2)) << "}, material: m"
              << uniformInt(0, materials - 1) << "}\n";
        }
        for (int i = uniformInt(0, 2); i > 0; --i)
        {
            y << "  - {plane: {point: " << vec(-1.0, 1.0) << ", normal: " << vec(-1.0, 1.0, 0.2)
              << "}, material: m" << uniformInt(0, materials - 1) << "}\n";
        }
        return y.str();
    }

private:
    std::mt19937 m_rng;
    size_t m_bandCount = 3;
    int m_direct = 0;
    std::vector<std::string> m_spectra;  ///< light spectra given so far (some are repeated)

    double uniform(double a, double b)
    {
        return std::uniform_real_distribution<double>(a, b)(m_rng);
    }
    int uniformInt(int a, int b) { return std::uniform_int_distribution<int>(a, b)(m_rng); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }
    template <typename T>
    T pick(std::initializer_list<T> items)
    {
        return *(items.begin() + uniformInt(0, int(items.size()) - 1));
    }

    std::string vec(double a, double b, double minNorm = 0.0)
    {
        double x, y, z;
        do
        {
            x = uniform(a, b), y = uniform(a, b), z = uniform(a, b);
        } while (std::sqrt(x * x + y * y + z * z) < minNorm);
        return "[" + Num(x) + ", " + Num(y) + ", " + Num(z) + "]";
    }

    std::string camera()
    {
        // On a sphere around the origin, never straight above (up is +y).
        const double az = uniform(0.0, 6.283), el = uniform(-0.9, 0.9), r = uniform(4.0, 8.0);
        std::ostringstream c;
        c << "camera:\n  position: [" << Num(r * std::cos(el) * std::cos(az)) << ", "
          << Num(r * std::sin(el)) << ", " << Num(r * std::cos(el) * std::sin(az)) << "]\n"
          << "  look_at: " << vec(-0.3, 0.3) << "\n  width: 24\n  height: 16\n";
        if (chance(0.35))
        {
            c << "  type: orthographic\n  size: " << Num(uniform(2.0, 6.0)) << "\n";
        }
        else
        {
            c << "  fov: " << Num(uniform(20.0, 60.0)) << "\n";
        }
        return c.str();
    }

    std::string bandValues(size_t n, bool light)
    {
        std::string v = "[";
        for (size_t i = 0; i < n; ++i)
        {
            // A light has power in at least its first band.
            const double x = light && i == 0 ? uniform(0.2, 1.0)
                             : chance(0.2)   ? 0.0
                                             : uniform(0.0, 1.0);
            v += (i ? ", " : "") + Num(x);
        }
        return v + "]";
    }

    std::string lightSpectrum()
    {
        if (!m_spectra.empty() && chance(0.3))
        {
            return m_spectra[size_t(uniformInt(0, int(m_spectra.size()) - 1))];  // shared: one term
        }
        std::string s;
        switch (uniformInt(0, 5))
        {
            case 0:
                s = pick<std::string>({"A", "D65", "D50", "F2", "F11", "F7", "C", "3200K"});
                break;
            case 1:
                s = "{cct: " + std::to_string(uniformInt(40, 90) * 100) + "}";
                break;
            case 2:
                s = "{blackbody: " + std::to_string(uniformInt(20, 80) * 100) + "}";
                break;
            case 3:
            {
                s = "{lines: [";
                const int n = uniformInt(1, 3);
                for (int i = 0; i < n; ++i)
                {
                    s += (i ? ", [" : "[") + Num(uniform(405.0, 695.0)) + ", " +
                         Num(uniform(0.2, 2.0)) + "]";
                }
                if (chance(0.3))
                {
                    s += ", [790, 1]";  // outside the default range
                }
                s += "]}";
                break;
            }
            case 4:
                s = "{bands: " + bandValues(m_bandCount, true) + "}";
                break;
            default:
                s = "{file: " + kScenes + "/counterexample_light.csv}";
                break;
        }
        m_spectra.push_back(s);
        return s;
    }

    std::string lights()
    {
        std::ostringstream l;
        l << "lights:\n";
        m_direct = 0;
        m_spectra.clear();
        const int n = uniformInt(1, 5);
        for (int i = 0; i < n; ++i)
        {
            const int kind = i == 0 ? uniformInt(1, 2) : uniformInt(0, 2);  // one direct at least
            l << "  - {";
            if (kind == 0)
            {
                l << "type: ambient";
            }
            else if (kind == 1)
            {
                l << (chance(0.5) ? "type: point, " : "") << "position: " << vec(-5.0, 5.0, 1.5);
                if (chance(0.4))
                {
                    l << ", attenuation: [" << Num(uniform(0.5, 1.0)) << ", "
                      << Num(uniform(0.0, 0.3)) << ", " << Num(uniform(0.0, 0.1)) << "]";
                }
                ++m_direct;
            }
            else
            {
                l << "type: directional, direction: " << vec(-1.0, 1.0, 0.2);
                ++m_direct;
            }
            if (chance(0.7))
            {
                l << ", intensity: " << Num(uniform(0.1, 2.0));
            }
            l << ", spectrum: " << lightSpectrum() << "}\n";
        }
        return l.str();
    }

    std::string remittance()
    {
        switch (uniformInt(0, 3))
        {
            case 0:
                return Num(uniform(0.0, 1.0));
            case 1:
            {
                const int k = uniformInt(1, 15);
                return std::string(k < 10 ? "TCS0" : "TCS") + std::to_string(k);
            }
            case 2:
                return "{bands: " + bandValues(m_bandCount, false) + "}";
            default:
                return "{file: " + kScenes + "/counterexample_surface.csv}";
        }
    }

    std::string material(int index)
    {
        std::ostringstream m;
        m << "  m" << index << ": ";
        const int form = uniformInt(0, 4);
        if (form == 0 && m_bandCount == 3)
        {
            m << "{lecture: "
              << pick<std::string>({"copper", "gold", "silver", "aluminium", "tin", "matte lacquer",
                                    "gloss lacquer"})
              << "}\n";
            return m.str();
        }
        std::vector<std::string> parts;
        if (form <= 2)
        {
            // The compact form.
            if (chance(0.6))
                parts.push_back("ambient: " + remittance());
            parts.push_back("diffuse: " + remittance());
            if (chance(0.6))
            {
                parts.push_back("specular: " + remittance());
                if (chance(0.8))
                    parts.push_back("exponent: " + Num(pick<double>({0, 1, 4, 16.5, 64, 300})));
            }
        }
        else
        {
            // The full form.
            for (const char* p : {"a", "d", "s"})
            {
                if (chance(0.7))
                {
                    parts.push_back(std::string("k_") + p + ": " + Num(uniform(0.0, 1.0)));
                    if (chance(0.6))
                        parts.push_back(std::string("O_") + p + ": " + remittance());
                }
            }
            if (parts.empty())
                parts.push_back("k_d: 0.5");
            const bool specular =
                std::any_of(parts.begin(), parts.end(),
                            [](const std::string& s) { return s.rfind("k_s", 0) == 0; });
            if (specular && chance(0.8))
                parts.push_back("n: " + Num(pick<double>({0, 2, 8, 32, 128})));
        }
        if (m_direct == 1 && chance(0.3))
        {
            parts.push_back("ambient_star: " + remittance());
        }
        m << "{";
        for (size_t i = 0; i < parts.size(); ++i)
        {
            m << (i ? ", " : "") << parts[i];
        }
        m << "}\n";
        return m.str();
    }
};

const std::string kBandLights = R"(
camera: {position: [0, 0, 3], look_at: [0, 0, 0], width: 4, height: 4, fov: 20}
render: {mode: band3, output: bands}
lights:
  - {type: directional, direction: [0, 0, -1], intensity: 0.5, spectrum: {bands: [0, 1, 0.5]}}
  - {type: directional, direction: [-0.8660254037844386, 0, -0.5], intensity: 0.36,
     spectrum: {bands: [1, 0, 0.2]}}
materials:
  m: {diffuse: {bands: [0.4, 0.5, 0]}}
objects:
  - {plane: {point: [0, 0, 0], normal: [0, 0, 1]}, material: m}
)";

}  // namespace

TEST_CASE("Band-valued lights with different values are two terms, not one", "[render][plan]")
{
    // Both lights are called "bands ..." by their form; only their values
    // tell them apart. Light 1: 0.5 × cos 0 × (0, 1, 0.5) ⊙ (0.4, 0.5, 0) =
    // (0, 0.25, 0); light 2: 0.36 × cos 60° × (1, 0, 0.2) ⊙ R = (0.072, 0, 0).
    // Grouped by name they came out (0, 0.34, 0).
    const Scene s = ReadSceneText(kBandLights, "bandlights.yaml");
    const ScenePlan plan = PlanScene(s);
    CHECK(plan.groups.size() == 2);
    for (const RenderedImage& img : {RenderScene(s, plan, 1), RenderSceneUnplanned(s, 1)})
    {
        const float* p = Pixel(img, 2, 2);
        CHECK(p[0] == Approx(0.072).epsilon(1e-6));
        CHECK(p[1] == Approx(0.250).epsilon(1e-6));
        CHECK(p[2] == 0.0f);
    }
    Scene spectral = s;
    spectral.settings.mode = RenderSettings::Mode::SPECTRAL;
    spectral.settings.output = "acescg";
    CHECK(PlannedAgainstLiteral(spectral) <= 1e-6);
}

TEST_CASE("Lights with the same values share a term whatever they are called", "[render][plan]")
{
    // "1" and "1.0" name the same spectrum differently; A and D65 differ.
    const std::string yaml = R"(
camera: {position: [0, 0, 3], look_at: [0, 0, 0], width: 8, height: 8}
lights:
  - {type: point, position: [1, 1, 2], spectrum: {bands: [1, 0.5, 0.25]}}
  - {type: point, position: [-1, 1, 2], spectrum: {bands: [1.0, 0.50, 0.25]}}
  - {type: directional, direction: [0, 0, -1], spectrum: A}
  - {type: directional, direction: [0, -1, -1], spectrum: D65}
  - {type: directional, direction: [1, 0, -1], spectrum: d65}
materials:
  m: {diffuse: TCS09, specular: 0.2, exponent: 8}
objects:
  - {sphere: {radius: 1}, material: m}
)";
    const Scene s = ReadSceneText(yaml, "same.yaml");
    const ScenePlan plan = PlanScene(s);
    CHECK(plan.groups == std::vector<std::vector<int>>{{0, 1}, {2}, {3, 4}});
    CHECK(PlannedAgainstLiteral(s) <= 1e-6);
}

TEST_CASE("Planned equals literal on 400 generated scenes, band and spectral mode",
          "[render][plan][property]")
{
    // The fixed cases first: the band-valued lights the planner once merged
    // by name, as band values, as RGB, and spectrally.
    for (const char* render : {"{mode: band3, output: bands}", "{mode: band3, output: acescg}",
                               "{mode: spectral, output: lin-rec709}"})
    {
        std::string yaml = kBandLights;
        yaml.replace(yaml.find("{mode: band3, output: bands}"), 28, render);
        INFO(yaml);
        CHECK(PlannedAgainstLiteral(ReadSceneText(yaml, "fixed.yaml")) <= 1e-6);
    }
    // Seeded: the same scenes on every run. 200 per mode, 24×16 pixels.
    SceneGenerator generate(20240613u);
    const auto t0 = std::chrono::steady_clock::now();
    int rendered = 0;
    int orthographic = 0;
    uint64_t pixels = 0, hits = 0, specular = 0, attenuation = 0;
    for (int i = 0; i < 400; ++i)
    {
        const bool spectral = i % 2 == 1;
        const std::string yaml = generate.scene(spectral);
        INFO("scene " << i << ":\n" << yaml);
        Scene s;
        REQUIRE_NOTHROW(s = ReadSceneText(yaml, "generated.yaml"));
        orthographic += s.camera.projection == Camera::Projection::ORTHOGRAPHIC;
        RenderCounters c;
        const double worst = PlannedAgainstLiteral(s, &c);
        CHECK(worst <= 1e-6);
        ++rendered;
        pixels += c.pixels;
        hits += c.hits;
        specular += c.specularTerms > 0;
        attenuation += c.attenuationTerms > 0;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK(rendered == 400);
    // The scenes are not empty pictures: objects fill a good part of them,
    // and the planner's optional effects are exercised.
    CHECK(orthographic > 80);
    CHECK(hits > pixels / 5);
    CHECK(specular > 120);
    CHECK(attenuation > 60);
    WARN("400 generated scenes, planned against literal, in "
         << seconds << " s; " << hits << " of " << pixels << " pixels hit, " << orthographic
         << " orthographic, " << specular << " with specular, " << attenuation << " attenuating");
}
