// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "transforms/IlluminantChange.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

/// ΔE00 of one method for one illuminant pair over one reflectance set,
/// against the spectral reference (the remittances rendered under `to`).
struct AccuracyRow
{
    std::string method;
    std::string from;
    std::string to;
    std::string set;
    double mean = 0.0;
    double p95 = 0.0;
    double max = 0.0;
    std::string worstSample;
};

struct AccuracyOptions
{
    std::vector<Light> lights;  ///< every ordered pair of distinct lights
    std::vector<std::string> methods;
    std::vector<ReflectanceSet> sets;
    std::string workingSpace = "acescg";
    Observer observer = Observer::CIE1931_2DEG;
};

/// The default comparison: A, C, D50, D65, E, F1–F12; every image method;
/// the sets tcs (TCS01–15), tcs09-15 (held out from fitting) and random
/// (100 smooth random remittances, none of them in the training set).
AccuracyOptions DefaultAccuracyOptions();

/// Measures every (method, pair, set). For each remittance: its colour under
/// `from` (working RGB, white Y = 1) goes through the method and is
/// compared in CIEDE2000 — L*a*b* relative to `to`'s white — with its
/// colour rendered under `to`. `progress` (0–1) is called as pairs finish.
std::vector<AccuracyRow> MeasureAccuracy(const AccuracyOptions& options,
                                         const std::function<void(double)>& progress = {});

/// Percentile p (0–1) of values, nearest rank; 0 for none.
double Percentile(std::vector<double> values, double p);

}  // namespace bandlight
