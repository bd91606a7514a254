// SPDX-License-Identifier: BSD-3-Clause
// The config job (jobs/ConfigJob) run in process, as a C++ host runs it,
// against what the command writes for the same request.
#include <string>

#include <catch2/catch.hpp>

#include "jobs/ConfigJob.h"
#include "requests/Inputs.h"
#include "spectral/Exception.h"
#include "jobs/JobsTestSupport.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("the config job with a default request writes the command's config.ocio", "[jobs]")
{
    const std::string lib = test::Fresh("config_lib"), cli = test::Fresh("config_cli");
    jobs::ConfigRequest request;
    request.out = lib;
    const jobs::ConfigResult result = jobs::MakeConfig(request);
    CHECK(result.options.lights.size() == 5);
    CHECK(result.options.plates.balanced());
    CHECK(result.options.lutSize == defaults::CONFIG_LUT_SIZE);
    REQUIRE(test::Bandlight("config --out '" + cli + "'").code == 0);
    const std::string written = test::ReadAll(lib + "/config.ocio");
    REQUIRE(!written.empty());
    CHECK(written == test::ReadAll(cli + "/config.ocio"));
    // The returned config resolves its files from where it was written.
    CHECK(std::string(result.package.config->getWorkingDir()) == lib);
}

TEST_CASE("a config needing LUT files is refused without a folder to write them into", "[jobs]")
{
    jobs::ConfigRequest request;
    request.methods = {"rootpoly"};
    request.lights = {jobs::ResolveIlluminant("A"), jobs::ResolveIlluminant("D65")};
    request.lutSize = 5;
    try
    {
        jobs::MakeConfig(request);
        FAIL("accepted");
    }
    catch (const ParameterError& e)
    {
        CHECK_THAT(e.spelled(Face::PYTHON), Contains("give out=DIR"));
    }
    request.lutSize = 1;
    CHECK_THROWS_AS(jobs::MakeConfig(request), ParameterError);
}
