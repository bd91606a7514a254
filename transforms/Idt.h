// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Camera input transforms (IDTs) fitted from spectral sensitivities the way
// the Academy's rawtoaces fits them, iterated to the optimum of its
// objective; their interpolation by colour temperature (as DNG does), the
// light a camera's as-shot neutral stands for, and IDTs from a photographed
// chart. Plain matrices: no OCIO here (plugin/ turns them into colour spaces).

#include <string>
#include <vector>

#include "bandlight/transforms/Camera.h"
#include "bandlight/transforms/RootPolynomial.h"

namespace bandlight
{

/// The light of an IDT named by a colour temperature, as rawtoaces and the
/// DNG specification choose it: CIE daylight (CIE 15:2004 §3.1) at 4000 K
/// and above, a Planckian radiator below. Valid 1000–25000 K; throws
/// Exception outside.
Spectrum IdtLightForCct(double kelvin);

/// Parses a colour temperature written "3200K" (or "3200k"; digits, an
/// optional decimal part, then K): true and the value when `text` has that
/// form, false when it does not look like a temperature at all (no digit
/// first or no K last). Throws Exception for text that starts with a digit
/// and ends in K but is not a number ("32OOK").
bool ParseCct(const std::string& text, double& kelvin);

/// The objective rawtoaces minimises for a 3×3 IDT: the sum over the
/// training colours of the squared CIELAB difference (ΔE*ab²) between
/// M·input and the target, both seen through data.rgbToXyz and taken
/// relative to data.labWhite.
double LabObjective(const ColourFit& data, const Mat3& m);

/// Minimises LabObjective over the 3×3 matrices with M·whiteIn = whiteOut
/// (six free parameters when whiteIn = (1, 1, 1): each row sums to its
/// whiteOut), by Levenberg–Marquardt from `start` (which must keep the
/// white; the first-order fit FitLabMatrix does) with the exact Jacobian of
/// L*a*b*, until the step and the gradient vanish (relative 1e-13) or 200
/// iterations. `iterations` receives the number taken.
Mat3 OptimiseLabMatrix(const ColourFit& data, const Mat3& start, int* iterations = nullptr);

/// ΔE00 statistics of an IDT on a set of remittances.
struct IdtError
{
    std::string set;
    int count = 0;
    double mean = 0.0;
    double p95 = 0.0;  ///< nearest rank (Percentile)
    double max = 0.0;
};

/// One camera under one light: its white balance, the colours its
/// remittances should become (their colour under the light balanced to the
/// working white by `adaptation`, working RGB, white (1, 1, 1)) and the
/// measures of a fit.
class IdtProblem
{
public:
    IdtProblem(const SpectralCamera& camera, const Spectrum& light, const RgbSpace& working,
               AdaptationMethod adaptation, Observer observer = Observer::CIE1931_2DEG);

    /// Raw → balanced gains, normalised so that the green gain is 1 (the
    /// raw developer's white-balance multipliers).
    Vec3 gains() const;
    /// The balanced camera RGB of every remittance as the fit's inputs and
    /// their balanced working RGB as targets; whites (1, 1, 1) → (1, 1, 1).
    ColourFit data(const std::vector<NamedSpectrum>& set) const;
    /// The light's white in CIE XYZ (Y = 1), as the observer sees it.
    Vec3 whiteXyz() const { return m_whiteXyz; }
    /// ΔE00 of `idt` (balanced camera RGB → working RGB) against the
    /// targets over `set`, L*a*b* relative to the working white.
    IdtError errors(const Mat3& idt, const std::vector<NamedSpectrum>& set,
                    const std::string& name) const;
    /// The raw camera RGB of a remittance, in the units the gains apply to.
    Vec3 raw(const Spectrum& remittance) const;
    const CameraShot& shot() const noexcept { return m_shot; }

private:
    CameraShot m_shot;
    SurfaceRenderer m_eye;
    Mat3 m_balance;
    Vec3 m_labWhite;
    Vec3 m_whiteXyz;
};

/// An IDT fitted for one light.
struct IdtFit
{
    Vec3 gains = Vec3::Ones();           ///< IdtProblem::gains
    Mat3 matrix = Mat3::Identity();      ///< balanced camera RGB → working RGB, the optimum
    Mat3 firstOrder = Mat3::Identity();  ///< the first-order fit it started from
    double rmsDe76 = 0.0;                ///< √(objective / count) at the optimum
    double firstOrderRmsDe76 = 0.0;      ///< the same for the first-order fit
    int iterations = 0;

    /// Raw camera RGB → working RGB: matrix · diag(gains).
    Mat3 rawToWorking() const { return matrix * gains.asDiagonal(); }
};

/// Fits the IDT of `problem` on `training` (rawtoaces' 190 when empty):
/// the first-order fit, then OptimiseLabMatrix from it. Throws Exception
/// when the camera's channels do not separate colours (a singular result).
IdtFit FitIdtOptimal(const IdtProblem& problem, const std::vector<NamedSpectrum>& training = {},
                     const std::string& cameraLabel = "camera");

/// DNG-style interpolation between two IDTs by inverse colour temperature
/// (Adobe DNG Specification 1.6, "Mapping Camera Color Space to CIE XYZ
/// Space"): weight g = (1/T − 1/T2) / (1/T1 − 1/T2), result
/// g·M1 + (1 − g)·M2. DNG clamps g to [0, 1] (the nearer IDT outside the
/// pair); with `extrapolate` the line in mired goes on beyond the pair.
/// Both matrices keep white, so the result does.
Mat3 InterpolateIdt(const Mat3& m1, double cct1, const Mat3& m2, double cct2, double cct,
                    bool extrapolate = false);

/// What a camera's as-shot neutral says about the light.
struct AsShotEstimate
{
    double cct = 0.0;           ///< K, of the estimated white (CIE 15:2004 §9.5)
    double duv = 0.0;           ///< its distance from the Planckian locus in CIE 1960 UCS
    std::string family;         ///< "daylight" or "planckian": the light whose response matched
    double familyKelvin = 0.0;  ///< that light's temperature parameter
    double residual = 0.0;      ///< log-chromaticity mismatch of its response (0: exact)
    std::string nearest;        ///< the standard illuminant nearest in CIE 1960 (u, v)
    Spectrum light;             ///< the matched light, to fit the IDT for
};

/// The daylight (4000–25000 K) or Planckian (1000–25000 K) light whose raw
/// camera response has the chromaticity (R/G, B/G) of `neutral` (any
/// scale; every channel > 0 and finite, else Exception), searched in mired
/// and refined by golden section; the white it stands for is the neutral
/// carried through that light's white balance and first-order IDT back to
/// XYZ under the light (exactly the light's white when the response
/// matches), whose CCT and Duv are reported.
AsShotEstimate EstimateAsShot(const SpectralCamera& camera, const Vec3& neutral,
                              const RgbSpace& working, AdaptationMethod adaptation,
                              Observer observer = Observer::CIE1931_2DEG);

/// The index of the flattest remittance of a set (smallest relative
/// spread over 400–700 nm): the chart's neutral, whose raw RGB gives the
/// white balance of a chart IDT.
size_t FlattestRemittance(const std::vector<NamedSpectrum>& set);

/// The IDT from a photographed chart: `raw` camera RGB per patch of
/// `chart` (same order and count) under `light`. The white balance is that
/// of the chart's flattest patch; the fit is FitIdtOptimal's on the chart
/// (its targets the patches' colours under the light). For RGB simulated
/// from sensitivities it equals the sensitivity IDT fitted on the chart.
IdtFit FitChartIdt(const std::vector<Vec3>& raw, const std::vector<NamedSpectrum>& chart,
                   const Spectrum& light, const RgbSpace& working, AdaptationMethod adaptation,
                   Observer observer = Observer::CIE1931_2DEG);

/// The chart's targets and balanced inputs as FitChartIdt fits them.
ColourFit ChartFitData(const std::vector<Vec3>& raw, const std::vector<NamedSpectrum>& chart,
                       const Spectrum& light, const RgbSpace& working, AdaptationMethod adaptation,
                       Observer observer, Vec3* gains = nullptr);

/// The name of a camera's input colour space for a light:
/// "Input - <camera> - <light>".
std::string IdtColorSpaceName(const std::string& camera, const std::string& light);

}  // namespace bandlight
