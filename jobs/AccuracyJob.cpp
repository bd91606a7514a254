// SPDX-License-Identifier: BSD-3-Clause
// `accuracy`: every method measured against the exact spectral render, the
// request resolved and the tables written by measure/.
#include "jobs/AccuracyJob.h"

#include <mutex>
#include <thread>

#include "farm/Frames.h"
#include "measure/detail/AccuracySummary.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{

/// Every row, with the pairs' progress passed on in tenths.
std::vector<AccuracyRow> MeasureRows(const AccuracyOptions& options, Reporter& reporter)
{
    const size_t pairs = PairCount(options);
    reporter.progress("accuracy: " + std::to_string(options.methods.size()) + " methods x " +
                      std::to_string(pairs) +
                      (pairs == 1 ? " illuminant pair x " : " illuminant pairs x ") +
                      std::to_string(options.sets.size()) + " reflectance sets");
    std::mutex mu;
    int lastTenth = -1;
    double lastFraction = 0.0;
    return MeasureAccuracy(options,
                           [&](double done)
                           {
                               std::lock_guard<std::mutex> lock(mu);
                               // Pairs finish on several threads and their reports can arrive
                               // out of order: what the reporter sees only grows.
                               lastFraction = std::max(lastFraction, done);
                               const double f = lastFraction;
                               const int tenth = int(f * 10.0);
                               std::string line;
                               if (tenth != lastTenth)
                               {
                                   lastTenth = tenth;
                                   line = "accuracy: " + std::to_string(int(f * 100.0 + 0.5)) +
                                          "% of pairs done";
                               }
                               reporter.progress(line, f);
                           });
}

/// The fitted methods cross-validated, the floor, and what each method costs.
void MeasureFitsAndCost(const AccuracyRequest& r, Reporter& reporter, AccuracyResult& result)
{
    const AccuracyOptions& options = result.options;
    if (r.crossValidation || r.floor)
    {
        reporter.progress("accuracy: cross-validating the fitted methods and fitting the floor");
    }
    if (r.crossValidation)
    {
        result.crossValidation = CrossValidate(options, CROSS_VALIDATION_FOLDS);
    }
    if (r.floor)
    {
        result.floor = MeasureFloor(options);
    }
    if (r.cost)
    {
        reporter.progress("accuracy: timing each method on 1920x1080 float RGBA");
        result.cost = MeasureCost(options.methods, options.workingSpace, 1920L * 1080L,
                                  options.camera, {options.idtLightName, options.idtLight});
        result.setupCost = MeasureSetupCost(options.workingSpace);
    }
    result.costAllThreads = CostAllThreads(result.cost);
}

/// A ΔE00 map per image and method, added to `outputs`. The maps are drawn
/// for the default plate convention when both are measured.
void WriteHeatmaps(const AccuracyRequest& r, Reporter& reporter, OutputSet& outputs,
                   AccuracyResult& result)
{
    SpectralOptions imageOptions = AccuracyImageOptions(r);
    imageOptions.plates = r.plates;
    if (imageOptions.plates.both())
    {
        imageOptions.plates.plates = defaults::PLATES;
    }
    const std::vector<std::string> stems = HeatmapStems(r.images);
    for (size_t i = 0; i < r.images.size(); ++i)
    {
        const std::string& image = r.images[i];
        reporter.progress("accuracy: heat maps of " + image);
        for (HeatmapSummary& h : WriteAccuracyHeatmaps(image, imageOptions, result.options.methods,
                                                       r.heatmaps, stems[i], outputs, reporter))
        {
            h.image = image;
            result.written.push_back(h.exr);
            result.written.push_back(h.png);
            result.heatmaps.push_back(std::move(h));
        }
    }
}

/// Every output of the run (heat maps, JSON, plot) is one set, committed
/// after all of the work: a failure anywhere leaves every previous output
/// as it was.
void WriteOutputs(const AccuracyRequest& r, Reporter& reporter, AccuracyResult& result)
{
    OutputSet outputs;
    if (!r.heatmaps.empty())
    {
        WriteHeatmaps(r, reporter, outputs, result);
    }
    if (!r.json.empty())
    {
        const std::string document = AccuracyDocument(result);
        outputs.write(r.json, [&](std::ostream& os) { os << document << "\n"; });
        result.written.push_back(r.json);
    }
    if (!r.plot.empty())
    {
        PlotAccuracy(r.plot, result, outputs);
        result.written.push_back(r.plot);
    }
    outputs.commit();
}

}  // namespace

AccuracyResult MeasureAccuracyJob(const AccuracyRequest& r, Reporter& reporter)
{
    AccuracyResult result;
    ResolveAccuracyRequest(r, reporter, result);
    result.rows = MeasureRows(result.options, reporter);
    MeasureFitsAndCost(r, reporter, result);
    WriteOutputs(r, reporter, result);
    return result;
}

}  // namespace bandlight::jobs
