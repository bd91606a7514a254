// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "spectral/Statistics.h"
#include "transforms/Defaults.h"
#include "transforms/IlluminantChange.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

/// Where an accuracy row's plate came from: how the plates are simulated.
/// One table in Accuracy.cpp gives each its key and how its plates are made;
/// MeasureAccuracy measures them in this order.
enum class PlateSource
{
    CIE,     ///< the colour as the observer sees it
    CAMERA,  ///< the camera's record through an IDT fitted (rawtoaces' way) for the shooting light
    /// The camera's record balanced by gains for the shooting light, through
    /// one IDT fitted for the daylight.
    CAMERA_DAYLIGHT_IDT,
};

/// Its key in reports and JSON: "cie", "camera", "camera-daylight-idt".
const char* PlateSourceName(PlateSource source) noexcept;

/// The plates key of the rows that measure the lit looks on `balanced`
/// plates (AccuracyOptions::measureMismatch): "<key>-through-lit-looks".
std::string ThroughLitLooksKey(const Plates& balanced);

/// The folds CrossValidate cuts each training set into.
inline constexpr int CROSS_VALIDATION_FOLDS = 5;
/// CrossValidate's set names: "training, in-sample" and "training, N-fold".
std::string InSampleSetName();
std::string CrossValidatedSetName(int folds);

/// MeasureFloor's methods, in the order it measures them: "floor-3x3" and
/// "floor-rootpoly".
const std::vector<std::string>& FloorMethodNames();

/// ΔE00 of one method for one illuminant pair over one reflectance set at
/// one exposure, against the spectral reference (the remittances rendered
/// under `to`).
struct AccuracyRow
{
    std::string method;
    std::string from;
    std::string to;
    std::string set;
    double exposure = 1.0;  ///< k: the pixel k·c went in, the result was divided by k
    bool shipped = false;   ///< through the form a user gets (OCIO processor, LUT included)
    /// The plate convention (Plates::key()): "lit", or "balanced-cat02" /
    /// "balanced-bradford", where input and reference are both balanced to
    /// the working white and L*a*b* is relative to that white.
    std::string plates = "lit";
    /// Where the plate came from; the reference is always the CIE truth.
    PlateSource source = PlateSource::CIE;
    double mean = 0.0;
    double p95 = 0.0;
    double max = 0.0;
    std::string worstSample;
};

/// A method's form applied in place to interleaved float RGB.
using PixelBatch = std::function<void(float* rgb, size_t count)>;

/// The shipped form of a method for one pair — what a config's look does
/// (its OCIO processor: guard and matrix, or shaper, 3D LUT and inverse
/// shaper). Supplied by the layer that knows OCIO; nullptr: no shipped form.
using ShippedFactory =
    std::function<PixelBatch(const Light& from, const Light& to, const MethodSpec& method)>;

struct AccuracyOptions
{
    std::vector<Light> lights;  ///< every ordered pair of distinct lights
    /// Only each light to those after it in `lights` (an image measured for
    /// one change of light, --from → --to), not back.
    bool forwardOnly = false;
    std::vector<std::string> methods;
    std::vector<ReflectanceSet> sets;
    std::string workingSpace = defaults::WORKING_SPACE;
    Observer observer = Observer::CIE1931_2DEG;
    /// The levels k the colours are seen at: 2^-8 … 2^4 of the white.
    std::vector<double> exposures = {1.0 / 256, 1.0 / 64, 1.0 / 16, 1.0 / 4, 1.0, 4.0, 16.0};
    /// When set, every method is measured in its shipped form too (on the
    /// "cie" plates).
    ShippedFactory shipped;
    /// The plate conventions measured, each a full set of rows.
    std::vector<Plates> plates = {Plates{PlateConvention::LIT, AdaptationMethod::CAT02},
                                  Plates{PlateConvention::BALANCED, AdaptationMethod::CAT02}};
    /// When set, the plates are also simulated as this camera records them
    /// (sources "camera" and "camera-daylight-idt", ideal forms), and
    /// rootpoly-camera is measured on the daylight-IDT plates.
    std::shared_ptr<const SpectralCamera> camera;
    std::string idtLightName = DEFAULT_IDT_LIGHT;  ///< the daylight IDT's light
    Spectrum idtLight;                             ///< empty: the built-in idtLightName
    /// For each balanced convention, also the lit looks applied to the
    /// balanced plates (plates "<key>-through-lit-looks", ideal forms, "cie"
    /// source): the error of a pipeline that balances its plates and then
    /// corrects the cast again.
    bool measureMismatch = true;
};

/// How many pairs of lights `options` measures.
size_t PairCount(const AccuracyOptions& options);

/// The default comparison: A, C, D50, D65, E, F1–F12; every image method;
/// the sets tcs (TCS01–15), tcs09-15 (held out from fitting) and random
/// (100 smooth random remittances, none of them in the training set).
AccuracyOptions DefaultAccuracyOptions();

/// Measures every (plates, source, method, pair, set, exposure, form). For
/// balanced plates the input is the colour under `from` balanced to the
/// working white (BalanceMatrix) and the reference the colour under `to`
/// balanced the same way. For each remittance:
/// its colour under `from` (working RGB, white Y = 1) times k goes through
/// the method, is divided by k and is compared in CIEDE2000 — L*a*b*
/// relative to `to`'s white — with its colour rendered under `to`. An
/// exposure-invariant method gives the same figure at every k. `progress`
/// (0–1) is called as pairs finish.
std::vector<AccuracyRow> MeasureAccuracy(const AccuracyOptions& options,
                                         const std::function<void(double)>& progress = {});

/// How well the fitted methods (fit3x3, rootpoly, rootpoly3 among
/// `options.methods`) generalise: for every pair, each method fitted on its
/// own training set and measured on it (set "training, in-sample"), and
/// `folds`-fold cross-validated — fitted on all folds but one, measured on
/// that one (set "training, N-fold"). Ideal forms, k = 1.
std::vector<AccuracyRow> CrossValidate(const AccuracyOptions& options,
                                       int folds = CROSS_VALIDATION_FOLDS);

/// The floor of pixel-only methods on each set: per pair, the best 3×3
/// ("floor-3x3") and the best degree-2 root polynomial ("floor-rootpoly")
/// fitted in CIELAB on that very set and measured on it, k = 1. No method
/// that sees only the pixel does much better on that set.
std::vector<AccuracyRow> MeasureFloor(const AccuracyOptions& options);

}  // namespace bandlight
