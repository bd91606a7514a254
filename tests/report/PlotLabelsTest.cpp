// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "report/detail/PlotLabels.h"

using namespace bandlight::detail;

namespace
{
/// The default report's points (docs/accuracy.txt: balanced-cat02 plates,
/// shipped, worst exposure, sets tcs, tcs09-15, random; all-thread costs,
/// every 3×3 at their median, native root polynomials at 2 threads).
std::vector<PlotPoint> ReportPoints()
{
    return {
        {"none", 1.8, {2.82, 3.34, 2.25}},
        {"vonkries", 1.8, {3.25, 3.73, 2.79}},
        {"bradford", 1.8, {2.82, 3.33, 2.31}},
        {"cat02", 1.8, {2.82, 3.34, 2.25}},
        {"band3", 1.8, {8.31, 7.79, 10.74}},
        {"band3-wp", 1.8, {3.45, 4.01, 2.90}},
        {"band6", 1.8, {4.79, 5.27, 5.75}},
        {"band6-wp", 1.8, {3.25, 4.03, 2.44}},
        {"fit3x3", 1.8, {1.51, 2.28, 0.74}},
        {"prefilter", 1.8, {2.64, 3.11, 2.22}},
        {"metamer", 1.8, {1.47, 2.06, 0.95}},
        {"rootpoly (native)", 5.32, {0.90, 1.27, 0.80}},
        {"upsample", 33.0, {1.32, 1.69, 0.77}},
        {"rootpoly", 33.0, {0.92, 1.29, 0.82}},
        {"rootpoly3", 32.0, {0.77, 1.06, 1.05}},
        {"spectral", 36.0, {0.0, 0.0, 0.0}},
        {"rootpoly3 (native)", 171.48, {0.76, 1.04, 1.00}},
    };
}

void CheckLayout(const PlotLayout& l, size_t markers)
{
    REQUIRE(l.boxes.size() == l.requests.size());
    for (size_t i = 0; i < l.boxes.size(); ++i)
    {
        const LabelBox& b = l.boxes[i];
        CHECK(b.left >= 0.0);
        CHECK(b.right() <= 1.0);
        CHECK(b.bottom >= 0.0);
        CHECK(b.top() <= 1.0);
        for (size_t j = i + 1; j < l.boxes.size(); ++j)
        {
            INFO("labels " << i << " and " << j);
            CHECK_FALSE(Overlap(b, l.boxes[j]));
        }
    }
    CHECK(markers == l.requests.size());
}
}  // namespace

TEST_CASE("Overlap counts shared area only", "[jobs]")
{
    CHECK(Overlap({0, 0, 1, 1}, {0.5, 0.5, 1, 1}));
    CHECK_FALSE(Overlap({0, 0, 1, 1}, {1, 0, 1, 1}));  // touching edges
    CHECK_FALSE(Overlap({0, 0, 1, 1}, {0, 2, 1, 1}));
}

TEST_CASE("The accuracy plot's labels never overlap", "[jobs]")
{
    const std::vector<PlotPoint> pts = ReportPoints();
    for (size_t anchor = 0; anchor < 3; ++anchor)
    {
        INFO("labels beside set " << anchor);
        const PlotLayout l = LayOutAccuracyPlot(pts, anchor);
        CheckLayout(l, pts.size());
        // Eleven 3×3s share one cost: their labels stack beside that column.
        size_t moved = 0;
        for (size_t i = 0; i < l.boxes.size(); ++i)
        {
            const bool onLine =
                l.requests[i].y >= l.boxes[i].bottom && l.requests[i].y <= l.boxes[i].top();
            moved += onLine ? 0 : 1;
        }
        CHECK(moved > 0);
        // The 4-illuminant run's points, where native rootpoly sits apart.
        const PlotLayout few = LayOutAccuracyPlot({{"bradford", 1.8, {3.1, 3.4, 2.3}},
                                                   {"rootpoly (native)", 4.1, {1.1, 1.3, 0.8}},
                                                   {"upsample", 33.0, {1.5, 1.7, 0.8}},
                                                   {"rootpoly", 33.0, {1.1, 1.3, 0.8}},
                                                   {"spectral", 36.0, {0, 0, 0}}},
                                                  anchor);
        CheckLayout(few, 5);
    }
}

TEST_CASE("Labels of points at one place are placed alike every time", "[jobs]")
{
    std::vector<LabelRequest> same(6, LabelRequest{0.5, 0.5, 0.2, 0.05});
    const std::vector<LabelBox> a = PlaceLabels(same, {}, 0.02, 0.02);
    const std::vector<LabelBox> b = PlaceLabels(same, {}, 0.02, 0.02);
    for (size_t i = 0; i < a.size(); ++i)
    {
        CHECK(a[i].left == b[i].left);
        CHECK(a[i].bottom == b[i].bottom);
        for (size_t j = i + 1; j < a.size(); ++j)
        {
            CHECK_FALSE(Overlap(a[i], a[j]));
        }
    }
}
