// SPDX-License-Identifier: BSD-3-Clause
// The accuracy job's text report: one table per plate convention and set.
#include <cstdio>
#include <sstream>

#include "bandlight/jobs/AccuracyJob.h"
#include "bandlight/report/detail/AccuracySummary.h"

namespace bandlight::jobs
{

using namespace detail;

std::string AccuracyReport(const AccuracyResult& result)
{
    const AccuracyOptions& options = result.options;
    const std::vector<AccuracyRow>& rows = result.rows;
    const std::vector<AccuracyRow>& cvRows = result.crossValidation;
    const std::vector<AccuracyRow>& floorRows = result.floor;
    const std::vector<CostRow>& cost = result.cost;
    const std::vector<SetupCost>& setup = result.setupCost;
    const std::map<std::string, double>& costAll = result.costAllThreads;
    const size_t pairs = PairCount(options);
    const Pairs& lecturePairs = LecturePairs();
    const bool anyShipped = bool(options.shipped);
    std::ostringstream out;
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
    for (const Plates& plates : options.plates)
    {
        const std::string key = plates.key();
        out << "\n== plates: " << key << " ==\n";
        for (const ReflectanceSet& set : options.sets)
        {
            out << "\nset " << set.name << " (" << set.samples.size() << " remittances)\n"
                << "  method       ideal  shipped  " << (anyShipped ? "shipped" : "  ideal")
                << " worst (at)   p95     max   worst sample and pair      A/F2/F11->D65 worst  "
                   "ns/pixel\n";
            for (const std::string& m : options.methods)
            {
                if (FindMethod(m).needsCamera)
                {
                    continue;  // measured on camera plates below
                }
                const Filter idealF{1.0, false, key, PlateSource::CIE};
                const bool hasShipped = anyShipped && !FindMethod(m).isReference();
                const Filter shippedF{1.0, hasShipped, key, PlateSource::CIE};
                const Summary ideal = Summarise(rows, m, set.name, idealF);
                const Summary shipped = Summarise(rows, m, set.name, shippedF);
                const auto worst = WorstExposure(rows, m, set.name, shippedF, options.exposures);
                const auto lecture =
                    WorstExposure(rows, m, set.name, shippedF, options.exposures, lecturePairs);
                const Summary all =
                    Summarise(rows, m, set.name, {-1.0, hasShipped, key, PlateSource::CIE});
                // Without shipped forms (--ideal-only) the shipped column is
                // empty, and the worst exposure is the ideal form's.
                char shippedMean[16] = "       -";
                if (hasShipped)
                {
                    std::snprintf(shippedMean, sizeof shippedMean, "%8.2f", shipped.mean);
                }
                char line[320];
                std::snprintf(line, sizeof line,
                              "  %-10s %7.2f %s %8.2f (%-5s)   %6.2f %7.2f   %-26s %8.2f   %10s\n",
                              m.c_str(), ideal.mean, shippedMean, worst.second,
                              Stops(worst.first).c_str(), all.p95, all.max, all.worst.c_str(),
                              lecture.second,
                              costAll.count(m) ? Fixed(costAll.at(m), 2).c_str() : "-");
                out << line;
            }
            if (!plates.balanced())
            {
                for (const char* floor : {"floor-3x3", "floor-rootpoly"})
                {
                    const Summary f = Summarise(floorRows, floor, set.name, {1.0, false});
                    const Summary fl =
                        Summarise(floorRows, floor, set.name, {1.0, false}, lecturePairs);
                    char line[200];
                    std::snprintf(line, sizeof line,
                                  "  %-14s %5.2f   (fitted on this set itself: in-sample; "
                                  "A/F2/F11->D65 %.2f)\n",
                                  floor, f.mean, fl.mean);
                    out << line;
                }
            }
        }
        if (plates.balanced() && options.measureMismatch)
        {
            out << "\nlit looks on these balanced plates (the cast corrected twice), ideal, k = 1: "
                   "mean over pairs (A/F2/F11->D65)\n  method    ";
            for (const ReflectanceSet& set : options.sets)
            {
                char h[64];
                std::snprintf(h, sizeof h, " %20s", set.name.substr(0, 20).c_str());
                out << h;
            }
            out << "\n";
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
                    const Filter f{1.0, false, key + "-through-lit-looks", PlateSource::CIE};
                    std::snprintf(line, sizeof line, " %10.2f (%6.2f)",
                                  Summarise(rows, m, set.name, f).mean,
                                  Summarise(rows, m, set.name, f, lecturePairs).mean);
                    out << line;
                }
                out << "\n";
            }
        }
        bool anyCv = false;
        for (const std::string& m : options.methods)
        {
            const Summary in = Summarise(cvRows, m, "training, in-sample", {1.0, false, key});
            const Summary cv = Summarise(cvRows, m, "training, 5-fold", {1.0, false, key});
            if (in.mean == 0.0 && cv.mean == 0.0)
            {
                continue;
            }
            if (!anyCv)
            {
                out << "\nfitted methods on their own training data (ideal, k = 1): in-sample "
                       "against 5-fold cross-validated\n";
                anyCv = true;
            }
            const Summary inL =
                Summarise(cvRows, m, "training, in-sample", {1.0, false, key}, lecturePairs);
            const Summary cvL =
                Summarise(cvRows, m, "training, 5-fold", {1.0, false, key}, lecturePairs);
            char line[200];
            std::snprintf(line, sizeof line,
                          "  %-10s in-sample %5.2f  5-fold %5.2f   (A/F2/F11->D65: %5.2f, %5.2f)\n",
                          m.c_str(), in.mean, cv.mean, inL.mean, cvL.mean);
            out << line;
        }
        if (options.camera)
        {
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
                    if (FindMethod(m).isReference())
                    {
                        continue;
                    }
                    const bool cameraMethod = FindMethod(m).needsCamera;
                    const auto at = [&](PlateSource source, bool lecture)
                    {
                        return Summarise(rows, m, set.name, {1.0, false, key, source},
                                         lecture ? lecturePairs : Pairs{})
                            .mean;
                    };
                    char line[240];
                    if (cameraMethod)
                    {
                        std::snprintf(line, sizeof line, "  %-16s %18s %18s %18s %8.2f (%6.2f)\n",
                                      m.c_str(), "-", "-", "-",
                                      at(PlateSource::CAMERA_DAYLIGHT_IDT, false),
                                      at(PlateSource::CAMERA_DAYLIGHT_IDT, true));
                    }
                    else
                    {
                        std::snprintf(line, sizeof line,
                                      "  %-16s %8.2f (%6.2f) %8.2f (%6.2f) %+8.2f (%+6.2f) "
                                      "%8.2f (%6.2f)\n",
                                      m.c_str(), at(PlateSource::CIE, false),
                                      at(PlateSource::CIE, true), at(PlateSource::CAMERA, false),
                                      at(PlateSource::CAMERA, true),
                                      at(PlateSource::CAMERA, false) - at(PlateSource::CIE, false),
                                      at(PlateSource::CAMERA, true) - at(PlateSource::CIE, true),
                                      at(PlateSource::CAMERA_DAYLIGHT_IDT, false),
                                      at(PlateSource::CAMERA_DAYLIGHT_IDT, true));
                    }
                    out << line;
                }
            }
        }
    }
    if (!cost.empty())
    {
        out << "\ncost per pixel, 1920x1080 float RGBA (best of 3)\n";
        for (const CostRow& c : cost)
        {
            char line[160];
            std::snprintf(line, sizeof line,
                          "  %-10s %-12s %d thread%s %10.2f ns  %8.1f Mpixel/s\n", c.method.c_str(),
                          c.form.c_str(), c.threads, c.threads > 1 ? "s" : " ", c.nsPerPixel,
                          1e3 / c.nsPerPixel);
            out << line;
        }
        for (const SetupCost& s : setup)
        {
            out << "  one-off: " << s.what << ": " << Fixed(s.seconds, 3) << " s\n";
        }
    }

    return out.str();
}

}  // namespace bandlight::jobs
