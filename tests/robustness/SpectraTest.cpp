// SPDX-License-Identifier: BSD-3-Clause
// Hard spectra: illuminants with an empty band, pure line spectra at every
// grid step, singular and ill-conditioned band sets, remittances outside
// [0, 1], spectra that stop short of the visible range.
#include <cmath>
#include <fstream>

#include <Eigen/SVD>
#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "render/SceneFile.h"
#include "render/SceneRenderer.h"
#include "robustness/HardValues.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/SpectrumIO.h"
#include "transforms/BandModel.h"
#include "transforms/IlluminantChange.h"

using namespace bandlight;
using namespace bandlight::test;

namespace
{
const std::string kData = ROBUSTNESS_DATA;

Light FileLight(const std::string& file)
{
    const NamedSpectrum s = ReadSpectraFile(kData + "/" + file).front();
    return {s.name, s.spectrum};
}

std::string Message(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const Exception& e)
    {
        return e.what();
    }
    return "(no error)";
}
}  // namespace

TEST_CASE("An illuminant with empty bands: band3 from it is refused by name, to it is defined",
          "[robustness][spectra]")
{
    const Light laser = FileLight("laser532.csv");
    const Light d65{"D65", BuiltinIlluminant("D65")};
    const RgbSpace& working = FindRgbSpace("acescg");
    CHECK(IlluminantBands(laser.spectrum, BandSet::Lecture()) == std::vector<double>{0.0, 1.0, 0.0});

    CHECK(Message([&] { IlluminantChangeMatrix(laser, d65, ParseMethod("band3"), working); }) ==
          "illuminant laser has no power in band VB: the band ratio D65/laser is undefined");
    CHECK_THAT(
        Message([&] { IlluminantChangeMatrix(laser, d65, ParseMethod("band3-wp"), working); }),
        Catch::StartsWith("band-wp: a white has a non-positive band coordinate in band") &&
            Catch::EndsWith("no white-preserving band ratio exists"));

    // Towards the laser the ratio is 0 in VB and VR: a finite matrix of rank 1.
    const Mat3 m = IlluminantChangeMatrix(d65, laser, ParseMethod("band3"), working);
    REQUIRE(m.allFinite());
    const Eigen::JacobiSVD<Mat3> svd(m);
    CHECK(svd.singularValues()(1) < 1e-12 * svd.singularValues()(0));
}

TEST_CASE("An empty band through the CLI: exit 2, one line, no LUT written, old LUT kept",
          "[robustness][spectra][cli]")
{
    const std::string out = TempFile("laser.clf");
    {
        std::ofstream(out) << "previous output\n";
    }
    const Result r = Bandlight("lut --from '" + kData + "/laser532.csv' --to D65 --method band3 "
                               "--format clf -o '" + out + "'");
    CHECK(r.code == 2);
    CHECK(r.err == "bandlight: illuminant laser has no power in band VB: the band ratio D65/laser is "
                   "undefined\n");
    std::ifstream in(out);
    std::string kept;
    std::getline(in, kept);
    CHECK(kept == "previous output");
}

TEST_CASE("Line spectra integrate exactly at every grid step", "[robustness][spectra]")
{
    // Mercury lines of F-lamps, and a laser line exactly on a band edge.
    const LineSpectrum mercury({{404.66, 1.0}, {435.83, 2.0}, {546.07, 3.0}, {576.96, 0.5},
                                {579.07, 0.5}});
    const Vec3 exact = IntegrateXyz(mercury, Observer::CIE1931_2DEG);
    // 546.07 nm lies 21.4 % of the way from 545 to 550 nm in the CIE 1931 table.
    const LineSpectrum green({{546.07, 1.0}});
    const double f = (546.07 - 545.0) / 5.0;
    const Vec3 g = IntegrateXyz(green, Observer::CIE1931_2DEG);
    CHECK(g.x() == Approx(0.3597 + f * (0.4334499 - 0.3597)).epsilon(1e-12));
    CHECK(g.y() == Approx(0.9803 + f * (0.9949501 - 0.9803)).epsilon(1e-12));
    CHECK(g.z() == Approx(0.0134 + f * (0.008749999 - 0.0134)).epsilon(1e-12));

    // Sampled onto the CIE grid or any refinement of it, the lines keep their integral.
    for (double step : {1.0, 2.5, 5.0})
    {
        INFO("step " << step << " nm");
        const size_t n = size_t(std::lround(400.0 / step)) + 1;
        const Vec3 sampled = IntegrateXyz(mercury.sampled(380.0, step, n), Observer::CIE1931_2DEG);
        CHECK((sampled - exact).norm() < 1e-9 * exact.norm());
    }
    // A line on a band edge belongs to the band that starts there ([a, b)).
    const LineSpectrum edge({{500.0, 1.0}});
    CHECK(BandMeans(edge, BandSet::Lecture()) == std::vector<double>{0.0, 0.01, 0.0});
}

TEST_CASE("A line-spectrum scene renders the same at 1, 2, 5 and 10 nm", "[robustness][spectra]")
{
    auto render = [](double step)
    {
        const std::string yaml = R"(
camera: {position: [0, 0, 3], look_at: [0, 0, 0], width: 8, height: 6, fov: 40}
render: {mode: spectral, step: )" + std::to_string(step) +
                                 R"(}
lights:
  - {type: directional, direction: [0, 0, -1], spectrum: {lines: [[404.66, 1], [435.83, 2], [546.07, 3], [578, 1]]}}
materials:
  card: {diffuse: TCS09}
objects:
  - {plane: {point: [0, 0, 0], normal: [0, 0, 1]}, material: card}
)";
        const Scene scene = ReadSceneText(yaml, "lines.yaml");
        return RenderScene(scene, PlanScene(scene), 1).pixels;
    };
    const std::vector<float> ref = render(5.0);
    REQUIRE(ref[0] > 0.0f);
    for (double step : {1.0, 2.0, 10.0})
    {
        const std::vector<float> px = render(step);
        REQUIRE(px.size() == ref.size());
        for (size_t i = 0; i < px.size(); ++i)
        {
            CHECK(px[i] == Approx(ref[i]).epsilon(1e-6));
        }
    }
}

TEST_CASE("Singular and ill-conditioned band sets are refused with their condition number",
          "[robustness][spectra]")
{
    const Light a{"A", BuiltinIlluminant("A")};
    const Light d65{"D65", BuiltinIlluminant("D65")};
    const RgbSpace& working = FindRgbSpace("acescg");
    CHECK(ConditionNumber(MatchingBandMatrix(BandSet::Lecture(), MatchingSet::XYZ,
                                             Observer::CIE1931_2DEG)) == Approx(4.348).margin(1e-3));
    // Two bands the matching functions barely see (380-390, 390-400 nm).
    CHECK(Message(
              [&] { IlluminantChangeMatrix(a, d65, ParseMethod("bands380-390-400-780"), working); }) ==
          "band matrix for bands 380,390,400,780 nm is ill-conditioned: condition number 1.36e+05 "
          "exceeds the limit 1000 (band values would amplify pixel errors that much); widen the "
          "bands the matching functions barely see");
    // Beyond 700 nm z̄ is zero in every band: its row cannot be normalised.
    CHECK_THAT(Message([&]
                       { IlluminantChangeMatrix(a, d65, ParseMethod("bands700-740-760-780"), working); }),
               Catch::StartsWith("matching function 3 has zero band sum"));
    // A wide set stays well inside the limit and gives a finite matrix.
    CHECK(IlluminantChangeMatrix(a, d65, ParseMethod("bands380-420-700-780"), working).allFinite());

    const Result r = Bandlight("tables --bands 380,390,400,780");
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Catch::Contains("Condition number of the xyz band matrix: 136") &&
                          Catch::Contains("(above the limit 1000: band methods refuse this set)"));
}

TEST_CASE("Remittances slightly outside [0, 1] are used as given, and said so",
          "[robustness][spectra]")
{
    const std::vector<NamedSpectrum> s = ReadSpectraFile(kData + "/outside_0_1.csv");
    const Spectrum d65 = BuiltinIlluminant("D65");
    const Vec3 white = IlluminantWhiteXyz(d65, Observer::CIE1931_2DEG);
    CHECK(SurfaceXyz(s[0].spectrum, d65, Observer::CIE1931_2DEG).y() ==
          Approx(1.02 * white.y()).epsilon(1e-12));
    CHECK(SurfaceXyz(s[1].spectrum, d65, Observer::CIE1931_2DEG).y() ==
          Approx(-0.01 * white.y()).epsilon(1e-12));

    const Result r = Bandlight("xyz --illuminant D65 --reflectance '" + kData + "/outside_0_1.csv'");
    CHECK(r.code == 0);
    CHECK_THAT(r.err, Catch::Contains("outside_0_1.csv: bright has remittance values outside [0, 1] "
                                      "(1.02 to 1.02): used as given, not clipped"));
}

TEST_CASE("Spectra that stop short of 380-780 nm: what is extrapolated is defined and said",
          "[robustness][spectra]")
{
    const std::string file = kData + "/grey_400_700.csv";
    const NamedSpectrum grey = ReadSpectraFile(file).front();
    const Spectrum d65 = BuiltinIlluminant("D65");
    // As a remittance its end values are held: the same as 0.5 everywhere.
    const Spectrum flat(380.0, 10.0, std::vector<double>(41, 0.5));
    CHECK(SurfaceXyz(grey.spectrum, d65, Observer::CIE1931_2DEG)
              .isApprox(SurfaceXyz(flat, d65, Observer::CIE1931_2DEG), 1e-12));
    // As an illuminant it is zero outside its data: less than the flat one.
    CHECK(IntegrateXyz(grey.spectrum, Observer::CIE1931_2DEG).x() <
          IntegrateXyz(flat, Observer::CIE1931_2DEG).x());

    CHECK(CoverageNote(grey, "g.csv", true) ==
          "g.csv: grey400_700 covers 400–700 nm; over 380–400 nm and 700–780 nm its end values "
          "are held constant (CIE 15:2004 §7.2.1)");
    CHECK(CoverageNote(grey, "g.csv", false) ==
          "g.csv: grey400_700 covers 400–700 nm; over 380–400 nm and 700–780 nm it is taken as "
          "zero");
    const Result r = Bandlight("xyz --illuminant '" + file + "' --reflectance '" + file + "'");
    CHECK(r.code == 0);
    CHECK_THAT(r.err, Catch::Contains("note: " + file + ": grey400_700 covers 400–700 nm; over "
                                      "380–400 nm and 700–780 nm it is taken as zero") &&
                          Catch::Contains("its end values are held constant"));
}

TEST_CASE("A light with no power in the bands is refused by both render paths alike",
          "[robustness][spectra]")
{
    // Lines at 820 nm and 59 µm: nothing in 400-700 nm, so no I_max to normalise by.
    const Scene s = ReadSceneText(
        "render: {mode: spectral}\nlights:\n  - {type: point, spectrum: {lines: [[820, 1], "
        "[59003, 1]]}}\n",
        "ir.yaml");
    const std::string expected = "light 'lines 820:1 59003:1' has no power in bands 400,500,600,700";
    CHECK_THROWS_WITH(PlanScene(s), expected);
    CHECK_THROWS_WITH(RenderSceneUnplanned(s, 1), expected);
}
