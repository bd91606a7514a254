// SPDX-License-Identifier: BSD-3-Clause
// Covers, through the entry points it calls: transforms/AccuracyFitted.cpp,
// transforms/AccuracyScoring.cpp.
#include <catch2/catch.hpp>

#include "spectral/Illuminants.h"
#include "transforms/Accuracy.h"

#include <memory>

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
    o.plates = {Plates::Lit()};  // lit: the counts below are for one convention
    for (const char* n : {"A", "F2", "F11", "D65"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.methods = AllMethodNames();
    o.methods.push_back("spectral");
    o.sets = {HeldOutTcs()};
    o.exposures = {1.0};
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
    o.plates = {Plates::Lit()};  // lit: the counts below are for one convention
    o.lights = {{"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}};
    o.methods = {"bradford", "band3"};
    o.sets = {AllTcs(), RandomSmoothSet(20, 5, "random20")};
    o.exposures = {1.0};
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

TEST_CASE("The exposure sweep: invariant methods score alike at every level, shipped rows too",
          "[transforms][accuracy]")
{
    AccuracyOptions o;
    o.plates = {Plates::Lit()};  // lit: the counts below are for one convention
    o.lights = {{"F11", BuiltinIlluminant("F11")}, {"D65", BuiltinIlluminant("D65")}};
    o.methods = {"bradford", "rootpoly", "upsample"};
    o.sets = {HeldOutTcs()};
    // A stand-in for the OCIO processor: the ideal form, rounded to float.
    o.shipped = [&](const Light& from, const Light& to, const MethodSpec& m) -> PixelBatch
    {
        auto r = std::make_shared<Relighter>(from, to, m, FindRgbSpace(o.workingSpace));
        return [r](float* rgb, size_t n) { r->apply(rgb, n, 1); };
    };
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    REQUIRE(rows.size() == 2 * 3 * 7 * 2);  // pairs, methods, exposures, forms
    for (const std::string& m : o.methods)
    {
        for (const bool shipped : {false, true})
        {
            double at1 = -1.0;
            for (const AccuracyRow& r : rows)
            {
                if (r.method == m && r.shipped == shipped && r.from == "F11" && r.exposure == 1.0)
                {
                    at1 = r.mean;
                }
            }
            REQUIRE(at1 > 0.0);
            for (const AccuracyRow& r : rows)
            {
                if (r.method == m && r.shipped == shipped && r.from == "F11")
                {
                    INFO(m << (shipped ? " shipped" : " ideal") << " at " << r.exposure);
                    CHECK(r.mean == Approx(at1).margin(1e-3));
                }
            }
        }
    }
}

TEST_CASE("Cross-validation and the floor", "[transforms][accuracy]")
{
    AccuracyOptions o;
    o.plates = {Plates::Lit()};  // lit: the counts below are for one convention
    o.lights = {{"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}};
    o.methods = {"bradford", "fit3x3", "rootpoly"};
    o.sets = {HeldOutTcs(), RandomSmoothSet(30, 9, "random30")};
    const std::vector<AccuracyRow> cv = CrossValidate(o, 5);
    REQUIRE(cv.size() == 2 * 2 * 2);  // pairs, fitted methods, in-sample and 5-fold
    for (size_t i = 0; i + 1 < cv.size(); i += 2)
    {
        INFO(cv[i].method << " " << cv[i].from << ": in-sample " << cv[i].mean << ", 5-fold "
                          << cv[i + 1].mean);
        CHECK(cv[i].set == "training, in-sample");
        CHECK(cv[i + 1].set == "training, 5-fold");
        // Held-out folds cannot be fitted better than the data they were cut from.
        CHECK(cv[i + 1].mean >= cv[i].mean * 0.98);
    }
    // The floor is fitted on the set itself: no fitted method beats it there.
    o.exposures = {1.0};
    const std::vector<AccuracyRow> rows = MeasureAccuracy(o);
    const std::vector<AccuracyRow> floor = MeasureFloor(o);
    REQUIRE(floor.size() == 2 * 2 * 2);
    for (const AccuracyRow& f : floor)
    {
        for (const AccuracyRow& r : rows)
        {
            if (r.from == f.from && r.set == f.set && r.method == "fit3x3" &&
                f.method == "floor-3x3")
            {
                INFO(f.set << " " << f.from << ": floor " << f.mean << ", fit3x3 " << r.mean);
                CHECK(f.mean <= r.mean + 1e-9);
            }
        }
    }
}
