// SPDX-License-Identifier: BSD-3-Clause
// `bandlight plot`: the band model's pictures — a spectrum and its band means as
// steps, for the matching functions, an illuminant or a test colour.
#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "jobs/Gnuplot.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

namespace bandlight::cli
{

namespace
{

struct PlotOptions
{
    bool cmf = false;
    std::string illuminant;
    std::string reflectance;
    std::string bands = "400,500,600,700";
    std::string observer;
    std::string out;
};

struct Curve
{
    std::string name;
    Spectrum spectrum;
    double scale = 1.0;  ///< applied to curve and steps alike
};

void RunPlot(const PlotOptions& o)
{
    const int chosen = int(o.cmf) + int(!o.illuminant.empty()) + int(!o.reflectance.empty());
    if (chosen != 1)
    {
        throw Exception("plot one of --cmf, --illuminant NAME|FILE or --reflectance NAME|FILE");
    }
    const BandSet bands = BandSet::Parse(o.bands);
    const Observer observer = ParseObserver(o.observer);
    std::vector<Curve> curves;
    std::string title, ylabel;
    if (o.cmf)
    {
        const MatchingFunctions& m = GetMatchingFunctions(observer);
        curves = {{"x̄", m.x}, {"ȳ", m.y}, {"z̄", m.z}};
        title =
            std::string(ObserverName(observer)) + " colour-matching functions and their band means";
        ylabel = "tristimulus value";
    }
    else if (!o.illuminant.empty())
    {
        CommandReporter reporter;
        const Light s = jobs::ResolveIlluminant(o.illuminant, reporter);
        curves = {{s.name, s.spectrum}};
        // The band model normalises illuminant band means to the largest band = 1.
        const std::vector<double> means = BandMeans(s.spectrum, bands);
        curves[0].scale = 1.0 / *std::max_element(means.begin(), means.end());
        title = "Illuminant " + s.name + " and its band means (largest band = 1)";
        ylabel = "relative spectral power";
    }
    else
    {
        CommandReporter reporter;
        for (const NamedSpectrum& s : jobs::ResolveReflectances(o.reflectance, reporter))
        {
            curves.push_back({s.name, s.spectrum});
        }
        title = "Remittance and its band means";
        ylabel = "remittance";
    }
    bands.validateRange(curves[0].spectrum.start(),
                        curves[0].spectrum.end() + curves[0].spectrum.step(), curves[0].name);

    std::ostringstream data, plot;
    // Names and titles come from files and file names: quoted so gnuplot
    // shows them and never evaluates them.
    plot << "set title " << jobs::GnuplotQuote(title)
         << "\nset xlabel 'wavelength (nm)'\nset ylabel " << jobs::GnuplotQuote(ylabel)
         << "\nset grid\nset key top right\nset xrange [360:830]\n";
    for (const Band& b : bands)
    {
        plot << "set arrow from " << b.minNm << ", graph 0 to " << b.minNm
             << ", graph 1 nohead dt 3 lc rgb '#888888'\n";
        plot << "set label " << jobs::GnuplotQuote(b.name) << " at " << 0.5 * (b.minNm + b.maxNm)
             << ", graph 0.97 center\n";
    }
    plot << "set arrow from " << bands.bands().back().maxNm << ", graph 0 to "
         << bands.bands().back().maxNm << ", graph 1 nohead dt 3 lc rgb '#888888'\n";
    const char* colours[] = {"#c0392b", "#27ae60", "#2a7ab0", "#8e44ad", "#d35400", "#16a085"};
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
        const char* colour = colours[c % 6];
        plot << (c ? ", \\\n     " : "") << "$bandlight_data index " << index
             << " using 1:2 with lines lw 2 lc rgb '" << colour << "' title "
             << jobs::GnuplotQuote(cv.name) << ", \\\n     $bandlight_data index " << index + 1
             << " using 1:2 with lines lw 3 dt 2 lc rgb '" << colour << "' title "
             << jobs::GnuplotQuote(cv.name + " band means");
        index += 2;
    }
    plot << "\n";
    jobs::RunGnuplot(plot.str(), data.str(), o.out);
    std::cout << "Wrote " << o.out << "\n";
}

}  // namespace

void AddPlotCommand(CLI::App& app)
{
    auto o = std::make_shared<PlotOptions>();
    CLI::App* cmd = app.add_subcommand(
        "plot",
        "Draw a spectrum with its band means as steps (matching functions, an illuminant "
        "or remittances)");
    cmd->add_flag("--cmf", o->cmf, "The colour-matching functions of --observer");
    cmd->add_option("--illuminant", o->illuminant, "An illuminant (name or spectrum file)");
    cmd->add_option("--reflectance", o->reflectance,
                    "Remittances (TCS01-TCS15, TCS, or a spectrum file)");
    cmd->add_option("--bands", o->bands, "Band edges in nm")->capture_default_str();
    AddObserverOption(*cmd, o->observer);
    cmd->add_option("-o,--out", o->out, "Output FILE.png or FILE.svg")->required();
    cmd->callback([o] { RunPlot(*o); });
}

}  // namespace bandlight::cli
