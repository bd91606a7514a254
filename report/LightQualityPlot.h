// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The picture of `quality --plot`: for each light, its spectrum against the
// references its scores compare it with, and the ANSI/IES TM-30 colour
// vector graphic (how hue and chroma shift, bin by bin).

#include <array>
#include <string>
#include <vector>

#include "spectral/Spectrum.h"

namespace bandlight
{

/// One light's row of the plot.
struct QualityPlotRow
{
    std::string light;
    Spectrum spectrum;
    /// References drawn dashed beside it (CIE 224's blend, SSI's), each
    /// scaled to the light's luminance by the caller.
    std::vector<std::pair<std::string, Spectrum>> references;
    /// A line under the light's name in its panel's title (what the
    /// reference is), or empty.
    std::string note;
    /// TM-30 per hue bin: the mean (a', b') of the samples under the
    /// reference and under the light (CAM02-UCS); no vectors when
    /// `vectors` is false (a light TM-30 gives no value for).
    bool vectors = false;
    std::array<std::array<double, 2>, 16> referenceAb{};
    std::array<std::array<double, 2>, 16> testAb{};
    double rf = 0.0;
    double rg = 0.0;
};

/// Most lights one plot holds: a row each, and a row must stay legible.
constexpr size_t QUALITY_PLOT_MAX_LIGHTS = 12;

/// Draws the rows into `output` (.png or .svg) through gnuplot: a row per
/// light, the spectra (normalised to the light's peak) on the left, the
/// colour vector graphic on the right (the reference the unit circle, the
/// light's bins normalised by the reference's radius per bin as TM-30-20
/// Annex draws them, an arrow per bin). Throws ParameterError for more
/// than QUALITY_PLOT_MAX_LIGHTS rows, Exception when gnuplot fails.
void DrawQualityPlot(const std::vector<QualityPlotRow>& rows, const std::string& output);

}  // namespace bandlight
