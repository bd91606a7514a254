// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "spectral/LightScores.h"
#include "transforms/Methods.h"

namespace bandlight::jobs
{

/// `quality`: every light-quality score of the registry
/// (spectral/LightScores.h) for one light or many.
struct QualityRequest
{
    /// Lights as `--from` takes them: a built-in name (D65, F11, 3200K,
    /// D5600), daylight:K, planck:K, or a spectrum file (CSV, CGATS .sp/.ti3).
    std::vector<std::string> lights;
    /// A reference light the same way: TLMF is computed against it, and
    /// SSI uses it instead of its default reference. Not given: none (given
    /// empty: refused).
    std::optional<std::string> reference;
    /// FILE.png or FILE.svg: each light's spectrum against its references
    /// and the TM-30 colour vector graphic. Not given: no plot.
    std::optional<std::string> plot;
    int threads = 0;  ///< 0: all cores
};

struct QualityResult
{
    std::vector<LightQuality> lights;  ///< in the order asked
    std::string plot;                  ///< the plot written, if any
};

/// Scores every light of `request`. Every light and the plot path are
/// checked before any score is computed: ParameterError for no light, an
/// empty reference, a plot path that is not .png/.svg, Exception naming the light or file
/// that cannot be read or has no power in the visible range.
QualityResult MakeQuality(const QualityRequest& request, Reporter& reporter = SilentReporter());

/// The scores of lights already resolved (`reference`: none when its name
/// is empty), on `threads` threads (0: all cores): what MakeQuality and
/// the Python module's quality() compute. Throws Exception naming the
/// first light that cannot be scored.
std::vector<LightQuality> ScoreLights(const std::vector<Light>& lights, const Light& reference,
                                      int threads = 0);

}  // namespace bandlight::jobs
