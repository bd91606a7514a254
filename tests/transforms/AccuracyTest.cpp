// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "spectral/Illuminants.h"
#include "transforms/Accuracy.h"

using namespace bandlight;

namespace
{
const AccuracyRow& Row(const std::vector<AccuracyRow>& rows, const std::string& method,
                       const std::string& from, const std::string& set)
{
    for (const AccuracyRow& r : rows)
    {
        if (r.method == method && r.from == from && r.to == "D65" && r.set == set)
        {
            return r;
        }
    }
    FAIL("no row " << method << " " << from << " " << set);
    return rows.front();
}
}  // namespace

TEST_CASE("On the held-out colours the best method beats Bradford and band3",
          "[transforms][accuracy]")
{
    AccuracyOptions o;
    for (const char* n : {"A", "F2", "F11", "D65"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.methods = AllMethodNames();
    o.methods.push_back("spectral");
    o.sets = {HeldOutTcs()};
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    CHECK(rows.size() == 12 * o.methods.size());
    for (const char* from : {"A", "F2", "F11"})
    {
        double best = 1e9;
        std::string bestMethod;
        for (const std::string& m : AllMethodNames())
        {
            const double e = Row(rows, m, from, HeldOutTcs().name).mean;
            if (e < best)
            {
                best = e;
                bestMethod = m;
            }
        }
        const double bradford = Row(rows, "bradford", from, HeldOutTcs().name).mean;
        const double band3 = Row(rows, "band3", from, HeldOutTcs().name).mean;
        INFO(from << " -> D65: best " << bestMethod << " " << best << ", bradford " << bradford
                  << ", band3 " << band3);
        CHECK(best < bradford);
        CHECK(best < band3);
        CHECK(Row(rows, "spectral", from, HeldOutTcs().name).max == 0.0);
        // Nothing at all is worse than a proper method.
        CHECK(Row(rows, "none", from, HeldOutTcs().name).mean > bradford);
    }
}

TEST_CASE("Accuracy rows carry mean <= p95 <= max and the worst sample", "[transforms][accuracy]")
{
    AccuracyOptions o;
    o.lights = {{"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}};
    o.methods = {"bradford", "band3"};
    o.sets = {AllTcs(), RandomSmoothSet(20, 5, "random20")};
    int calls = 0;
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o, [&](double) { ++calls; });
    CHECK(calls == 2);
    REQUIRE(rows.size() == 2 * 2 * 2);
    for (const AccuracyRow& r : rows)
    {
        CHECK(r.mean > 0.0);
        CHECK(r.mean <= r.max);
        CHECK(r.p95 <= r.max);
        CHECK_FALSE(r.worstSample.empty());
    }
    CHECK(Percentile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0.95) == 10.0);
    CHECK(Percentile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0.5) == 5.0);
    CHECK(Percentile({}, 0.5) == 0.0);
}
