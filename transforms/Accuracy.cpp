// SPDX-License-Identifier: BSD-3-Clause
// The default comparison, and MeasureAccuracy: every method on the plates of
// each simulation kind (the observer's colour, a camera's record through its
// IDT), in each plate convention and form, at every exposure. What the
// accuracy measures share is transforms/AccuracyScoring.cpp; the fitted
// methods' measures (CrossValidate, MeasureFloor) are
// transforms/AccuracyFitted.cpp.
#include "transforms/Accuracy.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/Upsampler.h"
#include "transforms/detail/AccuracyParts.h"

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

using detail::Errors;
using detail::ForEachPair;
using detail::MakePairPlates;
using detail::MakeRow;
using detail::PairPlates;
using detail::Score;
using detail::WithPlates;

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

}  // namespace bandlight
