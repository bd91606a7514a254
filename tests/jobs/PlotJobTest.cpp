// SPDX-License-Identifier: BSD-3-Clause
// The plot job in process, against the command's file.
// Covers, through the entry points it calls: report/Gnuplot.cpp.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "jobs/PlotJob.h"
#include "spectral/Exception.h"

using namespace bandlight;
namespace fs = std::filesystem;

namespace
{
std::string ReadAll(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string Fresh(const std::string& name)
{
    const std::string dir = test::TempPath("plotjob_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}
}  // namespace

TEST_CASE("the plot job draws the command's picture", "[jobs][plot]")
{
    const std::string dir = Fresh("a");
    jobs::PlotRequest request;
    request.illuminant = "A";
    request.out = dir + "/lib.svg";
    const jobs::PlotResult result = jobs::MakePlot(request);
    CHECK(result.out == request.out);
    CHECK(result.title == "Illuminant A and its band means (largest band = 1)");
    CHECK(result.curves == std::vector<std::string>{"A"});
    const test::Result r = test::Bandlight("plot --illuminant A -o '" + dir + "/cli.svg'");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.out == "Wrote " + dir + "/cli.svg\n");
    const std::string svg = ReadAll(request.out);
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(svg == ReadAll(dir + "/cli.svg"));
}

TEST_CASE("the plot job draws the matching functions and remittances", "[jobs][plot]")
{
    const std::string dir = Fresh("cmf");
    jobs::PlotRequest cmf;
    cmf.cmf = true;
    cmf.observer = "1964";
    cmf.out = dir + "/cmf.png";
    const jobs::PlotResult c = jobs::MakePlot(cmf);
    CHECK(c.curves == std::vector<std::string>{"x̄", "ȳ", "z̄"});
    CHECK(c.title.find("colour-matching functions and their band means") != std::string::npos);
    CHECK(fs::file_size(cmf.out) > 1000);

    jobs::PlotRequest tcs;
    tcs.reflectance = "TCS";
    tcs.bands = "400,450,500,550,600,650,700";
    tcs.out = dir + "/tcs.svg";
    CHECK(jobs::MakePlot(tcs).curves.size() == 15);
}

TEST_CASE("the plot job takes one thing to draw, and names its parameters", "[jobs][plot]")
{
    const std::string out = test::TempPath("plotjob_never.svg");
    fs::remove(out);
    jobs::PlotRequest none;
    none.out = out;
    CHECK_THROWS_WITH(jobs::MakePlot(none),
                      "plot one of cmf, illuminant NAME|FILE or reflectance NAME|FILE");
    jobs::PlotRequest two = none;
    two.cmf = true;
    two.illuminant = "D65";
    CHECK_THROWS_AS(jobs::MakePlot(two), ParameterError);
    const test::Result r = test::Bandlight("plot --cmf --illuminant D65 -o '" + out + "'");
    CHECK(r.code == 2);
    CHECK(r.err ==
          "bandlight: plot one of --cmf, --illuminant NAME|FILE or --reflectance NAME|FILE\n");
    CHECK_FALSE(fs::exists(out));
}
