// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "transforms/Defaults.h"

namespace bandlight::jobs
{

/// `plot`: the band model's pictures — a spectrum and its band means as steps,
/// for the matching functions, an illuminant or remittances.
struct PlotRequest
{
    /// What to draw, one of the three: the colour-matching functions of
    /// `observer`, an illuminant (a built-in name or a spectrum file), or
    /// remittances (TCS01–TCS15, TCS, or a spectrum file).
    bool cmf = false;
    std::string illuminant;
    std::string reflectance;
    std::string bands = defaults::BANDS;  ///< band edges in nm
    std::string observer = defaults::OBSERVER;
    std::string out;  ///< FILE.png or FILE.svg (chosen by the extension)
};

struct PlotResult
{
    std::string out;                  ///< the file written
    std::string title;                ///< the plot's title
    std::vector<std::string> curves;  ///< the spectra drawn, each with its band means
};

/// Draws the plot of `request` through gnuplot (RunGnuplot) into `out`,
/// replaced whole or not at all. An illuminant is scaled so that its
/// largest band mean is 1, as the band model normalises it. Throws
/// ParameterError unless exactly one of cmf, illuminant, reflectance is
/// given, Exception for bands outside the spectra's range.
PlotResult MakePlot(const PlotRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
