// SPDX-License-Identifier: BSD-3-Clause
// --plates, --adaptation and --camera on the commands that take them: what a
// user gets from apply, lut, config and accuracy.
#include <cmath>
#include <fstream>
#include <map>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli/RunCommand.h"
#include "spectral/CieData.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::Result;
using test::TempPath;

namespace
{
/// A one-row float EXR of the given RGB pixels.
void WriteRow(const std::string& path, const std::vector<float>& rgb)
{
    const int width = int(rgb.size() / 3);
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, OIIO::ImageSpec(width, 1, 3, OIIO::TypeDesc::FLOAT)));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
    out->close();
}

std::vector<float> ReadRow(const std::string& path)
{
    OIIO::ImageBuf buf(path);
    REQUIRE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT));
    std::vector<float> px(size_t(buf.spec().width) * 3);
    buf.get_pixels(OIIO::ROI(0, buf.spec().width, 0, 1, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT,
                   px.data());
    return px;
}

/// The CIE 1931 observer written as a camera file (CSV, columns x̄ ȳ z̄ as R G B).
std::string ObserverCameraFile()
{
    const std::string path = TempPath("observer_camera.csv");
    std::ofstream f(path);
    f.precision(17);
    f << "wavelength,R,G,B\n";
    const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
    for (size_t i = 0; i < cmf.x.size(); ++i)
    {
        f << cmf.x.wavelength(i) << "," << cmf.x[i] << "," << cmf.y[i] << "," << cmf.z[i] << "\n";
    }
    return path;
}
}  // namespace

TEST_CASE("apply: balanced plates keep greys grey, lit plates lose the cast", "[cli][plates]")
{
    const std::string in = TempPath("greys.exr");
    WriteRow(in, {0.18f, 0.18f, 0.18f, 1.0f, 1.0f, 1.0f, 4.0f, 4.0f, 4.0f});
    for (const char* method : {"bradford", "cat02", "rootpoly", "fit3x3"})
    {
        INFO(method);
        const std::string out = TempPath(std::string("greys_") + method + ".exr");
        // The default: balanced plates (CAT02).
        Result r =
            Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method " + method);
        REQUIRE(r.code == 0);
        std::vector<float> px = ReadRow(out);
        for (size_t i = 0; i < px.size(); ++i)
        {
            const float k = i < 3 ? 0.18f : i < 6 ? 1.0f : 4.0f;
            CHECK(std::abs(px[i] / k - 1.0f) < 1e-5f);
        }
        r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method " + method +
                      " --plates balanced --adaptation bradford");
        REQUIRE(r.code == 0);
        px = ReadRow(out);
        CHECK(std::abs(px[3] - 1.0f) < 1e-5f);
        CHECK(std::abs(px[5] - 1.0f) < 1e-5f);
        // Lit plates: a grey is D65's white seen as if under A; the look
        // makes it bluer (the cast removed a second time).
        r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method " + method +
                      " --plates lit");
        REQUIRE(r.code == 0);
        px = ReadRow(out);
        CHECK(px[5] > 1.5f * px[3]);
    }
}

TEST_CASE("lut and config say which plates they were written for", "[cli][plates]")
{
    const std::string dir = TempPath("plates_config");
    Result r = Bandlight("config --out '" + dir + "' --illuminants A,D65 --methods bradford");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("for white-balanced plates"));
    std::ifstream f(dir + "/config.ocio");
    std::stringstream text;
    text << f.rdbuf();
    CHECK_THAT(text.str(), Contains("For white-balanced plates (the ACES convention)"));
    r = Bandlight("config --out '" + dir + "' --illuminants A,D65 --methods bradford --plates lit");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("for lit plates"));

    const std::string lut = TempPath("plates_bradford.clf");
    r = Bandlight(
        "lut --from A --to D65 --method bradford --plates balanced --adaptation "
        "bradford -o '" +
        lut + "'");
    REQUIRE(r.code == 0);
    std::ifstream l(lut);
    std::stringstream clf;
    clf << l.rdbuf();
    CHECK_THAT(clf.str(), Contains("balanced to ACEScg&apos;s white by Bradford"));
}

TEST_CASE(
    "accuracy --camera: the observer as a camera reproduces plain accuracy, and the JSON "
    "names the camera",
    "[cli][plates][camera][accuracy]")
{
    const std::string camera = ObserverCameraFile();
    const std::string json = TempPath("accuracy_camera.json");
    const Result r = Bandlight(
        "accuracy --illuminants A,F11,D65 --methods bradford,rootpoly "
        "--no-cost --ideal-only --camera '" +
        camera + "' --json '" + json + "'");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("the camera adds"));
    std::ifstream f(json);
    const nlohmann::json j = nlohmann::json::parse(f);
    CHECK(j["camera"]["file"] == camera);
    CHECK(j["camera"]["idt_light"] == "D55");
    std::map<std::string, double> cie;
    for (const auto& row : j["rows"])
    {
        if (row["camera"] == "cie")
        {
            cie[row["method"].get<std::string>() + row["from"].get<std::string>() +
                row["to"].get<std::string>() + row["set"].get<std::string>() +
                row["plates"].get<std::string>() + std::to_string(row["exposure"].get<double>())] =
                row["mean"];
        }
    }
    int compared = 0;
    for (const auto& row : j["rows"])
    {
        const std::string source = row["camera"];
        if (source == "camera" || row["method"] == "rootpoly-camera")
        {
            const std::string method =
                row["method"] == "rootpoly-camera" ? "rootpoly" : row["method"].get<std::string>();
            const std::string key = method + row["from"].get<std::string>() +
                                    row["to"].get<std::string>() + row["set"].get<std::string>() +
                                    row["plates"].get<std::string>() +
                                    std::to_string(row["exposure"].get<double>());
            REQUIRE(cie.count(key));
            CHECK(std::abs(row["mean"].get<double>() - cie[key]) < 1e-9);
            ++compared;
        }
    }
    CHECK(compared > 100);
}

TEST_CASE("Bad plates and cameras: one line, exit code 2", "[cli][plates]")
{
    const std::string in = TempPath("greys_bad.exr");
    WriteRow(in, {0.18f, 0.18f, 0.18f});
    const std::string out = TempPath("greys_bad_out.exr");
    Result r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --plates graded");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("unknown plates 'graded' (lit, balanced)"));
    r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --adaptation hunt");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("unknown adaptation 'hunt' (cat02, bradford)"));
    r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method rootpoly-camera");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("needs the camera that shot the plates (--camera FILE)"));
    r = Bandlight("lut --from A --to D65 --method rootpoly-camera --camera /nonexistent.json -o '" +
                  TempPath("x.clf") + "'");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("/nonexistent.json"));
    const std::string bad = TempPath("bad_camera.json");
    std::ofstream(bad) << "{\n  \"spectral_data\": {\"data\": {\"main\": {\n    \"400\": [1, 0],\n"
                          "    \"410\": [0, 1, 0]}}}\n}\n";
    r = Bandlight("accuracy --illuminants A,D65 --no-cost --ideal-only --camera '" + bad + "'");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(bad + ": spectral_data.data.main \"400\": needs three numbers"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}
