// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What the accuracy measures share (transforms/AccuracyScoring.cpp): the
// pairs of lights they run over, each pair's plate matrices, and the score
// of predictions as a row. Used by MeasureAccuracy (transforms/Accuracy.cpp),
// CrossValidate and MeasureFloor (transforms/AccuracyFitted.cpp). Not
// installed.

#include <functional>
#include <string>
#include <vector>

#include "transforms/Accuracy.h"

namespace bandlight::detail
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

/// Judges colours lit under `to`: its RGB → XYZ, and its white.
Judge LitJudge(const SurfaceRenderer& to);

/// ΔE00 of each prediction against its reference (a non-finite prediction
/// scores as a colour far off); `names` name the samples, for the worst.
Errors Score(const Judge& judge, const std::vector<Vec3>& predicted,
             const std::vector<Vec3>& reference, const std::vector<NamedSpectrum>& names);

/// A row of the figures `e`.
AccuracyRow MakeRow(const std::string& method, const Light& from, const Light& to,
                    const std::string& set, double exposure, bool shipped, const Errors& e,
                    const std::string& plates = "lit", PlateSource source = PlateSource::CIE);

/// Runs `perPair(pair, rows)` for every pair on all cores, rows in pair order.
std::vector<AccuracyRow> ForEachPair(
    const AccuracyOptions& o, const std::function<void(double)>& progress,
    const std::function<void(const Light&, const Light&, std::vector<AccuracyRow>&)>& perPair);

/// The plate conventions' matrices for one pair.
struct PairPlates
{
    Plates plates;
    Mat3 balanceFrom = Mat3::Identity();  ///< lit under `from` → this convention's plate
    Mat3 balanceTo = Mat3::Identity();    ///< the truth under `to` → this convention's reference
    Judge judge;
};

/// The matrices of plate convention `p` for the pair `from` → `to` (`r2`
/// renders under `to`); identities for lit plates.
PairPlates MakePairPlates(const Plates& p, const Light& from, const Light& to,
                          const SurfaceRenderer& r2, const RgbSpace& working, Observer observer);

/// `m` for plate convention `p`, with the options' camera and IDT light.
MethodSpec WithPlates(MethodSpec m, const Plates& p, const AccuracyOptions& o);

}  // namespace bandlight::detail
