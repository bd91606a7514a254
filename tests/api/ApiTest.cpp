// SPDX-License-Identifier: BSD-3-Clause
// The public API (include/bandlight/bandlight.h) in process: what it writes
// is what the command writes for the same request, a field left empty is the
// default every face has, and its errors are the command's one line.
// Covers, through the entry points it calls: jobs/MethodsJob.cpp.
#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include <bandlight/bandlight.h>

#include "jobs/JobsTestSupport.h"
#include "jobs/MethodsJob.h"
#include "transforms/Defaults.h"

namespace fs = std::filesystem;
namespace OCIO = OCIO_NAMESPACE;
using Catch::Matchers::Contains;

namespace
{

/// A pixel through the transform.
std::array<float, 3> Through(const OCIO::ConstTransformRcPtr& t, std::array<float, 3> rgb)
{
    OCIO::Config::CreateRaw()->getProcessor(t)->getDefaultCPUProcessor()->applyRGB(rgb.data());
    return rgb;
}

}  // namespace

TEST_CASE("api: WriteLut and WriteConfig write the command's files", "[api]")
{
    const std::string dir = bandlight::test::Fresh("api");
    fs::create_directories(dir);
    bandlight::ChangeOfLight change;
    change.from = "F11";
    change.to = "D65";
    change.method = "rootpoly";
    bandlight::LutSettings settings;
    settings.size = 9;
    const bandlight::WrittenLut lut = bandlight::WriteLut(change, dir + "/api.clf", settings);
    CHECK(lut.size == 9);
    CHECK(lut.shaper.empty());  // CLF carries its shaper
    REQUIRE(bandlight::test::Bandlight("lut --from F11 --to D65 --method rootpoly --size 9 -o '" +
                                       dir + "/cli.clf'")
                .code == 0);
    CHECK(bandlight::test::ReadAll(dir + "/api.clf") == bandlight::test::ReadAll(dir + "/cli.clf"));

    bandlight::ConfigSettings config;
    config.out = dir + "/api_config";
    const bandlight::WrittenConfig written = bandlight::WriteConfig(config);
    REQUIRE(bandlight::test::Bandlight("config --out '" + dir + "/cli_config'").code == 0);
    CHECK(bandlight::test::ReadAll(written.file) ==
          bandlight::test::ReadAll(dir + "/cli_config/config.ocio"));
    CHECK_FALSE(written.looks.empty());
    CHECK(written.workingSpace == bandlight::defaults::WORKING_SPACE);
}

TEST_CASE("api: a field left empty is the default every face has", "[api]")
{
    bandlight::ChangeOfLight given;
    given.from = "A";
    given.to = "D65";
    bandlight::ChangeOfLight spelled = given;
    spelled.method = bandlight::defaults::METHOD;
    spelled.workingSpace = bandlight::defaults::WORKING_SPACE;
    spelled.observer = bandlight::defaults::OBSERVER;
    spelled.plates = bandlight::defaults::PLATES;
    spelled.adaptation = bandlight::defaults::ADAPTATION;
    const std::array<float, 3> a = Through(bandlight::MakeTransform(given), {0.3f, 0.2f, 0.1f});
    const std::array<float, 3> b = Through(bandlight::MakeTransform(spelled), {0.3f, 0.2f, 0.1f});
    CHECK(a == b);
    // And another method does change the pixel: the fields are read.
    spelled.method = "band3";
    CHECK(Through(bandlight::MakeTransform(spelled), {0.3f, 0.2f, 0.1f}) != a);
}

TEST_CASE("api: errors are the command's one line, the registry its list", "[api]")
{
    bandlight::ChangeOfLight change;
    change.from = "A";
    change.to = "D65";
    change.method = "no-such-method";
    const std::string dir = bandlight::test::Fresh("api_error");
    fs::create_directories(dir);
    const bandlight::test::Result cli = bandlight::test::Bandlight(
        "lut --from A --to D65 --method no-such-method -o '" + dir + "/x.cube'");
    CHECK(cli.code == 2);
    try
    {
        bandlight::MakeTransform(change);
        FAIL("an unknown method was accepted");
    }
    catch (const std::runtime_error& e)
    {
        CHECK_THAT(cli.err, Contains(e.what()));
        CHECK_THAT(e.what(), Contains("no-such-method"));
    }
    const std::vector<bandlight::MethodInfo> methods = bandlight::ListMethods();
    REQUIRE(methods.size() == bandlight::jobs::ListMethods().size());
    CHECK(methods.front().names == bandlight::jobs::ListMethods().front().names);
    CHECK(bandlight::Version() == BANDLIGHT_VERSION);
}

TEST_CASE("api: what hosts get wrong is refused before any work, nothing written", "[api]")
{
    const std::string dir = bandlight::test::Fresh("api_mistakes");
    fs::create_directories(dir);
    bandlight::ChangeOfLight change;
    change.from = "A";
    change.to = "D65";
    // An empty path, a folder where the LUT file goes, a format the path's
    // extension does not name, a light that is no light.
    CHECK_THROWS_AS(bandlight::WriteLut(change, ""), std::runtime_error);
    CHECK_THROWS_AS(bandlight::WriteLut(change, dir), std::runtime_error);
    bandlight::LutSettings cube;
    cube.format = "cube";
    CHECK_THROWS_AS(bandlight::WriteLut(change, dir + "/x.clf", cube), std::runtime_error);
    bandlight::ChangeOfLight dark = change;
    dark.to = dir + "/missing.csv";
    CHECK_THROWS_WITH(bandlight::MakeTransform(dark), Contains("missing.csv"));
    // A config needs its folder; images need a look of the config.
    CHECK_THROWS_AS(bandlight::WriteConfig({}), std::runtime_error);
    CHECK_THROWS_AS(bandlight::ApplyLook(dir + "/in.exr", dir + "/out.exr", dir, "no_look"),
                    std::runtime_error);
    CHECK(fs::is_empty(dir));
}
