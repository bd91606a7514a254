// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The one summary of a sample of errors that every table gives (ΔE00 of a
// method over a reflectance set, of an IDT over a chart, of a look over an
// image's pixels, of a light group's relight): count, mean, median, 95th
// percentile and max, each percentile by one rule.

#include <cstddef>
#include <vector>

namespace bandlight
{

/// Percentile p (0–1) of `values` by the nearest-rank rule: the smallest
/// value with at least p·n of the n values at or below it, i.e. the
/// ⌈p·n⌉-th smallest (the first for p = 0, the largest for p = 1); 0 for
/// no values. Every percentile bandlight reports is this one.
double Percentile(std::vector<double> values, double p);

/// Summary statistics of a sample (all zero for an empty one).
struct Statistics
{
    size_t count = 0;
    double mean = 0.0;    ///< Σ values / count, summed in the order given
    double median = 0.0;  ///< Percentile(values, 0.5)
    double p95 = 0.0;     ///< Percentile(values, 0.95)
    double max = 0.0;     ///< Percentile(values, 1)
};

/// The statistics of `values` (sorted once).
Statistics Summarise(std::vector<double> values);

}  // namespace bandlight
