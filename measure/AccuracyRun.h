// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `accuracy`'s request and result, the step that resolves a request, and
// the result's tables: the text report, the JSON document, the plot.

#include <map>
#include <string>
#include <vector>

#include "measure/Cost.h"
#include "requests/Inputs.h"
#include "measure/SpectralAccuracy.h"
#include "transforms/Accuracy.h"
#include "requests/Defaults.h"
#include "spectral/AtomicFile.h"

namespace bandlight::jobs
{

/// `accuracy`: every method against the spectral answer, ideal and as
/// shipped, and what each costs.
struct AccuracyRequest
{
    std::vector<Light> lights;         ///< every ordered pair (empty: A, C, D50, D65, E, F1–F12)
    std::vector<std::string> methods;  ///< empty: every image method; "spectral" is always added
    /// More sets of remittances, measured after the default sets (unless
    /// `defaultSets` is false): tcs, tcs09-15 and random.
    std::vector<ReflectanceSet> sets;
    bool defaultSets = true;
    std::string workingSpace = defaults::WORKING_SPACE;
    std::string observer = defaults::OBSERVER;
    std::vector<double> exposures;            ///< multiples of the white; empty: 2^-8 … 2^4
    int lutSize = defaults::CONFIG_LUT_SIZE;  ///< the shipped non-linear looks' 3D LUT size
    bool idealOnly = false;                   ///< skip the shipped forms (the OCIO processors)
    bool crossValidation = true;              ///< the fitted methods on their own training data
    bool floor = true;  ///< the best a pixel-only method fitted on each set reaches
    bool cost = true;   ///< time every method (a few seconds)
    /// "both" (default: balanced and lit), "balanced" or "lit".
    PlatesRequest plates{defaults::ACCURACY_PLATES, defaults::ADAPTATION, "", defaults::IDT_LIGHT};
    /// Spectral images measured as sets, each named after its file: every
    /// method on the image's pixels (as remittances) against the exact
    /// relight. `imageOptions.from` is the light an emissive image was lit
    /// by; with images and no `lights`, the lights are from and to.
    std::vector<std::string> images;
    SpectralOptions imageOptions;
    /// With images: a ΔE00 map per image and method in this folder ("" none).
    std::string heatmaps;
    std::string json;  ///< write the JSON document to this file ("" none)
    std::string plot;  ///< draw accuracy against cost into this .png or .svg ("" none)
};

struct AccuracyResult
{
    AccuracyOptions options;  ///< what was measured (lights, methods, sets, plates, camera)
    std::string cameraFile;
    std::vector<AccuracyRow> rows;
    std::vector<AccuracyRow> crossValidation;
    std::vector<AccuracyRow> floor;
    std::vector<CostRow> cost;
    std::vector<SetupCost> setupCost;
    /// Each method's cost on all threads as one applies it to an image (the
    /// 3×3 methods share the median of their timings), ns a pixel.
    std::map<std::string, double> costAllThreads;
    std::vector<HeatmapSummary> heatmaps;  ///< with request.heatmaps
    std::vector<std::string> written;      ///< the files written (json, plot, heat maps)
};

/// Every option of `request` checked and resolved into `result.options`
/// (lights, plates and methods, sets, exposures, the shipped forms), the
/// outputs checked first, before any measurement.
void ResolveAccuracyRequest(const AccuracyRequest& request, Reporter& reporter,
                            AccuracyResult& result);

/// How the images are read: the request's options, in the run's working
/// space and observer.
SpectralOptions AccuracyImageOptions(const AccuracyRequest& request);

/// Each method's cost on every thread, by the native form when it has one.
std::map<std::string, double> CostAllThreads(const std::vector<CostRow>& cost);

/// Accuracy against cost: one series per reflectance set (its mean over
/// every pair at its worst exposure, as shipped, first plate convention),
/// the native root polynomials beside their LUTs, the Pareto front of the
/// held-out set (or the first set) joined, and one label per method placed
/// where no label overlaps another (PlaceLabels). Written with `outputs`.
void PlotAccuracy(const std::string& path, const AccuracyResult& result, OutputSet& outputs);

/// The JSON document of a result (`accuracy --json`): an object with
/// camera, rows, cross_validation, floor, cost and setup_cost.
std::string AccuracyDocument(const AccuracyResult& result);

/// The text report of a result: one table per plate convention and set.
std::string AccuracyReport(const AccuracyResult& result);

}  // namespace bandlight::jobs

namespace bandlight::jobs
{
/// A file of remittances as an accuracy set named by its path, read as it is.
ReflectanceSet ReflectanceSetFromFile(const std::string& path);
}  // namespace bandlight::jobs
