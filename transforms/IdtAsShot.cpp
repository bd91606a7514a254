// SPDX-License-Identifier: BSD-3-Clause
// The light an as-shot neutral stands for: the daylight and Planckian
// families searched by temperature, or a list of lights, the white the
// neutral stands for, and its distance from the light it matched.
#include "transforms/Idt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>

#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/GoldenSection.h"
#include "spectral/Illuminants.h"
#include "transforms/Accuracy.h"
#include "transforms/Plates.h"
#include "transforms/detail/IdtParts.h"

namespace bandlight
{

using detail::kDaylightFromK;
using detail::kHighestCctK;
using detail::kLowestCctK;
using detail::LogChromaticity;
using detail::Response;

namespace
{

/// A family of lights an as-shot neutral is matched against, by
/// temperature (K) from `lowK` to kHighestCctK.
struct LightFamily
{
    const char* name;
    double lowK;
    Spectrum (*light)(double kelvin);
};

/// CIE daylight from kDaylightFromK as rawtoaces and DNG take it, a
/// Planckian radiator over the whole range.
const LightFamily kLightFamilies[] = {
    {"planckian", kLowestCctK, [](double k) { return Planckian(k); }},
    {"daylight", kDaylightFromK, [](double k) { return Daylight(k); }},
};

/// The temperature of a family whose camera response matches a neutral.
struct FamilyMatch
{
    double kelvin = 0.0;
    double residual = 0.0;  ///< log-chromaticity mismatch (infinite: no response in a channel)
};

/// The light of `family` whose raw response has the log chromaticity
/// `target`: a 0.5 mired grid, then golden section inside the grid step
/// either side of its best point.
FamilyMatch MatchFamily(const SpectralCamera& camera, const Eigen::Vector2d& target,
                        const LightFamily& family)
{
    // Mismatch of the response at `mired` (1e6 / K).
    const auto mismatch = [&](double mired)
    {
        const Vec3 r =
            Response(camera, family.light(std::clamp(1e6 / mired, family.lowK, kHighestCctK)));
        if (!(r.minCoeff() > 0.0))
        {
            return std::numeric_limits<double>::infinity();
        }
        return (LogChromaticity(r) - target).norm();
    };
    const double lo = 1e6 / kHighestCctK, hi = 1e6 / family.lowK;
    constexpr double kStepMired = 0.5;
    double at = lo, atValue = std::numeric_limits<double>::infinity();
    for (double m = lo; m <= hi + 1e-9; m += kStepMired)
    {
        const double v = mismatch(std::min(m, hi));
        if (v < atValue)
        {
            atValue = v;
            at = std::min(m, hi);
        }
    }
    // Golden section inside the grid step either side.
    const double a = std::max(lo, at - kStepMired), b = std::min(hi, at + kStepMired);
    const GoldenSectionResult r = GoldenSectionMinimum(mismatch, a, b, 1e-10, 80);
    const double mired = r.x;
    const double value = r.value;
    return {1e6 / (value <= atValue ? mired : at), std::min(value, atValue)};
}

/// The standard illuminant whose white (CIE 1931 2°) is nearest `uv` in
/// CIE 1960 UCS.
std::string NearestStandardIlluminant(const Eigen::Vector2d& uv)
{
    std::string nearestName;
    double nearest = std::numeric_limits<double>::infinity();
    for (const std::string& name : StandardIlluminantNames())
    {
        const double dist =
            (XyzToUv1960(IntegrateXyz(BuiltinIlluminant(name), Observer::CIE1931_2DEG)) - uv)
                .norm();
        if (dist < nearest)
        {
            nearest = dist;
            nearestName = name;
        }
    }
    return nearestName;
}

}  // namespace

std::string AsShotSearch::describe() const
{
    if (!lights.empty())
    {
        std::string names;
        for (const auto& [name, light] : lights)
        {
            names += (names.empty() ? "" : ", ") + name;
        }
        return names;
    }
    return daylight && planckian ? "daylight or Planckian light"
           : daylight            ? "daylight"
                                 : "Planckian light";
}

AsShotEstimate EstimateAsShot(const SpectralCamera& camera, const Vec3& given,
                              const RgbSpace& working, AdaptationMethod adaptation,
                              Observer observer, const AsShotSearch& search)
{
    for (int c = 0; c < 3; ++c)
    {
        if (!(given[c] > 0.0) || !std::isfinite(given[c]))
        {
            throw Exception("an as-shot neutral has three positive, finite channels");
        }
    }
    // Its chromaticity alone counts: scaled so that nothing underflows.
    const Vec3 neutral = given / given.maxCoeff();
    const Eigen::Vector2d target = LogChromaticity(neutral);
    AsShotEstimate best;
    best.residual = std::numeric_limits<double>::infinity();
    bool atRangeEnd = false;
    if (search.lights.empty())
    {
        const LightFamily* matched = nullptr;
        for (const LightFamily& f : kLightFamilies)
        {
            if ((std::string(f.name) == "daylight" && !search.daylight) ||
                (std::string(f.name) == "planckian" && !search.planckian))
            {
                continue;
            }
            const FamilyMatch m = MatchFamily(camera, target, f);
            if (m.residual < best.residual)
            {
                best.family = f.name;
                best.familyKelvin = m.kelvin;
                best.residual = m.residual;
                matched = &f;
            }
        }
        if (!matched)
        {
            throw Exception(camera.label() + ": no " + search.describe() +
                            " gives a response in every channel");
        }
        // A best match at either end of the range: the neutral lies beyond it.
        const double lowK = matched->lowK;
        atRangeEnd = best.familyKelvin <= lowK * (1.0 + 1e-6) ||
                     best.familyKelvin >= kHighestCctK * (1.0 - 1e-6);
        best.familyKelvin = std::clamp(best.familyKelvin, kLowestCctK, kHighestCctK);
        best.light = matched->light(std::max(best.familyKelvin, matched->lowK));
        best.lightName = best.family + " " + std::to_string(std::lround(best.familyKelvin)) + "K";
    }
    else
    {
        for (const auto& [name, light] : search.lights)
        {
            const Vec3 r = Response(camera, light);
            const double residual = r.minCoeff() > 0.0 ? (LogChromaticity(r) - target).norm()
                                                       : std::numeric_limits<double>::infinity();
            if (residual < best.residual)
            {
                best.residual = residual;
                best.light = light;
                best.lightName = name;
            }
        }
        if (!std::isfinite(best.residual))
        {
            throw Exception(camera.label() + ": none of " + search.describe() +
                            " gives a response in every channel");
        }
        best.family = "list";
        best.familyKelvin = ComputeCct(IlluminantWhiteXyz(best.light, observer)).cctK;
    }
    // The white the neutral stands for: balanced by the matched light's
    // gains, through its IDT to balanced working RGB, and back to XYZ under
    // the light (the balance undone). An exact match gives the light's white.
    const IdtProblem problem(camera, best.light, working, adaptation, observer);
    const ColourFit d = problem.data(Rawtoaces190());
    const Mat3 idt = FitLabMatrix(d);
    Vec3 balanced = neutral.cwiseProduct(problem.shot().gains());
    balanced /= balanced.y();
    const Mat3 balance = BalanceMatrix(best.light, working, adaptation, observer);
    const Vec3 xyz = d.rgbToXyz * balance.inverse() * idt * balanced;
    const CctDuv cd = ComputeCct(xyz);
    best.cct = cd.cctK;
    best.duv = cd.duv;
    best.nearest = NearestStandardIlluminant(XyzToUv1960(xyz));
    // The grey under the matched light against that light's white.
    const Vec3 white = IlluminantWhiteXyz(best.light, observer);
    const Vec3 grey = xyz * (white.y() / xyz.y());
    best.greyDeltaE = DeltaE2000(XyzToLab(grey, white), XyzToLab(white, white));
    if (!(best.greyDeltaE <= kAsShotLimitDeltaE))
    {
        std::ostringstream why;
        why.precision(3);
        why << camera.label() << ": the as-shot neutral is no " << search.describe()
            << " this camera records: the closest, " << best.lightName << ", leaves its grey "
            << best.greyDeltaE << " ΔE00 from that light's white (Duv " << best.duv
            << (atRangeEnd ? ", at the end of the temperature range" : "") << "; the limit is "
            << kAsShotLimitDeltaE
            << " ΔE00): give the lights to search with {as_shot_light} (fluorescent, a list of "
               "lights or spectrum files), or fit the IDT for a light with {lights}";
        throw ParameterError(why.str());
    }
    return best;
}

}  // namespace bandlight
