// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "spectral/Statistics.h"

using namespace bandlight;

// The nearest-rank method's worked example (Wikipedia, "Percentile",
// section "The nearest-rank method", first example): of {15, 20, 35, 40, 50}
// the 5th percentile is 15, the 30th and 40th are 20, the 50th is 35, the
// 100th is 50.
TEST_CASE("Percentiles follow the nearest-rank rule", "[spectral]")
{
    const std::vector<double> v{50, 15, 40, 20, 35};
    CHECK(Percentile(v, 0.05) == 15);
    CHECK(Percentile(v, 0.30) == 20);
    CHECK(Percentile(v, 0.40) == 20);
    CHECK(Percentile(v, 0.50) == 35);
    CHECK(Percentile(v, 0.95) == 50);
    CHECK(Percentile(v, 1.00) == 50);
    CHECK(Percentile(v, 0.0) == 15);
    CHECK(Percentile({}, 0.5) == 0.0);
}

TEST_CASE("Summarise gives count, mean, median, p95 and max of one sample", "[spectral]")
{
    // 1 … 100: mean 50.5; nearest rank: median the 50th value, p95 the 95th.
    std::vector<double> v;
    for (int i = 100; i >= 1; --i)
    {
        v.push_back(i);
    }
    const Statistics s = Summarise(v);
    CHECK(s.count == 100);
    CHECK(s.mean == 50.5);
    CHECK(s.median == 50);
    CHECK(s.p95 == 95);
    CHECK(s.max == 100);
    // 19 values: p95 is the ⌈18.05⌉ = 19th, the largest; floor(0.95 n) would
    // have given the 18th.
    v.assign(19, 1.0);
    v.back() = 7.0;
    CHECK(Summarise(v).p95 == 7.0);
    const Statistics none = Summarise({});
    CHECK(none.count == 0);
    CHECK(none.mean == 0.0);
    CHECK(none.max == 0.0);
}
