// SPDX-License-Identifier: BSD-3-Clause
// `bandlight quality` as scripts use it and as users get it wrong: the
// table, JSON and CSV agree; a mistake is one line on stderr and exit 2
// before any work, a bad spectrum named by file and line.
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli/MistakesSupport.h"
#include "cli/RunCommand.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::CheckOneLine;
using test::Folder;

TEST_CASE("quality: one table, JSON and CSV with a row per light", "[cli][quality]")
{
    const auto json = Bandlight("quality F2 planck:3200 daylight:5600 --json");
    REQUIRE(json.code == 0);
    const auto j = nlohmann::json::parse(json.out);
    REQUIRE(j.size() == 3);
    // CIE 15:2004 Table T.8.2: FL2, Ra 64.
    CHECK(std::lround(j[0]["cri"]["Ra"].get<double>()) == 64);
    CHECK(j[1]["cct"].get<double>() == Approx(3200.0).epsilon(1e-6));
    CHECK(j[2]["cct"].get<double>() == Approx(5600.0).margin(1.0));

    const auto csv = Bandlight("quality F2 planck:3200 daylight:5600 --csv");
    REQUIRE(csv.code == 0);
    CHECK(std::count(csv.out.begin(), csv.out.end(), '\n') == 4);  // header + 3 lights
    const auto table = Bandlight("quality F2 planck:3200 daylight:5600");
    REQUIRE(table.code == 0);
    CHECK_THAT(table.out, Contains("F2") && Contains("Ra") && Contains("CCT K"));
    // The plot: written whole, a PNG of a row per light (2 here).
    const std::string dir = Folder("quality_plot");
    const auto plot = Bandlight("quality F2 F11 --reference D65 --plot '" + dir + "/q.png'");
    REQUIRE(plot.code == 0);
    std::ifstream png(dir + "/q.png", std::ios::binary);
    char magic[8] = {};
    png.read(magic, 8);
    CHECK(std::string(magic + 1, 3) == "PNG");
}

TEST_CASE("quality: mistakes are one line and exit 2", "[cli][quality][mistakes]")
{
    const std::string dir = Folder("quality");
    CheckOneLine(Bandlight("quality"), "light is required");
    CheckOneLine(Bandlight("quality F2 --json --csv"), "excludes");
    CheckOneLine(Bandlight("quality F2 --plot '" + dir + "/scores.txt'"), ".png or .svg");
    CheckOneLine(
        Bandlight("quality F1 F2 F3 F4 F5 F6 F7 F8 F9 F10 F11 F12 A --plot '" + dir + "/many.png'"),
        "--plot draws 12 lights at most");
    CHECK_FALSE(std::filesystem::exists(dir + "/many.png"));
    CheckOneLine(Bandlight("quality F2 nolight"), "unknown illuminant 'nolight'");
    CheckOneLine(Bandlight("quality F2 --reference ''"), "--reference is empty");
    CheckOneLine(Bandlight("quality F2 --plot ''"), ".png or .svg");
    CheckOneLine(Bandlight("quality F2 --reference nolight"), "unknown illuminant 'nolight'");
    // A measured spectrum with a NaN: the file and line named, no table.
    {
        std::ofstream f(dir + "/led.csv");
        f << "nm,led\n380,0.1\n385,0.2\n390,nan\n395,0.3\n400,0.2\n";
    }
    const auto bad = Bandlight("quality F2 '" + dir + "/led.csv'");
    CheckOneLine(bad, "led.csv:4");
    CHECK(bad.out.empty());
    // A light with no power where the eye sees.
    {
        std::ofstream f(dir + "/ir.csv");
        f << "nm,ir\n800,1\n805,1\n810,1\n815,1\n820,1\n825,1\n";
    }
    CheckOneLine(Bandlight("quality '" + dir + "/ir.csv'"), "ir.csv");
    // The plot over one of its own lights: refused, the light kept.
    {
        std::ofstream f(dir + "/lamp.svg");
        f << "nm,lamp\n380,1\n480,1\n580,1\n680,1\n780,1\n";
    }
    CheckOneLine(Bandlight("quality '" + dir + "/lamp.svg' --plot '" + dir + "/lamp.svg'"),
                 "would overwrite it");
    CHECK(test::Slurp(dir + "/lamp.svg").rfind("nm,lamp", 0) == 0);
}
