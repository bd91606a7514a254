// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `wall`'s request and result, the one step that checks a request before
// any work, and the wall's emitters read and checked.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "farm/Reporter.h"
#include "requests/Defaults.h"
#include "spectral/LightScores.h"
#include "spectral/Statistics.h"
#include "transforms/De00Fit.h"
#include "transforms/Idt.h"
#include "transforms/Methods.h"

namespace bandlight::jobs
{

/// One emitter of an LED wall or fixture: its name (a drive channel) and
/// the file of its spectrum at full drive (CSV or CGATS, any grid).
struct WallEmitterSpec
{
    std::string name;
    std::string file;
};

/// "NAME=FILE" as {emitter} takes it; throws ParameterError for text that
/// is not a name, '=' and a file.
WallEmitterSpec ParseEmitter(const std::string& text);

/// `wall`: an LED wall or fixture of N emitters as a camera sees it in the
/// frustum and as a light outside it, for each of the camera's white
/// balances, delivered as an OCIO config selected by a context variable.
struct WallRequest
{
    /// The emitters, at least three, in drive-channel order.
    std::vector<WallEmitterSpec> emitters;
    /// Camera sensitivities (rawtoaces JSON, CSV or CGATS with R, G, B).
    std::string camera;
    /// The camera's white balances: colour temperatures ("5600K": daylight
    /// from 4000 K, Planckian below), built-in names or spectrum files.
    std::vector<std::string> whiteBalances;
    /// The RGB space of the wall's content (a built-in linear space).
    std::string contentSpace;
    /// The folder config.ocio, its CLF files and report.json go into.
    std::string out;
    /// Training remittances (a file or a built-in set); empty: rawtoaces' 190.
    std::string training;
    /// The second set errors are measured on, fitted on by no correction.
    std::string testSet = defaults::WALL_TEST_SET;
    std::string workingSpace = defaults::IDT_WORKING_SPACE;
    std::string adaptation = defaults::ADAPTATION;  ///< of the IDTs: "cat02" or "bradford"
    std::string observer = defaults::OBSERVER;
};

/// A corner of the content's RGB cube (or its white) and the drive it takes.
struct WallCorner
{
    std::string name;  ///< "red", ..., "white"
    Vec3 content = Vec3::Zero();
    Eigen::VectorXd drive;
    bool negative = false;  ///< some emitter would have to emit less than nothing
};

/// The in-frustum transform: content RGB → drive values that make the
/// camera record the content as intended (docs/wall.md).
struct WallInFrustum
{
    /// N × 3: content RGB → the N emitters' drives (1: the emitter's
    /// spectrum as its file gives it).
    Eigen::MatrixXd drive;
    /// "exact" (three emitters); with more, "non-negative minimum-norm"
    /// (the least non-negative drive of the exact solutions) or, when no
    /// exact solution is non-negative, "non-negative least-squares" (the
    /// closest non-negative one: `residual` says how close).
    std::string solution;
    /// The camera's balanced record of the wall driven for content c is
    /// exposure × the record the content asks for: one scale, chosen so that
    /// content white drives the most driven emitter at 1.
    double exposure = 1.0;
    /// Of the camera's 3 × N response, each emitter's column of unit length.
    double condition = 0.0;
    /// The largest relative difference, over the corners, between what the
    /// camera records of the driven wall and exposure × the intended record.
    double residual = 0.0;
    std::vector<WallCorner> corners;
    int negativeCorners = 0;
};

/// A correction's ΔE00 over the data it was fitted on, against the plain
/// least-squares fit of the same form on the same data (`fit`: "ciede2000",
/// bandlight's reweighted fit, or "least-squares" when nothing beats the
/// plain fit there).
using WallFitFigures = De00FitFigures;

/// The out-of-frustum errors on one set of remittances under the wall
/// showing one light.
struct WallSetErrors
{
    std::string set;
    Statistics before;         ///< the wall driven through the in-frustum transform
    Statistics preCorrected;   ///< its drive through the lighting pre-correction
    Statistics postCorrected;  ///< the plate through the post-camera look
};

/// The wall showing one light, as a light.
struct WallShown
{
    std::string light;
    Eigen::VectorXd drive;     ///< through the in-frustum transform, largest 1
    Eigen::VectorXd preDrive;  ///< through the pre-correction as well
    bool negative = false;     ///< either drive has a negative channel
    std::vector<WallSetErrors> errors;
    /// The light-quality scores (spectral/LightScores.h) of the wall's
    /// light at `drive` and at `preDrive`; none where a drive is negative.
    std::optional<LightQuality> scores;
    std::optional<LightQuality> preScores;
};

/// Everything of one camera white balance.
struct WallBalance
{
    std::string light;  ///< as given
    std::string key;    ///< its value of the context variable
    double cct = 0.0;
    double duv = 0.0;
    IdtFit idt;  ///< bandlight's IDT for the light (balanced camera RGB → working)
    WallInFrustum inFrustum;
    /// The scores of the wall's own white: its light driven for content
    /// white (1, 1, 1) through the in-frustum transform.
    std::optional<LightQuality> whiteScores;
    Eigen::MatrixXd preCorrection;  ///< N × N on the drive
    WallFitFigures preFit;
    Mat3 post = Mat3::Identity();  ///< the post-camera look (working RGB)
    WallFitFigures postFit;
    /// Its non-linear form: the method registry's op `postMethod`
    /// (rootpoly-plate, lit plates through this white balance's IDT) from
    /// `postFrom` (the wall showing the light, its spectrum) to `postTo`
    /// (the light); the op's root polynomial, and its figures on the
    /// training plates.
    Light postFrom;
    Light postTo;
    MethodSpec postMethod;
    RootPolynomial postRootPolynomial;
    WallFitFigures postRootPolynomialFit;
    /// The method registry's rootpoly-camera op for the same change of
    /// light on the same plates (RegistryPostErrors), training set.
    Statistics postRegistry;
    std::vector<WallShown> shown;  ///< one per white-balance light
};

struct WallResult
{
    std::string camera;
    std::vector<WallEmitterSpec> emitters;
    std::string contentSpace;  ///< keys of the built-in spaces
    std::string workingSpace;
    std::string adaptation;
    std::string trainingName;
    int trainingCount = 0;
    std::string testName;
    int testCount = 0;
    /// The lights the pre-correction is fitted over (the white balances first).
    std::vector<std::string> depicted;
    std::string contextVariable = defaults::WALL_CONTEXT_VARIABLE;
    std::vector<WallBalance> balances;
    /// How the config carries the drive: "RGB" (three emitters), "RGBA"
    /// (four: the fourth in alpha), "" (more: not at all, see configNote).
    std::string drives;
    std::string configNote;
    std::vector<std::string> written;
};

/// Every option and output path of `request`, before any work: at least
/// three emitters of distinct names, a camera, white balances of distinct
/// names, a content space, {out} given, not empty and none of the inputs.
void CheckWallRequest(const WallRequest& request);

/// The emitters' spectra as their files give them (the first spectrum of
/// each, its scale kept: drives are relative to it), named by {emitter}.
/// Refused, naming the file and line: a negative sample (an emission is
/// not negative); naming the file: no power over 380–780 nm.
std::vector<NamedSpectrum> ReadEmitters(const WallRequest& request,
                                        Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
