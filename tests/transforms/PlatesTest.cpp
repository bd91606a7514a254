// SPDX-License-Identifier: BSD-3-Clause
// White-balanced plates and the camera that shot them: the balance is exact
// and invertible, neutrals stay neutral, balanced looks on balanced plates
// score as lit looks on lit plates, and the CIE observer as a camera
// reproduces the plain path.
// Covers, through the entry points it calls: spectral/CameraFile.cpp, transforms/Camera.cpp.
#include <cmath>
#include <map>
#include <sstream>

#include <catch2/catch.hpp>

#include "transforms/LitMethod.h"

#include <Eigen/LU>

#include "spectral/CameraFile.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/Accuracy.h"
#include "transforms/Camera.h"
#include "transforms/IlluminantChange.h"
#include "transforms/Plates.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
Light L(const char* name)
{
    return {name, BuiltinIlluminant(name)};
}

MethodSpec Balanced(const std::string& name, AdaptationMethod a = AdaptationMethod::CAT02)
{
    MethodSpec m = ParseMethod(name);
    m.plates = Plates{PlateConvention::BALANCED, a};
    return m;
}

/// A camera of three Gaussian channels (peaks and widths in nm): not
/// colorimetric, like every real camera.
CameraSensitivities GaussianCamera(double r, double g, double b, double width)
{
    std::ostringstream csv;
    csv << "wavelength,R,G,B\n";
    for (int l = 380; l <= 780; l += 5)
    {
        const auto gauss = [&](double peak)
        { return std::exp(-0.5 * std::pow((l - peak) / width, 2)); };
        csv << l << "," << gauss(r) << "," << gauss(g) << "," << gauss(b) << "\n";
    }
    return ReadCameraText(csv.str(), "gaussian.csv");
}

std::map<std::string, double> MeanBy(const std::vector<AccuracyRow>& rows,
                                     const std::string& plates, PlateSource source,
                                     const std::string& set)
{
    std::map<std::string, double> sum;
    std::map<std::string, int> n;
    for (const AccuracyRow& r : rows)
    {
        if (r.plates == plates && r.source == source && r.set == set && !r.shipped)
        {
            sum[r.method] += r.mean;
            ++n[r.method];
        }
    }
    for (auto& [m, v] : sum)
    {
        v /= n[m];
    }
    return sum;
}
}  // namespace

TEST_CASE("The balance maps a light's white onto the working white exactly", "[transforms][plates]")
{
    for (const char* space : {"acescg", "rec709", "aces2065-1"})
    {
        const RgbSpace& ws = FindRgbSpace(space);
        for (const char* light : {"A", "F2", "F11", "D65", "D50"})
        {
            for (const AdaptationMethod a : {AdaptationMethod::CAT02, AdaptationMethod::BRADFORD})
            {
                INFO(space << " " << light);
                const SurfaceRenderer r(BuiltinIlluminant(light), ws);
                const Vec3 w = BalanceMatrix(BuiltinIlluminant(light), ws, a) * r.white();
                CHECK((w - Vec3::Ones()).cwiseAbs().maxCoeff() < 1e-12);
            }
        }
    }
    CHECK(ParsePlates("Balanced", "Bradford").key() == "balanced-bradford");
    CHECK(ParsePlates("lit").key() == "lit");
    CHECK_THROWS_WITH(ParsePlates("graded"), Contains("unknown plates 'graded' (lit, balanced)"));
    CHECK_THROWS_WITH(ParsePlates("balanced", "vonkries"),
                      Contains("unknown adaptation 'vonkries' (cat02, bradford)"));
}

TEST_CASE("Balanced looks keep neutrals neutral", "[transforms][plates]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    // Every method that is exact on white in the lit convention.
    for (const char* method : {"none", "vonkries", "bradford", "cat02", "band3-wp", "fit3x3",
                               "prefilter", "metamer", "rootpoly", "rootpoly3"})
    {
        for (const auto& [from, to] : {std::pair{"A", "D65"}, std::pair{"F2", "D65"},
                                       std::pair{"F11", "D65"}, std::pair{"D65", "A"}})
        {
            for (const AdaptationMethod a : {AdaptationMethod::CAT02, AdaptationMethod::BRADFORD})
            {
                INFO(method << " " << from << "->" << to);
                const Relighter r(L(from), L(to), Balanced(method, a), ws);
                for (const double k : {1.0 / 256, 0.18, 1.0, 16.0})
                {
                    const Vec3 out = r.apply(Vec3(k, k, k));
                    CHECK((out / k - Vec3::Ones()).cwiseAbs().maxCoeff() < 1e-6);
                    float px[3] = {float(k), float(k), float(k)};
                    r.apply(px, 1);
                    CHECK(std::abs(px[0] / k - 1.0) < 1e-5);
                    CHECK(std::abs(px[2] / k - 1.0) < 1e-5);
                }
            }
        }
    }
    // The band model's plain band model is not exact on white in either convention.
    const Relighter band(L("A"), L("D65"), Balanced("band3"), ws);
    CHECK((band.apply(Vec3::Ones()) - Vec3::Ones()).cwiseAbs().maxCoeff() > 1e-3);
}

TEST_CASE("A balanced look is the lit look between the balance's inverse and the balance",
          "[transforms][plates]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    const Mat3 bA = BalanceMatrix(BuiltinIlluminant("A"), ws, AdaptationMethod::CAT02);
    const Mat3 bD = BalanceMatrix(BuiltinIlluminant("D65"), ws, AdaptationMethod::CAT02);
    for (const char* method : {"bradford", "band3", "fit3x3", "rootpoly", "upsample"})
    {
        INFO(method);
        const Relighter lit(L("A"), L("D65"), test::LitMethod(method), ws);
        const Relighter bal(L("A"), L("D65"), Balanced(method), ws);
        for (const NamedSpectrum& t : TestColourSamples())
        {
            const Vec3 c = SurfaceRenderer(BuiltinIlluminant("A"), ws).render(t.spectrum);
            const Vec3 expected = bD * lit.apply(c);
            CHECK((bal.apply(bA * c) - expected).cwiseAbs().maxCoeff() <
                  1e-9 * std::max(1.0, expected.cwiseAbs().maxCoeff()));
        }
    }
}

TEST_CASE("Balanced plates through balanced looks score as lit plates through lit looks",
          "[transforms][plates][accuracy]")
{
    AccuracyOptions o;
    for (const char* n : {"A", "F2", "F11", "D65"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.methods = {"bradford", "cat02", "fit3x3", "metamer", "rootpoly", "rootpoly3"};
    o.sets = {HeldOutTcs(), RandomSmoothSet(60, 7, "random")};
    o.exposures = {1.0};
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    const std::vector<AccuracyRow> cv = CrossValidate(o, 5);
    // The acceptance pairs: A, F2, F11 -> D65.
    for (const std::string& set :
         {HeldOutTcs().name, std::string("random"), std::string("training, 5-fold")})
    {
        const std::vector<AccuracyRow>& from = set.rfind("training", 0) == 0 ? cv : rows;
        for (const std::string& m : o.methods)
        {
            double lit = 0.0, bal = 0.0, doubled = 0.0;
            int n = 0;
            for (const AccuracyRow& r : from)
            {
                if (r.method != m || r.set != set || r.to != "D65" || r.shipped)
                {
                    continue;
                }
                if (r.plates == "lit")
                {
                    lit += r.mean;
                    ++n;
                }
                else if (r.plates == "balanced-cat02")
                {
                    bal += r.mean;
                }
                else if (r.plates == "balanced-cat02-through-lit-looks")
                {
                    doubled += r.mean;
                }
            }
            if (n == 0)
            {
                continue;  // cross-validation covers fit3x3 and rootpoly only
            }
            INFO(set << " " << m << ": lit " << lit / n << ", balanced " << bal / n
                     << ", lit looks on balanced plates " << doubled / n);
            CHECK(std::abs(bal - lit) / n < 0.1);
            if (&from == &rows)
            {
                // Correcting the cast twice is far worse than either.
                CHECK(doubled / n > 4.0 * lit / n);
            }
        }
    }
}

TEST_CASE("The IDT of a colorimetric camera is exact", "[transforms][camera]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    const SpectralCamera observer(ObserverCamera());
    for (const char* light : {"A", "D55", "F11"})
    {
        INFO(light);
        const Spectrum s = BuiltinIlluminant(light);
        const Mat3 idt = FitIdt(observer, s, ws, AdaptationMethod::CAT02);
        // White-balanced camera RGB is XYZ / W: the exact IDT is
        // M⁻¹ · CAT02(W → W_aces) · diag(W).
        const SurfaceRenderer r(s, ws);
        const Vec3 w = r.rgbToXyz() * r.white();
        const Mat3 exact = r.rgbToXyz().inverse() *
                           AdaptationMatrix(w, WorkingWhiteXyz(ws), AdaptationMethod::CAT02) *
                           w.asDiagonal();
        CHECK((idt - exact).cwiseAbs().maxCoeff() < 1e-9);
        CHECK((idt * Vec3::Ones() - Vec3::Ones()).cwiseAbs().maxCoeff() < 1e-12);
    }
}

TEST_CASE("With the CIE observer as the camera, accuracy --camera equals plain accuracy",
          "[transforms][camera][accuracy]")
{
    AccuracyOptions o;
    for (const char* n : {"A", "F11", "D65"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.methods = {"none", "bradford", "band3", "rootpoly", "upsample", "rootpoly-camera"};
    o.sets = {HeldOutTcs()};
    o.exposures = {0.25, 1.0};
    o.camera = std::make_shared<const SpectralCamera>(ObserverCamera());
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    std::map<std::string, const AccuracyRow*> cie;
    for (const AccuracyRow& r : rows)
    {
        if (r.source == PlateSource::CIE)
        {
            std::ostringstream key;
            key << r.method << r.from << r.to << r.plates << r.exposure;
            cie[key.str()] = &r;
        }
    }
    int compared = 0, cameraAware = 0;
    for (const AccuracyRow& r : rows)
    {
        std::ostringstream key;
        // rootpoly-camera on the daylight-IDT plates against rootpoly on the CIE plates.
        const std::string plain = r.method == "rootpoly-camera" ? "rootpoly" : r.method;
        key << plain << r.from << r.to << r.plates << r.exposure;
        if (r.source == PlateSource::CAMERA || r.method == "rootpoly-camera")
        {
            INFO(r.method << " " << r.from << "->" << r.to << " " << r.plates << " "
                          << PlateSourceName(r.source));
            REQUIRE(cie.count(key.str()));
            CHECK(std::abs(r.mean - cie[key.str()]->mean) < 1e-9);
            CHECK(std::abs(r.max - cie[key.str()]->max) < 1e-9);
            ++compared;
            cameraAware += r.method == "rootpoly-camera" ? 1 : 0;
        }
    }
    // 6 pairs × 2 conventions × 2 exposures: 5 methods on camera plates, rootpoly-camera once.
    CHECK(compared == 6 * 2 * 2 * 6);
    CHECK(cameraAware == 6 * 2 * 2);
}

TEST_CASE("Each simulation kind keeps its key, its order and the forms measured on its plates",
          "[transforms][camera][accuracy]")
{
    // The keys are the JSON document's "camera" values and the report's.
    CHECK(std::string(PlateSourceName(PlateSource::CIE)) == "cie");
    CHECK(std::string(PlateSourceName(PlateSource::CAMERA)) == "camera");
    CHECK(std::string(PlateSourceName(PlateSource::CAMERA_DAYLIGHT_IDT)) == "camera-daylight-idt");

    AccuracyOptions o;
    o.lights = {{"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}};
    o.methods = {"bradford", "rootpoly-camera"};
    o.sets = {HeldOutTcs()};
    o.exposures = {1.0};
    o.camera = std::make_shared<const SpectralCamera>(ObserverCamera());
    // A shipped form that changes nothing: only where shipped rows appear matters here.
    o.shipped = [](const Light&, const Light&, const MethodSpec&) -> PixelBatch
    { return [](float*, size_t) {}; };
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    // Per pair: lit plates, bradford on cie (ideal, shipped), camera and daylight IDT;
    // balanced plates, the same and the lit looks on cie; rootpoly-camera once on each.
    CHECK(rows.size() == 2 * ((4 + 1) + (5 + 1)));
    for (size_t i = 0; i < rows.size(); ++i)
    {
        const AccuracyRow& r = rows[i];
        INFO(r.method << " " << r.from << "->" << r.to << " " << r.plates << " "
                      << PlateSourceName(r.source) << (r.shipped ? " shipped" : ""));
        if (r.shipped || r.plates == ThroughLitLooksKey(o.plates.back()))
        {
            CHECK(r.source == PlateSource::CIE);
        }
        if (r.method == "rootpoly-camera")
        {
            CHECK(r.source == PlateSource::CAMERA_DAYLIGHT_IDT);
        }
        // A method's rows for one pair and convention come kind by kind, in the enum's order.
        if (i > 0 && rows[i - 1].method == r.method && rows[i - 1].from == r.from)
        {
            CHECK(int(rows[i - 1].source) <= int(r.source));
        }
    }
}

TEST_CASE("Knowing the camera wins back error on daylight-IDT plates", "[transforms][camera]")
{
    AccuracyOptions o;
    for (const char* n : {"A", "F2", "F11", "D65"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.plates = {Plates{PlateConvention::BALANCED, AdaptationMethod::CAT02}};
    o.methods = {"rootpoly", "rootpoly-camera"};
    o.sets = {HeldOutTcs(), RandomSmoothSet(100, 2, "random")};
    o.exposures = {1.0};
    o.camera = std::make_shared<const SpectralCamera>(GaussianCamera(600, 540, 455, 30));
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    for (const std::string& set : {HeldOutTcs().name, std::string("random")})
    {
        const auto cie = MeanBy(rows, "balanced-cat02", PlateSource::CIE, set);
        const auto camera = MeanBy(rows, "balanced-cat02", PlateSource::CAMERA, set);
        const auto daylight = MeanBy(rows, "balanced-cat02", PlateSource::CAMERA_DAYLIGHT_IDT, set);
        INFO(set << ": rootpoly cie " << cie.at("rootpoly") << ", camera " << camera.at("rootpoly")
                 << ", daylight IDT " << daylight.at("rootpoly") << ", rootpoly-camera "
                 << daylight.at("rootpoly-camera"));
        // The camera adds error; one daylight IDT adds more; knowing the camera wins it back.
        CHECK(camera.at("rootpoly") > cie.at("rootpoly"));
        CHECK(daylight.at("rootpoly") > camera.at("rootpoly"));
        CHECK(daylight.at("rootpoly-camera") < daylight.at("rootpoly") - 0.3);
    }
}

TEST_CASE("Camera files: rawtoaces JSON, CSV and CGATS, and clear errors", "[transforms][camera]")
{
    const std::string json = R"({
  "header": {"manufacturer": "acme", "model": "one"},
  "spectral_data": {"index": {"main": ["B", "G", "R"]},
    "data": {"main": {"400": [0.9, 0.1, 0.0], "500": [0.1, 0.9, 0.1], "600": [0.0, 0.1, 0.9],
                      "700": [0.0, 0.0, 0.3]}}}})";
    const CameraSensitivities c = ReadCameraText(json, "acme.json");
    CHECK(c.name == "acme one");
    CHECK(c.red.start() == 400.0);
    CHECK(c.red.step() == 100.0);
    CHECK(c.red[2] == 0.9);  // index.main puts R last
    CHECK(c.blue[0] == 0.9);
    const CameraSensitivities csv = ReadCameraText(
        "nm,blue,green,red\n400,0.9,0.1,0\n500,0.1,0.9,0.1\n600,0,0.1,0.9\n", "cam.csv");
    CHECK(csv.red[2] == 0.9);
    CHECK(csv.blue[0] == 0.9);
    const CameraSensitivities cgats = ReadCameraText(
        "CGATS.17\nSPECTRAL_BANDS 3\nSPECTRAL_START_NM 400\nSPECTRAL_END_NM 600\n"
        "NUMBER_OF_FIELDS 4\nBEGIN_DATA_FORMAT\nSAMPLE_ID SPEC_400 SPEC_500 SPEC_600\n"
        "END_DATA_FORMAT\nNUMBER_OF_SETS 3\nBEGIN_DATA\nR 0 0.1 0.9\nG 0.1 0.9 0.1\n"
        "B 0.9 0.1 0\nEND_DATA\n",
        "cam.sp");
    CHECK(cgats.green[1] == 0.9);

    CHECK_THROWS_WITH(
        ReadCameraText("{\n \"header\": {},\n \"spectral_data\": [1,, 2]\n}\n", "bad.json"),
        Contains("bad.json:3: not valid JSON"));
    CHECK_THROWS_WITH(ReadCameraText("{\"header\": {}}", "nodata.json"),
                      Contains("nodata.json: no \"spectral_data\""));
    CHECK_THROWS_WITH(
        ReadCameraText(R"({"spectral_data": {"data": {"main": {"400": [1, 0, 0], "410": [0, 1, 0],
                          "430": [0, 0, 1]}}}})",
                       "irregular.json"),
        Contains("irregular.json: wavelengths 410 and 430 break the regular grid"));
    CHECK_THROWS_WITH(
        ReadCameraText(
            R"({"spectral_data": {"data": {"main": {"400": [1, "x", 0], "410": [0, 1, 0]}}}})",
            "text.json"),
        Contains("text.json: spectral_data.data.main \"400\": value \"x\" is not a finite number"));
    CHECK_THROWS_WITH(
        ReadCameraText(
            R"({"spectral_data": {"data": {"main": {"400": [1, 0, 0], "410": [0, 1, 0]}}}})",
            "blind.json"),
        Contains("blind.json: the blue channel has no response over 380-780 nm"));
    CHECK_THROWS_WITH(
        ReadCameraText(
            R"({"spectral_data": {"data": {"main": {"400": [1, -0.5, 1], "410": [0, 1, 1]}}}})",
            "negative.json"),
        Contains("negative.json: the green channel responds -0.5 at 400 nm"));
    // A wavelength given twice: JSON keeps the last value, so it is refused
    // before any value is lost (the CSV reader refuses the same).
    CHECK_THROWS_WITH(
        ReadCameraText(R"({"spectral_data": {"data": {"main": {"400": [1, 0, 0], "500": [0, 1, 0],
                          "400": [0, 0, 1]}}}})",
                       "twice.json"),
        Contains("twice.json: the key \"400\" appears twice"));
    CHECK_THROWS_WITH(
        ReadCameraText(R"({"spectral_data": {"data": {"main": {"400": [1, 0, 0], "400.0": [0, 1, 0],
                          "500": [0, 0, 1]}}}})",
                       "twice.json"),
        Contains("twice.json: the wavelength 400 nm is given twice"));
    CHECK_THROWS_WITH(
        ReadCameraText("nm,a,b\n400,1,0\n500,0,1\n", "two.csv"),
        Contains("two.csv: a camera file holds three spectra (R, G, B), this one has 2"));
    // A camera blind to a light cannot be balanced for it.
    const SpectralCamera blue(
        ReadCameraText("nm,r,g,b\n380,0,0,1\n420,0,0,1\n440,0,0,0\n"
                       "450,1,1,0\n780,1,1,0\n",
                       "ir.csv"));
    std::vector<double> red(81, 0.0);
    red[80] = 1.0;
    CHECK_NOTHROW(CameraShot(blue, BuiltinIlluminant("D65")));
    CHECK_THROWS_WITH(
        CameraShot(blue, Spectrum(380.0, 5.0, red)),
        Contains("ir.csv: camera: its blue channel records nothing under this light"));
    // Nor one whose channel records a denormal trace of what the others do:
    // its gain would be infinite (found by fuzz_camera; corpus
    // dead-blue-channel.csv).
    const SpectralCamera trace(
        ReadCameraText("nm,R,G,B\n380,1,1,1e-320\n780,1,1,1e-320\n", "trace.csv"));
    CHECK_THROWS_WITH(CameraShot(trace, BuiltinIlluminant("D65")),
                      Contains("trace.csv: camera: its blue channel records nothing under this "
                               "light"));
}

TEST_CASE("A camera file's scale does not change its IDT, up to 1e300 and down to 1e-300",
          "[transforms][camera]")
{
    // docs/robustness.md: an IDT is the same for any scale of the
    // sensitivities; a file in counts of 1e300 is read, not refused.
    const auto file = [](double scale)
    {
        std::ostringstream j;
        j.precision(17);
        j << R"({"spectral_data": {"data": {"main": {)";
        for (int nm = 380; nm <= 780; nm += 10)
        {
            const double x = (nm - 380) / 400.0;
            const double r = std::exp(-std::pow((x - 0.75) / 0.12, 2));
            const double g = std::exp(-std::pow((x - 0.45) / 0.12, 2));
            const double b = std::exp(-std::pow((x - 0.2) / 0.1, 2));
            j << (nm > 380 ? ", " : "") << '"' << nm << "\": [" << scale * r << ", " << scale * g
              << ", " << scale * b << "]";
        }
        j << "}}}}";
        return j.str();
    };
    const Spectrum d65 = BuiltinIlluminant("D65");
    const RgbSpace& acescg = FindRgbSpace("acescg");
    const Mat3 one = FitIdt(SpectralCamera(ReadCameraText(file(1.0), "one.json")), d65, acescg,
                            AdaptationMethod::CAT02);
    for (const double scale : {1e300, 1e-300, 3.0})
    {
        INFO("scale " << scale);
        const SpectralCamera scaled(ReadCameraText(file(scale), "scaled.json"));
        const Mat3 b = FitIdt(scaled, d65, acescg, AdaptationMethod::CAT02);
        CHECK((b - one).cwiseAbs().maxCoeff() < 1e-9 * one.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("rootpoly-camera needs a camera", "[transforms][camera]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    // The library names the parameter; the command spells it --camera FILE.
    CHECK_THROWS_WITH(Relighter(L("A"), L("D65"), ParseMethod("rootpoly-camera"), ws),
                      Contains("needs the camera that shot the plates (camera = FILE)"));
    CHECK_THROWS_AS(Relighter(L("A"), L("D65"), ParseMethod("rootpoly-camera"), ws),
                    ParameterError);
    AccuracyOptions o;
    o.lights = {L("A"), L("D65")};
    o.methods = {"rootpoly-camera"};
    o.sets = {HeldOutTcs()};
    CHECK_THROWS_WITH(MeasureAccuracy(o), Contains("needs the camera"));
}
