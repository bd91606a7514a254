// SPDX-License-Identifier: BSD-3-Clause
#include "bandlight/transforms/Accuracy.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include <Eigen/LU>

#include "bandlight/spectral/Exception.h"
#include "bandlight/spectral/Illuminants.h"
#include "bandlight/spectral/Parallel.h"
#include "bandlight/transforms/Upsampler.h"

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

double Percentile(std::vector<double> values, double p)
{
    if (values.empty())
    {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    const size_t rank = size_t(std::ceil(p * double(values.size())));
    return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
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
        e.mean += d;
        if (d > worst)
        {
            worst = d;
            e.worst = names[k].name;
        }
    }
    e.mean = de.empty() ? 0.0 : e.mean / double(de.size());
    e.p95 = Percentile(de, 0.95);
    e.max = std::max(worst, 0.0);
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

}  // namespace

const char* PlateSourceName(PlateSource source) noexcept
{
    switch (source)
    {
        case PlateSource::CAMERA:
            return "camera";
        case PlateSource::CAMERA_DAYLIGHT_IDT:
            return "camera-daylight-idt";
        case PlateSource::CIE:
        default:
            return "cie";
    }
}

size_t PairCount(const AccuracyOptions& options)
{
    return Pairs(options).size();
}

std::vector<AccuracyRow> MeasureAccuracy(const AccuracyOptions& o,
                                         const std::function<void(double)>& progress)
{
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        methods.push_back(ParseMethod(m));
        RequireCamera(methods.back(), bool(o.camera));
    }
    // Remittances sampled once.
    std::vector<std::vector<SurfaceRenderer::Samples>> samples(o.sets.size());
    for (size_t s = 0; s < o.sets.size(); ++s)
    {
        for (const NamedSpectrum& r : o.sets[s].samples)
        {
            samples[s].push_back(SurfaceRenderer::Sample(r.spectrum));
        }
    }
    // upsample's fits under each source light, held for the whole run: every
    // target light, plate convention and form (ideal, and the shipped
    // lattice's nodes) shares them.
    std::vector<std::shared_ptr<UpsampleFits>> fits;
    if (std::any_of(methods.begin(), methods.end(),
                    [](const MethodSpec& m) { return m.entry().kernel == MethodKernel::UPSAMPLE; }))
    {
        for (const Light& light : o.lights)
        {
            fits.push_back(
                UpsampleFits::ForSource(SurfaceRenderer(light.spectrum, working, o.observer)));
        }
    }
    const Spectrum daylight = !o.camera            ? Spectrum()
                              : o.idtLight.empty() ? BuiltinIlluminant(o.idtLightName)
                                                   : o.idtLight;
    return ForEachPair(
        o, progress,
        [&](const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
        {
            const SurfaceRenderer r1(from.spectrum, working, o.observer);
            const SurfaceRenderer r2(to.spectrum, working, o.observer);
            for (const Plates& plates : o.plates)
            {
                const PairPlates pp = MakePairPlates(plates, from, to, r2, working, o.observer);
                // The plates each source delivers (before exposure), per set.
                struct Source
                {
                    PlateSource name;
                    std::vector<std::vector<Vec3>> plate;
                };
                std::vector<Source> sources(1);
                sources[0].name = PlateSource::CIE;
                for (size_t s = 0; s < o.sets.size(); ++s)
                {
                    sources[0].plate.emplace_back();
                    for (const auto& r : samples[s])
                    {
                        sources[0].plate.back().push_back(pp.balanceFrom * r1.render(r));
                    }
                }
                if (o.camera)
                {
                    // The camera's plates are balanced by their IDT; lit
                    // plates are those with the cast put back.
                    const CameraShot shot(*o.camera, from.spectrum);
                    const Mat3 toPlate =
                        pp.balanceFrom *
                        BalanceMatrix(from.spectrum, working, plates.adaptation, o.observer)
                            .inverse();
                    const Mat3 idts[2] = {
                        FitIdt(*o.camera, from.spectrum, working, plates.adaptation, o.observer),
                        FitIdt(*o.camera, daylight, working, plates.adaptation, o.observer)};
                    const PlateSource names[2] = {PlateSource::CAMERA,
                                                  PlateSource::CAMERA_DAYLIGHT_IDT};
                    for (int k = 0; k < 2; ++k)
                    {
                        Source src{names[k], {}};
                        const Mat3 m = toPlate * idts[k];
                        for (size_t s = 0; s < o.sets.size(); ++s)
                        {
                            src.plate.emplace_back();
                            for (const auto& r : samples[s])
                            {
                                src.plate.back().push_back(m * shot.record(r));
                            }
                        }
                        sources.push_back(std::move(src));
                    }
                }
                for (const MethodSpec& parsed : methods)
                {
                    const MethodSpec method = WithPlates(parsed, plates, o);
                    if (method.entry().isReference())
                    {
                        for (size_t s = 0; s < o.sets.size(); ++s)
                        {
                            for (const double k : o.exposures)
                            {
                                rows.push_back(MakeRow(method.name, from, to, o.sets[s].name, k,
                                                       false, Errors{}, plates.key()));
                            }
                        }
                        continue;
                    }
                    const auto relight =
                        std::make_shared<Relighter>(from, to, method, working, o.observer);
                    // Lit looks on balanced plates: the doubled correction.
                    std::shared_ptr<Relighter> litLooks;
                    if (o.measureMismatch && plates.balanced())
                    {
                        litLooks = std::make_shared<Relighter>(
                            from, to, WithPlates(parsed, Plates::Lit(), o), working, o.observer);
                    }
                    for (const Source& source : sources)
                    {
                        // rootpoly-camera is made for the daylight-IDT plates only.
                        const bool cameraMethod = method.entry().needsCamera;
                        if (cameraMethod && source.name != PlateSource::CAMERA_DAYLIGHT_IDT)
                        {
                            continue;
                        }
                        // A form takes the plates (already scaled by k) and gives the
                        // predictions: the ideal form in double precision (the method's
                        // exact answer), the shipped one as a host runs it, in float.
                        using Batch = std::function<void(std::vector<Vec3>&)>;
                        struct Form
                        {
                            bool shipped;
                            Batch apply;
                            std::string plates;
                        };
                        const auto exact = [](const std::shared_ptr<Relighter>& r) -> Batch
                        { return [r](std::vector<Vec3>& px) { r->apply(px.data(), px.size()); }; };
                        const auto asFloat = [](const PixelBatch& f) -> Batch
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
                                    px[i] =
                                        Vec3(buffer[3 * i], buffer[3 * i + 1], buffer[3 * i + 2]);
                                }
                            };
                        };
                        std::vector<Form> forms = {{false, exact(relight), plates.key()}};
                        if (o.shipped && source.name == PlateSource::CIE)
                        {
                            if (PixelBatch shipped = o.shipped(from, to, method))
                            {
                                forms.push_back({true, asFloat(shipped), plates.key()});
                            }
                        }
                        if (litLooks && source.name == PlateSource::CIE)
                        {
                            forms.push_back(
                                {false, exact(litLooks), plates.key() + "-through-lit-looks"});
                        }
                        for (size_t s = 0; s < o.sets.size(); ++s)
                        {
                            const size_t n = samples[s].size();
                            std::vector<Vec3> reference(n);
                            for (size_t i = 0; i < n; ++i)
                            {
                                reference[i] = pp.balanceTo * r2.render(samples[s][i]);
                            }
                            for (const Form& form : forms)
                            {
                                // Colour-major: a colour's exposures side by side.
                                const size_t ne = o.exposures.size();
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
                                    rows.push_back(MakeRow(
                                        method.name, from, to, o.sets[s].name, o.exposures[e],
                                        form.shipped,
                                        Score(pp.judge, predicted, reference, o.sets[s].samples),
                                        form.plates, source.name));
                                }
                            }
                        }
                    }
                }
            }
        });
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
    const std::string inSample = "training, in-sample";
    const std::string crossName = "training, " + std::to_string(folds) + "-fold";
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
                rows.push_back(MakeRow("floor-3x3", from, to, set.name, 1.0, false,
                                       Score(LitJudge(r2), by3x3, ref, set.samples)));
                rows.push_back(MakeRow("floor-rootpoly", from, to, set.name, 1.0, false,
                                       Score(LitJudge(r2), byRoot, ref, set.samples)));
            }
        });
}

}  // namespace bandlight
