// SPDX-License-Identifier: BSD-3-Clause
#include "report/LightQualityPlot.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "report/Gnuplot.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

/// The colour of hue bin `j` (of 16, bin 1 centred on 11.25°): a hue
/// circle at the bin's angle, as TM-30's graphic colours its bins.
std::string BinColour(size_t j)
{
    const double h = (double(j) + 0.5) / 16.0 * 6.0;  // 0..6 around the hue circle
    const double s = 0.75, v = 0.8;
    const double c = v * s, x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0)), m = v - c;
    double r = 0, g = 0, b = 0;
    switch (int(h))
    {
        case 0:
            r = c, g = x;
            break;
        case 1:
            r = x, g = c;
            break;
        case 2:
            g = c, b = x;
            break;
        case 3:
            g = x, b = c;
            break;
        case 4:
            r = x, b = c;
            break;
        default:
            r = c, b = x;
            break;
    }
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02x%02x%02x", int(255 * (r + m)), int(255 * (g + m)),
                  int(255 * (b + m)));
    return buf;
}

/// The normalised test point of bin j: the reference's mean at radius 1 on
/// its own angle, the test's offset from it divided by the reference's
/// radius (TM-30-20, the colour vector graphic).
std::array<double, 2> NormalisedTest(const QualityPlotRow& r, size_t j)
{
    const auto& ref = r.referenceAb[j];
    const auto& test = r.testAb[j];
    const double radius = std::max(std::hypot(ref[0], ref[1]), 1e-12);
    const double angle = std::atan2(ref[1], ref[0]);
    return {std::cos(angle) + (test[0] - ref[0]) / radius,
            std::sin(angle) + (test[1] - ref[1]) / radius};
}

}  // namespace

void DrawQualityPlot(const std::vector<QualityPlotRow>& rows, const std::string& output)
{
    if (rows.size() > QUALITY_PLOT_MAX_LIGHTS)
    {
        throw ParameterError("--plot draws " + std::to_string(QUALITY_PLOT_MAX_LIGHTS) +
                             " lights at most (a row each), not " + std::to_string(rows.size()) +
                             ": plot fewer, or use --json/--csv for the scores of many");
    }
    std::ostringstream data, plot;
    data.precision(8);
    plot << "set multiplot layout " << rows.size() << ",2\n";
    int index = 0;
    for (const QualityPlotRow& r : rows)
    {
        // Left: the spectra, each normalised to its peak in 380–780 nm.
        const auto peak = [](const Spectrum& s)
        {
            double p = 0.0;
            for (size_t i = 0; i < s.size(); ++i)
            {
                if (s.wavelength(i) >= 380.0 && s.wavelength(i) <= 780.0)
                {
                    p = std::max(p, s[i]);
                }
            }
            return p > 0.0 ? p : 1.0;
        };
        const double lightPeak = peak(r.spectrum);
        for (size_t i = 0; i < r.spectrum.size(); ++i)
        {
            data << r.spectrum.wavelength(i) << " " << r.spectrum[i] / lightPeak << "\n";
        }
        data << "\n\n";
        plot << "set title " << GnuplotQuote(r.note.empty() ? r.light : r.light + " (reference: " + r.note + ")")
             << "\nset size noratio\nunset arrow\nset xlabel 'wavelength (nm)'\n"
                "set ylabel 'relative power'\nset xrange [380:780]\nset yrange [0:*]\n"
                "set grid\nset offsets 0, 0, graph 0.4, 0\nset key top right opaque box\nplot $bandlight_data index "
             << index++ << " using 1:2 with lines lw 2 lc rgb '#202020' title "
             << GnuplotQuote(r.light);
        for (const auto& [name, s] : r.references)
        {
            // On the light's scale: the caller matched their luminance.
            for (size_t i = 0; i < s.size(); ++i)
            {
                data << s.wavelength(i) << " " << s[i] / lightPeak << "\n";
            }
            data << "\n\n";
            plot << ", $bandlight_data index " << index++
                 << " using 1:2 with lines lw 2 dt 2 title " << GnuplotQuote(name);
        }
        plot << "\n";

        // Right: the colour vector graphic.
        plot << "set title "
             << GnuplotQuote(r.vectors ? "TM-30 colour vector graphic (Rf " +
                                             std::to_string(std::lround(r.rf)) + ", Rg " +
                                             std::to_string(std::lround(r.rg)) + ")"
                                       : "TM-30: no value for this light")
             << "\nset size ratio -1\nset xrange [-1.6:1.6]\nset yrange [-1.6:1.6]\n"
                "unset xlabel\nunset ylabel\nset key off\nunset grid\nunset arrow\nset offsets 0, 0, 0, 0\n";
        // The reference: the unit circle.
        for (int k = 0; k <= 128; ++k)
        {
            const double a = 2.0 * kPi * k / 128.0;
            data << std::cos(a) << " " << std::sin(a) << "\n";
        }
        data << "\n\n";
        const int circle = index++;
        int polygon = -1;
        if (r.vectors)
        {
            for (size_t j = 0; j <= 16; ++j)
            {
                const auto t = NormalisedTest(r, j % 16);
                data << t[0] << " " << t[1] << "\n";
            }
            data << "\n\n";
            polygon = index++;
            for (size_t j = 0; j < 16; ++j)
            {
                const auto& ref = r.referenceAb[j];
                const double angle = std::atan2(ref[1], ref[0]);
                const auto t = NormalisedTest(r, j);
                plot << "set arrow from " << std::cos(angle) << "," << std::sin(angle) << " to "
                     << t[0] << "," << t[1] << " lw 2 lc rgb '#" << BinColour(j) << "'\n";
            }
        }
        plot << "plot $bandlight_data index " << circle
             << " using 1:2 with lines lw 2 lc rgb '#202020'";
        if (polygon >= 0)
        {
            plot << ", $bandlight_data index " << polygon
                 << " using 1:2 with lines lw 2 lc rgb '#c0392b'";
        }
        plot << "\n";
    }
    plot << "unset multiplot\n";
    RunGnuplot(plot.str(), data.str(), output, nullptr,
               {1200, int(420 * std::max<size_t>(rows.size(), 1))});
}

}  // namespace bandlight
