// SPDX-License-Identifier: BSD-3-Clause
// The lut job (jobs/LutJob) run in process, as a C++ host runs it, against
// what the command writes for the same request: byte for byte.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "requests/Inputs.h"
#include "jobs/LutJob.h"
#include "jobs/JobsTestSupport.h"

using namespace bandlight;
namespace fs = std::filesystem;

TEST_CASE("the lut job writes the command's file", "[jobs]")
{
    const std::string dir = test::Fresh("lut");
    fs::create_directories(dir);
    jobs::LutRequest request;
    request.relight.src = jobs::ResolveIlluminant("F11");
    request.relight.dst = jobs::ResolveIlluminant("D65");
    request.relight.method = "rootpoly";
    request.size = 9;
    request.out = dir + "/lib.clf";
    const jobs::LutResult result = jobs::MakeLut(request);
    CHECK(result.files.lattice);
    CHECK(result.size == 9);
    REQUIRE(test::Bandlight("lut --from F11 --to D65 --method rootpoly --size 9 -o '" + dir +
                            "/cli.clf'")
                .code == 0);
    CHECK(test::ReadAll(dir + "/lib.clf") == test::ReadAll(dir + "/cli.clf"));
}
