// SPDX-License-Identifier: BSD-3-Clause
#include "report/detail/PlotLabels.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bandlight::detail
{

bool Overlap(const LabelBox& a, const LabelBox& b) noexcept
{
    return a.left < b.right() && b.left < a.right() && a.bottom < b.top() && b.bottom < a.top();
}

namespace
{
double OverlapArea(const LabelBox& a, const LabelBox& b) noexcept
{
    const double w = std::min(a.right(), b.right()) - std::max(a.left, b.left);
    const double h = std::min(a.top(), b.top()) - std::max(a.bottom, b.bottom);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
}
}  // namespace

std::vector<LabelBox> PlaceLabels(const std::vector<LabelRequest>& labels,
                                  const std::vector<std::pair<double, double>>& obstacles,
                                  double markerWidth, double markerHeight)
{
    std::vector<LabelBox> markers;
    const auto marker = [&](double x, double y) {
        markers.push_back({x - markerWidth / 2, y - markerHeight / 2, markerWidth, markerHeight});
    };
    for (const auto& [x, y] : obstacles)
    {
        marker(x, y);
    }
    for (const LabelRequest& l : labels)
    {
        marker(l.x, l.y);
    }
    std::vector<size_t> order(labels.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) {
                         return labels[a].y < labels[b].y ||
                                (labels[a].y == labels[b].y && labels[a].x < labels[b].x);
                     });
    std::vector<LabelBox> out(labels.size());
    std::vector<LabelBox> placed;
    const double gap = markerWidth * 0.75;
    for (const size_t i : order)
    {
        const LabelRequest& l = labels[i];
        LabelBox best;
        double bestCover = -1.0;
        bool found = false;
        for (int step = 0; step <= 80 && !found; ++step)
        {
            // 0, +1, -1, +2, -2, ... lines away from the point.
            const int lines = step % 2 ? (step + 1) / 2 : -(step / 2);
            for (int side = 0; side < 2 && !found; ++side)
            {
                LabelBox b;
                b.width = l.width;
                b.height = l.height;
                b.left = side == 0 ? l.x + gap : l.x - gap - l.width;
                b.bottom = l.y - l.height / 2 + lines * l.height;
                if (b.left < 0.0 || b.right() > 1.0 || b.bottom < 0.0 || b.top() > 1.0)
                {
                    continue;
                }
                double cover = 0.0;
                for (const LabelBox& p : placed)
                {
                    cover += OverlapArea(b, p);
                }
                for (const LabelBox& m : markers)
                {
                    cover += OverlapArea(b, m);
                }
                // Only labels must never overlap: keep the least-covering
                // candidate that is clear of every label as the fallback.
                const bool clearOfLabels = std::none_of(
                    placed.begin(), placed.end(), [&](const LabelBox& p) { return Overlap(b, p); });
                if (cover == 0.0)
                {
                    best = b;
                    found = true;
                }
                else if (clearOfLabels && (bestCover < 0.0 || cover < bestCover))
                {
                    best = b;
                    bestCover = cover;
                }
            }
        }
        if (!found && bestCover < 0.0)
        {
            // No place inside the plot clear of other labels: stack it above them all.
            double top = l.y;
            for (const LabelBox& p : placed)
            {
                top = std::max(top, p.top());
            }
            best = {l.x + gap, top, l.width, l.height};
        }
        out[i] = best;
        placed.push_back(best);
    }
    return out;
}

double PlotLayout::toX(double f) const
{
    return std::exp(std::log(xMin) + f * (std::log(xMax) - std::log(xMin)));
}

double PlotLayout::toY(double f) const
{
    return f * yMax;
}

PlotLayout LayOutAccuracyPlot(const std::vector<PlotPoint>& pts, size_t anchor)
{
    PlotLayout l;
    double xMin = 1e30, xMax = 0.0, yMax = 0.0;
    for (const PlotPoint& p : pts)
    {
        xMin = std::min(xMin, p.ns);
        xMax = std::max(xMax, p.ns);
        for (const double d : p.de)
        {
            yMax = std::max(yMax, d);
        }
    }
    if (pts.empty())
    {
        xMin = 1.0;
        xMax = 10.0;
    }
    // Room left of the cheapest point and for labels right of the dearest.
    l.xMin = xMin / 1.6;
    l.xMax = xMax * 3.0;
    l.yMax = std::max(yMax, 0.1) * 1.1;
    const double charW = 7.0 / kPlotAreaWidthPx, lineH = 15.0 / kPlotAreaHeightPx;
    const auto fx = [&](double ns)
    { return (std::log(ns) - std::log(l.xMin)) / (std::log(l.xMax) - std::log(l.xMin)); };
    std::vector<std::pair<double, double>> obstacles;
    for (const PlotPoint& p : pts)
    {
        const double y = anchor < p.de.size() ? p.de[anchor] : 0.0;
        l.requests.push_back({fx(p.ns), y / l.yMax, charW * (double(p.name.size()) + 0.5), lineH});
        for (size_t s = 0; s < p.de.size(); ++s)
        {
            if (s != anchor)
            {
                obstacles.push_back({fx(p.ns), p.de[s] / l.yMax});
            }
        }
    }
    l.boxes = PlaceLabels(l.requests, obstacles, 12.0 / kPlotAreaWidthPx, 12.0 / kPlotAreaHeightPx);
    return l;
}

}  // namespace bandlight::detail
