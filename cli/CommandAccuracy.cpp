// SPDX-License-Identifier: BSD-3-Clause
// `bandlight accuracy`: every method against the spectral reference, and
// what each costs — one table, one JSON document, one picture.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "cli/Common.h"
#include "cli/Cost.h"
#include "cli/Diagnostics.h"
#include "cli/Gnuplot.h"
#include "plugin/OcioTransforms.h"
#include "spectral/AtomicFile.h"
#include "spectral/Exception.h"
#include "transforms/Accuracy.h"

namespace bandlight::cli
{

namespace
{

struct AccuracyCommandOptions
{
    std::string illuminants;
    std::string methods;
    std::vector<std::string> reflectances;
    std::string workingSpace = "acescg";
    std::string json;
    std::string plot;
    bool noCost = false;
    bool idealOnly = false;
    int lutSize = 65;
    PlatesOptions plates;
};

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
    std::string source = "cie";
};

Summary Summarise(const std::vector<AccuracyRow>& rows, const std::string& method,
                  const std::string& set, Filter f,
                  const std::vector<std::pair<std::string, std::string>>& onlyPairs = {})
{
    Summary s;
    std::vector<double> p95s;
    int n = 0;
    for (const AccuracyRow& r : rows)
    {
        if (r.method != method || r.set != set || r.shipped != f.shipped || r.plates != f.plates ||
            r.source != f.source || (f.exposure > 0.0 && r.exposure != f.exposure))
        {
            continue;
        }
        if (!onlyPairs.empty() && std::find(onlyPairs.begin(), onlyPairs.end(),
                                            std::pair{r.from, r.to}) == onlyPairs.end())
        {
            continue;
        }
        s.mean += r.mean;
        p95s.push_back(r.p95);
        if (r.max > s.max)
        {
            s.max = r.max;
            s.worst = r.worstSample + " " + r.from + "->" + r.to;
        }
        ++n;
    }
    s.mean = n ? s.mean / n : 0.0;
    s.p95 = Percentile(p95s, 0.95);
    return s;
}

/// The exposure whose mean is worst, and that mean.
std::pair<double, double> WorstExposure(
    const std::vector<AccuracyRow>& rows, const std::string& method, const std::string& set,
    Filter f, const std::vector<double>& exposures,
    const std::vector<std::pair<std::string, std::string>>& onlyPairs = {})
{
    std::pair<double, double> worst{1.0, -1.0};
    for (const double k : exposures)
    {
        f.exposure = k;
        const double m = Summarise(rows, method, set, f, onlyPairs).mean;
        if (m > worst.second)
        {
            worst = {k, m};
        }
    }
    return worst;
}

/// "2^-8" for 1/256.
std::string Stops(double k)
{
    const int e = int(std::lround(std::log2(k)));
    return e == 0 ? "1" : "2^" + std::to_string(e);
}

void Plot(const std::string& path, const std::vector<std::string>& methods,
          const std::map<std::string, double>& error, const std::map<std::string, double>& cost,
          const std::string& setName, OutputSet& outputs)
{
    // One point per method (ns/pixel, mean ΔE00), the Pareto front joined:
    // the methods no other method beats in both error and cost.
    struct Point
    {
        std::string name;
        double ns, de;
    };
    std::vector<Point> pts;
    for (const std::string& m : methods)
    {
        if (cost.count(m) && error.count(m))
        {
            pts.push_back({m, std::max(cost.at(m), 1e-3), error.at(m)});
        }
    }
    std::sort(pts.begin(), pts.end(),
              [](const Point& a, const Point& b)
              { return a.ns < b.ns || (a.ns == b.ns && a.de < b.de); });
    // Labels of methods at the same cost alternate right and left of their points.
    std::ostringstream data;
    for (size_t i = 0; i < pts.size(); ++i)
    {
        size_t rank = 0;
        for (size_t k = 0; k < i; ++k)
        {
            rank += pts[k].ns == pts[i].ns ? 1 : 0;
        }
        data << pts[i].ns << " " << pts[i].de << " " << GnuplotDataLabel(pts[i].name) << " "
             << (rank % 2 ? -1 : 1) << "\n";
    }
    data << "\n\n";
    double best = 1e30;
    for (const Point& p : pts)
    {
        if (p.de < best)
        {
            best = p.de;
            data << p.ns << " " << p.de << "\n";
        }
    }
    const std::string script = "set title " +
                               GnuplotQuote("What accuracy costs: re-lighting " + setName +
                                            ", as shipped, at its worst exposure (2^-8 ... 2^4), "
                                            "mean over every illuminant pair") +
                               "\n"
                               "set xlabel 'cost, ns per pixel (all threads, log scale)'\n"
                               "set ylabel 'mean CIEDE2000 against the spectral answer'\n"
                               "set logscale x\nset grid\nset key top right\nset yrange [0:*]\n"
                               "set offsets graph 0.1, graph 0.1, graph 0.08, 0\n"
                               "plot $bandlight_data index 1 using 1:2 with lines lw 2 lc rgb "
                               "'#2a7ab0' title 'Pareto front', \\\n"
                               "     $bandlight_data index 0 using 1:2 with points pt 7 ps 1.4 lc "
                               "rgb '#c0392b' notitle, \\\n"
                               "     $bandlight_data index 0 using 1:($4 > 0 ? $2 : 1/0):3 with "
                               "labels left offset char 1,0 "
                               "font ',10' notitle, \\\n"
                               "     $bandlight_data index 0 using 1:($4 < 0 ? $2 : 1/0):3 with "
                               "labels right offset char -1,0 "
                               "font ',10' notitle\n";
    RunGnuplot(script, data.str(), path, &outputs);
}

void RunAccuracy(const AccuracyCommandOptions& o)
{
    AccuracyOptions options = DefaultAccuracyOptions();
    options.workingSpace = o.workingSpace;
    FindRgbSpace(o.workingSpace);
    if (!o.illuminants.empty())
    {
        options.lights.clear();
        for (const std::string& name : SplitList(o.illuminants))
        {
            const NamedSpectrum s = ResolveIlluminant(name);
            options.lights.push_back({s.name, s.spectrum});
        }
        if (options.lights.size() < 2)
        {
            throw Exception("accuracy needs at least two illuminants");
        }
    }
    if (!o.methods.empty())
    {
        options.methods = SplitList(o.methods);
    }
    if (o.plates.plates == "both")
    {
        options.plates = {ParsePlates("balanced", o.plates.adaptation),
                          ParsePlates("lit", o.plates.adaptation)};
    }
    else
    {
        options.plates = {o.plates.parsed()};
    }
    options.camera = o.plates.loadCamera();
    if (options.camera)
    {
        const NamedSpectrum idt = ResolveIlluminant(o.plates.idtLight);
        options.idtLightName = idt.name;
        options.idtLight = idt.spectrum;
        if (o.methods.empty())
        {
            options.methods.push_back("rootpoly-camera");
        }
    }
    options.methods.push_back("spectral");
    for (const std::string& m : options.methods)
    {
        const MethodSpec spec = ParseMethod(m);
        if (spec.method == ChangeMethod::ROOTPOLY_CAMERA && !options.camera)
        {
            throw Exception("method '" + spec.name +
                            "' needs the camera that shot the plates (--camera FILE)");
        }
    }
    for (const std::string& file : o.reflectances)
    {
        options.sets.push_back({file, ReadSpectraFile(file)});
    }
    if (!o.idealOnly)
    {
        // The shipped form: the OCIO processor of the transform a config's
        // look holds (guard + matrix, or shaper + 3D LUT + inverse shaper).
        const RgbSpace& working = FindRgbSpace(options.workingSpace);
        const Observer observer = options.observer;
        const int lutSize = o.lutSize;
        options.shipped = [&working, observer, lutSize](const Light& from, const Light& to,
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

    const size_t pairs = options.lights.size() * (options.lights.size() - 1);
    Progress("accuracy: " + std::to_string(options.methods.size()) + " methods x " +
             std::to_string(pairs) + " illuminant pairs x " + std::to_string(options.sets.size()) +
             " reflectance sets");
    std::mutex mu;
    int lastTenth = -1;
    const std::vector<AccuracyRow> rows = MeasureAccuracy(
        options,
        [&](double f)
        {
            std::lock_guard<std::mutex> lock(mu);
            const int tenth = int(f * 10.0);
            if (tenth != lastTenth)
            {
                lastTenth = tenth;
                Progress("accuracy: " + std::to_string(int(f * 100.0 + 0.5)) + "% of pairs done");
            }
        });

    Progress("accuracy: cross-validating the fitted methods and fitting the floor");
    const std::vector<AccuracyRow> cvRows = CrossValidate(options, 5);
    const std::vector<AccuracyRow> floorRows = MeasureFloor(options);

    std::vector<CostRow> cost;
    std::vector<SetupCost> setup;
    if (!o.noCost)
    {
        Progress("accuracy: timing each method on 1920x1080 float RGBA");
        cost = MeasureCost(options.methods, options.workingSpace, 1920L * 1080L);
        setup = MeasureSetupCost(options.workingSpace);
    }
    // Cost of each method as one would apply it to an image (all threads):
    // its OCIO form, and the per-pixel computation for spectral. Every 3×3
    // costs the same — one matrix per pixel, bound by memory — so the 3×3
    // methods share the median of their timings rather than their noise.
    std::map<std::string, double> costAll;
    std::vector<double> matrixCosts;
    const int allThreads = int(std::max(1u, std::thread::hardware_concurrency()));
    for (const CostRow& c : cost)
    {
        if (c.threads == allThreads && c.form != "direct-fit" && c.form != "native")
        {
            costAll[c.method] = c.nsPerPixel;
            if (c.form == "ocio-matrix")
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

    const std::string heldOut = HeldOutTcs().name;
    const std::vector<std::pair<std::string, std::string>> lecturePairs = {
        {"A", "D65"}, {"F2", "D65"}, {"F11", "D65"}};
    const bool anyShipped = bool(options.shipped);
    std::map<std::string, double> plotError;
    // With --json - stdout carries the JSON alone.
    std::ostringstream table;
    std::ostream& out = o.json == "-" ? table : std::cout;
    out << "Re-lighting accuracy, CIEDE2000 against the spectral answer (" << options.lights.size()
        << " illuminants, " << pairs << " ordered pairs, "
        << FindRgbSpace(o.workingSpace).displayName << "), exposures "
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
                << "  method       ideal  shipped  shipped worst (at)   p95     max   worst "
                   "sample and pair      A/F2/F11->D65 worst  ns/pixel\n";
            for (const std::string& m : options.methods)
            {
                if (m == "rootpoly-camera" || m == "rootpoly3-camera")
                {
                    continue;  // measured on camera plates below
                }
                const Filter idealF{1.0, false, key, "cie"};
                const bool hasShipped = anyShipped && m != "spectral";
                const Filter shippedF{1.0, hasShipped, key, "cie"};
                const Summary ideal = Summarise(rows, m, set.name, idealF);
                const Summary shipped = Summarise(rows, m, set.name, shippedF);
                const auto worst = WorstExposure(rows, m, set.name, shippedF, options.exposures);
                const auto lecture =
                    WorstExposure(rows, m, set.name, shippedF, options.exposures, lecturePairs);
                const Summary all = Summarise(rows, m, set.name, {-1.0, hasShipped, key, "cie"});
                if (set.name == heldOut && &plates == &options.plates.front())
                {
                    plotError[m] = worst.second;
                }
                char line[320];
                std::snprintf(
                    line, sizeof line,
                    "  %-10s %7.2f %8.2f %8.2f (%-5s)   %6.2f %7.2f   %-26s %8.2f   %10s\n",
                    m.c_str(), ideal.mean, shipped.mean, worst.second, Stops(worst.first).c_str(),
                    all.p95, all.max, all.worst.c_str(), lecture.second,
                    costAll.count(m) ? Fixed(costAll[m], 2).c_str() : "-");
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
                if (m == "spectral" || m == "none" || m.find("-camera") != std::string::npos)
                {
                    continue;
                }
                char line[64];
                std::snprintf(line, sizeof line, "  %-10s", m.c_str());
                out << line;
                for (const ReflectanceSet& set : options.sets)
                {
                    const Filter f{1.0, false, key + "-through-lit-looks", "cie"};
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
                    if (m == "spectral")
                    {
                        continue;
                    }
                    const bool cameraMethod = m.find("-camera") != std::string::npos;
                    const auto at = [&](const std::string& source, bool lecture)
                    {
                        return Summarise(rows, m, set.name, {1.0, false, key, source},
                                         lecture
                                             ? lecturePairs
                                             : std::vector<std::pair<std::string, std::string>>{})
                            .mean;
                    };
                    char line[240];
                    if (cameraMethod)
                    {
                        std::snprintf(line, sizeof line, "  %-16s %18s %18s %18s %8.2f (%6.2f)\n",
                                      m.c_str(), "-", "-", "-", at("camera-daylight-idt", false),
                                      at("camera-daylight-idt", true));
                    }
                    else
                    {
                        std::snprintf(
                            line, sizeof line,
                            "  %-16s %8.2f (%6.2f) %8.2f (%6.2f) %+8.2f (%+6.2f) "
                            "%8.2f (%6.2f)\n",
                            m.c_str(), at("cie", false), at("cie", true), at("camera", false),
                            at("camera", true), at("camera", false) - at("cie", false),
                            at("camera", true) - at("cie", true), at("camera-daylight-idt", false),
                            at("camera-daylight-idt", true));
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

    // The JSON file and the plot are one set of outputs.
    OutputSet outputs;
    std::string wrote;
    if (!o.json.empty())
    {
        nlohmann::ordered_json j;
        const auto toJson = [](const std::vector<AccuracyRow>& from)
        {
            nlohmann::ordered_json a = nlohmann::ordered_json::array();
            for (const AccuracyRow& r : from)
            {
                a.push_back({{"method", r.method},
                             {"from", r.from},
                             {"to", r.to},
                             {"set", r.set},
                             {"plates", r.plates},
                             {"camera", r.source},
                             {"exposure", r.exposure},
                             {"shipped", r.shipped},
                             {"mean", r.mean},
                             {"p95", r.p95},
                             {"max", r.max},
                             {"worst_sample", r.worstSample}});
            }
            return a;
        };
        if (options.camera)
        {
            j["camera"] = {{"name", options.camera->name()},
                           {"file", o.plates.camera},
                           {"idt_light", options.idtLightName}};
        }
        else
        {
            j["camera"] = nullptr;
        }
        j["rows"] = toJson(rows);
        j["cross_validation"] = toJson(cvRows);
        j["floor"] = toJson(floorRows);
        j["cost"] = nlohmann::ordered_json::array();
        for (const CostRow& c : cost)
        {
            j["cost"].push_back({{"method", c.method},
                                 {"form", c.form},
                                 {"ns_per_pixel", c.nsPerPixel},
                                 {"mpixel_per_s", 1e3 / c.nsPerPixel},
                                 {"threads", c.threads}});
        }
        j["setup_cost"] = nlohmann::ordered_json::array();
        for (const SetupCost& s : setup)
        {
            j["setup_cost"].push_back({{"what", s.what}, {"seconds", s.seconds}});
        }
        if (o.json == "-")
        {
            std::cout << j.dump(2) << "\n";
        }
        else
        {
            outputs.write(o.json, [&](std::ostream& os) { os << j.dump(2) << "\n"; });
            wrote += "accuracy: wrote " + o.json + "\n";
        }
    }
    if (!o.plot.empty())
    {
        if (costAll.empty())
        {
            throw Exception("--plot needs the cost measurement (drop --no-cost)");
        }
        Plot(o.plot, options.methods, plotError, costAll, heldOut, outputs);
        wrote += "accuracy: wrote " + o.plot + "\n";
    }
    outputs.commit();
    std::cerr << wrote;
}

}  // namespace

void AddAccuracyCommand(CLI::App& app)
{
    auto o = std::make_shared<AccuracyCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "accuracy",
        "CIEDE2000 of every method against the spectral answer, and what each costs per pixel");
    cmd->add_option("--illuminants", o->illuminants,
                    "Comma-separated illuminants (default: A,C,D50,D65,E,F1-F12)");
    cmd->add_option("--methods", o->methods,
                    "Comma-separated methods (default: all image methods: none, vonkries, "
                    "bradford, cat02, band3, band3-wp, band6, band6-wp, fit3x3, prefilter, "
                    "metamer, upsample, rootpoly, rootpoly3)");
    cmd->add_option("--reflectances", o->reflectances,
                    "CSV or CGATS file of remittances to add as a set (repeatable)");
    cmd->add_option("--working-space", o->workingSpace, "Working space")->capture_default_str();
    cmd->add_option("--json", o->json, "Write all rows and costs as JSON to FILE (- for stdout)");
    cmd->add_option("--plot", o->plot, "Draw accuracy against cost into FILE.png or FILE.svg");
    cmd->add_flag("--no-cost", o->noCost, "Skip the timing");
    cmd->add_option("--lut-size", o->lutSize,
                    "3D LUT size of the shipped non-linear looks (as `config --lut-size`)")
        ->check(CLI::Range(2, 129))
        ->capture_default_str();
    cmd->add_flag("--ideal-only", o->idealOnly,
                  "Measure only the methods' exact forms, not the OCIO transforms that ship");
    o->plates.plates = "both";
    AddPlatesOptions(*cmd, o->plates, true);
    cmd->callback([o] { RunAccuracy(*o); });
}

}  // namespace bandlight::cli
