// SPDX-License-Identifier: BSD-3-Clause
// The render job in process: its comparison against the spectral render,
// its outputs as one set, its checks before the work, the command's bytes,
// and light groups whose sum is the beauty.
// Covers, through the entry points it calls: imaging/RenderFiles.cpp, requests/Render.cpp.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "imaging/LightGroups.h"
#include "jobs/RenderJob.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "cli/RunCommand.h"
#include "jobs/LightGroupsTestSupport.h"

using namespace bandlight;
namespace fs = std::filesystem;

namespace
{
/// The image module is found beside the bandlight executable; this test
/// program lives elsewhere, so it says where.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

/// Gold, copper and a grey plane under A and a dim ambient: far from the
/// spectral answer in band mode, 40x30 pixels with background.
const std::string kScene =
    R"(camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 30, width: 40, height: 30}
render: {mode: band3, output: acescg}
lights:
  - {type: point, position: [3, 4, 5], spectrum: A}
  - {type: ambient, spectrum: A, intensity: 0.1}
materials:
  gold: lecture
  copper: lecture
objects:
  - {sphere: {center: [-0.6, 0, 0], radius: 0.5}, material: gold}
  - {sphere: {center: [0.6, 0, 0], radius: 0.5}, material: copper}
)";

std::string Fresh(const std::string& name)
{
    const std::string dir = test::TempPath("renderjob_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string ReadAll(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// An image file's bytes without the time stamp OpenImageIO writes into
/// EXRs (capDate, 19 characters), as tests/docs/run_examples.py compares them.
std::string ImageBytes(const std::string& path)
{
    std::string bytes = ReadAll(path);
    // The attribute's name, type and size (19), then "YYYY:MM:DD HH:MM:SS".
    const std::string tag("capDate\0string\0\x13\0\0\0", 19);
    const size_t at = bytes.find(tag);
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".exr") == 0)
    {
        REQUIRE(at != std::string::npos);
        REQUIRE(at + 38 <= bytes.size());
        bytes.replace(at + 19, 19, 19, '0');
    }
    return bytes;
}

std::vector<float> ReadPixels(const std::string& path, int& width, int& height)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    width = spec.width;
    height = spec.height;
    std::vector<float> px(size_t(spec.image_pixels()) * size_t(spec.nchannels));
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

jobs::RenderRequest TextRequest(const std::string& out)
{
    jobs::RenderRequest r;
    r.text = kScene;
    r.source = "gold_copper.yaml";
    r.out = out;
    r.threads = 2;
    return r;
}
}  // namespace

TEST_CASE("render --compare: the summary is the ΔE00 of the band render against the spectral one",
          "[jobs][render]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = Fresh("compare");
    jobs::RenderRequest request = TextRequest(dir + "/gold.exr");
    request.compare = true;
    const jobs::RenderResult result = jobs::MakeRender(request);
    REQUIRE(result.comparison);
    const DeltaESummary& s = result.comparison->summary;
    CHECK(result.image.width == 40);
    CHECK(result.image.height == 30);
    CHECK(result.comparison->exr == dir + "/gold_dE00.exr");
    CHECK(result.comparison->png == dir + "/gold_dE00.png");
    CHECK(result.written() == std::vector<std::string>{dir + "/gold.exr", dir + "/gold.png",
                                                       dir + "/gold_dE00.exr",
                                                       dir + "/gold_dE00.png"});

    // The two renders, made apart, and CIEDE2000 between them here.
    jobs::RenderRequest band = TextRequest("");
    jobs::RenderRequest spectral = TextRequest("");
    spectral.mode = "spectral";
    const RenderedImage a = jobs::MakeRender(band).image;
    const RenderedImage b = jobs::MakeRender(spectral).image;
    REQUIRE(a.pixels == result.image.pixels);
    const Mat3 toXyz = RgbToXyzMatrix(FindRgbSpace("acescg").chromaticities);
    const Vec3 white = Vec3::Ones() * 1.1;  // the lights' summed intensity
    double sum = 0.0;
    double max = 0.0;
    size_t hits = 0;
    for (size_t i = 0; i < a.pixels.size() / 3; ++i)
    {
        const Vec3 xa = toXyz * Vec3(a.pixels[3 * i], a.pixels[3 * i + 1], a.pixels[3 * i + 2]);
        const Vec3 xb = toXyz * Vec3(b.pixels[3 * i], b.pixels[3 * i + 1], b.pixels[3 * i + 2]);
        if (xa.isZero(0.0) && xb.isZero(0.0))
        {
            continue;
        }
        const double e = DeltaE2000(XyzToLab(xa, white), XyzToLab(xb, white));
        sum += e;
        max = std::max(max, e);
        ++hits;
    }
    REQUIRE(hits > 100);
    REQUIRE(hits < a.pixels.size() / 3);  // there is background
    CHECK(s.pixels == hits);
    CHECK(s.mean == Approx(sum / double(hits)).epsilon(1e-12));
    CHECK(s.max == Approx(max).epsilon(1e-12));
    CHECK(s.p95 <= s.max);
    CHECK(s.p95 >= s.mean);
    // Band3 under A is visibly off on gold and copper, not wildly.
    CHECK(s.mean > 0.5);
    CHECK(s.mean < 20.0);

    // The map written is the same values: its own mean over the pixels hit
    // is the summary's (float storage: to 1e-6).
    int w = 0, h = 0;
    const std::vector<float> map = ReadPixels(result.comparison->exr, w, h);
    REQUIRE(w == 40);
    REQUIRE(h == 30);
    double mapSum = 0.0;
    for (const float v : map)
    {
        mapSum += v;
    }
    CHECK(mapSum / double(s.pixels) == Approx(s.mean).epsilon(1e-6));
    // The PNG is the accuracy heat maps' picture (gnuplot, 1000x650 with the
    // title and colour scale), not a 40x30 grey image.
    const std::vector<float> png = ReadPixels(result.comparison->png, w, h);
    CHECK(w == 1000);
    CHECK(h == 650);
}

TEST_CASE("render --compare of a spectral render is refused before any work", "[jobs][render]")
{
    // Against itself its map would be 0 everywhere: a comparison that says nothing.
    const std::string dir = Fresh("self");
    jobs::RenderRequest request = TextRequest(dir + "/self.exr");
    request.mode = "spectral";
    request.compare = true;
    request.preview = false;
    CHECK_THROWS_AS(jobs::MakeRender(request), ParameterError);
    CHECK_FALSE(fs::exists(dir + "/self.exr"));
    CHECK_FALSE(fs::exists(dir + "/self_dE00.exr"));
}

TEST_CASE("a render's outputs are one set: a failing output leaves every file as it was",
          "[jobs][render]")
{
    const std::string dir = Fresh("set");
    const std::string out = dir + "/shot.exr";
    const std::string preview = dir + "/shot.png";
    const auto listing = [&]
    {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir))
        {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    };
    std::ofstream(out) << "the previous render";
    std::ofstream(preview) << "the previous preview";
    jobs::RenderRequest request = TextRequest(out);
    request.compare = true;

    SECTION("an output whose folder is missing is refused before the render")
    {
        request.previewPath = dir + "/missing/shot.png";
        CHECK_THROWS_WITH(jobs::MakeRender(request),
                          Catch::Contains("/missing") && Catch::Contains("cannot write there"));
    }
    SECTION("the last output failing while it is written leaves the others unwritten")
    {
        // The map's PNG is drawn by gnuplot, after the render, its preview
        // and the map's EXR were written to their temporary files: without
        // gnuplot on the PATH the fourth output fails.
        const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
        ::setenv("PATH", (dir + "/no-programs-here").c_str(), 1);
        CHECK_THROWS_WITH(jobs::MakeRender(request), Catch::Contains("gnuplot is not installed"));
        ::setenv("PATH", path.c_str(), 1);
    }
    CHECK(ReadAll(out) == "the previous render");
    CHECK(ReadAll(preview) == "the previous preview");
    // No map, no temporary file.
    CHECK(listing() == std::vector<std::string>{"shot.exr", "shot.png"});
}

TEST_CASE("outputs that do not go together are refused before rendering", "[jobs][render]")
{
    jobs::RenderRequest spectra = TextRequest(test::TempPath("renderjob_never.exr"));
    spectra.spectra = true;
    CHECK_THROWS_WITH(jobs::MakeRender(spectra),
                      "spectra needs spectral mode (mode = spectral): band mode has no spectrum "
                      "to write");
    try
    {
        jobs::MakeRender(spectra);
    }
    catch (const ParameterError& e)
    {
        CHECK(e.spelled(Face::COMMAND) ==
              "--spectra needs spectral mode (--mode spectral): band mode has no spectrum to "
              "write");
    }
    jobs::RenderRequest compare = TextRequest("");
    compare.compare = true;
    CHECK_THROWS_WITH(jobs::MakeRender(compare),
                      "compare writes its ΔE00 map beside the render: give out");
    jobs::RenderRequest bands = TextRequest(test::TempPath("renderjob_never.exr"));
    bands.text = std::regex_replace(kScene, std::regex("output: acescg"), "output: bands");
    bands.compare = true;
    CHECK_THROWS_WITH(jobs::MakeRender(bands),
                      "compare needs an RGB output: the spectral reference has no bands");
    // Only explaining writes nothing, so nothing is refused.
    bands.explain = true;
    const jobs::RenderResult explained = jobs::MakeRender(bands);
    CHECK(explained.explanation.rfind("plan: band mode, 40x30", 0) == 0);
    CHECK(explained.image.pixels.empty());
    CHECK_FALSE(fs::exists(test::TempPath("renderjob_never.exr")));
}

TEST_CASE("the render job writes the command's files, byte for byte", "[jobs][render]")
{
    const std::string lib = Fresh("lib"), cli = Fresh("cli");
    const std::string scene = cli + "/gold.yaml";
    std::ofstream(scene) << kScene;
    jobs::RenderRequest request;
    request.scene = scene;
    request.out = lib + "/gold.exr";
    request.mode = "band6";
    request.compare = true;
    const jobs::RenderResult result = jobs::MakeRender(request);
    const test::Result r =
        test::Bandlight("render '" + scene + "' --mode band6 --compare -o '" + cli + "/gold.exr'");
    INFO(r.err);
    REQUIRE(r.code == 0);
    for (const char* file : {"gold.exr", "gold.png", "gold_dE00.exr", "gold_dE00.png"})
    {
        INFO(file);
        CHECK(ImageBytes(lib + "/" + file) == ImageBytes(cli + "/" + file));
    }
    // What the command prints is the result's.
    CHECK(r.out.find(result.explanation) == 0);
    CHECK(r.out.find("Wrote " + cli + "/gold.exr (40x30, 3 channels, ACEScg)\n") !=
          std::string::npos);
    CHECK(r.out.find("compare with spectral: " + std::to_string(result.comparison->summary.pixels) +
                     " pixels, ΔE00 mean ") != std::string::npos);
}

TEST_CASE("the command prints the plan, then refuses outputs that do not go together",
          "[jobs][render]")
{
    const std::string dir = Fresh("refused");
    const std::string scene = dir + "/gold.yaml";
    std::ofstream(scene) << kScene;
    jobs::RenderRequest request;
    request.scene = scene;
    const test::Result r =
        test::Bandlight("render '" + scene + "' --spectra -o '" + dir + "/x.exr'");
    CHECK(r.code == 2);
    CHECK(r.out == jobs::PrepareRender(request).explanation);  // and no "rendered" line
    CHECK(r.err ==
          "bandlight: --spectra needs spectral mode (--mode spectral): band mode has no spectrum "
          "to write\n");
    CHECK_FALSE(fs::exists(dir + "/x.exr"));
}

TEST_CASE("render --light-groups in band and N-band mode: beauty = Σ groups in the file",
          "[jobs][lightgroups][render]")
{
    const std::string dir = test::FreshLightGroupDir("bandrender");
    for (const std::string mode : {"band3", "band6"})
    {
        INFO(mode);
        jobs::RenderRequest r;
        r.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
        r.mode = mode;
        r.lightGroups = true;
        r.preview = false;
        r.out = dir + "/" + mode + ".exr";
        const jobs::RenderResult result = jobs::MakeRender(r);
        const test::Exr::Part file = test::ReadExr(r.out)[0];
        CHECK(file.spec.get_string_attribute(jobs::LIGHT_GROUPS_ATTRIBUTE) == "key,fill");
        CHECK(file.spec.nchannels == 9);
        // The beauty is what a render without groups gives, to float rounding.
        jobs::RenderRequest plain = r;
        plain.lightGroups = false;
        plain.out.clear();
        const std::vector<float> whole = jobs::MakeRender(plain).image.pixels;
        const double peak = test::MaxAbs(whole);
        REQUIRE(peak > 0.0);
        double worstSum = 0.0, worstWhole = 0.0;
        for (size_t p = 0; p < file.count(); ++p)
        {
            for (int c = 0; c < 3; ++c)
            {
                const std::string ch(1, "RGB"[c]);
                worstSum =
                    std::max(worstSum, std::abs(double(file.at(p, ch)) - file.at(p, "key." + ch) -
                                                file.at(p, "fill." + ch)));
                worstWhole = std::max(worstWhole,
                                      std::abs(double(file.at(p, ch)) - whole[3 * p + size_t(c)]));
                CHECK(result.image.pixels[3 * p + size_t(c)] == file.at(p, ch));
            }
        }
        CHECK(worstSum <= 1e-6 * peak);
        CHECK(worstWhole <= 1e-5 * peak);
        // Each group lights only its part: the key's light is warm (A).
        double keyR = 0.0, keyB = 0.0;
        for (size_t p = 0; p < file.count(); ++p)
        {
            keyR += file.at(p, "key.R");
            keyB += file.at(p, "key.B");
        }
        CHECK(keyR > 1.5 * keyB);
    }
}
