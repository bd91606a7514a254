// SPDX-License-Identifier: BSD-3-Clause
// Light-group accuracy (jobs/LightGroupAccuracy): one global look against a
// look per group, both against the exact spectral groups of a render.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "measure/LightGroupAccuracy.h"
#include "jobs/RenderJob.h"
#include "jobs/LightGroupsTestSupport.h"

using namespace bandlight;
using namespace bandlight::jobs;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace
{
/// The image module is found beside the bandlight executable; this test
/// program lives elsewhere, so it says where.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;
}  // namespace

TEST_CASE(
    "accuracy --light-group: one global look against a look per group, against the exact "
    "spectral groups",
    "[jobs][lightgroups][accuracy]")
{
    const std::string dir = test::FreshLightGroupDir("accuracy");
    RenderRequest render;
    render.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
    render.spectra = true;
    render.lightGroups = true;
    render.preview = false;
    render.out = dir + "/shot.exr";
    MakeRender(render);
    LightGroupAccuracyRequest r;
    r.image = render.out;
    r.methods = {"bradford"};
    r.changes = {{"key", ResolveIlluminant("A"), ResolveIlluminant("D65")}};
    CHECK_THROWS_WITH(MeasureLightGroups(r), Contains("light group 'fill' has no change"));
    r.changes.push_back({"fill", ResolveIlluminant("F11"), ResolveIlluminant("D50")});
    const LightGroupAccuracyResult result = MeasureLightGroups(r);
    REQUIRE(result.rows.size() == 1);
    CHECK(result.pixels > 10000);
    CHECK(result.noChangeMean > 10.0);
    CHECK(result.rows[0].globalMean > 2.0);
    CHECK(result.rows[0].groupsMean < 0.7 * result.rows[0].globalMean);
    CHECK(result.globalFrom == "key A + fill F11");
    // Nothing of the run is left in the temporary folder.
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
    {
        CHECK(e.path().filename().string().rfind(
                  ".bandlight-lightgroups-" + std::to_string(::getpid()), 0) == std::string::npos);
    }
}
