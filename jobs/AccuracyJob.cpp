// SPDX-License-Identifier: BSD-3-Clause
// The accuracy job: the measurement, its JSON document and its plot.
#include "jobs/AccuracyJob.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "farm/Frames.h"
#include "farm/OutputPaths.h"
#include "plugin/OcioTransforms.h"
#include "report/Gnuplot.h"
#include "measure/detail/AccuracySummary.h"
#include "report/detail/PlotLabels.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{
namespace OCIO = OCIO_NAMESPACE;
using namespace detail;

/// A method's native cost (the map itself, no LUT) on all threads, or on
/// one when that is all the cost rows hold; 0 when it has none.
double NativeCost(const std::vector<CostRow>& cost, const std::string& method)
{
    double ns = 0.0;
    int threads = 0;
    for (const CostRow& c : cost)
    {
        if (c.method == method && c.form == CostForm::NATIVE && c.threads > threads)
        {
            ns = c.nsPerPixel;
            threads = c.threads;
        }
    }
    return ns;
}

/// One point of the accuracy-against-cost plot: a method's cost and its
/// mean ΔE00 on each set.
struct CostPoint
{
    std::string name;
    double ns;
    std::vector<double> de;  ///< one per set
};

/// Every method with a cost (the camera methods have none on the observer's
/// plates) as shipped, at its worst exposure, and beside it its native map
/// when it has one; by cost, then error.
std::vector<CostPoint> PlotPoints(const AccuracyResult& result)
{
    const AccuracyOptions& options = result.options;
    const std::string key = options.plates.front().key();
    const bool anyShipped = bool(options.shipped);
    std::vector<CostPoint> pts;
    for (const std::string& m : options.methods)
    {
        if (FindMethod(m).needsCamera || !result.costAllThreads.count(m))
        {
            continue;
        }
        CostPoint p{m, std::max(result.costAllThreads.at(m), 1e-3), {}};
        const double native = NativeCost(result.cost, m);
        CostPoint n{m + " (native)", std::max(native, 1e-3), {}};
        for (const ReflectanceSet& set : options.sets)
        {
            const Filter shippedF{1.0, anyShipped && !FindMethod(m).isReference(), key,
                                  PlateSource::CIE};
            p.de.push_back(
                WorstExposure(result.rows, m, set.name, shippedF, options.exposures).second);
            // The native map is the ideal form itself.
            const Filter idealF{1.0, false, key, PlateSource::CIE};
            n.de.push_back(
                WorstExposure(result.rows, m, set.name, idealF, options.exposures).second);
        }
        pts.push_back(p);
        if (native > 0.0)
        {
            pts.push_back(n);
        }
    }
    std::sort(pts.begin(), pts.end(),
              [](const CostPoint& a, const CostPoint& b)
              { return a.ns < b.ns || (a.ns == b.ns && a.de < b.de); });
    return pts;
}

/// The set the labels and the Pareto front follow: the held-out set, or
/// the first.
size_t AnchorSet(const std::vector<ReflectanceSet>& sets)
{
    size_t anchor = 0;
    for (size_t s = 0; s < sets.size(); ++s)
    {
        anchor = sets[s].name == HeldOutTcs().name ? s : anchor;
    }
    return anchor;
}

/// The plot's datablock: index s holds set s's points; then the labels,
/// the leader lines and the Pareto front.
std::string PlotData(const std::vector<CostPoint>& pts, size_t sets, const PlotLayout& layout,
                     size_t anchor)
{
    std::ostringstream data;
    data.precision(9);
    for (size_t s = 0; s < sets; ++s)
    {
        for (const CostPoint& p : pts)
        {
            data << p.ns << " " << p.de[s] << "\n";
        }
        data << "\n\n";
    }
    // The labels (x, y, text) at their boxes' left middles.
    for (size_t i = 0; i < pts.size(); ++i)
    {
        const LabelBox& b = layout.boxes[i];
        data << layout.toX(b.left) << " " << (b.bottom + b.height / 2) * layout.yMax << " "
             << GnuplotDataLabel(pts[i].name) << "\n";
    }
    data << "\n\n";
    // A leader line from each moved label's point to its box.
    bool anyLeader = false;
    for (size_t i = 0; i < pts.size(); ++i)
    {
        const LabelRequest& r = layout.requests[i];
        const LabelBox& b = layout.boxes[i];
        if (r.y >= b.bottom && r.y <= b.top())
        {
            continue;
        }
        anyLeader = true;
        const double edge = b.left >= r.x ? b.left : b.right();
        data << pts[i].ns << " " << r.y * layout.yMax << "\n"
             << layout.toX(edge) << " " << (b.bottom + b.height / 2) * layout.yMax << "\n\n";
    }
    if (!anyLeader)
    {
        data << layout.xMax << " " << 0.0 << "\n";  // an empty index would stop gnuplot
    }
    data << "\n\n";
    // The Pareto front of the anchor set.
    double best = 1e30;
    for (const CostPoint& p : pts)
    {
        if (!p.de.empty() && p.de[anchor] < best)
        {
            best = p.de[anchor];
            data << p.ns << " " << best << "\n";
        }
    }
    return data.str();
}

/// The gnuplot script that draws PlotData's indices.
std::string PlotScript(const std::vector<ReflectanceSet>& sets, const PlotLayout& layout,
                       size_t anchor)
{
    const size_t labels = sets.size(), leaders = labels + 1, front = labels + 2;
    std::ostringstream script;
    script.precision(9);
    script << "set title "
           << GnuplotQuote(
                  "What accuracy costs: each set re-lit as shipped, at its worst exposure "
                  "(2^-8 ... 2^4), mean over the pairs")
           << "\n"
              "set xlabel 'cost, ns per pixel (all threads, log scale)'\n"
              "set ylabel 'mean CIEDE2000 against the spectral answer'\n"
              "set logscale x\nset grid\n"
              "set key outside right top\n"
           << "set lmargin at screen " << kPlotLeft << "\nset rmargin at screen " << kPlotRight
           << "\nset bmargin at screen " << kPlotBottom << "\nset tmargin at screen " << kPlotTop
           << "\nset xrange [" << layout.xMin << ":" << layout.xMax
           << "]\nset yrange [0:" << layout.yMax << "]\n"
           << "plot $bandlight_data index " << front
           << " using 1:2 with lines lw 2 lc rgb '#2a7ab0' title "
           << GnuplotQuote("Pareto front, " + (sets.empty() ? std::string() : sets[anchor].name))
           << ", \\\n     $bandlight_data index " << leaders
           << " using 1:2 with lines lw 1 lc rgb '#888888' notitle";
    const char* colours[] = {"#c0392b", "#27ae60", "#8e44ad", "#d35400", "#16a085", "#2c3e50"};
    for (size_t s = 0; s < sets.size(); ++s)
    {
        script << ", \\\n     $bandlight_data index " << s << " using 1:2 with points pt "
               << (5 + 2 * int(s % 4)) << " ps 1.3 lc rgb '" << colours[s % 6] << "' title "
               << GnuplotQuote(sets[s].name);
    }
    script << ", \\\n     $bandlight_data index " << labels
           << " using 1:2:3 with labels left font ',10' notitle\n";
    return script.str();
}

/// Accuracy against cost: one series per reflectance set (its mean over
/// every pair at its worst exposure, as shipped, first plate convention),
/// the native root polynomials beside their LUTs, the Pareto front of the
/// held-out set (or the first set) joined, and one label per method placed
/// where no label overlaps another (PlaceLabels).
void Plot(const std::string& path, const AccuracyResult& result, OutputSet& outputs)
{
    const std::vector<ReflectanceSet>& sets = result.options.sets;
    const std::vector<CostPoint> pts = PlotPoints(result);
    const size_t anchor = AnchorSet(sets);
    std::vector<PlotPoint> plotted;
    for (const CostPoint& p : pts)
    {
        plotted.push_back({p.name, p.ns, p.de});
    }
    const PlotLayout layout = LayOutAccuracyPlot(plotted, anchor);
    RunGnuplot(PlotScript(sets, layout, anchor), PlotData(pts, sets.size(), layout, anchor), path,
               &outputs);
}

/// Each method's cost as one would apply it to an image (all threads): its
/// OCIO form, and the per-pixel computation for spectral. Every 3×3 costs
/// the same — one matrix per pixel, bound by memory — so the 3×3 methods
/// share the median of their timings rather than their noise.
std::map<std::string, double> CostAllThreads(const std::vector<CostRow>& cost)
{
    std::map<std::string, double> costAll;
    std::vector<double> matrixCosts;
    const int allThreads = CoreCount();
    for (const CostRow& c : cost)
    {
        if (c.threads == allThreads && c.form != CostForm::DIRECT_FIT && c.form != CostForm::NATIVE)
        {
            costAll[c.method] = c.nsPerPixel;
            if (c.form == CostForm::OCIO_MATRIX)
            {
                matrixCosts.push_back(c.nsPerPixel);
            }
        }
    }
    for (auto& [method, ns] : costAll)
    {
        if (ParseMethod(method).isLinear() && !matrixCosts.empty())
        {
            ns = Percentile(matrixCosts, 0.5);
        }
    }
    return costAll;
}

/// Accuracy rows as the JSON document's arrays; "camera" is the row's
/// simulation kind (PlateSourceName).
nlohmann::ordered_json RowsJson(const std::vector<AccuracyRow>& from)
{
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const AccuracyRow& r : from)
    {
        a.push_back({{"method", r.method},
                     {"from", r.from},
                     {"to", r.to},
                     {"set", r.set},
                     {"plates", r.plates},
                     {"camera", PlateSourceName(r.source)},
                     {"exposure", r.exposure},
                     {"shipped", r.shipped},
                     {"mean", r.mean},
                     {"p95", r.p95},
                     {"max", r.max},
                     {"worst_sample", r.worstSample}});
    }
    return a;
}

/// Every output before the measurement: a run of minutes must not fail at
/// its end for a folder that does not exist.
void CheckOutputs(const AccuracyRequest& r)
{
    OutputPlan plan;
    if (!r.json.empty())
    {
        plan.file("{json}", r.json);
    }
    if (!r.plot.empty())
    {
        CheckPlotPath(r.plot);
        plan.file("{plot}", r.plot);
    }
    if (!r.heatmaps.empty())
    {
        plan.folder("{heatmaps}", r.heatmaps);
    }
    for (const std::string& image : r.images)
    {
        CheckImageInput(image);
        plan.input(image);
    }
    plan.check();
}

/// The working space, the observer and the pairs of lights: those given,
/// the change of light an image was given for, or the defaults.
void ChooseLights(const AccuracyRequest& r, AccuracyOptions& options)
{
    options.workingSpace = r.workingSpace;
    FindRgbSpace(r.workingSpace);
    options.observer = ParseObserver(r.observer);
    if (!r.images.empty() && r.lights.empty())
    {
        if (r.imageOptions.from.spectrum.empty() || r.imageOptions.to.spectrum.empty())
        {
            throw ParameterError(
                "{image} is measured for one change of light: give {src=}S1 and "
                "{dst=}S2 (or {illuminants})");
        }
        options.lights = {r.imageOptions.from, r.imageOptions.to};
        options.forwardOnly = true;  // the change of light the image was given for
    }
    if (!r.heatmaps.empty() && r.images.empty())
    {
        throw ParameterError("{heatmaps} maps the error over a spectral image: give {image}");
    }
    if (!r.lights.empty())
    {
        options.lights = r.lights;
        if (options.lights.size() < 2)
        {
            throw Exception("accuracy needs at least two illuminants");
        }
    }
}

/// The plate conventions, the camera that shoots them (with its methods
/// when none are named) and the methods, the reference always among them.
void ChoosePlatesAndMethods(const AccuracyRequest& r, Reporter& reporter, AccuracyResult& result)
{
    AccuracyOptions& options = result.options;
    if (!r.methods.empty())
    {
        options.methods = r.methods;
    }
    options.plates = r.plates.all();
    options.camera = r.plates.loadCamera();
    result.cameraFile = r.plates.camera;
    if (options.camera)
    {
        const Light idt = r.plates.idt(reporter);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
        if (r.methods.empty())
        {
            const std::vector<std::string>& camera = CameraMethodNames();
            options.methods.insert(options.methods.end(), camera.begin(), camera.end());
        }
    }
    if (std::find(options.methods.begin(), options.methods.end(), ReferenceMethodName()) ==
        options.methods.end())
    {
        options.methods.push_back(ReferenceMethodName());
    }
    for (const std::string& m : options.methods)
    {
        RequireCamera(ParseMethod(m), bool(options.camera));
    }
}

/// How the images are read: the request's, in the run's working space
/// and observer.
SpectralOptions ImageOptions(const AccuracyRequest& r)
{
    SpectralOptions imageOptions = r.imageOptions;
    imageOptions.workingSpace = r.workingSpace;
    imageOptions.observer = r.observer;
    return imageOptions;
}

/// The sets of remittances: the default sets (unless left out), the files
/// given, and each image's pixels.
void ChooseSets(const AccuracyRequest& r, Reporter& reporter, AccuracyOptions& options)
{
    if (!r.defaultSets)
    {
        options.sets.clear();
    }
    for (const ReflectanceSet& s : r.sets)
    {
        options.sets.push_back(s);
    }
    const SpectralOptions imageOptions = ImageOptions(r);
    for (const std::string& image : r.images)
    {
        options.sets.push_back(
            ReflectanceSetFromSpectralImage(image, imageOptions, kMaxImageSamples, reporter));
    }
    if (options.sets.empty())
    {
        throw ParameterError(
            "no reflectance sets to measure: give {reflectances}, or keep the default sets");
    }
}

void ChooseExposures(const AccuracyRequest& r, AccuracyOptions& options)
{
    if (r.exposures.empty())
    {
        return;
    }
    for (const double k : r.exposures)
    {
        if (!(k > 0.0) || !std::isfinite(k))
        {
            throw ParameterError("{exposures} must be positive and finite");
        }
    }
    options.exposures = r.exposures;
}

/// The shipped form: the OCIO processor of the transform a config's look
/// holds (guard + matrix, or shaper + 3D LUT + inverse shaper).
ShippedFactory ShippedForms(const AccuracyOptions& options, int lutSize)
{
    const RgbSpace& working = FindRgbSpace(options.workingSpace);
    const Observer observer = options.observer;
    return [&working, observer, lutSize](const Light& from, const Light& to,
                                         const MethodSpec& method) -> PixelBatch
    {
        const OCIO::ConstCPUProcessorRcPtr cpu =
            OCIO::Config::CreateRaw()
                ->getProcessor(
                    IlluminantChangeTransform(from, to, method, working, observer, lutSize))
                ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                           OCIO::OPTIMIZATION_DEFAULT);
        return [cpu](float* rgb, size_t n)
        {
            OCIO::PackedImageDesc desc(rgb, long(n), 1, 3);
            cpu->apply(desc);
        };
    };
}

/// The request checked and turned into what MeasureAccuracy measures, in
/// the order the checks report their errors.
void ResolveOptions(const AccuracyRequest& r, Reporter& reporter, AccuracyResult& result)
{
    AccuracyOptions& options = result.options;
    options = DefaultAccuracyOptions();
    ChooseLights(r, options);
    ChoosePlatesAndMethods(r, reporter, result);
    ChooseSets(r, reporter, options);
    ChooseExposures(r, options);
    const int lutSize = CheckedLutSize(r.lutSize, "lut_size");
    if (!r.plot.empty() && !r.cost)
    {
        throw ParameterError("{plot} needs the cost measurement (drop {no_cost})");
    }
    if (!r.idealOnly)
    {
        options.shipped = ShippedForms(options, lutSize);
    }
}

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
    SpectralOptions imageOptions = ImageOptions(r);
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
        Plot(r.plot, result, outputs);
        result.written.push_back(r.plot);
    }
    outputs.commit();
}
}  // namespace

ReflectanceSet ReflectanceSetFromFile(const std::string& path)
{
    return {path, ReadSpectraFile(path)};
}

AccuracyResult MeasureAccuracyJob(const AccuracyRequest& r, Reporter& reporter)
{
    CheckOutputs(r);
    AccuracyResult result;
    ResolveOptions(r, reporter, result);
    result.rows = MeasureRows(result.options, reporter);
    MeasureFitsAndCost(r, reporter, result);
    WriteOutputs(r, reporter, result);
    return result;
}

std::string AccuracyDocument(const AccuracyResult& result)
{
    const AccuracyOptions& options = result.options;
    nlohmann::ordered_json j;
    if (options.camera)
    {
        j["camera"] = {{"name", options.camera->name()},
                       {"file", result.cameraFile},
                       {"idt_light", options.idtLightName}};
    }
    else
    {
        j["camera"] = nullptr;
    }
    j["rows"] = RowsJson(result.rows);
    j["cross_validation"] = RowsJson(result.crossValidation);
    j["floor"] = RowsJson(result.floor);
    j["cost"] = nlohmann::ordered_json::array();
    for (const CostRow& c : result.cost)
    {
        j["cost"].push_back({{"method", c.method},
                             {"form", c.formName()},
                             {"ns_per_pixel", c.nsPerPixel},
                             {"mpixel_per_s", 1e3 / c.nsPerPixel},
                             {"threads", c.threads}});
    }
    j["setup_cost"] = nlohmann::ordered_json::array();
    for (const SetupCost& s : result.setupCost)
    {
        j["setup_cost"].push_back({{"what", s.what}, {"seconds", s.seconds}});
    }
    if (!result.heatmaps.empty())
    {
        j["heatmaps"] = nlohmann::ordered_json::array();
        for (const HeatmapSummary& h : result.heatmaps)
        {
            j["heatmaps"].push_back({{"image", h.image},
                                     {"method", h.method},
                                     {"mean", h.mean},
                                     {"p95", h.p95},
                                     {"max", h.max},
                                     {"exr", h.exr},
                                     {"png", h.png}});
        }
    }
    return j.dump(2);
}

}  // namespace bandlight::jobs
