// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `idt`'s request and result, and the one step that checks a request
// before any work.

#include <string>
#include <vector>

#include "requests/Defaults.h"
#include "farm/Reporter.h"
#include "transforms/Idt.h"

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight::jobs
{

/// `idt`: camera input transforms from a camera's spectral sensitivities
/// (or a photographed chart), one per light, fitted as rawtoaces fits them
/// and iterated to the optimum; optionally as OCIO input colour spaces, the
/// DNG interpolation between two of them and the light of an as-shot
/// neutral.
struct IdtRequest
{
    /// Camera sensitivities (rawtoaces JSON, CSV or CGATS); not with a chart.
    std::string camera;
    /// Lights: built-in names (A, D55, F11, ...), colour temperatures
    /// ("3200K": daylight from 4000 K, Planckian below) or spectrum files.
    std::vector<std::string> lights;
    std::string workingSpace = defaults::IDT_WORKING_SPACE;
    std::string adaptation = defaults::ADAPTATION;  ///< "cat02" or "bradford"
    std::string observer = defaults::OBSERVER;
    /// Training remittances (a file or a built-in set); empty: rawtoaces' 190.
    std::string training;
    /// The second set errors are measured on.
    std::string testSet = defaults::IDT_TEST_SET;
    /// Two lights to fit and interpolate between as DNG does (InterpolateIdt:
    /// the colour matrix in mired, extrapolated beyond the pair, DNG's clamp
    /// reported beside; white balance and CAT for each light).
    std::vector<std::string> interpolate;
    /// The camera's as-shot neutral (raw R, G, B; any scale), or empty.
    std::vector<double> asShotNeutral;
    /// The lights the as-shot neutral is searched among: "" (daylight or
    /// Planckian), "daylight", "planckian", "fluorescent" (F1–F12), or a
    /// list of lights as {lights} takes them.
    std::string asShotLight;
    /// A chart's camera RGB per patch (CSV: optional name column, then R, G,
    /// B), the chart's remittances and the light it was shot under: the IDT
    /// from the chart instead of sensitivities.
    std::string chartRgb;
    std::string chart;
    std::string chartLight;
    /// With a chart: also fit a root polynomial of this degree (2 or 3;
    /// 0 none) on it, exposure invariant (Finlayson et al. 2015), and report
    /// its error beside the 3×3's.
    int chartRootPolynomial = defaults::IDT_CHART_ROOTPOLY;
    /// Write the JSON document here ("" none).
    std::string json;
    /// Write a new OCIO v2 config of the input spaces into this folder.
    std::string config;
    /// Extend this config with the input spaces, written into `out`.
    std::string base;
    std::string out;
    /// The primaries of the base's scene_linear space, when the base does
    /// not tell them (empty: identified from the base, as `config --base`).
    std::string baseSpace;
};

/// One light's IDT as reported.
struct IdtEntry
{
    std::string light;
    double cct = 0.0;  ///< K, of the light's white (CIE 15:2004 §9.5)
    double duv = 0.0;
    IdtFit fit;
    std::vector<IdtError> errors;  ///< training set, then the test set
    std::string colorSpace;        ///< its colour space in the config ("" none)
};

/// The interpolated IDT at one colour temperature against one fitted there,
/// ΔE00 on the test set (L*a*b* relative to the working white).
struct IdtInterpolationPoint
{
    double cct = 0.0;  ///< K, the nominal temperature of the light (IdtLightForCct)
    /// The interpolated IDT's output against the fitted IDT's, same
    /// balanced camera RGB: mean, p95 (nearest rank) and max.
    double meanVsDirect = 0.0;
    double p95VsDirect = 0.0;
    double maxVsDirect = 0.0;
    double clampedMeanVsDirect = 0.0;  ///< the same mean with DNG's clamp to the pair
    double interpolatedMean = 0.0;     ///< mean ΔE00 against the truth
    double directMean = 0.0;
    double clampedMean = 0.0;  ///< mean ΔE00 against the truth with DNG's clamp to the pair
};

struct IdtResult
{
    std::string camera;
    std::string workingSpace;  ///< the space's key (aces2065-1)
    std::string adaptation;
    std::string trainingName;
    int trainingCount = 0;
    std::string testName;
    int testCount = 0;
    std::vector<IdtEntry> idts;
    bool hasAsShot = false;
    AsShotEstimate asShot;
    std::vector<double> asShotNeutral;
    /// --interpolate: the pair (indices into idts) and the sweep.
    int interpolateFrom = -1;
    int interpolateTo = -1;
    IdtCalibration interpolateCalibrations[2];  ///< the colour matrices interpolated
    std::vector<IdtInterpolationPoint> interpolation;
    bool chart = false;        ///< fitted from a chart
    std::string chartNeutral;  ///< the chart patch that set the white balance
    /// With chartRootPolynomial: its fit on the chart (balanced camera RGB →
    /// working RGB) and its error there.
    RootPolynomial chartRootPolynomial;
    IdtError chartRootPolynomialError;
    bool hasChartRootPolynomial = false;
    std::vector<std::string> written;
};

/// What the IDTs are fitted from: the camera's spectral sensitivities, or a
/// chart photographed under one light (any chart option asks for a chart).
enum class IdtSource
{
    SENSITIVITIES,
    CHART
};
IdtSource SourceOf(const IdtRequest& request);

/// {as_shot_neutral}'s three numbers, each positive and finite; throws
/// ParameterError otherwise.
Vec3 CheckedNeutral(const std::vector<double>& neutral);

/// Every option and output path of `request`, before any work: options
/// that do not go together, a chart's three options, the config's, and
/// each output writable and none of them an input (one line each).
void CheckIdtRequest(const IdtRequest& request);

/// The config already in {config}'s folder ("" when there is none): a
/// second camera's input spaces are added to it.
std::string ExistingIdtConfig(const IdtRequest& request);

/// The {base} config, or the config already in {config}'s folder (null
/// without either), read and its scene_linear's primaries identified (or
/// {base_space} checked) before any fit.
OCIO_NAMESPACE::ConstConfigRcPtr ReadIdtBase(const IdtRequest& request);

}  // namespace bandlight::jobs
