// SPDX-License-Identifier: BSD-3-Clause
// The accuracy job (jobs/AccuracyJob) run in process, as a C++ host runs
// it: its document and report are the command's.
// Covers, through the entry points it calls: measure/AccuracyOptions.cpp,
// measure/AccuracyPlot.cpp, measure/AccuracyReport.cpp, measure/Cost.cpp.
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "jobs/AccuracyJob.h"
#include "requests/Inputs.h"
#include "cli/RunCommand.h"

using namespace bandlight;

TEST_CASE("the accuracy job's document is the command's, row for row", "[jobs]")
{
    jobs::AccuracyRequest request;
    request.lights = {jobs::ResolveIlluminant("A"), jobs::ResolveIlluminant("D65")};
    request.methods = {"bradford", "band3"};
    request.idealOnly = true;
    request.cost = false;
    const jobs::AccuracyResult result = jobs::MeasureAccuracyJob(request);
    const test::Result cli = test::Bandlight(
        "accuracy --illuminants A,D65 --methods bradford,band3 --ideal-only --no-cost --json -");
    REQUIRE(cli.code == 0);
    CHECK(jobs::AccuracyDocument(result) + "\n" == cli.out);
    // The reference's own row is always there, and bradford beats band3
    // (docs/accuracy.md).
    const nlohmann::json doc = nlohmann::json::parse(cli.out);
    double bradford = 0, band3 = 0;
    bool spectral = false;
    for (const auto& r : doc["rows"])
    {
        spectral = spectral || r["method"] == "spectral";
        if (r["set"] == "tcs09-15" && r["exposure"] == 1.0 && r["plates"] == "lit")
        {
            (r["method"] == "bradford" ? bradford : band3) += r["mean"].get<double>();
        }
    }
    CHECK(spectral);
    CHECK(band3 > bradford);
    // The text report is the command's table.
    const test::Result text = test::Bandlight(
        "accuracy --illuminants A,D65 --methods bradford,band3 --ideal-only --no-cost");
    CHECK(jobs::AccuracyReport(result) == text.out);
}
