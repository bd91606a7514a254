// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "spectral/Exception.h"
#include "transforms/BandSet.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("The lecture's bands are VB, VG, VR of 100 nm", "[transforms]")
{
    const BandSet b = BandSet::Lecture();
    REQUIRE(b.size() == 3);
    CHECK(b[0].name == "VB");
    CHECK(b[0].minNm == 400.0);
    CHECK(b[1].name == "VG");
    CHECK(b[2].maxNm == 700.0);
    CHECK(b.describe() == "400,500,600,700");
}

TEST_CASE("Equal and user bands", "[transforms]")
{
    const BandSet e = BandSet::Equal(6, 400.0, 700.0);
    REQUIRE(e.size() == 6);
    CHECK(e[5].name == "B6");
    CHECK(e[1].minNm == Approx(450.0));
    const BandSet u = BandSet::Parse("380,480,560,780");
    CHECK(u[1].width() == Approx(80.0));
    CHECK(BandSet({{"a", 400, 450}, {"b", 500, 550}}).describe() == "400,450,500,550");
}

TEST_CASE("Band sets are validated", "[transforms]")
{
    CHECK_THROWS_WITH(BandSet::Parse("400,500,500,700"), Contains("empty or not increasing"));
    CHECK_THROWS_WITH(BandSet::Parse("400,600,500"), Contains("empty or not increasing"));
    CHECK_THROWS_WITH(BandSet::Parse("400"), Contains("need at least two edges"));
    CHECK_THROWS_WITH(BandSet::Parse("400,x,600"), Contains("'x' is not a wavelength"));
    CHECK_THROWS_WITH(BandSet({{"a", 400, 500}, {"b", 450, 550}}), Contains("overlaps"));
    CHECK_THROWS_WITH(BandSet(std::vector<Band>{}), Contains("no bands"));
    CHECK_THROWS_WITH(BandSet::Parse("300,500,700").validateRange(380, 780, "F2"),
                      "band B1 [300, 500) nm lies outside the 380–780 nm covered by F2");
}
