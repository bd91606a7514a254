// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/IdtJob.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "jobs/ConfigJob.h"
#include "jobs/Inputs.h"
#include "farm/OutputPaths.h"
#include "plugin/SceneLinearEvidence.h"
#include "spectral/AtomicFile.h"
#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/TextFile.h"
#include "transforms/Accuracy.h"
#include "transforms/Plates.h"

namespace bandlight::jobs
{

namespace
{

/// A chart IDT has six free parameters and three residuals a patch; fewer
/// than eight patches leave it barely determined (and no test of its fit).
constexpr size_t kFewestChartPatches = 8;

bool Exists(const std::string& path)
{
    std::ifstream f(path);
    return bool(f);
}

/// A light of an IDT: a colour temperature ("3200K": daylight from 4000 K,
/// Planckian below), a built-in name or a spectrum file.
Light ResolveIdtLight(const std::string& text, Reporter& reporter)
{
    double kelvin = 0.0;
    if (!Exists(text) && ParseCct(text, kelvin))
    {
        std::ostringstream name;
        name << kelvin << "K";
        return {name.str(), IdtLightForCct(kelvin)};
    }
    return ResolveIlluminant(text, reporter);
}

/// The chart's camera RGB: one row per patch, "[name,] R, G, B", an
/// optional header row and '#' comments.
std::vector<Vec3> ReadChartRgb(const std::string& path)
{
    std::string text = ReadTextFile(path, "chart RGB file");
    CheckUtf8Text(text, path);
    std::istringstream in(text);
    std::vector<Vec3> rgb;
    std::string line;
    size_t lineNo = 0;
    bool header = false;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
        {
            line.pop_back();
        }
        const size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#')
        {
            continue;
        }
        std::vector<std::string> fields;
        std::stringstream row(line);
        for (std::string f; std::getline(row, f, ',');)
        {
            const size_t a = f.find_first_not_of(" \t"), b = f.find_last_not_of(" \t");
            fields.push_back(a == std::string::npos ? "" : f.substr(a, b - a + 1));
        }
        if (fields.size() < 3 || fields.size() > 4)
        {
            throw Exception(SourcePosition(path, lineNo) +
                            ": a chart RGB row is [name,] R, G, B, not " +
                            std::to_string(fields.size()) + " fields");
        }
        Vec3 v;
        bool numbers = true;
        for (int c = 0; c < 3; ++c)
        {
            const std::string& f = fields[fields.size() - 3 + c];
            char* end = nullptr;
            errno = 0;
            v[c] = std::strtod(f.c_str(), &end);
            numbers = numbers && !f.empty() && end && *end == '\0';
        }
        if (!numbers && !header && rgb.empty())
        {
            header = true;  // R, G, B column names
            continue;
        }
        if (!numbers || !v.allFinite())
        {
            throw Exception(SourcePosition(path, lineNo) +
                            ": a patch's camera RGB must be three finite numbers, not '" +
                            OneLine(line, 80) + "'");
        }
        rgb.push_back(v);
    }
    return rgb;
}

/// Items of a "R,G,B" list given as numbers.
Vec3 CheckedNeutral(const std::vector<double>& n)
{
    if (n.size() != 3)
    {
        throw ParameterError("{as_shot_neutral} is three numbers R,G,B, not " +
                             std::to_string(n.size()));
    }
    for (const double v : n)
    {
        if (!(v > 0.0) || !std::isfinite(v))
        {
            throw ParameterError(
                "{as_shot_neutral} has a channel that is zero, negative or not "
                "finite: a neutral has three positive channels");
        }
    }
    return {n[0], n[1], n[2]};
}

/// What the IDTs are fitted from: the camera's spectral sensitivities, or a
/// chart photographed under one light.
enum class IdtSource
{
    SENSITIVITIES,
    CHART
};

/// Any chart option asks for a chart IDT (CheckChartOptions then asks for
/// all three).
IdtSource SourceOf(const IdtRequest& r)
{
    const bool chart = !r.chartRgb.empty() || !r.chart.empty() || !r.chartLight.empty();
    return chart ? IdtSource::CHART : IdtSource::SENSITIVITIES;
}

/// A chart IDT: the chart's three options together, none of the
/// sensitivities'.
void CheckChartOptions(const IdtRequest& r)
{
    if (r.chartRgb.empty() || r.chart.empty() || r.chartLight.empty())
    {
        throw ParameterError("a chart IDT needs {chart_rgb}, {chart} and {light} together");
    }
    if (r.chartRootPolynomial != 0 && r.chartRootPolynomial != 2 && r.chartRootPolynomial != 3)
    {
        throw ParameterError(
            "{rootpoly} is the degree of the chart's root polynomial: 2 "
            "or 3, not " +
            std::to_string(r.chartRootPolynomial));
    }
    if (!r.camera.empty() || !r.lights.empty() || !r.interpolate.empty() ||
        !r.asShotNeutral.empty() || !r.training.empty())
    {
        throw ParameterError(
            "a chart IDT is fitted on the chart under its {light}: "
            "{camera}, {lights}, {training}, {interpolate} and "
            "{as_shot_neutral} are for sensitivities");
    }
}

/// A sensitivity IDT: a camera, something to fit for it, and no chart's
/// root polynomial.
void CheckSensitivityOptions(const IdtRequest& r)
{
    if (r.camera.empty())
    {
        throw ParameterError(
            "give the camera's sensitivities as {camera=}FILE (or a chart "
            "with {chart_rgb}, {chart} and {light})");
    }
    if (r.lights.empty() && r.interpolate.empty() && r.asShotNeutral.empty())
    {
        throw ParameterError(
            "name the lights to fit IDTs for ({lights}), two to "
            "{interpolate} between, or an {as_shot_neutral}");
    }
    if (r.chartRootPolynomial != 0)
    {
        throw ParameterError(
            "{rootpoly} is fitted on a chart: give {chart_rgb}, {chart} and "
            "{light}");
    }
}

/// The config outputs: a new one into {config}, or {base} extended into
/// {out} ({base_space} only with a base).
void CheckConfigOptions(const IdtRequest& r)
{
    if (!r.base.empty() && r.out.empty())
    {
        throw ParameterError("{base} is extended into a folder of its own: give {out=}DIR");
    }
    if (!r.out.empty() && r.base.empty())
    {
        throw ParameterError(
            "{out} is where an extended {base} config goes; for a new config "
            "give {config=}DIR");
    }
    if (!r.baseSpace.empty() && r.base.empty())
    {
        throw ParameterError(
            "{base_space} names the primaries of a {base} config's "
            "scene_linear: give the base, or leave {base_space} out");
    }
    if (!r.config.empty() && !r.base.empty())
    {
        throw ParameterError(
            "{config} writes a new config, {base} with {out} extends one: "
            "give one of them");
    }
}

/// Options that do not go together, refused before anything is read.
void CheckOptions(const IdtRequest& r)
{
    switch (SourceOf(r))
    {
        case IdtSource::CHART:
            CheckChartOptions(r);
            break;
        case IdtSource::SENSITIVITIES:
            CheckSensitivityOptions(r);
            break;
    }
    if (!r.interpolate.empty() && r.interpolate.size() != 2)
    {
        throw ParameterError("{interpolate} takes two lights, not " +
                             std::to_string(r.interpolate.size()));
    }
    if (!r.asShotNeutral.empty())
    {
        CheckedNeutral(r.asShotNeutral);
    }
    CheckConfigOptions(r);
}

/// Every output can be written and no input is written over, before any
/// work (OutputPlan::check).
void CheckOutputPaths(const IdtRequest& r)
{
    OutputPlan plan;
    if (!r.json.empty())
    {
        plan.file("{json}", r.json);
    }
    if (!r.config.empty())
    {
        plan.folder("{config}", r.config, {"config.ocio"});
    }
    if (!r.out.empty())
    {
        plan.folder("{out}", r.out, {"config.ocio"});
    }
    for (const std::string* in : {&r.camera, &r.training, &r.chartRgb, &r.base})
    {
        if (!in->empty())
        {
            plan.input(*in);
        }
    }
    plan.check();
}

/// The {base} config (null without one), read and its scene_linear's
/// primaries identified (or {base_space} checked) before any fit.
OCIO_NAMESPACE::ConstConfigRcPtr ReadBase(const IdtRequest& r)
{
    if (r.base.empty())
    {
        return nullptr;
    }
    OCIO_NAMESPACE::ConstConfigRcPtr base = ReadConfigFile(r.base, false);
    if (r.baseSpace.empty())
    {
        try
        {
            IdentifySceneLinear(base);
        }
        catch (const ParameterError&)
        {
            throw ParameterError("cannot tell the primaries of the scene_linear space of {base} " +
                                 ShowPath(r.base) + ": name them with {base_space} (" +
                                 RgbSpaceChoices() + ")");
        }
    }
    else
    {
        FindRgbSpace(r.baseSpace);
    }
    return base;
}

nlohmann::ordered_json MatrixJson(const Mat3& m)
{
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (int r = 0; r < 3; ++r)
    {
        a.push_back({m(r, 0), m(r, 1), m(r, 2)});
    }
    return a;
}

std::string Row(const Mat3& m, int r)
{
    return Fixed(m(r, 0), 6) + " " + Fixed(m(r, 1), 6) + " " + Fixed(m(r, 2), 6);
}

std::string Describe(const IdtEntry& e, const std::string& camera, const IdtResult& r)
{
    std::ostringstream d;
    d << "Camera " << camera << " under " << e.light << " (CCT " << Fixed(e.cct, 0) << " K, Duv "
      << Fixed(e.duv, 4) << "): raw camera RGB to " << FindRgbSpace(r.workingSpace).displayName
      << ", white-balance gains R " << Fixed(e.fit.gains.x(), 4) << ", G 1, B "
      << Fixed(e.fit.gains.z(), 4) << " folded in, then the 3x3 fitted as rawtoaces fits it (white "
      << "kept, CIELAB error of " << r.trainingName << " minimised, "
      << AdaptationName(ParsePlates("balanced", r.adaptation).adaptation)
      << " to the working white). Training error " << Fixed(e.errors.front().mean, 2)
      << " dE00 mean, " << Fixed(e.errors.front().max, 2) << " max; " << r.testName << " "
      << Fixed(e.errors.back().mean, 2) << " mean. Generated by `bandlight idt`.";
    return d.str();
}

/// ΔE00 of `idt`'s output against `reference`'s on the same balanced
/// camera RGB (d.input), L*a*b* relative to d.labWhite.
IdtError ErrorAgainst(const ColourFit& d, const Mat3& idt, const Mat3& reference)
{
    std::vector<double> de;
    for (const Vec3& c : d.input)
    {
        de.push_back(DeltaE2000(XyzToLab(d.rgbToXyz * (idt * c), d.labWhite),
                                XyzToLab(d.rgbToXyz * (reference * c), d.labWhite)));
    }
    return IdtError::Of(Summarise(std::move(de)));
}

/// What every fit of a request shares: the working space, the adaptation of
/// each light's white to the working white, and the observer.
struct FitSetting
{
    const RgbSpace& working;
    AdaptationMethod adaptation;
    Observer observer;

    IdtProblem problem(const SpectralCamera& camera, const Spectrum& light) const
    {
        return IdtProblem(camera, light, working, adaptation, observer);
    }
};

/// The remittances the IDTs are fitted on (training) and also measured on
/// (test), with the names the errors are reported under.
struct RemittanceSets
{
    std::vector<NamedSpectrum> training;
    std::string trainingName;
    std::vector<NamedSpectrum> test;
    std::string testName;
};

/// {training} (rawtoaces' 190 when empty), then {test_set}.
RemittanceSets ResolveRemittances(const IdtRequest& r, Reporter& reporter)
{
    RemittanceSets s;
    s.training = r.training.empty() ? Rawtoaces190() : ResolveReflectances(r.training, reporter);
    s.trainingName = r.training.empty() ? "rawtoaces 190" : r.training;
    s.test = ResolveReflectances(r.testSet, reporter);
    s.testName = r.testSet;
    return s;
}

/// A light of a sensitivity IDT and the camera's view of it.
struct PlannedLight
{
    Light light;
    std::unique_ptr<IdtProblem> problem;
};

/// Every light ({lights}, then the {interpolate} pair, whose indices go into
/// `result`) and the camera's view of it, before any fit: a dead channel or
/// a light a channel does not see is refused here, naming the light.
std::vector<PlannedLight> PlanLights(const IdtRequest& r, const SpectralCamera& camera,
                                     const FitSetting& s, Reporter& reporter, IdtResult& result)
{
    std::vector<PlannedLight> planned;
    const auto plan = [&](const std::string& text)
    {
        PlannedLight p{ResolveIdtLight(text, reporter), nullptr};
        try
        {
            p.problem = std::make_unique<IdtProblem>(camera, p.light.spectrum, s.working,
                                                     s.adaptation, s.observer);
        }
        catch (const FileError&)
        {
            throw;
        }
        catch (const Exception& e)
        {
            throw Exception(std::string(e.what()) + " (" + p.light.name + ")");
        }
        planned.push_back(std::move(p));
    };
    for (const std::string& l : r.lights)
    {
        plan(l);
    }
    if (!r.interpolate.empty())
    {
        result.interpolateFrom = int(planned.size());
        plan(r.interpolate[0]);
        result.interpolateTo = int(planned.size());
        plan(r.interpolate[1]);
    }
    // One colour space per light: two lights of one name would clash.
    for (size_t i = 0; i < planned.size(); ++i)
    {
        for (size_t k = 0; k < i; ++k)
        {
            if (planned[i].light.name == planned[k].light.name)
            {
                throw ParameterError("the light '" + planned[i].light.name +
                                     "' is named twice ({lights}, {interpolate}): give "
                                     "each once");
            }
        }
    }
    return planned;
}

/// The IDT of one light, reported as `name`: fitted on the training set,
/// its ΔE00 on the training set, then on the test set.
IdtEntry FitEntry(const std::string& name, const IdtProblem& problem, const RemittanceSets& sets,
                  const std::string& cameraLabel)
{
    IdtEntry e;
    e.light = name;
    const CctDuv cd = ComputeCct(problem.whiteXyz());
    e.cct = cd.cctK;
    e.duv = cd.duv;
    e.fit = FitIdtOptimal(problem, sets.training, cameraLabel);
    e.errors.push_back(problem.errors(e.fit.matrix, sets.training, sets.trainingName));
    e.errors.push_back(problem.errors(e.fit.matrix, sets.test, sets.testName));
    return e;
}

/// {as_shot_neutral}: the light it stands for (EstimateAsShot) and that
/// light's IDT, reported after the named lights'.
void AddAsShot(const IdtRequest& r, const SpectralCamera& camera, const FitSetting& s,
               const RemittanceSets& sets, IdtResult& result)
{
    result.asShotNeutral = r.asShotNeutral;
    result.asShot = EstimateAsShot(camera, CheckedNeutral(r.asShotNeutral), s.working, s.adaptation,
                                   s.observer);
    result.hasAsShot = true;
    std::ostringstream name;
    name << "as shot (" << result.asShot.family << " " << std::lround(result.asShot.familyKelvin)
         << "K)";
    const IdtProblem problem = s.problem(camera, result.asShot.light);
    result.idts.push_back(FitEntry(name.str(), problem, sets, camera.label()));
}

/// The IDT interpolated between the pair's calibrations at `kelvin`
/// (InterpolateIdt, extrapolated and with DNG's clamp) against one fitted
/// there, and each against the truth: ΔE00 on the test set.
IdtInterpolationPoint SweepPoint(double kelvin, const IdtCalibration& a, const IdtCalibration& b,
                                 const SpectralCamera& camera, const FitSetting& s,
                                 const RemittanceSets& sets)
{
    const IdtProblem problem = s.problem(camera, IdtLightForCct(kelvin));
    const IdtFit direct = FitIdtOptimal(problem, sets.training, camera.label());
    const Mat3 m = InterpolateIdt(a, b, problem, true);
    const Mat3 clamped = InterpolateIdt(a, b, problem, false);
    const ColourFit d = problem.data(sets.test);
    IdtInterpolationPoint p;
    p.cct = kelvin;
    const IdtError e = ErrorAgainst(d, m, direct.matrix);
    p.meanVsDirect = e.mean;
    p.p95VsDirect = e.p95;
    p.maxVsDirect = e.max;
    p.clampedMeanVsDirect = ErrorAgainst(d, clamped, direct.matrix).mean;
    p.interpolatedMean = problem.errors(m, sets.test, sets.testName).mean;
    p.directMean = problem.errors(direct.matrix, sets.test, sets.testName).mean;
    p.clampedMean = problem.errors(clamped, sets.test, sets.testName).mean;
    return p;
}

/// {interpolate}: the calibrations of the pair's fitted IDTs, and the sweep
/// over defaults::IDT_SWEEP_MIN_K–IDT_SWEEP_MAX_K.
void SweepInterpolation(const std::vector<PlannedLight>& planned, const SpectralCamera& camera,
                        const FitSetting& s, const RemittanceSets& sets, IdtResult& result)
{
    const int ends[2] = {result.interpolateFrom, result.interpolateTo};
    for (int end = 0; end < 2; ++end)
    {
        const size_t i = size_t(ends[end]);
        result.interpolateCalibrations[end] =
            CalibrationOf(*planned[i].problem, result.idts[i].fit);
    }
    const IdtCalibration& a = result.interpolateCalibrations[0];
    const IdtCalibration& b = result.interpolateCalibrations[1];
    for (double k = defaults::IDT_SWEEP_MIN_K; k <= defaults::IDT_SWEEP_MAX_K + 1e-9;
         k += defaults::IDT_SWEEP_STEP_K)
    {
        result.interpolation.push_back(SweepPoint(k, a, b, camera, s, sets));
    }
}

/// IDTs from the camera's sensitivities: one per light, then the as-shot
/// light's, then the interpolation sweep.
void FitFromSensitivities(const IdtRequest& r, const FitSetting& s, const RemittanceSets& sets,
                          Reporter& reporter, IdtResult& result)
{
    const SpectralCamera camera(ReadCameraFile(r.camera));
    result.camera = camera.name();
    const std::vector<PlannedLight> planned = PlanLights(r, camera, s, reporter, result);
    for (const PlannedLight& p : planned)
    {
        result.idts.push_back(FitEntry(p.light.name, *p.problem, sets, camera.label()));
    }
    if (!r.asShotNeutral.empty())
    {
        AddAsShot(r, camera, s, sets, result);
    }
    if (result.interpolateFrom >= 0)
    {
        SweepInterpolation(planned, camera, s, sets, result);
    }
}

/// A photographed chart: its remittances, each patch's camera RGB (same
/// order) and the light it was shot under.
struct ChartShot
{
    std::vector<NamedSpectrum> chart;
    std::vector<Vec3> rgb;
    Light light;
};

ChartShot ReadChart(const IdtRequest& r, Reporter& reporter)
{
    ChartShot c;
    c.chart = ResolveReflectances(r.chart, reporter);
    c.rgb = ReadChartRgb(r.chartRgb);
    c.light = ResolveIdtLight(r.chartLight, reporter);
    if (c.rgb.size() != c.chart.size() || c.rgb.size() < kFewestChartPatches)
    {
        throw Exception(r.chartRgb + ": " + std::to_string(c.rgb.size()) +
                        " patches of camera RGB for a chart of " + std::to_string(c.chart.size()) +
                        " (" + r.chart +
                        "): give one row per patch, in the chart's order, at least " +
                        std::to_string(kFewestChartPatches));
    }
    return c;
}

/// ΔE00 of `apply` on the chart's balanced camera RGB (d.input) against the
/// patches' colours under the light (d.target), L*a*b* relative to
/// d.labWhite, reported under `set`.
IdtError ChartError(const ColourFit& d, const std::string& set,
                    const std::function<Vec3(const Vec3&)>& apply)
{
    std::vector<double> de;
    for (size_t i = 0; i < d.input.size(); ++i)
    {
        de.push_back(DeltaE2000(XyzToLab(d.rgbToXyz * apply(d.input[i]), d.labWhite),
                                XyzToLab(d.rgbToXyz * d.target[i], d.labWhite)));
    }
    IdtError err = IdtError::Of(Summarise(std::move(de)));
    err.set = set;
    return err;
}

/// The IDT from a chart, which is its own training set (its error is the
/// fit's; no test set), with {rootpoly} the root polynomial's beside it.
void FitFromChart(const IdtRequest& r, const FitSetting& s, Reporter& reporter, IdtResult& result)
{
    const ChartShot shot = ReadChart(r, reporter);
    const Spectrum& light = shot.light.spectrum;
    result.camera = "chart";
    result.chart = true;
    IdtEntry e;
    e.light = shot.light.name;
    const SurfaceRenderer eye(light, s.working, s.observer);
    const CctDuv cd = ComputeCct(eye.rgbToXyz() * eye.white());
    e.cct = cd.cctK;
    e.duv = cd.duv;
    e.fit = FitChartIdt(shot.rgb, shot.chart, light, s.working, s.adaptation, s.observer);
    result.chartNeutral = shot.chart[FlattestRemittance(shot.chart)].name;
    const ColourFit d =
        ChartFitData(shot.rgb, shot.chart, light, s.working, s.adaptation, s.observer);
    e.errors.push_back(
        ChartError(d, r.chart, [&](const Vec3& c) { return Vec3(e.fit.matrix * c); }));
    if (r.chartRootPolynomial != 0)
    {
        result.chartRootPolynomial = FitRootPolynomial(d, r.chartRootPolynomial);
        result.chartRootPolynomialError = ChartError(
            d, r.chart, [&](const Vec3& c) { return result.chartRootPolynomial.apply(c); });
        result.hasChartRootPolynomial = true;
    }
    result.trainingName = r.chart;
    result.trainingCount = int(shot.chart.size());
    result.testName.clear();
    result.testCount = 0;
    result.idts.push_back(e);
}

/// The config (a new one in {config}, or {base} extended into {out}), each
/// IDT an input colour space named in `result`, and the JSON document:
/// committed together.
void WriteOutputs(const IdtRequest& r, const OCIO_NAMESPACE::ConstConfigRcPtr& base,
                  Reporter& reporter, IdtResult& result)
{
    OutputSet outputs;
    if (!r.config.empty() || !r.out.empty())
    {
        ConfigRequest c;
        c.out = r.config.empty() ? r.out : r.config;
        c.base = r.base;
        c.baseConfig = base;
        c.workingSpace = r.base.empty() ? result.workingSpace : r.baseSpace;
        c.observer = r.observer;
        c.looks = false;
        for (IdtEntry& e : result.idts)
        {
            e.colorSpace = IdtColorSpaceName(result.camera, e.light);
            c.inputSpaces.push_back({e.colorSpace, Describe(e, result.camera, result),
                                     e.fit.rawToWorking(), result.workingSpace});
        }
        MakeConfig(c, reporter, &outputs);
        result.written.push_back(*c.out + "/config.ocio");
    }
    if (!r.json.empty())
    {
        const std::string document = IdtDocument(result);
        outputs.write(r.json, [&](std::ostream& os) { os << document << "\n"; });
        result.written.push_back(r.json);
    }
    outputs.commit();
}

}  // namespace

IdtResult MakeIdt(const IdtRequest& r, Reporter& reporter)
{
    CheckOptions(r);
    CheckOutputPaths(r);
    const RgbSpace& working = FindRgbSpace(r.workingSpace);
    const OCIO_NAMESPACE::ConstConfigRcPtr base = ReadBase(r);
    const FitSetting setting{working, ParsePlates("balanced", r.adaptation).adaptation,
                             ParseObserver(r.observer)};

    IdtResult result;
    result.workingSpace = working.name;
    result.adaptation = AdaptationName(setting.adaptation);
    const RemittanceSets sets = ResolveRemittances(r, reporter);
    result.trainingName = sets.trainingName;
    result.trainingCount = int(sets.training.size());
    result.testName = sets.testName;
    result.testCount = int(sets.test.size());
    switch (SourceOf(r))
    {
        case IdtSource::CHART:
            FitFromChart(r, setting, reporter, result);
            break;
        case IdtSource::SENSITIVITIES:
            FitFromSensitivities(r, setting, sets, reporter, result);
            break;
    }
    WriteOutputs(r, base, reporter, result);
    return result;
}

std::string IdtDocument(const IdtResult& r)
{
    nlohmann::ordered_json j;
    j["camera"] = r.camera;
    j["working_space"] = r.workingSpace;
    j["adaptation"] = r.adaptation;
    j["training"] = {{"name", r.trainingName}, {"count", r.trainingCount}};
    if (!r.testName.empty())
    {
        j["test_set"] = {{"name", r.testName}, {"count", r.testCount}};
    }
    j["idts"] = nlohmann::ordered_json::array();
    for (const IdtEntry& e : r.idts)
    {
        nlohmann::ordered_json i;
        i["light"] = e.light;
        i["cct"] = e.cct;
        i["duv"] = e.duv;
        i["gains"] = {e.fit.gains.x(), e.fit.gains.y(), e.fit.gains.z()};
        i["matrix"] = MatrixJson(e.fit.matrix);
        i["first_order_matrix"] = MatrixJson(e.fit.firstOrder);
        i["raw_to_working"] = MatrixJson(e.fit.rawToWorking());
        i["objective_rms_de76"] = {{"optimum", e.fit.rmsDe76},
                                   {"first_order", e.fit.firstOrderRmsDe76},
                                   {"iterations", e.fit.iterations}};
        nlohmann::ordered_json err;
        for (const IdtError& s : e.errors)
        {
            err[s.set] = {{"mean", s.mean}, {"p95", s.p95}, {"max", s.max}};
        }
        i["error"] = err;
        if (!e.colorSpace.empty())
        {
            i["colorspace"] = e.colorSpace;
        }
        j["idts"].push_back(i);
    }
    if (r.hasAsShot)
    {
        j["as_shot"] = {{"neutral", r.asShotNeutral},  {"cct", r.asShot.cct},
                        {"duv", r.asShot.duv},         {"nearest", r.asShot.nearest},
                        {"family", r.asShot.family},   {"family_kelvin", r.asShot.familyKelvin},
                        {"light", r.idts.back().light}};
    }
    if (r.interpolateFrom >= 0)
    {
        nlohmann::ordered_json curve = nlohmann::ordered_json::array();
        for (const IdtInterpolationPoint& p : r.interpolation)
        {
            curve.push_back({{"cct", p.cct},
                             {"mean_vs_direct", p.meanVsDirect},
                             {"p95_vs_direct", p.p95VsDirect},
                             {"max_vs_direct", p.maxVsDirect},
                             {"dng_clamped_mean_vs_direct", p.clampedMeanVsDirect},
                             {"interpolated_mean", p.interpolatedMean},
                             {"direct_mean", p.directMean},
                             {"dng_clamped_mean", p.clampedMean}});
        }
        nlohmann::ordered_json calibrations = nlohmann::ordered_json::array();
        for (int end = 0; end < 2; ++end)
        {
            const IdtCalibration& c = r.interpolateCalibrations[end];
            calibrations.push_back(
                {{"light", r.idts[size_t(end == 0 ? r.interpolateFrom : r.interpolateTo)].light},
                 {"cct", c.cct},
                 {"color_matrix", MatrixJson(c.colorMatrix)}});
        }
        j["interpolation"] = {{"from", r.idts[size_t(r.interpolateFrom)].light},
                              {"to", r.idts[size_t(r.interpolateTo)].light},
                              {"set", r.testName},
                              {"count", r.testCount},
                              {"interpolated", "color_matrix"},
                              {"beyond_pair", "extrapolated"},
                              {"calibrations", calibrations},
                              {"curve", curve}};
    }
    if (r.chart)
    {
        j["chart"] = {{"patches", r.trainingCount}, {"neutral_patch", r.chartNeutral}};
        if (r.hasChartRootPolynomial)
        {
            const Eigen::MatrixXd& m = r.chartRootPolynomial.matrix();
            nlohmann::ordered_json rows = nlohmann::ordered_json::array();
            for (int row = 0; row < 3; ++row)
            {
                std::vector<double> v(size_t(m.cols()));
                for (int c = 0; c < m.cols(); ++c)
                {
                    v[size_t(c)] = m(row, c);
                }
                rows.push_back(v);
            }
            const IdtError& e = r.chartRootPolynomialError;
            j["chart"]["rootpoly"] = {
                {"degree", r.chartRootPolynomial.degree()},
                {"matrix", rows},
                {"error", {{e.set, {{"mean", e.mean}, {"p95", e.p95}, {"max", e.max}}}}}};
        }
    }
    return j.dump(2);
}

std::string IdtReport(const IdtResult& r)
{
    std::ostringstream o;
    const RgbSpace& ws = FindRgbSpace(r.workingSpace);
    if (r.chart)
    {
        o << "Chart IDT: " << r.trainingCount << " patches of " << r.trainingName
          << ", white balance from " << r.chartNeutral << "; to " << ws.displayName << " ("
          << r.adaptation << ")\n";
        if (r.hasChartRootPolynomial)
        {
            const IdtError& e = r.chartRootPolynomialError;
            o << "Root polynomial of degree " << r.chartRootPolynomial.degree()
              << " on the chart (exposure invariant): dE00 mean " << Fixed(e.mean, 3) << ", p95 "
              << Fixed(e.p95, 3) << ", max " << Fixed(e.max, 3) << "\n";
        }
    }
    else
    {
        o << "Camera " << r.camera << " to " << ws.displayName << " (" << r.adaptation
          << "), fitted on " << r.trainingName << " (" << r.trainingCount << "), tested on "
          << r.testName << " (" << r.testCount << ")\n";
    }
    for (const IdtEntry& e : r.idts)
    {
        o << "\n"
          << e.light << ": CCT " << Fixed(e.cct, 0) << " K, Duv " << Fixed(e.duv, 4)
          << "\n  gains     " << Fixed(e.fit.gains.x(), 6) << " " << Fixed(e.fit.gains.y(), 6)
          << " " << Fixed(e.fit.gains.z(), 6) << "\n  matrix    " << Row(e.fit.matrix, 0)
          << "\n            " << Row(e.fit.matrix, 1) << "\n            " << Row(e.fit.matrix, 2)
          << "\n  objective rms dE76 " << Fixed(e.fit.rmsDe76, 4) << " (first order "
          << Fixed(e.fit.firstOrderRmsDe76, 4) << ", " << e.fit.iterations << " iterations)\n";
        for (const IdtError& s : e.errors)
        {
            o << "  dE00 " << s.set << ": mean " << Fixed(s.mean, 3) << ", p95 " << Fixed(s.p95, 3)
              << ", max " << Fixed(s.max, 3) << "\n";
        }
        if (!e.colorSpace.empty())
        {
            o << "  colour space \"" << e.colorSpace << "\"\n";
        }
    }
    if (r.hasAsShot)
    {
        o << "\nAs-shot neutral " << r.asShotNeutral[0] << "," << r.asShotNeutral[1] << ","
          << r.asShotNeutral[2] << ": CCT " << Fixed(r.asShot.cct, 0) << " K, Duv "
          << Fixed(r.asShot.duv, 4) << " (" << r.asShot.family << " "
          << Fixed(r.asShot.familyKelvin, 0) << " K matches), nearest " << r.asShot.nearest << "\n";
    }
    if (r.interpolateFrom >= 0)
    {
        const IdtCalibration& a = r.interpolateCalibrations[0];
        const IdtCalibration& b = r.interpolateCalibrations[1];
        o << "\nInterpolated as DNG does between " << r.idts[size_t(r.interpolateFrom)].light
          << " (" << Fixed(a.cct, 0) << " K) and " << r.idts[size_t(r.interpolateTo)].light << " ("
          << Fixed(b.cct, 0)
          << " K): the colour matrix (XYZ to raw) in mired, extrapolated beyond the pair; the "
             "white balance from the camera's response to each light; "
          << r.adaptation << " to the working white.\n"
          << "dE00 on " << r.testName << " (" << r.testCount
          << ", fitted on by no IDT): the interpolated IDT's output against that of an IDT "
             "fitted at each CCT, and each IDT against the truth (DNG clamps to the pair):\n"
             "         interpolated vs fitted there   against the truth\n"
             "  CCT K    mean    p95    max  clamped   interpolated  fitted  clamped\n";
        for (const IdtInterpolationPoint& p : r.interpolation)
        {
            o << std::setw(7) << Fixed(p.cct, 0) << std::setw(8) << Fixed(p.meanVsDirect, 3)
              << std::setw(7) << Fixed(p.p95VsDirect, 3) << std::setw(7) << Fixed(p.maxVsDirect, 3)
              << std::setw(9) << Fixed(p.clampedMeanVsDirect, 3) << std::setw(15)
              << Fixed(p.interpolatedMean, 3) << std::setw(8) << Fixed(p.directMean, 3)
              << std::setw(9) << Fixed(p.clampedMean, 3) << "\n";
        }
    }
    return o.str();
}

}  // namespace bandlight::jobs
