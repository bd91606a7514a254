// SPDX-License-Identifier: BSD-3-Clause
// Lights' scores written once (report/LightQualityReport.h): the JSON the
// interface promises, CSV with one column per value and a row per light,
// and the terminal table; every face walks the same fields.
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "report/LightQualityReport.h"
#include "spectral/Illuminants.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
std::vector<LightQuality> TwoLights()
{
    return {ScoreLight("F2", BuiltinIlluminant("F2")),
            ScoreLight("hot, \"blue\"", Planckian(30000.0, 360.0, 5.0, 95))};
}
}  // namespace

TEST_CASE("quality JSON: a list, one object a light, scores by key", "[report][quality]")
{
    const auto j = nlohmann::json::parse(QualityJson(TwoLights()));
    REQUIRE(j.is_array());
    REQUIRE(j.size() == 2);
    const auto& f2 = j[0];
    CHECK(f2["light"] == "F2");
    // CIE 15:2004 Table T.8.2: FL2 has CCT 4230 K and Ra 64.
    CHECK(f2["cct"].get<double>() == Approx(4230.0).margin(15.0));
    CHECK(f2["duv"].is_number());
    CHECK(std::lround(f2["cri"]["Ra"].get<double>()) == 64);
    CHECK(f2["cri"]["R"].size() == 15);
    CHECK(f2["warnings"].empty());
    // A score its standard gives no value for is null, and a warning says
    // why, naming the score.
    CHECK(j[1]["cri"].is_null());
    REQUIRE(j[1]["warnings"].size() >= 1);
    CHECK_THAT(j[1]["warnings"][0].get<std::string>(), Contains("cri: "));
}

TEST_CASE("quality CSV: a header and a row a light, RFC 4180 quoting", "[report][quality]")
{
    std::istringstream csv(QualityCsv(TwoLights()));
    std::string header, first, second, extra;
    REQUIRE(std::getline(csv, header));
    REQUIRE(std::getline(csv, first));
    REQUIRE(std::getline(csv, second));
    CHECK_FALSE(std::getline(csv, extra));
    CHECK(header.rfind("light,cct,duv,", 0) == 0);
    CHECK_THAT(header, Contains("cri.Ra,cri.R1,"));
    CHECK_THAT(header, Contains(",cri.R15,"));
    CHECK(header.substr(header.size() - 9) == ",warnings");
    CHECK(first.rfind("F2,", 0) == 0);
    // The name with a comma and quotes is quoted, quotes doubled; its CRI
    // cells are empty.
    CHECK(second.rfind("\"hot, \"\"blue\"\"\",", 0) == 0);
    const auto commas = [](const std::string& s)
    {
        size_t n = 0;
        bool quoted = false;
        for (const char c : s)
        {
            quoted = c == '"' ? !quoted : quoted;
            n += !quoted && c == ',';
        }
        return n;
    };
    CHECK(commas(first) == commas(header));
    CHECK(commas(second) == commas(header));
}

TEST_CASE("quality table: a row a light, warnings numbered under it", "[report][quality]")
{
    const std::string text = QualityText(TwoLights());
    CHECK_THAT(text, Contains("CCT K"));
    CHECK_THAT(text, Contains("Ra"));
    CHECK_THAT(text, Contains("F2"));
    CHECK_THAT(text, Contains("\n2! cri: no value"));
}
