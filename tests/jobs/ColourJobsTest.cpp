// SPDX-License-Identifier: BSD-3-Clause
// The colour jobs (jobs/ColourJobs: xyz, cri, tables) run in process, as a
// C++ host runs them: their documents are the command's --json.
#include <string>

#include <catch2/catch.hpp>

#include "jobs/ColourJobs.h"
#include "requests/Inputs.h"
#include "cli/RunCommand.h"

using namespace bandlight;

TEST_CASE("the colour jobs' documents are the command's --json", "[jobs]")
{
    const test::Result xyz = test::Bandlight("xyz --illuminant F11 --reflectance TCS --json");
    REQUIRE(xyz.code == 0);
    jobs::XyzRequest request;
    request.illuminant = jobs::ResolveIlluminant("F11");
    request.reflectances = jobs::ResolveReflectances("TCS");
    CHECK(jobs::XyzDocument(jobs::MakeXyz(request)) + "\n" == xyz.out);

    const test::Result cri = test::Bandlight("cri --illuminant F2 --json");
    REQUIRE(cri.code == 0);
    const jobs::CriResult f2 = jobs::MakeCri(jobs::ResolveIlluminant("F2"));
    CHECK(jobs::CriDocument(f2) + "\n" == cri.out);
    // CIE 13.3-1995 Table 3 (via CIE 15:2004): F2 has Ra 64.
    CHECK(f2.rendering.ra == Approx(64.0).margin(0.5));

    const test::Result tables = test::Bandlight("tables --json --rule exact");
    REQUIRE(tables.code == 0);
    jobs::TablesRequest t;
    t.rule = "exact";
    CHECK(jobs::TablesDocument(jobs::MakeTables(t)) + "\n" == tables.out);
}
