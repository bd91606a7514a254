// SPDX-License-Identifier: BSD-3-Clause
#include "camera/IdtFit.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <sstream>

#include "requests/Inputs.h"
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

}  // namespace

std::string KelvinName(double kelvin)
{
    std::ostringstream name;
    name << kelvin << "K";
    return name.str();
}

Light ResolveIdtLight(const std::string& text, Reporter& reporter)
{
    double kelvin = 0.0;
    if (!PathExists(text) && ParseCct(text, kelvin))
    {
        return {KelvinName(kelvin), IdtLightForCct(kelvin)};
    }
    return ResolveIlluminant(text, reporter);
}

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

namespace
{

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

/// {as_shot_light}: the families by name, the fluorescent tubes F1–F12, or
/// a list of lights as {lights} takes them.
AsShotSearch AsShotSearchOf(const IdtRequest& r, Reporter& reporter)
{
    AsShotSearch search;
    if (r.asShotLight.empty())
    {
        return search;
    }
    if (r.asShotLight == "daylight" || r.asShotLight == "planckian")
    {
        search.daylight = r.asShotLight == "daylight";
        search.planckian = !search.daylight;
        return search;
    }
    const std::vector<std::string> names =
        r.asShotLight == "fluorescent"
            ? std::vector<std::string>{"F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10",
                                       "F11", "F12"}
            : SplitList(r.asShotLight);
    for (const std::string& name : names)
    {
        const Light light = ResolveIdtLight(name, reporter);
        search.lights.emplace_back(light.name, light.spectrum);
    }
    return search;
}

/// {as_shot_neutral}: the light it stands for (EstimateAsShot) and that
/// light's IDT, reported after the named lights'.
void AddAsShot(const IdtRequest& r, const SpectralCamera& camera, const FitSetting& s,
               const RemittanceSets& sets, Reporter& reporter, IdtResult& result)
{
    result.asShotNeutral = r.asShotNeutral;
    result.asShot = EstimateAsShot(camera, CheckedNeutral(r.asShotNeutral), s.working, s.adaptation,
                                   s.observer, AsShotSearchOf(r, reporter));
    result.hasAsShot = true;
    const IdtProblem problem = s.problem(camera, result.asShot.light);
    result.idts.push_back(
        FitEntry("as shot (" + result.asShot.lightName + ")", problem, sets, camera.label()));
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

}  // namespace

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
        AddAsShot(r, camera, s, sets, reporter, result);
    }
    if (result.interpolateFrom >= 0)
    {
        SweepInterpolation(planned, camera, s, sets, result);
    }
}

namespace
{

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

}  // namespace

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


}  // namespace bandlight::jobs
