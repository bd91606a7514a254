// SPDX-License-Identifier: BSD-3-Clause
// `idt` as a C++ host calls it: the config it writes holds the fitted
// matrices (measured through OCIO's processors and its CLF reader), a
// studio config extended with input spaces keeps its own, and the JSON
// document carries the result.
// Covers, through the entry points it calls: camera/IdtFit.cpp, report/IdtReport.cpp,
// plugin/ConfigInputSpaces.cpp.
#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "jobs/ConfigJob.h"
#include "jobs/IdtJob.h"
#include "plugin/ConfigBuilder.h"
#include "spectral/Exception.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace fs = std::filesystem;

namespace
{
const std::string kD21 = BANDLIGHT_TEST_DATA_ROOT "/rawtoaces/arri_d21_380_780_5.json";

std::string Fresh(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("bandlight_idtjob_" + name);
    fs::remove_all(dir);
    return dir.string();
}

Mat3 SpaceMatrix(const OCIO::ConstConfigRcPtr& config, const std::string& src,
                 const std::string& dst)
{
    return MeasureMatrix(config->getProcessor(src.c_str(), dst.c_str()));
}
}  // namespace

TEST_CASE("idt --config: each input space's processor is its IDT, gains folded in", "[jobs][idt]")
{
    jobs::IdtRequest r;
    r.camera = kD21;
    r.lights = {"A", "3200K", "D55"};
    r.config = Fresh("config");
    r.json = Fresh("json") + ".json";
    const jobs::IdtResult result = jobs::MakeIdt(r);
    REQUIRE(result.idts.size() == 3);
    CHECK(result.idts[1].light == "3200K");
    const OCIO::ConstConfigRcPtr config = jobs::LoadConfig(r.config);
    config->validate();
    for (const jobs::IdtEntry& e : result.idts)
    {
        INFO(e.light);
        CHECK(e.colorSpace == "Input - arri d21 - " + e.light);
        const OCIO::ConstColorSpaceRcPtr cs = config->getColorSpace(e.colorSpace.c_str());
        REQUIRE(cs);
        CHECK(std::string(cs->getFamily()) == "Input");
        CHECK(std::string(cs->getEncoding()) == "scene-linear");
        CHECK_THAT(cs->getDescription(), Contains("gains R"));
        CHECK_THAT(cs->getDescription(), Contains("Training error"));
        const Mat3 expected = e.fit.matrix * e.fit.gains.asDiagonal();
        const Mat3 got = SpaceMatrix(config, e.colorSpace, "ACES2065-1");
        CHECK((got - expected).cwiseAbs().maxCoeff() < 1e-6 * expected.cwiseAbs().maxCoeff());
        // White-balanced raw white → (1, 1, 1).
        CHECK((expected * e.fit.gains.cwiseInverse() - Vec3::Ones()).cwiseAbs().maxCoeff() < 1e-12);
        // The CLF beside it, read back through OCIO's own reader.
        OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
        f->setSrc((r.config + "/luts/" + SafeName(e.colorSpace) + ".clf").c_str());
        const Mat3 clf = MeasureMatrix(OCIO::Config::CreateRaw()->getProcessor(f));
        CHECK((clf - expected).cwiseAbs().maxCoeff() < 1e-6 * expected.cwiseAbs().maxCoeff());
    }
    // The JSON document: the interface's shape and the same numbers.
    std::ifstream in(r.json);
    const nlohmann::json j = nlohmann::json::parse(in);
    CHECK(j["camera"] == "arri d21");
    CHECK(j["working_space"] == "aces2065-1");
    REQUIRE(j["idts"].size() == 3);
    const nlohmann::json& a = j["idts"][0];
    CHECK(a["light"] == "A");
    CHECK(a["cct"].get<double>() == Approx(2856.0).epsilon(1e-3));
    CHECK(std::abs(a["duv"].get<double>()) < 1e-3);
    CHECK(a["gains"][1].get<double>() == 1.0);
    for (int row = 0; row < 3; ++row)
    {
        for (int col = 0; col < 3; ++col)
        {
            CHECK(a["matrix"][row][col].get<double>() == result.idts[0].fit.matrix(row, col));
            CHECK(a["first_order_matrix"][row][col].get<double>() ==
                  result.idts[0].fit.firstOrder(row, col));
        }
    }
    for (const char* set : {"rawtoaces 190", "TCS"})
    {
        const nlohmann::json& e = a["error"][set];
        CHECK(e["mean"].get<double>() > 0.0);
        CHECK(e["p95"].get<double>() >= e["mean"].get<double>() * 0.5);
        CHECK(e["max"].get<double>() >= e["p95"].get<double>());
    }
    CHECK(result.written.size() == 2);
}

TEST_CASE("idt --base: a studio config gains input spaces and keeps its own transforms",
          "[jobs][idt]")
{
    // The base: a config whose scene_linear is Linear Rec.709, as studios'.
    jobs::ConfigRequest base;
    base.out = Fresh("base");
    base.workingSpace = "rec709";
    jobs::MakeConfig(base);
    jobs::IdtRequest r;
    r.camera = kD21;
    r.lights = {"D55"};
    r.base = *base.out + "/config.ocio";
    r.out = Fresh("extended");
    // ExtendConfig checks every base transform's pixels in the result.
    const jobs::IdtResult result = jobs::MakeIdt(r);
    const OCIO::ConstConfigRcPtr b = jobs::LoadConfig(*base.out);
    const OCIO::ConstConfigRcPtr ext = jobs::LoadConfig(r.out);
    CHECK(ext->getNumColorSpaces() == b->getNumColorSpaces() + 1);
    CHECK(ext->getNumLooks() == b->getNumLooks());
    const jobs::IdtEntry& e = result.idts.front();
    const Mat3 expected =
        SpaceToSpace(FindRgbSpace("aces2065-1"), FindRgbSpace("rec709")) * e.fit.rawToWorking();
    const Mat3 got = SpaceMatrix(ext, e.colorSpace, "Linear Rec.709 (sRGB)");
    CHECK((got - expected).cwiseAbs().maxCoeff() < 1e-6 * expected.cwiseAbs().maxCoeff());
    // The same IDT added twice clashes.
    jobs::IdtRequest again = r;
    again.base = r.out + "/config.ocio";
    again.out = Fresh("again");
    CHECK_THROWS_WITH(jobs::MakeIdt(again), Contains("already has a colour space"));
}

TEST_CASE("idt --base: an OCIO v1 base stays v1, its IDT a CLF, when told its primaries",
          "[jobs][idt]")
{
    // A v1 base whose scene_linear says nothing bandlight can identify.
    const std::string dir = Fresh("v1base");
    fs::create_directories(dir);
    std::ofstream(dir + "/config.ocio") << R"(ocio_profile_version: 1
search_path: ""
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]
roles:
  default: lin
  scene_linear: lin
  reference: lin
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: lin}
active_displays: []
active_views: []
colorspaces:
  - !<ColorSpace>
    name: lin
    bitdepth: 32f
    isdata: false
    allocation: uniform
  - !<ColorSpace>
    name: log
    bitdepth: 32f
    isdata: false
    allocation: uniform
    to_reference: !<LogTransform> {base: 2, direction: inverse}
)";
    jobs::IdtRequest r;
    r.camera = kD21;
    r.lights = {"A"};
    r.base = dir + "/config.ocio";
    r.out = Fresh("v1out");
    CHECK_THROWS_WITH(jobs::MakeIdt(r), Contains("name them with base_space"));
    CHECK_FALSE(fs::exists(r.out));
    r.baseSpace = "rec2020";
    const jobs::IdtResult result = jobs::MakeIdt(r);
    const OCIO::ConstConfigRcPtr ext = jobs::LoadConfig(r.out);
    CHECK(ext->getMajorVersion() == 1);
    const jobs::IdtEntry& e = result.idts.front();
    const Mat3 expected =
        SpaceToSpace(FindRgbSpace("aces2065-1"), FindRgbSpace("rec2020")) * e.fit.rawToWorking();
    const Mat3 got = SpaceMatrix(ext, e.colorSpace, "lin");
    CHECK((got - expected).cwiseAbs().maxCoeff() < 1e-6 * expected.cwiseAbs().maxCoeff());
}

TEST_CASE("idt --interpolate: within 0.3 dE00 of the fitted IDT at every CCT, for both cameras",
          "[jobs][idt]")
{
    // rawtoaces' two cameras, 3200 K and 5600 K calibrations, measured on
    // the CIE test colours (fitted on by no IDT) over 2800–6500 K.
    for (const std::string& camera :
         {kD21, std::string(BANDLIGHT_TEST_DATA_ROOT "/rawtoaces/nikon_d200_380_780_5.json")})
    {
        jobs::IdtRequest r;
        r.camera = camera;
        r.interpolate = {"3200K", "5600K"};
        const jobs::IdtResult result = jobs::MakeIdt(r);
        REQUIRE(result.interpolation.size() == 38);
        for (const jobs::IdtInterpolationPoint& p : result.interpolation)
        {
            INFO(result.camera << " " << p.cct << " K");
            CHECK(p.meanVsDirect <= 0.3);
            CHECK(p.p95VsDirect >= p.meanVsDirect);
            CHECK(p.maxVsDirect >= p.p95VsDirect);
        }
        const std::string report = jobs::IdtReport(result);
        CHECK_THAT(report, Contains("dE00 on TCS (15, fitted on by no IDT)"));
        CHECK_THAT(report, Contains("colour matrix (XYZ to raw) in mired"));
        // The JSON's colour matrices are the calibrations interpolated.
        const nlohmann::json j = nlohmann::json::parse(jobs::IdtDocument(result));
        for (int end = 0; end < 2; ++end)
        {
            const nlohmann::json& c = j["interpolation"]["calibrations"][end];
            CHECK(c["cct"].get<double>() == result.interpolateCalibrations[end].cct);
            for (int row = 0; row < 3; ++row)
            {
                for (int col = 0; col < 3; ++col)
                {
                    CHECK(c["color_matrix"][row][col].get<double>() ==
                          result.interpolateCalibrations[end].colorMatrix(row, col));
                }
            }
        }
    }
}
