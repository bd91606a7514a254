// SPDX-License-Identifier: BSD-3-Clause
// The accuracy result's text report (one table per plate convention and
// set) and its JSON document.
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "report/ResultTable.h"

#include "measure/AccuracyRun.h"
#include "measure/detail/AccuracySummary.h"

namespace bandlight::jobs
{

using namespace detail;

namespace
{

/// What was measured and how to read the tables.
void WriteHeader(std::ostream& out, const AccuracyOptions& options)
{
    const size_t pairs = PairCount(options);
    out << "Re-lighting accuracy, CIEDE2000 against the spectral answer (" << options.lights.size()
        << " illuminants, " << pairs << (pairs == 1 ? " ordered pair, " : " ordered pairs, ")
        << FindRgbSpace(options.workingSpace).displayName << "), exposures "
        << Stops(options.exposures.front()) << " ... " << Stops(options.exposures.back())
        << " of the white.\n"
           "ideal: the method's exact form; shipped: the OCIO processor of the look as a config "
           "holds it (guard, matrix; or shaper, 3D LUT, inverse shaper). Means over pairs; "
           "worst: the exposure whose mean is worst.\n"
           "plates lit: images carrying the source light's cast; balanced: white-balanced to the "
           "working white (the ACES convention), the reference balanced the same way and "
           "L*a*b* relative to the working white.\n";
}

/// One method's line of a set's table, on the observer's plates.
void WriteMethodLine(std::ostream& out, const AccuracyResult& result, const std::string& key,
                     const ReflectanceSet& set, const std::string& m)
{
    const AccuracyOptions& options = result.options;
    const std::vector<AccuracyRow>& rows = result.rows;
    const bool hasShipped = bool(options.shipped) && !FindMethod(m).isReference();
    const Filter idealF{1.0, false, key, PlateSource::CIE};
    const Filter shippedF{1.0, hasShipped, key, PlateSource::CIE};
    const Summary ideal = Summarise(rows, m, set.name, idealF);
    const Summary shipped = Summarise(rows, m, set.name, shippedF);
    const auto worst = WorstExposure(rows, m, set.name, shippedF, options.exposures);
    const auto lecture =
        WorstExposure(rows, m, set.name, shippedF, options.exposures, LecturePairs());
    const Summary all = Summarise(rows, m, set.name, {-1.0, hasShipped, key, PlateSource::CIE});
    // Without shipped forms (--ideal-only) the shipped column is
    // empty, and the worst exposure is the ideal form's.
    char shippedMean[16] = "       -";
    if (hasShipped)
    {
        std::snprintf(shippedMean, sizeof shippedMean, "%8.2f", shipped.mean);
    }
    const std::map<std::string, double>& costAll = result.costAllThreads;
    char line[320];
    std::snprintf(line, sizeof line,
                  "  %-10s %7.2f %s %8.2f (%-5s)   %6.2f %7.2f   %-26s %8.2f   %10s\n", m.c_str(),
                  ideal.mean, shippedMean, worst.second, Stops(worst.first).c_str(), all.p95,
                  all.max, all.worst.c_str(), lecture.second,
                  costAll.count(m) ? Fixed(costAll.at(m), 2).c_str() : "-");
    out << line;
}

/// The floors of a set (lit plates only: they are fitted on lit colours).
void WriteFloorLines(std::ostream& out, const AccuracyResult& result, const ReflectanceSet& set)
{
    for (const std::string& floor : FloorMethodNames())
    {
        const Summary f = Summarise(result.floor, floor, set.name, {1.0, false});
        const Summary fl = Summarise(result.floor, floor, set.name, {1.0, false}, LecturePairs());
        char line[200];
        std::snprintf(line, sizeof line,
                      "  %-14s %5.2f   (fitted on this set itself: in-sample; "
                      "A/F2/F11->D65 %.2f)\n",
                      floor.c_str(), f.mean, fl.mean);
        out << line;
    }
}

/// One set's table: every method but the camera methods, ideal and shipped.
void WriteSetTable(std::ostream& out, const AccuracyResult& result, const Plates& plates,
                   const ReflectanceSet& set)
{
    const AccuracyOptions& options = result.options;
    out << "\nset " << set.name << " (" << set.samples.size() << " remittances)\n"
        << "  method       ideal  shipped  " << (options.shipped ? "shipped" : "  ideal")
        << " worst (at)   p95     max   worst sample and pair      A/F2/F11->D65 worst  "
           "ns/pixel\n";
    for (const std::string& m : options.methods)
    {
        if (FindMethod(m).needsCamera)
        {
            continue;  // measured on camera plates below
        }
        WriteMethodLine(out, result, plates.key(), set, m);
    }
    if (!plates.balanced())
    {
        WriteFloorLines(out, result, set);
    }
}

/// The lit looks applied to balanced plates: one column per set.
void WriteLitLooksTable(std::ostream& out, const AccuracyResult& result, const Plates& plates)
{
    const AccuracyOptions& options = result.options;
    out << "\nlit looks on these balanced plates (the cast corrected twice), ideal, k = 1: "
           "mean over pairs (A/F2/F11->D65)\n  method    ";
    for (const ReflectanceSet& set : options.sets)
    {
        char h[64];
        std::snprintf(h, sizeof h, " %20s", set.name.substr(0, 20).c_str());
        out << h;
    }
    out << "\n";
    const Filter f{1.0, false, ThroughLitLooksKey(plates), PlateSource::CIE};
    for (const std::string& m : options.methods)
    {
        const MethodEntry& entry = FindMethod(m);
        if (entry.isReference() || entry.identity || entry.needsCamera)
        {
            continue;
        }
        char line[64];
        std::snprintf(line, sizeof line, "  %-10s", m.c_str());
        out << line;
        for (const ReflectanceSet& set : options.sets)
        {
            std::snprintf(line, sizeof line, " %10.2f (%6.2f)",
                          Summarise(result.rows, m, set.name, f).mean,
                          Summarise(result.rows, m, set.name, f, LecturePairs()).mean);
            out << line;
        }
        out << "\n";
    }
}

/// The fitted methods on their own training data, in-sample and
/// cross-validated; nothing when no fitted method was measured.
void WriteCrossValidation(std::ostream& out, const AccuracyResult& result, const std::string& key)
{
    const std::vector<AccuracyRow>& cvRows = result.crossValidation;
    const std::string inSample = InSampleSetName();
    const std::string folds = CrossValidatedSetName(CROSS_VALIDATION_FOLDS);
    const Filter f{1.0, false, key};
    bool anyCv = false;
    for (const std::string& m : result.options.methods)
    {
        const Summary in = Summarise(cvRows, m, inSample, f);
        const Summary cv = Summarise(cvRows, m, folds, f);
        if (in.mean == 0.0 && cv.mean == 0.0)
        {
            continue;
        }
        if (!anyCv)
        {
            out << "\nfitted methods on their own training data (ideal, k = 1): in-sample "
                   "against "
                << CROSS_VALIDATION_FOLDS << "-fold cross-validated\n";
            anyCv = true;
        }
        const Summary inL = Summarise(cvRows, m, inSample, f, LecturePairs());
        const Summary cvL = Summarise(cvRows, m, folds, f, LecturePairs());
        char line[200];
        std::snprintf(line, sizeof line,
                      "  %-10s in-sample %5.2f  %d-fold %5.2f   (A/F2/F11->D65: %5.2f, %5.2f)\n",
                      m.c_str(), in.mean, CROSS_VALIDATION_FOLDS, cv.mean, inL.mean, cvL.mean);
        out << line;
    }
}

/// One method's line of a set's camera table: its mean on each simulation
/// kind's plates (all pairs, and the lecture pairs in brackets).
void WriteCameraLine(std::ostream& out, const std::vector<AccuracyRow>& rows,
                     const std::string& key, const ReflectanceSet& set, const std::string& m)
{
    const auto at = [&](PlateSource source, bool lecture)
    {
        return Summarise(rows, m, set.name, {1.0, false, key, source},
                         lecture ? LecturePairs() : Pairs{})
            .mean;
    };
    char line[240];
    if (FindMethod(m).needsCamera)
    {
        std::snprintf(line, sizeof line, "  %-16s %18s %18s %18s %8.2f (%6.2f)\n", m.c_str(), "-",
                      "-", "-", at(PlateSource::CAMERA_DAYLIGHT_IDT, false),
                      at(PlateSource::CAMERA_DAYLIGHT_IDT, true));
    }
    else
    {
        std::snprintf(line, sizeof line,
                      "  %-16s %8.2f (%6.2f) %8.2f (%6.2f) %+8.2f (%+6.2f) "
                      "%8.2f (%6.2f)\n",
                      m.c_str(), at(PlateSource::CIE, false), at(PlateSource::CIE, true),
                      at(PlateSource::CAMERA, false), at(PlateSource::CAMERA, true),
                      at(PlateSource::CAMERA, false) - at(PlateSource::CIE, false),
                      at(PlateSource::CAMERA, true) - at(PlateSource::CIE, true),
                      at(PlateSource::CAMERA_DAYLIGHT_IDT, false),
                      at(PlateSource::CAMERA_DAYLIGHT_IDT, true));
    }
    out << line;
}

/// The camera's plates against the observer's: one table per set.
void WriteCameraTables(std::ostream& out, const AccuracyResult& result, const std::string& key)
{
    const AccuracyOptions& options = result.options;
    out << "\ncamera " << options.camera->name()
        << ": the plates as it records them, ideal forms, k = 1, mean over pairs "
           "(A/F2/F11->D65)\n"
           "  cie: the colour as the observer sees it; camera: white-balanced and through "
           "an IDT fitted the rawtoaces way for the shooting light; daylight IDT: "
           "balanced by gains, through the one IDT fitted for "
        << options.idtLightName << "\n";
    for (const ReflectanceSet& set : options.sets)
    {
        out << "\n  set " << set.name
            << "\n  method                 cie             camera     the camera adds"
               "        daylight IDT\n";
        for (const std::string& m : options.methods)
        {
            if (!FindMethod(m).isReference())
            {
                WriteCameraLine(out, result.rows, key, set, m);
            }
        }
    }
}

/// Everything measured on one plate convention.
void WritePlatesSection(std::ostream& out, const AccuracyResult& result, const Plates& plates)
{
    const AccuracyOptions& options = result.options;
    const std::string key = plates.key();
    out << "\n== plates: " << key << " ==\n";
    for (const ReflectanceSet& set : options.sets)
    {
        WriteSetTable(out, result, plates, set);
    }
    if (plates.balanced() && options.measureMismatch)
    {
        WriteLitLooksTable(out, result, plates);
    }
    WriteCrossValidation(out, result, key);
    if (options.camera)
    {
        WriteCameraTables(out, result, key);
    }
}

/// What each method costs per pixel, and the one-off costs.
void WriteCost(std::ostream& out, const AccuracyResult& result)
{
    if (result.cost.empty())
    {
        return;
    }
    out << "\ncost per pixel, 1920x1080 float RGBA (best of 3)\n";
    for (const CostRow& c : result.cost)
    {
        char line[160];
        std::snprintf(line, sizeof line, "  %-10s %-12s %d thread%s %10.2f ns  %8.1f Mpixel/s\n",
                      c.method.c_str(), c.formName().c_str(), c.threads, c.threads > 1 ? "s" : " ",
                      c.nsPerPixel, 1e3 / c.nsPerPixel);
        out << line;
    }
    for (const SetupCost& s : result.setupCost)
    {
        out << "  one-off: " << s.what << ": " << Fixed(s.seconds, 3) << " s\n";
    }
}

/// Accuracy rows as one table; "camera" is the row's simulation kind
/// (PlateSourceName).
ResultTable RowsTable(const std::vector<AccuracyRow>& from)
{
    ResultTable t({"method", "from", "to", "set", "plates", "camera", "exposure", "shipped", "mean",
                   "p95", "max", "worst_sample"});
    for (const AccuracyRow& r : from)
    {
        t.add({r.method, r.from, r.to, r.set, r.plates, std::string(PlateSourceName(r.source)),
               r.exposure, r.shipped, r.mean, r.p95, r.max, r.worstSample});
    }
    return t;
}

}  // namespace

std::string AccuracyReport(const AccuracyResult& result)
{
    std::ostringstream out;
    WriteHeader(out, result.options);
    for (const Plates& plates : result.options.plates)
    {
        WritePlatesSection(out, result, plates);
    }
    WriteCost(out, result);
    return out.str();
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
    j["rows"] = RowsTable(result.rows).json();
    j["cross_validation"] = RowsTable(result.crossValidation).json();
    j["floor"] = RowsTable(result.floor).json();
    ResultTable cost({"method", "form", "ns_per_pixel", "mpixel_per_s", "threads"});
    for (const CostRow& c : result.cost)
    {
        cost.add({c.method, c.formName(), c.nsPerPixel, 1e3 / c.nsPerPixel,
                  static_cast<long long>(c.threads)});
    }
    j["cost"] = cost.json();
    ResultTable setup({"what", "seconds"});
    for (const SetupCost& s : result.setupCost)
    {
        setup.add({s.what, s.seconds});
    }
    j["setup_cost"] = setup.json();
    if (!result.heatmaps.empty())
    {
        ResultTable maps({"image", "method", "mean", "p95", "max", "exr", "png"});
        for (const HeatmapSummary& h : result.heatmaps)
        {
            maps.add({h.image, h.method, h.mean, h.p95, h.max, h.exr, h.png});
        }
        j["heatmaps"] = maps.json();
    }
    return j.dump(2);
}

}  // namespace bandlight::jobs
