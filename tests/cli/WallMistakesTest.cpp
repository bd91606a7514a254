// SPDX-License-Identifier: BSD-3-Clause
// `bandlight wall` as users get it wrong: emitter files with a negative or
// NaN sample or no visible power, too few emitters, a name given twice, an
// output folder that is an input or empty. Each is one line on stderr and
// exit code 2 before any work, nothing written. And the good case as a user
// checks it: ociocheck passes, ocioconvert with WALL_WB set gives each white
// balance's drive.
// Covers, through the entry points it calls: cli/CommandWall.cpp.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli/MistakesSupport.h"
#include "cli/RunCommand.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Bandlight;
using test::CheckOneLine;
using test::Folder;
using test::Result;

namespace fs = std::filesystem;

namespace
{

const std::string kD21 =
    std::string(BANDLIGHT_TEST_DATA_ROOT) + "/rawtoaces/arri_d21_380_780_5.json";

/// A Gaussian emitter (centre, FWHM in nm) every 5 nm over 380–780 nm, with
/// the sample at `badNm` replaced by `bad` when given.
std::string Emitter(const std::string& dir, const std::string& name, double centre, double fwhm,
                    int badNm = 0, const std::string& bad = "")
{
    const std::string path = dir + "/" + name + ".csv";
    std::ofstream o(path);
    o << "# " << name << "\nnm,power\n";
    const double sigma = fwhm / (2.0 * std::sqrt(2.0 * std::log(2.0)));
    for (int l = 380; l <= 780; l += 5)
    {
        o << l << ",";
        if (l == badNm)
        {
            o << bad << "\n";
        }
        else
        {
            o << std::exp(-0.5 * (l - centre) * (l - centre) / (sigma * sigma)) << "\n";
        }
    }
    return path;
}

/// R 630/20, G 530/30, B 460/20 (centre/FWHM, nm) in `dir`.
std::string Rgb(const std::string& dir)
{
    return "--emitter 'R=" + Emitter(dir, "red", 630, 20) +
           "' 'G=" + Emitter(dir, "green", 530, 30) + "' 'B=" + Emitter(dir, "blue", 460, 20) + "'";
}

std::string Rest(const std::string& out)
{
    return " --camera '" + kD21 + "' --white-balance 5600K --content-space rec709 --out '" + out +
           "'";
}

}  // namespace

TEST_CASE("wall: a good wall runs (the baseline of the mistakes below)", "[cli][mistakes]")
{
    const std::string dir = Folder("wall_good");
    const Result r = Bandlight("wall " + Rgb(dir) + Rest(dir + "/out"));
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Contains("in frustum: exact drive"));
    CHECK(fs::exists(dir + "/out/config.ocio"));
    CHECK(fs::exists(dir + "/out/report.json"));
    const Result check = test::Sh("ociocheck --iconfig '" + dir + "/out/config.ocio'");
    INFO(check.out << check.err);
    CHECK(check.code == 0);
    CHECK_THAT(check.out, Contains("passed"));
}

TEST_CASE("wall: ocioconvert with WALL_WB set gives each white balance's drive", "[cli][wall]")
{
    const std::string dir = Folder("wall_ocioconvert");
    const std::string out = dir + "/out";
    REQUIRE(Bandlight("wall " + Rgb(dir) + " --camera '" + kD21 +
                      "' --white-balance 5600K 3200K --content-space rec709 --out '" + out + "'")
                .code == 0);
    REQUIRE(test::Sh("oiiotool --pattern constant:color=0.2,0.5,0.9 2x2 3 -d float -o '" + dir +
                     "/content.exr'")
                .code == 0);
    const nlohmann::json report = nlohmann::json::parse(test::Slurp(out + "/report.json"));
    std::vector<Eigen::Vector3d> drives;
    for (const nlohmann::json& w : report["white_balances"])
    {
        const std::string key = w["key"];
        const std::string image = dir + "/drive_" + key + ".exr";
        const Result convert =
            test::Sh("OCIO='" + out + "/config.ocio' WALL_WB=" + key + " ocioconvert '" + dir +
                     "/content.exr' 'Linear Rec.709 (sRGB)' '" + image + "' 'LED wall drive'");
        INFO(convert.out << convert.err);
        REQUIRE(convert.code == 0);
        // The pixel ocioconvert wrote, as oiiotool's statistics give it.
        const Result stats = test::Sh("oiiotool '" + image + "' --printstats");
        const size_t at = stats.out.find("Stats Avg:");
        REQUIRE(at != std::string::npos);
        std::istringstream in(stats.out.substr(at + 10));
        Eigen::Vector3d got;
        in >> got(0) >> got(1) >> got(2);
        Eigen::Vector3d want = Eigen::Vector3d::Zero();
        for (int r = 0; r < 3; ++r)
        {
            for (int c = 0; c < 3; ++c)
            {
                want(r) += w["in_frustum"]["drive_matrix"][r][c].get<double>() *
                           Eigen::Vector3d(0.2, 0.5, 0.9)(c);
            }
        }
        INFO(key << ": " << got.transpose() << " against " << want.transpose());
        CHECK((got - want).norm() < 1e-5 * want.norm());
        drives.push_back(got);
    }
    REQUIRE(drives.size() == 2);
    CHECK((drives[0] - drives[1]).norm() > 1e-2 * drives[0].norm());
}

TEST_CASE("wall: an emitter file with a negative or NaN sample is refused at its line",
          "[cli][mistakes]")
{
    const std::string dir = Folder("wall_samples");
    // Line 2 + (630 - 380) / 5 + 1 = 53 holds 630 nm (a comment, a header first).
    const std::string negative = Emitter(dir, "negative", 630, 20, 630, "-0.25");
    CheckOneLine(
        Bandlight("wall --emitter 'R=" + negative + "' 'G=" + Emitter(dir, "green", 530, 30) +
                  "' 'B=" + Emitter(dir, "blue", 460, 20) + "'" + Rest(dir + "/out")),
        negative + ":53: emitter R has a negative sample (-0.25)");
    // A CGATS file (ArgyllCMS .sp, 10 nm): the line of its spectrum's row.
    const std::string cgats = dir + "/negative.sp";
    {
        std::ofstream o(cgats);
        o << "SPECT\n\nKEYWORD \"SPECTRAL_BANDS\"\nSPECTRAL_BANDS \"41\"\n"
             "KEYWORD \"SPECTRAL_START_NM\"\nSPECTRAL_START_NM \"380.0\"\n"
             "KEYWORD \"SPECTRAL_END_NM\"\nSPECTRAL_END_NM \"780.0\"\n\n"
             "NUMBER_OF_FIELDS 41\nBEGIN_DATA_FORMAT\n";
        for (int l = 380; l <= 780; l += 10)
        {
            o << "SPEC_" << l << (l < 780 ? " " : "\n");
        }
        o << "END_DATA_FORMAT\n\nNUMBER_OF_SETS 1\nBEGIN_DATA\n";
        for (int l = 380; l <= 780; l += 10)
        {
            o << (l == 630 ? -0.5 : 0.5) << (l < 780 ? " " : "\n");
        }
        o << "END_DATA\n";
    }
    CheckOneLine(Bandlight("wall --emitter 'R=" + cgats + "' 'G=" + Emitter(dir, "green", 530, 30) +
                           "' 'B=" + Emitter(dir, "blue", 460, 20) + "'" + Rest(dir + "/out")),
                 cgats + ":17: emitter R has a negative sample (-0.5)");
    const std::string nan = Emitter(dir, "nan", 530, 30, 530, "nan");
    CheckOneLine(Bandlight("wall --emitter 'R=" + Emitter(dir, "red", 630, 20) + "' 'G=" + nan +
                           "' 'B=" + Emitter(dir, "blue", 460, 20) + "'" + Rest(dir + "/out")),
                 nan + ":33: NaN");
    CHECK(!fs::exists(dir + "/out"));
}

TEST_CASE("wall: an emitter with no power where cameras see is refused", "[cli][mistakes]")
{
    const std::string dir = Folder("wall_invisible");
    const std::string infrared = dir + "/infrared.csv";
    std::ofstream(infrared) << "nm,power\n800,0.5\n850,1\n900,0.5\n950,0.2\n1000,0.1\n";
    CheckOneLine(Bandlight("wall " + Rgb(dir) + " 'IR=" + infrared + "'" + Rest(dir + "/out")),
                 infrared + ": emitter IR has no power over 380-780 nm");
    CHECK(!fs::exists(dir + "/out"));
}

TEST_CASE("wall: fewer than three emitters, a name given twice, NAME=FILE malformed",
          "[cli][mistakes]")
{
    const std::string dir = Folder("wall_emitters");
    const std::string red = Emitter(dir, "red", 630, 20);
    const std::string green = Emitter(dir, "green", 530, 30);
    CheckOneLine(Bandlight("wall --emitter 'R=" + red + "' 'G=" + green + "'" + Rest(dir + "/out")),
                 "a wall needs at least three emitters to show colour, not 2");
    CheckOneLine(Bandlight("wall --emitter 'R=" + red + "' 'G=" + green + "' 'r=" + green + "'" +
                           Rest(dir + "/out")),
                 "the emitter 'r' is named twice (--emitter)");
    CheckOneLine(Bandlight("wall --emitter 'R=" + red + "' 'G=" + green + "' '" + green + "'" +
                           Rest(dir + "/out")),
                 "--emitter is NAME=FILE");
    CheckOneLine(Bandlight("wall " + Rgb(dir) + Rest(dir + "/out") + " --white-balance 5600k"),
                 "the white balance '5600k' is given twice");
    std::string seventeen = "wall --emitter";
    for (int k = 0; k < 17; ++k)
    {
        seventeen += " 'E" + std::to_string(k) + "=" + Emitter(dir, "e" + std::to_string(k),
                                                                400 + 20 * k, 20) + "'";
    }
    CheckOneLine(Bandlight(seventeen + Rest(dir + "/out")),
                 "a wall of 17 emitters is more than bandlight solves (at most 16)");
    CHECK(!fs::exists(dir + "/out"));
}

TEST_CASE("wall: an output folder that is an input, empty or not given", "[cli][mistakes]")
{
    const std::string dir = Folder("wall_out");
    const std::string red = Emitter(dir, "red", 630, 20);
    const std::string before = test::Slurp(red);
    CheckOneLine(Bandlight("wall " + Rgb(dir) + Rest(red)), "--out '" + red + "' is an input");
    CHECK(test::Slurp(red) == before);
    CheckOneLine(Bandlight("wall " + Rgb(dir) + Rest("")), "--out is '' (an empty path)");
    CheckOneLine(Bandlight("wall " + Rgb(dir) + " --camera '" + kD21 +
                           "' --white-balance 5600K --content-space rec709"),
                 "give the folder the config goes into as --out DIR");
    CheckOneLine(
        Bandlight("wall " + Rgb(dir) + " --camera '" + kD21 +
                  "' --white-balance 5600K --content-space srgb-ish --out '" + dir + "/out'"),
        "srgb-ish");
    CHECK(!fs::exists(dir + "/out"));
}
