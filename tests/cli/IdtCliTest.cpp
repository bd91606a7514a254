// SPDX-License-Identifier: BSD-3-Clause
// `bandlight idt` as a user runs it: an ociocheck-clean config, the
// interpolation curve and the as-shot neutral read back from its JSON.
// Covers, through the entry points it calls: cli/CommandIdt.cpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli/RunCommand.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::Result;
using test::Sh;
using test::TempPath;

namespace
{
const std::string kD21 =
    std::string(BANDLIGHT_TEST_DATA_ROOT) + "/rawtoaces/arri_d21_380_780_5.json";

nlohmann::json Json(const std::string& args)
{
    const Result r = Bandlight("idt --camera '" + kD21 + "' " + args + " --json -");
    INFO(args << "\n" << r.err);
    REQUIRE(r.code == 0);
    return nlohmann::json::parse(r.out);
}
}  // namespace

TEST_CASE("idt --config writes a config ociocheck passes, with one input space per light",
          "[cli][idt]")
{
    const std::string dir = TempPath("idt_config");
    std::filesystem::remove_all(dir);
    const Result r =
        Bandlight("idt --camera '" + kD21 + "' --lights A,3200K,D55 --config '" + dir + "'");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("colour space \"Input - arri d21 - 3200K\""));
    const Result check = Sh("ociocheck --iconfig '" + dir + "/config.ocio'");
    INFO(check.out << check.err);
    CHECK(check.code == 0);
    CHECK_THAT(check.out, Contains("passed"));
    CHECK_THAT(check.out + check.err, !Contains("ERROR"));
    for (const char* light : {"A", "3200K", "D55"})
    {
        CHECK(std::filesystem::exists(dir + "/luts/Input_-_arri_d21_-_" + std::string(light) +
                                      ".clf"));
    }
}

TEST_CASE("A second camera into the same --config folder is added to it, a clash refused",
          "[cli][idt]")
{
    const std::string dir = TempPath("idt_two_cameras");
    std::filesystem::remove_all(dir);
    const std::string d200 =
        std::string(BANDLIGHT_TEST_DATA_ROOT) + "/rawtoaces/nikon_d200_380_780_5.json";
    REQUIRE(Bandlight("idt --camera '" + kD21 + "' --lights A,D55 --config '" + dir + "'").code ==
            0);
    const Result second =
        Bandlight("idt --camera '" + d200 + "' --lights A,D55 --config '" + dir + "'");
    INFO(second.err);
    REQUIRE(second.code == 0);
    CHECK_THAT(second.err, Contains("its colour spaces are kept and 2 input spaces added: "
                                    "Input - nikon d200 - A, Input - nikon d200 - D55"));
    const Result check = Sh("ociocheck --iconfig '" + dir + "/config.ocio'");
    CHECK(check.code == 0);
    for (const char* space : {"Input - arri d21 - A", "Input - arri d21 - D55",
                              "Input - nikon d200 - A", "Input - nikon d200 - D55"})
    {
        CHECK_THAT(check.out, Contains(space));
    }
    // The same camera and light again: refused, the config as it was.
    const Result before = Sh("cat '" + dir + "/config.ocio'");
    const Result clash = Bandlight("idt --camera '" + d200 + "' --lights A --config '" + dir + "'");
    CHECK(clash.code == 2);
    CHECK_THAT(clash.err, Contains("already has the colour space 'Input - nikon d200 - A'"));
    CHECK(Sh("cat '" + dir + "/config.ocio'").out == before.out);
}

TEST_CASE(
    "idt --interpolate: the DNG interpolation stays within 0.3 dE00 of IDTs fitted at each CCT",
    "[cli][idt]")
{
    const nlohmann::json j = Json("--interpolate 3200K,5600K");
    const nlohmann::json& in = j["interpolation"];
    CHECK(in["from"] == "3200K");
    CHECK(in["to"] == "5600K");
    CHECK(in["set"] == "TCS");
    CHECK(in["count"] == 15);
    CHECK(in["interpolated"] == "color_matrix");
    CHECK(in["beyond_pair"] == "extrapolated");
    REQUIRE(in["calibrations"].size() == 2);
    CHECK(in["calibrations"][0]["light"] == "3200K");
    CHECK(in["calibrations"][0]["cct"].get<double>() == Approx(3200.0).epsilon(1e-4));
    // The DNG SDK's normalisation: the working white gives a raw neutral
    // whose largest channel is 1 (ACES white x 0.32168, y 0.33767,
    // SMPTE ST 2065-1).
    const double white[3] = {0.32168 / 0.33767, 1.0, (1.0 - 0.32168 - 0.33767) / 0.33767};
    for (const nlohmann::json& c : in["calibrations"])
    {
        REQUIRE(c["color_matrix"].size() == 3);
        double largest = 0.0;
        for (int row = 0; row < 3; ++row)
        {
            double raw = 0.0;
            for (int col = 0; col < 3; ++col)
            {
                raw += c["color_matrix"][row][col].get<double>() * white[col];
            }
            largest = std::max(largest, raw);
        }
        CHECK(largest == Approx(1.0).epsilon(1e-9));
    }
    const nlohmann::json& curve = in["curve"];
    REQUIRE(curve.size() == 38);  // 2800–6500 K every 100 K
    CHECK(curve.front()["cct"] == 2800.0);
    CHECK(curve.back()["cct"] == 6500.0);
    for (const nlohmann::json& p : curve)
    {
        INFO(p.dump());
        CHECK(std::abs(p["interpolated_mean"].get<double>() - p["direct_mean"].get<double>()) <
              0.3);
        // The strict reading: the two IDTs' outputs on the same plate.
        CHECK(p["mean_vs_direct"].get<double>() <= 0.3);
        CHECK(p["p95_vs_direct"].get<double>() >= p["mean_vs_direct"].get<double>());
        CHECK(p["max_vs_direct"].get<double>() >= p["p95_vs_direct"].get<double>());
        CHECK(p["dng_clamped_mean_vs_direct"].get<double>() >= 0.0);
        if (p["cct"] == 3200.0 || p["cct"] == 5600.0)
        {
            CHECK(p["max_vs_direct"].get<double>() < 1e-6);
        }
    }
    CHECK(j["idts"].size() == 2);
}

TEST_CASE("idt --as-shot-neutral finds the light a camera's neutral stands for", "[cli][idt]")
{
    for (const char* light : {"2900K", "4500K", "6500K", "9000K"})
    {
        // The raw neutral is the reciprocal of the light's gains.
        const nlohmann::json fit = Json(std::string("--lights ") + light);
        const nlohmann::json& g = fit["idts"][0]["gains"];
        std::ostringstream neutral;
        neutral.precision(12);
        neutral << 1.0 / g[0].get<double>() << "," << 1.0 / g[1].get<double>() << ","
                << 1.0 / g[2].get<double>();
        const nlohmann::json j = Json("--as-shot-neutral " + neutral.str());
        INFO(light << " " << j["as_shot"].dump());
        CHECK(j["as_shot"]["cct"].get<double>() ==
              Approx(fit["idts"][0]["cct"].get<double>()).epsilon(0.01));
        CHECK(std::abs(j["as_shot"]["duv"].get<double>() - fit["idts"][0]["duv"].get<double>()) <
              0.001);
        CHECK(j["idts"].size() == 1);
        CHECK(j["as_shot"]["grey_de00"].get<double>() < 0.05);
    }
    // A fluorescent tube's neutral: no daylight or Planckian light explains
    // it (refused, naming the closest); searched among the tubes, F11 itself.
    const nlohmann::json f11 = Json("--lights F11");
    const nlohmann::json& g = f11["idts"][0]["gains"];
    std::ostringstream neutral;
    neutral.precision(12);
    neutral << 1.0 / g[0].get<double>() << "," << 1.0 / g[1].get<double>() << ","
            << 1.0 / g[2].get<double>();
    const Result refused = Bandlight("idt --camera '" + kD21 + "' --as-shot-neutral " +
                                     neutral.str());
    CHECK(refused.code == 2);
    CHECK_THAT(refused.err, Contains("the closest, daylight") && Contains("--as-shot-light"));
    const nlohmann::json tubes =
        Json("--as-shot-neutral " + neutral.str() + " --as-shot-light fluorescent");
    CHECK(tubes["as_shot"]["family"] == "list");
    CHECK(tubes["idts"].back()["light"] == "as shot (F11)");
    CHECK(tubes["as_shot"]["grey_de00"].get<double>() < 1e-6);
    CHECK(Bandlight("idt --camera '" + kD21 + "' --lights A --as-shot-light fluorescent").code == 2);
}
