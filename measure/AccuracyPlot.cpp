// SPDX-License-Identifier: BSD-3-Clause
// The accuracy-against-cost plot (gnuplot), and the cost on every thread.
#include "measure/AccuracyRun.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "measure/detail/AccuracySummary.h"
#include "report/Gnuplot.h"
#include "report/detail/PlotLabels.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

using namespace detail;

namespace
{

/// A method's native cost (the map itself, no LUT) on all threads, or on
/// one when that is all the cost rows hold; 0 when it has none.
double NativeCost(const std::vector<CostRow>& cost, const std::string& method)
{
    double ns = 0.0;
    int threads = 0;
    for (const CostRow& c : cost)
    {
        if (c.method == method && c.form == CostForm::NATIVE && c.threads > threads)
        {
            ns = c.nsPerPixel;
            threads = c.threads;
        }
    }
    return ns;
}

/// One point of the accuracy-against-cost plot: a method's cost and its
/// mean ΔE00 on each set.
struct CostPoint
{
    std::string name;
    double ns;
    std::vector<double> de;  ///< one per set
};

/// Every method with a cost (the camera methods have none on the observer's
/// plates) as shipped, at its worst exposure, and beside it its native map
/// when it has one; by cost, then error.
std::vector<CostPoint> PlotPoints(const AccuracyResult& result)
{
    const AccuracyOptions& options = result.options;
    const std::string key = options.plates.front().key();
    const bool anyShipped = bool(options.shipped);
    std::vector<CostPoint> pts;
    for (const std::string& m : options.methods)
    {
        if (FindMethod(m).needsCamera || !result.costAllThreads.count(m))
        {
            continue;
        }
        CostPoint p{m, std::max(result.costAllThreads.at(m), 1e-3), {}};
        const double native = NativeCost(result.cost, m);
        CostPoint n{m + " (native)", std::max(native, 1e-3), {}};
        for (const ReflectanceSet& set : options.sets)
        {
            const Filter shippedF{1.0, anyShipped && !FindMethod(m).isReference(), key,
                                  PlateSource::CIE};
            p.de.push_back(
                WorstExposure(result.rows, m, set.name, shippedF, options.exposures).second);
            // The native map is the ideal form itself.
            const Filter idealF{1.0, false, key, PlateSource::CIE};
            n.de.push_back(
                WorstExposure(result.rows, m, set.name, idealF, options.exposures).second);
        }
        pts.push_back(p);
        if (native > 0.0)
        {
            pts.push_back(n);
        }
    }
    std::sort(pts.begin(), pts.end(),
              [](const CostPoint& a, const CostPoint& b)
              { return a.ns < b.ns || (a.ns == b.ns && a.de < b.de); });
    return pts;
}

/// The set the labels and the Pareto front follow: the held-out set, or
/// the first.
size_t AnchorSet(const std::vector<ReflectanceSet>& sets)
{
    size_t anchor = 0;
    for (size_t s = 0; s < sets.size(); ++s)
    {
        anchor = sets[s].name == HeldOutTcs().name ? s : anchor;
    }
    return anchor;
}

/// The plot's datablock: index s holds set s's points; then the labels,
/// the leader lines and the Pareto front.
std::string PlotData(const std::vector<CostPoint>& pts, size_t sets, const PlotLayout& layout,
                     size_t anchor)
{
    std::ostringstream data;
    data.precision(9);
    for (size_t s = 0; s < sets; ++s)
    {
        for (const CostPoint& p : pts)
        {
            data << p.ns << " " << p.de[s] << "\n";
        }
        data << "\n\n";
    }
    // The labels (x, y, text) at their boxes' left middles.
    for (size_t i = 0; i < pts.size(); ++i)
    {
        const LabelBox& b = layout.boxes[i];
        data << layout.toX(b.left) << " " << (b.bottom + b.height / 2) * layout.yMax << " "
             << GnuplotDataLabel(pts[i].name) << "\n";
    }
    data << "\n\n";
    // A leader line from each moved label's point to its box.
    bool anyLeader = false;
    for (size_t i = 0; i < pts.size(); ++i)
    {
        const LabelRequest& r = layout.requests[i];
        const LabelBox& b = layout.boxes[i];
        if (r.y >= b.bottom && r.y <= b.top())
        {
            continue;
        }
        anyLeader = true;
        const double edge = b.left >= r.x ? b.left : b.right();
        data << pts[i].ns << " " << r.y * layout.yMax << "\n"
             << layout.toX(edge) << " " << (b.bottom + b.height / 2) * layout.yMax << "\n\n";
    }
    if (!anyLeader)
    {
        data << layout.xMax << " " << 0.0 << "\n";  // an empty index would stop gnuplot
    }
    data << "\n\n";
    // The Pareto front of the anchor set.
    double best = 1e30;
    for (const CostPoint& p : pts)
    {
        if (!p.de.empty() && p.de[anchor] < best)
        {
            best = p.de[anchor];
            data << p.ns << " " << best << "\n";
        }
    }
    return data.str();
}

/// The gnuplot script that draws PlotData's indices.
std::string PlotScript(const std::vector<ReflectanceSet>& sets, const PlotLayout& layout,
                       size_t anchor)
{
    const size_t labels = sets.size(), leaders = labels + 1, front = labels + 2;
    std::ostringstream script;
    script.precision(9);
    script << "set title "
           << GnuplotQuote(
                  "What accuracy costs: each set re-lit as shipped, at its worst exposure "
                  "(2^-8 ... 2^4), mean over the pairs")
           << "\n"
              "set xlabel 'cost, ns per pixel (all threads, log scale)'\n"
              "set ylabel 'mean CIEDE2000 against the spectral answer'\n"
              "set logscale x\nset grid\n"
              "set key outside right top\n"
           << "set lmargin at screen " << kPlotLeft << "\nset rmargin at screen " << kPlotRight
           << "\nset bmargin at screen " << kPlotBottom << "\nset tmargin at screen " << kPlotTop
           << "\nset xrange [" << layout.xMin << ":" << layout.xMax
           << "]\nset yrange [0:" << layout.yMax << "]\n"
           << "plot $bandlight_data index " << front
           << " using 1:2 with lines lw 2 lc rgb '#2a7ab0' title "
           << GnuplotQuote("Pareto front, " + (sets.empty() ? std::string() : sets[anchor].name))
           << ", \\\n     $bandlight_data index " << leaders
           << " using 1:2 with lines lw 1 lc rgb '#888888' notitle";
    const char* colours[] = {"#c0392b", "#27ae60", "#8e44ad", "#d35400", "#16a085", "#2c3e50"};
    for (size_t s = 0; s < sets.size(); ++s)
    {
        script << ", \\\n     $bandlight_data index " << s << " using 1:2 with points pt "
               << (5 + 2 * int(s % 4)) << " ps 1.3 lc rgb '" << colours[s % 6] << "' title "
               << GnuplotQuote(sets[s].name);
    }
    script << ", \\\n     $bandlight_data index " << labels
           << " using 1:2:3 with labels left font ',10' notitle\n";
    return script.str();
}

}  // namespace

void PlotAccuracy(const std::string& path, const AccuracyResult& result, OutputSet& outputs)
{
    const std::vector<ReflectanceSet>& sets = result.options.sets;
    const std::vector<CostPoint> pts = PlotPoints(result);
    const size_t anchor = AnchorSet(sets);
    std::vector<PlotPoint> plotted;
    for (const CostPoint& p : pts)
    {
        plotted.push_back({p.name, p.ns, p.de});
    }
    const PlotLayout layout = LayOutAccuracyPlot(plotted, anchor);
    RunGnuplot(PlotScript(sets, layout, anchor), PlotData(pts, sets.size(), layout, anchor), path,
               &outputs);
}

std::map<std::string, double> CostAllThreads(const std::vector<CostRow>& cost)
{
    std::map<std::string, double> costAll;
    std::vector<double> matrixCosts;
    const int allThreads = CoreCount();
    for (const CostRow& c : cost)
    {
        if (c.threads == allThreads && c.form != CostForm::DIRECT_FIT && c.form != CostForm::NATIVE)
        {
            costAll[c.method] = c.nsPerPixel;
            if (c.form == CostForm::OCIO_MATRIX)
            {
                matrixCosts.push_back(c.nsPerPixel);
            }
        }
    }
    for (auto& [method, ns] : costAll)
    {
        if (ParseMethod(method).isLinear() && !matrixCosts.empty())
        {
            ns = Percentile(matrixCosts, 0.5);
        }
    }
    return costAll;
}

}  // namespace bandlight::jobs
