// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Summaries of accuracy rows, shared by the report and the plot (not installed).

#include <string>
#include <utility>
#include <vector>

#include "transforms/Accuracy.h"

namespace bandlight::detail
{

/// Per method over all pairs: the mean of the pairs' means, the 95th
/// percentile of the pairs' 95th percentiles, the max, and where it is.
struct Summary
{
    double mean = 0.0;
    double p95 = 0.0;
    double max = 0.0;
    std::string worst;
};

/// Which rows a summary takes: one exposure (or all, < 0) and one form.
struct Filter
{
    double exposure = 1.0;
    bool shipped = false;
    std::string plates = "lit";
    PlateSource source = PlateSource::CIE;
};

using Pairs = std::vector<std::pair<std::string, std::string>>;

/// The band model's pairs: A, F2 and F11 to D65.
const Pairs& LecturePairs();

Summary Summarise(const std::vector<AccuracyRow>& rows, const std::string& method,
                  const std::string& set, Filter f, const Pairs& onlyPairs = {});

/// The exposure whose mean is worst, and that mean.
std::pair<double, double> WorstExposure(const std::vector<AccuracyRow>& rows,
                                        const std::string& method, const std::string& set, Filter f,
                                        const std::vector<double>& exposures,
                                        const Pairs& onlyPairs = {});

/// "2^-8" for 1/256.
std::string Stops(double k);

}  // namespace bandlight::detail
