// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Accuracy.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <mutex>
#include <optional>
#include <thread>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"
#include "transforms/Upsampler.h"

namespace bandlight
{

AccuracyOptions DefaultAccuracyOptions()
{
    AccuracyOptions o;
    for (const char* n : {"A", "C", "D50", "D65", "E", "F1", "F2", "F3", "F4", "F5", "F6", "F7",
                          "F8", "F9", "F10", "F11", "F12"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.methods = AllMethodNames();
    o.sets = {AllTcs(), HeldOutTcs(), RandomSmoothSet(100, 2, "random")};
    return o;
}

namespace
{

/// ΔE00 of predicted against reference colours (working RGB under `to`).
struct Errors
{
    double mean = 0.0, p95 = 0.0, max = 0.0;
    std::string worst;
};

/// How predictions are judged: their RGB → XYZ and the L*a*b* white.
struct Judge
{
    Mat3 rgbToXyz;
    Vec3 white;
};

Judge LitJudge(const SurfaceRenderer& to)
{
    return {to.rgbToXyz(), to.rgbToXyz() * to.white()};
}

Errors Score(const Judge& judge, const std::vector<Vec3>& predicted,
             const std::vector<Vec3>& reference, const std::vector<NamedSpectrum>& names)
{
    const Vec3& white = judge.white;
    std::vector<double> de;
    Errors e;
    double worst = -1.0;
    for (size_t k = 0; k < reference.size(); ++k)
    {
        const Vec3 p = predicted[k].allFinite() ? predicted[k] : Vec3(1e6, -1e6, 1e6);
        const double d = DeltaE2000(XyzToLab(judge.rgbToXyz * p, white),
                                    XyzToLab(judge.rgbToXyz * reference[k], white));
        de.push_back(d);
        if (d > worst)
        {
            worst = d;
            e.worst = names[k].name;
        }
    }
    const Statistics s = Summarise(std::move(de));
    e.mean = s.mean;
    e.p95 = s.p95;
    e.max = s.max;
    return e;
}

AccuracyRow MakeRow(const std::string& method, const Light& from, const Light& to,
                    const std::string& set, double exposure, bool shipped, const Errors& e,
                    const std::string& plates = "lit", PlateSource source = PlateSource::CIE)
{
    AccuracyRow r;
    r.plates = plates;
    r.source = source;
    r.method = method;
    r.from = from.name;
    r.to = to.name;
    r.set = set;
    r.exposure = exposure;
    r.shipped = shipped;
    r.mean = e.mean;
    r.p95 = e.p95;
    r.max = e.max;
    r.worstSample = e.worst;
    return r;
}

struct Pair
{
    size_t from, to;
};

std::vector<Pair> Pairs(const AccuracyOptions& o)
{
    std::vector<Pair> pairs;
    for (size_t i = 0; i < o.lights.size(); ++i)
    {
        for (size_t j = 0; j < o.lights.size(); ++j)
        {
            if (o.forwardOnly ? i < j : i != j)
            {
                pairs.push_back({i, j});
            }
        }
    }
    return pairs;
}

/// Runs `perPair(pair, rows)` for every pair on all cores, rows in pair order.
std::vector<AccuracyRow> ForEachPair(
    const AccuracyOptions& o, const std::function<void(double)>& progress,
    const std::function<void(const Light&, const Light&, std::vector<AccuracyRow>&)>& perPair)
{
    const std::vector<Pair> pairs = Pairs(o);
    std::vector<std::vector<AccuracyRow>> byPair(pairs.size());
    std::atomic<size_t> next{0};
    // Counted and reported under one lock, so progress arrives as 1/n, 2/n,
    // ... in order whichever thread finishes first (counted apart from the
    // report, two threads' reports could cross, and a step be lost).
    std::mutex reportMutex;
    size_t done = 0;
    ParallelRun(0, pairs.size(),
                [&]
                {
                    for (size_t p; (p = next++) < pairs.size();)
                    {
                        perPair(o.lights[pairs[p].from], o.lights[pairs[p].to], byPair[p]);
                        std::lock_guard<std::mutex> lock(reportMutex);
                        ++done;
                        if (progress)
                        {
                            progress(double(done) / double(pairs.size()));
                        }
                    }
                });
    std::vector<AccuracyRow> rows;
    for (auto& r : byPair)
    {
        rows.insert(rows.end(), r.begin(), r.end());
    }
    return rows;
}

/// The plate conventions' matrices for one pair.
struct PairPlates
{
    Plates plates;
    Mat3 balanceFrom = Mat3::Identity();  ///< lit under `from` → this convention's plate
    Mat3 balanceTo = Mat3::Identity();    ///< the truth under `to` → this convention's reference
    Judge judge;
};

PairPlates MakePairPlates(const Plates& p, const Light& from, const Light& to,
                          const SurfaceRenderer& r2, const RgbSpace& working, Observer observer)
{
    PairPlates out{p, Mat3::Identity(), Mat3::Identity(), LitJudge(r2)};
    if (p.balanced())
    {
        out.balanceFrom = BalanceMatrix(from.spectrum, working, p.adaptation, observer);
        out.balanceTo = BalanceMatrix(to.spectrum, working, p.adaptation, observer);
        out.judge = {r2.rgbToXyz(), WorkingWhiteXyz(working)};
    }
    return out;
}

MethodSpec WithPlates(MethodSpec m, const Plates& p, const AccuracyOptions& o)
{
    m.plates = p;
    m.camera = o.camera;
    m.idtLightName = o.idtLightName;
    m.idtLight = o.idtLight;
    return m;
}

/// How a simulation kind's plates are made: the observer's colour, or a
/// camera's record through the IDT fitted for one light.
enum class CameraIdt
{
    NONE,            ///< no camera: the colour the CIE observer sees
    SHOOTING_LIGHT,  ///< an IDT fitted (rawtoaces' way) for the light the plate was shot under
    /// Gains for the shooting light, then the one IDT fitted for the
    /// daylight (AccuracyOptions::idtLightName).
    DAYLIGHT,
};

/// One simulation kind: its key in the JSON document and the text report,
/// how its plates are made, and what is measured on them.
struct PlateSourceEntry
{
    PlateSource source;
    const char* key;
    CameraIdt idt;
    /// The shipped forms and the lit looks on balanced plates are measured
    /// on these plates too (the camera's plates take the ideal forms only).
    bool allForms;
    /// The camera methods (rootpoly-camera) are measured on these plates:
    /// they are made for the daylight IDT's plates only.
    bool cameraMethods;
};

// clang-format off
/// In measurement order, which is the rows' order.
constexpr PlateSourceEntry PLATE_SOURCES[] = {
    // source                          key                    IDT                        all forms  camera methods
    {PlateSource::CIE,                 "cie",                 CameraIdt::NONE,           true,      false},
    {PlateSource::CAMERA,              "camera",              CameraIdt::SHOOTING_LIGHT, false,     false},
    {PlateSource::CAMERA_DAYLIGHT_IDT, "camera-daylight-idt", CameraIdt::DAYLIGHT,       false,     true},
};
// clang-format on
static_assert(std::size(PLATE_SOURCES) == size_t(PlateSource::CAMERA_DAYLIGHT_IDT) + 1,
              "one entry per PlateSource");

const PlateSourceEntry& FindPlateSource(PlateSource source) noexcept
{
    for (const PlateSourceEntry& entry : PLATE_SOURCES)
    {
        if (entry.source == source)
        {
            return entry;
        }
    }
    return PLATE_SOURCES[0];
}

/// Remittances per set, each sampled once for the whole run.
using SampledSets = std::vector<std::vector<SurfaceRenderer::Samples>>;

/// What every pair of a run shares.
struct Run
{
    const AccuracyOptions& options;
    const RgbSpace& working;
    std::vector<MethodSpec> methods;  ///< parsed, each checked for the camera it needs
    SampledSets samples;
    /// upsample's fits under each source light, held for the whole run:
    /// every target light, plate convention and form (ideal, and the
    /// shipped lattice's nodes) shares them.
    std::vector<std::shared_ptr<void>> sharedPerLight;
    Spectrum daylight;  ///< the light of the camera's daylight IDT (empty: no camera)
};

std::vector<MethodSpec> ParseMethods(const AccuracyOptions& o)
{
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        methods.push_back(ParseMethod(m));
        RequireCamera(methods.back(), bool(o.camera));
    }
    return methods;
}

SampledSets SampleSets(const std::vector<ReflectanceSet>& sets)
{
    SampledSets samples(sets.size());
    for (size_t s = 0; s < sets.size(); ++s)
    {
        for (const NamedSpectrum& r : sets[s].samples)
        {
            samples[s].push_back(SurfaceRenderer::Sample(r.spectrum));
        }
    }
    return samples;
}

/// What the run's methods' ops share per source light (upsample's fits),
/// held for the whole run: each entry's share once per light.
std::vector<std::shared_ptr<void>> HoldSharedPerLight(const Run& run)
{
    std::vector<std::shared_ptr<void>> held;
    std::vector<SharedPerLight> makers;
    for (const MethodSpec& m : run.methods)
    {
        const SharedPerLight make = m.entry().sharedPerLight;
        if (make && std::find(makers.begin(), makers.end(), make) == makers.end())
        {
            makers.push_back(make);
        }
    }
    for (const SharedPerLight make : makers)
    {
        for (const Light& light : run.options.lights)
        {
            held.push_back(make(light, run.working, run.options.observer));
        }
    }
    return held;
}

Spectrum IdtDaylight(const AccuracyOptions& o)
{
    if (!o.camera)
    {
        return Spectrum();
    }
    return o.idtLight.empty() ? BuiltinIlluminant(o.idtLightName) : o.idtLight;
}

/// One pair of lights and the colours seen under each. The renderers are
/// the caller's locals, not members: Eigen picks a small product's packet
/// path by its operands' run-time alignment, so where a renderer lives can
/// move a figure's last bit, and the report and JSON are kept bit for bit.
struct LightPair
{
    const Light& from;
    const Light& to;
    const SurfaceRenderer& r1;  ///< under `from`
    const SurfaceRenderer& r2;  ///< under `to`
};

/// The plates one simulation kind delivers (before exposure), per set.
struct SourcePlates
{
    const PlateSourceEntry& kind;
    std::vector<std::vector<Vec3>> plate;
};

/// The observer's colours under `from`, in this convention's plates.
SourcePlates ObserverPlates(const Run& run, const LightPair& pair, const PairPlates& pp,
                            const PlateSourceEntry& kind)
{
    SourcePlates out{kind, {}};
    for (const auto& set : run.samples)
    {
        out.plate.emplace_back();
        for (const auto& r : set)
        {
            out.plate.back().push_back(pp.balanceFrom * pair.r1.render(r));
        }
    }
    return out;
}

/// The camera shooting under `from`, its records balanced by their IDT;
/// lit plates are those with the cast put back.
struct CameraRig
{
    CameraShot shot;
    Mat3 toPlate;  ///< a balanced record → this convention's plate

    CameraRig(const Run& run, const LightPair& pair, const PairPlates& pp)
        : shot(*run.options.camera, pair.from.spectrum),
          toPlate(pp.balanceFrom * BalanceMatrix(pair.from.spectrum, run.working,
                                                 pp.plates.adaptation, run.options.observer)
                                       .inverse())
    {
    }
};

/// The camera's plates through the IDT `kind` fits: for the shooting light,
/// or for the daylight.
SourcePlates CameraPlates(const Run& run, const LightPair& pair, const PairPlates& pp,
                          const CameraRig& rig, const PlateSourceEntry& kind)
{
    const AccuracyOptions& o = run.options;
    const Spectrum& idtLight =
        kind.idt == CameraIdt::SHOOTING_LIGHT ? pair.from.spectrum : run.daylight;
    const Mat3 m =
        rig.toPlate * FitIdt(*o.camera, idtLight, run.working, pp.plates.adaptation, o.observer);
    SourcePlates out{kind, {}};
    for (const auto& set : run.samples)
    {
        out.plate.emplace_back();
        for (const auto& r : set)
        {
            out.plate.back().push_back(m * rig.shot.record(r));
        }
    }
    return out;
}

/// The plates of every simulation kind the run has, in table order: the
/// observer's, and with a camera the camera's.
std::vector<SourcePlates> SimulatePlates(const Run& run, const LightPair& pair,
                                         const PairPlates& pp)
{
    std::vector<SourcePlates> sources;
    std::optional<CameraRig> rig;  // made once, for the first camera kind
    for (const PlateSourceEntry& kind : PLATE_SOURCES)
    {
        if (kind.idt == CameraIdt::NONE)
        {
            sources.push_back(ObserverPlates(run, pair, pp, kind));
        }
        else if (run.options.camera)
        {
            if (!rig)
            {
                rig.emplace(run, pair, pp);
            }
            sources.push_back(CameraPlates(run, pair, pp, *rig, kind));
        }
    }
    return sources;
}

/// A form takes the plates (already scaled by k) and gives the predictions:
/// the ideal form in double precision (the method's exact answer), the
/// shipped one as a host runs it, in float.
using Batch = std::function<void(std::vector<Vec3>&)>;

struct Form
{
    bool shipped;
    Batch apply;
    std::string plates;  ///< the rows' plates key
};

Batch Exact(const std::shared_ptr<Relighter>& r)
{
    return [r](std::vector<Vec3>& px) { r->apply(px.data(), px.size()); };
}

Batch AsFloat(const PixelBatch& f)
{
    return [f](std::vector<Vec3>& px)
    {
        std::vector<float> buffer(3 * px.size());
        for (size_t i = 0; i < px.size(); ++i)
        {
            for (int ch = 0; ch < 3; ++ch)
            {
                buffer[3 * i + size_t(ch)] = float(px[i][ch]);
            }
        }
        f(buffer.data(), px.size());
        for (size_t i = 0; i < px.size(); ++i)
        {
            px[i] = Vec3(buffer[3 * i], buffer[3 * i + 1], buffer[3 * i + 2]);
        }
    };
}

/// A method's relighters for one pair and plate convention: the ideal form,
/// and on balanced plates the lit looks (the doubled correction).
struct MethodForms
{
    MethodSpec method;
    std::shared_ptr<Relighter> ideal;
    std::shared_ptr<Relighter> litLooks;  ///< nullptr: not measured
};

MethodForms MakeMethodForms(const Run& run, const LightPair& pair, const Plates& plates,
                            const MethodSpec& parsed)
{
    const AccuracyOptions& o = run.options;
    MethodForms out{WithPlates(parsed, plates, o), nullptr, nullptr};
    out.ideal =
        std::make_shared<Relighter>(pair.from, pair.to, out.method, run.working, o.observer);
    if (o.measureMismatch && plates.balanced())
    {
        out.litLooks = std::make_shared<Relighter>(
            pair.from, pair.to, WithPlates(parsed, Plates::Lit(), o), run.working, o.observer);
    }
    return out;
}

/// The forms measured on one kind's plates: the ideal form, and on the
/// kinds that take all forms the shipped form and the lit looks.
std::vector<Form> FormsOn(const Run& run, const LightPair& pair, const PairPlates& pp,
                          const MethodForms& mf, const PlateSourceEntry& kind)
{
    const AccuracyOptions& o = run.options;
    const std::string key = pp.plates.key();
    std::vector<Form> forms = {{false, Exact(mf.ideal), key}};
    if (!kind.allForms)
    {
        return forms;
    }
    if (o.shipped)
    {
        if (PixelBatch shipped = o.shipped(pair.from, pair.to, mf.method))
        {
            forms.push_back({true, AsFloat(shipped), key});
        }
    }
    if (mf.litLooks)
    {
        forms.push_back({false, Exact(mf.litLooks), ThroughLitLooksKey(pp.plates)});
    }
    return forms;
}

/// The rows of one set: its colours at every exposure through each form,
/// divided by the exposure again and scored against the truth under `to`.
void MeasureSet(const Run& run, const LightPair& pair, const PairPlates& pp,
                const std::string& method, const SourcePlates& source,
                const std::vector<Form>& forms, size_t s, std::vector<AccuracyRow>& rows)
{
    const AccuracyOptions& o = run.options;
    const size_t n = run.samples[s].size();
    std::vector<Vec3> reference(n);
    for (size_t i = 0; i < n; ++i)
    {
        reference[i] = pp.balanceTo * pair.r2.render(run.samples[s][i]);
    }
    // Colour-major: a colour's exposures side by side.
    const size_t ne = o.exposures.size();
    for (const Form& form : forms)
    {
        std::vector<Vec3> px(n * ne);
        for (size_t i = 0; i < n; ++i)
        {
            for (size_t e = 0; e < ne; ++e)
            {
                px[i * ne + e] = o.exposures[e] * source.plate[s][i];
            }
        }
        form.apply(px);
        for (size_t e = 0; e < ne; ++e)
        {
            std::vector<Vec3> predicted(n);
            for (size_t i = 0; i < n; ++i)
            {
                predicted[i] = px[i * ne + e] / o.exposures[e];
            }
            rows.push_back(MakeRow(method, pair.from, pair.to, o.sets[s].name, o.exposures[e],
                                   form.shipped,
                                   Score(pp.judge, predicted, reference, o.sets[s].samples),
                                   form.plates, source.kind.source));
        }
    }
}

/// The reference method (the spectral answer itself) scores 0 everywhere.
void ReferenceRows(const Run& run, const LightPair& pair, const Plates& plates,
                   const std::string& method, std::vector<AccuracyRow>& rows)
{
    const AccuracyOptions& o = run.options;
    for (const ReflectanceSet& set : o.sets)
    {
        for (const double k : o.exposures)
        {
            rows.push_back(
                MakeRow(method, pair.from, pair.to, set.name, k, false, Errors{}, plates.key()));
        }
    }
}

/// One method on every kind's plates that it is measured on.
void MeasureMethod(const Run& run, const LightPair& pair, const PairPlates& pp,
                   const std::vector<SourcePlates>& sources, const MethodSpec& parsed,
                   std::vector<AccuracyRow>& rows)
{
    if (parsed.entry().isReference())
    {
        ReferenceRows(run, pair, pp.plates, parsed.name, rows);
        return;
    }
    const MethodForms mf = MakeMethodForms(run, pair, pp.plates, parsed);
    for (const SourcePlates& source : sources)
    {
        if (mf.method.entry().needsCamera && !source.kind.cameraMethods)
        {
            continue;
        }
        const std::vector<Form> forms = FormsOn(run, pair, pp, mf, source.kind);
        for (size_t s = 0; s < run.options.sets.size(); ++s)
        {
            MeasureSet(run, pair, pp, mf.method.name, source, forms, s, rows);
        }
    }
}

/// Every plate convention, kind and method for one pair of lights.
void MeasurePair(const Run& run, const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
{
    const AccuracyOptions& o = run.options;
    const SurfaceRenderer r1(from.spectrum, run.working, o.observer);
    const SurfaceRenderer r2(to.spectrum, run.working, o.observer);
    const LightPair pair{from, to, r1, r2};
    for (const Plates& plates : o.plates)
    {
        const PairPlates pp = MakePairPlates(plates, from, to, pair.r2, run.working, o.observer);
        const std::vector<SourcePlates> sources = SimulatePlates(run, pair, pp);
        for (const MethodSpec& parsed : run.methods)
        {
            MeasureMethod(run, pair, pp, sources, parsed, rows);
        }
    }
}

}  // namespace

const char* PlateSourceName(PlateSource source) noexcept
{
    return FindPlateSource(source).key;
}

std::string ThroughLitLooksKey(const Plates& balanced)
{
    return balanced.key() + "-through-lit-looks";
}

std::string InSampleSetName()
{
    return "training, in-sample";
}

std::string CrossValidatedSetName(int folds)
{
    return "training, " + std::to_string(folds) + "-fold";
}

const std::vector<std::string>& FloorMethodNames()
{
    static const std::vector<std::string> names = {"floor-3x3", "floor-rootpoly"};
    return names;
}

size_t PairCount(const AccuracyOptions& options)
{
    return Pairs(options).size();
}

std::vector<AccuracyRow> MeasureAccuracy(const AccuracyOptions& o,
                                         const std::function<void(double)>& progress)
{
    // In this order, as each may throw: the working space, the methods
    // (and the camera they need), the remittances, upsample's fits, the
    // daylight IDT's light.
    Run run{o, FindRgbSpace(o.workingSpace), ParseMethods(o), SampleSets(o.sets), {}, {}};
    run.sharedPerLight = HoldSharedPerLight(run);
    run.daylight = IdtDaylight(o);
    return ForEachPair(o, progress,
                       [&run](const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
                       { MeasurePair(run, from, to, rows); });
}

std::vector<AccuracyRow> CrossValidate(const AccuracyOptions& o, int folds)
{
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        const MethodSpec spec = ParseMethod(m);
        if (spec.entry().takesTraining)
        {
            methods.push_back(spec);
        }
    }
    if (methods.empty() || folds < 2)
    {
        return {};
    }
    const std::string inSample = InSampleSetName();
    const std::string crossName = CrossValidatedSetName(folds);
    return ForEachPair(
        o, {},
        [&](const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
        {
            const SurfaceRenderer r1(from.spectrum, working, o.observer);
            const SurfaceRenderer r2(to.spectrum, working, o.observer);
            for (const Plates& plates : o.plates)
            {
                const PairPlates pp = MakePairPlates(plates, from, to, r2, working, o.observer);
                for (const MethodSpec& parsed : methods)
                {
                    const MethodSpec method = WithPlates(parsed, plates, o);
                    const std::vector<NamedSpectrum>& all = TrainingOf(method);
                    const auto evaluate = [&](const MethodSpec& fitted,
                                              const std::vector<NamedSpectrum>& test,
                                              std::vector<Vec3>& predicted, std::vector<Vec3>& ref)
                    {
                        const Relighter relight(from, to, fitted, working, o.observer);
                        for (const NamedSpectrum& t : test)
                        {
                            const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
                            predicted.push_back(relight.apply(pp.balanceFrom * r1.render(r)));
                            ref.push_back(pp.balanceTo * r2.render(r));
                        }
                    };
                    {
                        MethodSpec fitted = method;
                        fitted.training = all;
                        std::vector<Vec3> predicted, ref;
                        evaluate(fitted, all, predicted, ref);
                        rows.push_back(MakeRow(method.name, from, to, inSample, 1.0, false,
                                               Score(pp.judge, predicted, ref, all), plates.key()));
                    }
                    // Folds by position (every folds-th sample), the same for every pair.
                    std::vector<Vec3> predicted, ref;
                    std::vector<NamedSpectrum> order;
                    for (int f = 0; f < folds; ++f)
                    {
                        MethodSpec fitted = method;
                        std::vector<NamedSpectrum> test;
                        for (size_t i = 0; i < all.size(); ++i)
                        {
                            (int(i % size_t(folds)) == f ? test : fitted.training)
                                .push_back(all[i]);
                        }
                        evaluate(fitted, test, predicted, ref);
                        order.insert(order.end(), test.begin(), test.end());
                    }
                    rows.push_back(MakeRow(method.name, from, to, crossName, 1.0, false,
                                           Score(pp.judge, predicted, ref, order), plates.key()));
                }
            }
        });
}

std::vector<AccuracyRow> MeasureFloor(const AccuracyOptions& o)
{
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    return ForEachPair(
        o, {},
        [&](const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
        {
            const SurfaceRenderer r1(from.spectrum, working, o.observer);
            const SurfaceRenderer r2(to.spectrum, working, o.observer);
            for (const ReflectanceSet& set : o.sets)
            {
                const Mat3 m = FitLabMatrix(r1, r2, set.samples);
                const RootPolynomial rp = FitRootPolynomial(r1, r2, set.samples, 2);
                std::vector<Vec3> by3x3, byRoot, ref;
                for (const NamedSpectrum& t : set.samples)
                {
                    const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
                    by3x3.push_back(m * r1.render(r));
                    byRoot.push_back(rp.apply(r1.render(r)));
                    ref.push_back(r2.render(r));
                }
                rows.push_back(MakeRow(FloorMethodNames()[0], from, to, set.name, 1.0, false,
                                       Score(LitJudge(r2), by3x3, ref, set.samples)));
                rows.push_back(MakeRow(FloorMethodNames()[1], from, to, set.name, 1.0, false,
                                       Score(LitJudge(r2), byRoot, ref, set.samples)));
            }
        });
}

}  // namespace bandlight
