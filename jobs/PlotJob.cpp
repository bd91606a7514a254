// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/PlotJob.h"

#include <algorithm>
#include <sstream>

#include "requests/Inputs.h"
#include "report/Gnuplot.h"
#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

namespace bandlight::jobs
{

namespace
{

struct Curve
{
    std::string name;
    Spectrum spectrum;
    double scale = 1.0;  ///< applied to curve and steps alike
};

/// The gnuplot script and its data: each curve as a line and its band
/// means as thick translucent steps of the same colour over the whole band,
/// the band edges dotted. One legend entry per curve, outside the plot when
/// there are many, in colours that do not repeat for 16 curves.
void DrawCurves(const std::vector<Curve>& curves, const BandSet& bands, const std::string& title,
                const std::string& ylabel, const std::string& out)
{
    std::ostringstream data, plot;
    const bool many = curves.size() > 4;
    // Names and titles come from files and file names: quoted so gnuplot
    // shows them and never evaluates them.
    plot << "set title " << GnuplotQuote(title + " (thick, translucent: band means)")
         << "\nset xlabel 'wavelength (nm)'\nset ylabel " << GnuplotQuote(ylabel)
         << "\nset grid\nset xrange [360:830]\n"
         << (many ? "set key outside right top vertical spacing 0.9\n" : "set key top right\n");
    for (const Band& b : bands)
    {
        plot << "set arrow from " << b.minNm << ", graph 0 to " << b.minNm
             << ", graph 1 nohead dt 3 lc rgb '#888888'\n";
        plot << "set label " << GnuplotQuote(b.name) << " at " << 0.5 * (b.minNm + b.maxNm)
             << ", graph 0.97 center\n";
    }
    plot << "set arrow from " << bands.bands().back().maxNm << ", graph 0 to "
         << bands.bands().back().maxNm << ", graph 1 nohead dt 3 lc rgb '#888888'\n";
    // 16 colours told apart on screen and in print (Tableau 10 and six more).
    static const char* colours[] = {"c0392b", "1f77b4", "2ca02c", "ff7f0e", "9467bd", "8c564b",
                                    "e377c2", "7f7f7f", "bcbd22", "17becf", "000080", "808000",
                                    "008080", "800000", "ff1493", "00bfff"};
    constexpr size_t kColours = sizeof colours / sizeof colours[0];
    plot << "plot ";
    int index = 0;
    for (size_t c = 0; c < curves.size(); ++c)
    {
        const Curve& cv = curves[c];
        for (size_t i = 0; i < cv.spectrum.size(); ++i)
        {
            data << cv.spectrum.wavelength(i) << " " << cv.spectrum[i] * cv.scale << "\n";
        }
        data << "\n\n";
        const std::vector<double> means = BandMeans(cv.spectrum, bands);
        for (size_t b = 0; b < bands.size(); ++b)
        {
            data << bands[b].minNm << " " << means[b] * cv.scale << "\n"
                 << bands[b].maxNm << " " << means[b] * cv.scale << "\n\n";
        }
        data << "\n";
        const std::string colour = colours[c % kColours];
        // Solid, so that each step runs from edge to edge (a dash pattern
        // ended in a gap short of the band's edge); '#AARRGGBB', 0x90 alpha.
        plot << (c ? ", \\\n     " : "") << "$bandlight_data index " << index
             << " using 1:2 with lines lw 2 lc rgb '#" << colour << "' title "
             << GnuplotQuote(cv.name) << ", \\\n     $bandlight_data index " << index + 1
             << " using 1:2 with lines lw 6 lc rgb '#90" << colour << "' notitle";
        index += 2;
    }
    plot << "\n";
    RunGnuplot(plot.str(), data.str(), out);
}

}  // namespace

PlotResult MakePlot(const PlotRequest& r, Reporter& reporter)
{
    const int chosen = int(r.cmf) + int(!r.illuminant.empty()) + int(!r.reflectance.empty());
    if (chosen != 1)
    {
        throw ParameterError(
            "plot one of {cmf}, {illuminant} NAME|FILE or {reflectance} NAME|FILE");
    }
    const BandSet bands = BandSet::Parse(r.bands);
    const Observer observer = ParseObserver(r.observer);
    std::vector<Curve> curves;
    std::string ylabel;
    PlotResult result;
    result.out = r.out;
    if (r.cmf)
    {
        const MatchingFunctions& m = GetMatchingFunctions(observer);
        curves = {{"x̄", m.x}, {"ȳ", m.y}, {"z̄", m.z}};
        result.title =
            std::string(ObserverName(observer)) + " colour-matching functions and their band means";
        ylabel = "tristimulus value";
    }
    else if (!r.illuminant.empty())
    {
        const Light s = ResolveIlluminant(r.illuminant, reporter);
        curves = {{s.name, s.spectrum}};
        // The band model normalises illuminant band means to the largest band = 1
        // (docs/science.md §1.2).
        const std::vector<double> means = BandMeans(s.spectrum, bands);
        curves[0].scale = 1.0 / *std::max_element(means.begin(), means.end());
        result.title = "Illuminant " + s.name + " and its band means (largest band = 1)";
        ylabel = "relative spectral power";
    }
    else
    {
        for (const NamedSpectrum& s : ResolveReflectances(r.reflectance, reporter))
        {
            curves.push_back({s.name, s.spectrum});
        }
        result.title = "Remittance and its band means";
        ylabel = "remittance";
    }
    bands.validateRange(curves[0].spectrum.start(),
                        curves[0].spectrum.end() + curves[0].spectrum.step(), curves[0].name);
    DrawCurves(curves, bands, result.title, ylabel, r.out);
    for (const Curve& c : curves)
    {
        result.curves.push_back(c.name);
    }
    return result;
}

}  // namespace bandlight::jobs
