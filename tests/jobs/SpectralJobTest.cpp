// SPDX-License-Identifier: BSD-3-Clause
// The spectral job's light groups (jobs/SpectralJob): a two-light render
// relit group by group against the same scene rendered under the new
// lights, and per-group RGB looks against one global look.
// Covers, through the entry points it calls: imaging/SpectralImages.cpp,
// imaging/SpectralGroups.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "jobs/ApplyJob.h"
#include "jobs/LightGroupsTestSupport.h"
#include "jobs/RenderJob.h"
#include "jobs/SpectralJob.h"
#include "render/SceneColour.h"
#include "spectral/Colorimetry.h"
#include "spectral/RgbSpaces.h"

using namespace bandlight;
using namespace bandlight::jobs;
using test::Change;
using test::Exr;
using test::MaxAbs;
using test::ReadExr;

namespace
{
/// The image module is found beside the bandlight executable; this test
/// program lives elsewhere, so it says where.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

/// The two-light scene of scenes/two_lights.yaml with other lights: the key
/// and fill replaced, each at the luminance of the light it replaces (as
/// the spectral relight keeps it).
Scene Relit(const Scene& scene, const std::map<std::string, std::string>& to)
{
    Scene s = scene;
    const detail::Grid grid = detail::MakeGrid(s.settings, s.settings.stepNm);
    const detail::Cmf cmf = detail::MakeCmf(grid, s.settings.bands);
    const auto luminance = [&](const SceneSpectrum& sp, double intensity)
    {
        const std::vector<double> v = detail::Sample(sp.continuous, grid);
        double y = 0.0;
        for (size_t i = 0; i < v.size(); ++i)
        {
            y += v[i] * cmf.weight[i].y();
        }
        return intensity * detail::LightScale(sp, s.settings.bands) * y;
    };
    for (SceneLight& l : s.lights)
    {
        const double before = luminance(l.spectrum, l.intensity);
        l.spectrum.name = to.at(l.name);
        l.spectrum.continuous = ResolveIlluminant(to.at(l.name)).spectrum;
        l.intensity *= before / luminance(l.spectrum, l.intensity);
    }
    return s;
}

/// ΔE00 of two acescg images per pixel hit, L*a*b* relative to the
/// equal-energy white at `level` (the lights' summed intensity, as
/// render --compare takes it).
double MeanDeltaE(const std::vector<float>& a, const std::vector<float>& ref, double level)
{
    const Mat3 toXyz = RgbToXyzMatrix(FindRgbSpace("acescg").chromaticities);
    const Vec3 white = Vec3::Ones() * level;
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i + 2 < ref.size(); i += 3)
    {
        const Vec3 r(ref[i], ref[i + 1], ref[i + 2]);
        if (r.isZero(0.0))
        {
            continue;
        }
        sum += DeltaE2000(XyzToLab(toXyz * Vec3(a[i], a[i + 1], a[i + 2]), white),
                          XyzToLab(toXyz * r, white));
        ++n;
    }
    return sum / double(n);
}

std::vector<float> Rgb(const Exr::Part& part, const std::string& prefix = "")
{
    std::vector<float> v(3 * part.count());
    for (size_t p = 0; p < part.count(); ++p)
    {
        v[3 * p] = part.at(p, prefix + "R");
        v[3 * p + 1] = part.at(p, prefix + "G");
        v[3 * p + 2] = part.at(p, prefix + "B");
    }
    return v;
}
}  // namespace

TEST_CASE(
    "Spectral light groups relight a two-light render exactly, RGB groups within the "
    "method's own error",
    "[jobs][lightgroups][spectral]")
{
    const std::string dir = test::FreshLightGroupDir("spectral");
    const std::string shot = dir + "/shot.exr";
    RenderRequest render;
    render.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
    render.spectra = true;
    render.lightGroups = true;
    render.preview = false;
    render.out = shot;
    const PreparedRender prepared = PrepareRender(render);
    MakeRender(prepared);
    const Exr::Part file = ReadExr(shot)[0];

    // Beauty = Σ groups in the file, RGB and every wavelength, to 1e-6.
    double peak = 0.0;
    for (size_t p = 0; p < file.count(); ++p)
    {
        peak = std::max(peak, double(file.at(p, "R")));
    }
    REQUIRE(peak > 0.0);
    for (const std::string& c :
         {std::string("R"), std::string("B"), SpectralChannelName(SpectralKind::EMISSIVE, 550.0)})
    {
        double worst = 0.0, level = 0.0;
        for (size_t p = 0; p < file.count(); ++p)
        {
            level = std::max(level, double(file.at(p, c)));
            worst = std::max(worst, std::abs(double(file.at(p, c)) - file.at(p, "key." + c) -
                                             file.at(p, "fill." + c)));
        }
        CHECK(worst <= 1e-6 * level);
    }

    // The reference: the same scene lit by D65 and D50.
    RenderRequest refRequest;
    refRequest.scene = render.scene;
    PreparedRender ref = PrepareRender(refRequest);
    ref.scene = Relit(prepared.scene, {{"key", "D65"}, {"fill", "D50"}});
    ref.plan = PlanScene(ref.scene);
    const std::vector<float> reference = MakeRender(ref).image.pixels;
    const double refPeak = MaxAbs(reference);

    SpectralRequest sr;
    sr.files.input = shot;
    sr.files.output = dir + "/relit.exr";
    sr.options.plates.plates = "lit";
    sr.options.lightGroups = {{"key", ResolveIlluminant("A"), ResolveIlluminant("D65")},
                              {"fill", ResolveIlluminant("F11"), ResolveIlluminant("D50")}};
    ConvertSpectralImages(sr);
    const Exr::Part relit = ReadExr(sr.files.output)[0];
    const std::vector<float> spectral = Rgb(relit);
    double worst = 0.0;
    for (size_t i = 0; i < reference.size(); ++i)
    {
        worst = std::max(worst, double(std::abs(spectral[i] - reference[i])));
    }
    std::printf(
        "spectral light groups against the D65/D50 render: max |difference| %.3g of the "
        "brightest value %.4g (%.2g relative)\n",
        worst, refPeak, worst / refPeak);
    CHECK(worst <= 1e-5 * refPeak);
    // Its groups sum to its beauty.
    const std::vector<float> key = Rgb(relit, "key."), fill = Rgb(relit, "fill.");
    for (size_t i = 0; i < spectral.size(); ++i)
    {
        CHECK(std::abs(spectral[i] - key[i] - fill[i]) <= 1e-6 * refPeak);
    }

    SECTION("identity spectral relight of every group reproduces the beauty")
    {
        SpectralRequest same = sr;
        same.files.output = dir + "/same.exr";
        same.options.lightGroups = {{"key", ResolveIlluminant("A"), ResolveIlluminant("A")},
                                    {"fill", ResolveIlluminant("F11"), ResolveIlluminant("F11")}};
        ConvertSpectralImages(same);
        const std::vector<float> s = Rgb(ReadExr(same.files.output)[0]);
        const std::vector<float> beauty = Rgb(file);
        for (size_t i = 0; i < s.size(); ++i)
        {
            CHECK(std::abs(s[i] - beauty[i]) <= 1e-6 * peak);
        }
    }

    SECTION("NaN and infinity in a group or the beauty are guarded, counted, never written")
    {
        // The policy of RGB light groups (docs/robustness.md): a non-finite
        // value is a pixel value, taken as +-1e16 after integration; the
        // other pixels relight as before.
        Exr::Part broken = file;
        const auto at = [&](size_t p, const std::string& c) -> float&
        {
            const auto& names = broken.spec.channelnames;
            const auto i = std::find(names.begin(), names.end(), c);
            REQUIRE(i != names.end());
            return broken.pixels[p * size_t(broken.spec.nchannels) + size_t(i - names.begin())];
        };
        at(0, "key." + SpectralChannelName(SpectralKind::EMISSIVE, 550.0)) = std::nanf("");
        at(1, SpectralChannelName(SpectralKind::EMISSIVE, 500.0)) =
            std::numeric_limits<float>::infinity();
        const std::string path = dir + "/broken.exr";
        auto out = OIIO::ImageOutput::create(path);
        REQUIRE(out);
        REQUIRE(out->open(path, broken.spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, broken.pixels.data()));
        REQUIRE(out->close());

        struct Notes : Reporter
        {
            std::vector<std::string> lines;
            void note(const std::string& line) override { lines.push_back(line); }
        } notes;
        SpectralRequest g = sr;
        g.files.input = path;
        g.files.output = dir + "/guarded.exr";
        ConvertSpectralImages(g, notes);
        const Exr::Part guarded = ReadExr(g.files.output)[0];
        for (const float v : guarded.pixels)
        {
            REQUIRE(std::isfinite(v));
        }
        CHECK(std::any_of(
            notes.lines.begin(), notes.lines.end(),
            [](const std::string& l)
            { return l.find("2 pixels held NaN or infinite values") != std::string::npos; }));
        // Every other pixel is what the clean file gives.
        for (size_t p = 2; p < guarded.count(); ++p)
        {
            for (const char* c : {"R", "G", "B", "key.R", "fill.B"})
            {
                REQUIRE(guarded.at(p, c) == relit.at(p, c));
            }
        }
        // The NaN in the key group: its RGB guarded to -1e16 in each channel.
        CHECK(guarded.at(0, "key.G") == float(-1e16));
    }

    SECTION("per-group RGB relighting beats one global look on the beauty")
    {
        // The global look goes from the mix of the scene's lights to the
        // mix of the new ones, each light weighed by its intensity on the
        // band model's scale (what a surface facing both receives).
        const auto mix = [&](const Scene& s, const std::string& name)
        {
            Spectrum sum = Spectrum::Constant(380.0, 5.0, 81, 0.0);
            for (const SceneLight& l : s.lights)
            {
                Spectrum part = l.spectrum.continuous.resampledLike(sum);
                part *= l.intensity * detail::LightScale(l.spectrum, s.settings.bands);
                sum += part;
            }
            return Light{name, sum};
        };
        const Light before = mix(prepared.scene, "key A + fill F11");
        const Light after = mix(ref.scene, "key D65 + fill D50");
        const double level = 1.6;  // the lights' summed intensity
        const double global0 = MeanDeltaE(Rgb(file), reference, level);
        std::printf("no change: mean dE00 %.3f\n", global0);
        // Every method's figures (docs/lightgroups.md) with
        // BANDLIGHT_LIGHT_GROUP_METHODS=all; by default the two checked.
        const char* all = std::getenv("BANDLIGHT_LIGHT_GROUP_METHODS");
        const std::vector<std::string> methods =
            all && std::string(all) == "all"
                ? std::vector<std::string>{"vonkries", "bradford", "cat02",  "band3",
                                           "band3-wp", "band6",    "fit3x3", "prefilter",
                                           "rootpoly", "upsample"}
                : std::vector<std::string>{"bradford", "rootpoly"};
        for (const std::string& method : methods)
        {
            ApplyRequest g;
            g.input = shot;
            g.output = dir + "/global_" + method + ".exr";
            RelightRequest change;
            change.src = before;
            change.dst = after;
            change.method = method;
            change.plates.plates = "lit";
            g.relight = change;
            ApplyImages(g);
            const double global = MeanDeltaE(Rgb(ReadExr(g.output)[0]), reference, level);
            ApplyRequest pg;
            pg.input = shot;
            pg.output = dir + "/groups_" + method + ".exr";
            pg.lightGroups = {{"key", Change("A", "D65", method)},
                              {"fill", Change("F11", "D50", method)}};
            ApplyImages(pg);
            const double groups = MeanDeltaE(Rgb(ReadExr(pg.output)[0]), reference, level);
            std::printf(
                "%-9s global look on the beauty: mean dE00 %.3f; per group: %.3f (%.2f of "
                "global)\n",
                method.c_str(), global, groups, groups / global);
            if (method == "rootpoly" || method == "bradford")
            {
                CHECK(groups <= 0.7 * global);
            }
        }
    }
}
