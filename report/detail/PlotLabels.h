// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Where a plot's point labels go so that none overlaps another (not installed).

#include <string>
#include <vector>

namespace bandlight::detail
{

/// A rectangle in the plot area's own coordinates: 0 … 1 left to right and
/// bottom to top.
struct LabelBox
{
    double left = 0.0, bottom = 0.0, width = 0.0, height = 0.0;
    double right() const noexcept { return left + width; }
    double top() const noexcept { return bottom + height; }
};

/// True when the boxes share any area (touching edges do not count).
bool Overlap(const LabelBox& a, const LabelBox& b) noexcept;

/// A point to label, in plot-area coordinates, with its label's size.
struct LabelRequest
{
    double x = 0.0, y = 0.0;
    double width = 0.0, height = 0.0;
};

/// One box per request, in the requests' order. Deterministic: the labels
/// are placed in order of their points (bottom to top, then left to right),
/// each at the first free candidate — right of its point, left of it, then
/// a line higher or lower at a time (up first), right before left — where
/// "free" means inside the plot area and clear of every box placed before
/// and of every point (`obstacles`, markers drawn markerWidth × markerHeight,
/// as well as the labelled points). No two boxes returned overlap; a label that
/// finds no free place within 40 lines of its point keeps the one least
/// covered (never expected at the sizes the accuracy plot uses).
std::vector<LabelBox> PlaceLabels(const std::vector<LabelRequest>& labels,
                                  const std::vector<std::pair<double, double>>& obstacles,
                                  double markerWidth, double markerHeight);

/// The accuracy plot's frame: a 1000 × 650 terminal (report/Gnuplot) whose
/// plot area is fixed at these fractions of the screen, and the label
/// font (',10'): about 7 px a character and 15 px a line.
constexpr double kPlotLeft = 0.08, kPlotRight = 0.76, kPlotBottom = 0.11, kPlotTop = 0.90;
constexpr double kPlotAreaWidthPx = 1000.0 * (kPlotRight - kPlotLeft);
constexpr double kPlotAreaHeightPx = 650.0 * (kPlotTop - kPlotBottom);

/// One method on the accuracy plot: its cost (ns a pixel, > 0) and its
/// error on each reflectance set.
struct PlotPoint
{
    std::string name;
    double ns = 1.0;
    std::vector<double> de;
};

/// The accuracy plot's axes (log x) and its labels: one per point, beside
/// its error on set `anchor`, every other set's marker an obstacle.
struct PlotLayout
{
    double xMin = 1.0, xMax = 10.0, yMax = 1.0;
    std::vector<LabelRequest> requests;  ///< in plot-area coordinates
    std::vector<LabelBox> boxes;
    double toX(double fraction) const;  ///< plot-area x → ns
    double toY(double fraction) const;  ///< plot-area y → ΔE00
};
PlotLayout LayOutAccuracyPlot(const std::vector<PlotPoint>& points, size_t anchor);

}  // namespace bandlight::detail
