// SPDX-License-Identifier: BSD-3-Clause
// One figure, two paths, for light groups: the ΔE00 `accuracy --image
// --light-group` reports for a per-group relight (measured in memory,
// MeasureLightGroups) is the figure of the files `apply --light-group` and
// `spectral --light-group` write, measured pixel by pixel with the metric
// registry's ΔE00 and summarised by Summarise (spectral/Statistics.h), with
// the convention the light-group table states: L*a*b* relative to the
// equal-energy white at the exact relight's brightest luminance, pixels the
// exact relight leaves black not counted.
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <algorithm>
#include <string>
#include <vector>

#include "jobs/ApplyJob.h"
#include "jobs/LightGroupsTestSupport.h"
#include "jobs/RenderJob.h"
#include "jobs/SpectralJob.h"
#include "measure/LightGroupAccuracy.h"
#include "spectral/Metrics.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Statistics.h"

using namespace bandlight;
using namespace bandlight::jobs;

namespace
{

const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

std::vector<Vec3> Beauty(const test::Exr::Part& part)
{
    std::vector<Vec3> v(part.count());
    for (size_t p = 0; p < part.count(); ++p)
    {
        v[p] = Vec3(part.at(p, "R"), part.at(p, "G"), part.at(p, "B"));
    }
    return v;
}

/// ΔE00 of `image` against `exact`, by the light-group table's convention.
Statistics FileFigure(const std::vector<Vec3>& image, const std::vector<Vec3>& exact)
{
    MetricContext context;
    context.rgbToXyz = RgbToXyzMatrix(FindRgbSpace("acescg").chromaticities);
    double level = 0.0;
    for (const Vec3& v : exact)
    {
        level = std::max(level, (context.rgbToXyz * v).y());
    }
    context.whiteXyz = Vec3::Ones() * level;
    std::vector<Vec3> lit, reference;
    for (size_t p = 0; p < exact.size(); ++p)
    {
        if (!exact[p].isZero(0.0))
        {
            lit.push_back(image[p]);
            reference.push_back(exact[p]);
        }
    }
    return Summarise(MetricValues(FindMetric("de00"), lit, reference, context));
}

}  // namespace

TEST_CASE("A light group's ΔE00 is one figure in memory and through the files",
          "[measure][lightgroups]")
{
    const std::string dir = test::FreshLightGroupDir("one_figure");
    RenderRequest render;
    render.scene = std::string(SCENES_DIR) + "/two_lights.yaml";
    render.spectra = true;
    render.lightGroups = true;
    render.preview = false;
    render.out = dir + "/shot.exr";
    MakeRender(PrepareRender(render));

    LightGroupAccuracyRequest request;
    request.image = render.out;
    request.changes = {{"key", ResolveIlluminant("A"), ResolveIlluminant("D65")},
                       {"fill", ResolveIlluminant("F11"), ResolveIlluminant("D50")}};
    request.methods = {"bradford"};
    const LightGroupAccuracyResult measured = MeasureLightGroups(request);
    REQUIRE(measured.rows.size() == 1);

    // The same relights as files: the exact one, and bradford per group.
    SpectralRequest exact;
    exact.files.input = render.out;
    exact.files.output = dir + "/exact.exr";
    exact.options.plates.plates = "lit";
    exact.options.lightGroups = request.changes;
    ConvertSpectralImages(exact);
    ApplyRequest groups;
    groups.input = render.out;
    groups.output = dir + "/bradford.exr";
    groups.lightGroups = {{"key", test::Change("A", "D65", "bradford")},
                          {"fill", test::Change("F11", "D50", "bradford")}};
    ApplyImages(groups);

    const std::vector<Vec3> reference = Beauty(test::ReadExr(exact.files.output)[0]);
    const Statistics relit = FileFigure(Beauty(test::ReadExr(groups.output)[0]), reference);
    const Statistics asShot = FileFigure(Beauty(test::ReadExr(render.out)[0]), reference);
    INFO("in memory: groups " << measured.rows[0].groupsMean << ", no change "
                              << measured.noChangeMean << "; files: " << relit.mean << ", "
                              << asShot.mean);
    CHECK(relit.count == measured.pixels);
    CHECK(relit.mean > 0.01);  // bradford is not exact
    // Float files and float memory: the same figure to float's precision.
    CHECK(relit.mean == Approx(measured.rows[0].groupsMean).epsilon(1e-5));
    CHECK(relit.p95 == Approx(measured.rows[0].groupsP95).epsilon(1e-5));
    CHECK(asShot.mean == Approx(measured.noChangeMean).epsilon(1e-5));
}
