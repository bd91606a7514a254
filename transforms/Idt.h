// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Camera input transforms (IDTs) fitted from spectral sensitivities the way
// the Academy's rawtoaces fits them, iterated to the optimum of its
// objective; their interpolation by colour temperature (as DNG does), the
// light a camera's as-shot neutral stands for, and IDTs from a photographed
// chart. Plain matrices: no OCIO here (plugin/ turns them into colour spaces).

#include <string>
#include <vector>

#include "spectral/Statistics.h"
#include "transforms/Camera.h"
#include "transforms/RootPolynomial.h"

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

    /// Its figures as a summary (the median, not kept, zero).
    Statistics statistics() const
    {
        Statistics s;
        s.count = size_t(count);
        s.mean = mean;
        s.p95 = p95;
        s.max = max;
        return s;
    }

    /// The figures of a summary (the set's name left empty).
    static IdtError Of(const Statistics& s)
    {
        IdtError e;
        e.count = int(s.count);
        e.mean = s.mean;
        e.p95 = s.p95;
        e.max = s.max;
        return e;
    }
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
    /// The working white in CIE XYZ (Y = 1): where the balance takes the
    /// light's white, and the L*a*b* reference white of the errors.
    Vec3 workingWhiteXyz() const { return m_labWhite; }
    /// Working RGB → CIE XYZ, as the observer sees the working primaries.
    Mat3 rgbToXyz() const { return m_eye.rgbToXyz(); }
    /// The chromatic adaptation that balances the light's white to the
    /// working white.
    AdaptationMethod adaptation() const noexcept { return m_adaptation; }
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
    AdaptationMethod m_adaptation;
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

/// DNG's interpolation weight of the first of two calibrations at `cct`
/// (Adobe DNG Specification 1.6, "Mapping Camera Color Space to CIE XYZ
/// Space"): g = (1/T − 1/T2) / (1/T1 − 1/T2), linear in inverse colour
/// temperature (mired). DNG clamps g to [0, 1] (the nearer calibration
/// outside the pair); with `extrapolate` the line in mired goes on beyond
/// the pair. 1 when the two temperatures are equal. Temperatures in K.
double MiredWeight(double cct1, double cct2, double cct, bool extrapolate);

/// A camera's characterisation under one light, as a DNG file carries it
/// (ColorMatrixN for CalibrationIlluminantN): what is interpolated between
/// two lights, because it varies slowly with the light, while the white
/// balance and the chromatic adaptation are worked out for the light at
/// hand.
struct IdtCalibration
{
    double cct = 0.0;  ///< K, of the light's white (CIE 15:2004 §9.5)
    /// CIE XYZ under the light → raw camera RGB (DNG's ColorMatrix),
    /// scaled as the DNG SDK's NormalizeColorMatrix scales it: the working
    /// white (where DNG takes D50, the white of its connection space) gives
    /// a camera neutral whose largest channel is 1. Without that common scale the
    /// two matrices' weights would depend on each light's brightness.
    Mat3 colorMatrix = Mat3::Identity();
};

/// The characterisation an IDT fitted for `problem`'s light stands for:
/// raw camera RGB → diag(gains) → fit.matrix → working RGB → XYZ, the
/// balance to the working white undone (CAT⁻¹), inverted and scaled as
/// IdtCalibration::colorMatrix says. Throws Exception for a singular IDT.
IdtCalibration CalibrationOf(const IdtProblem& problem, const IdtFit& fit);

/// The IDT (balanced camera RGB → working RGB, as IdtFit::matrix) for the
/// light of `target`, between two calibrations as DNG maps camera colour to
/// XYZ: the colour matrix interpolated in mired by the CCT of the target
/// light's white (MiredWeight), the white balance the camera's own response
/// to that light (IdtProblem::gains: known from the sensitivities, where a
/// raw developer reads the as-shot neutral), and the white that neutral
/// stands for through the interpolated matrix adapted to the working white
/// by the target's chromatic adaptation (CAT02 as rawtoaces). White
/// (1, 1, 1) goes to (1, 1, 1) at every temperature, and at a calibration's
/// own light the result is the IDT it came from (to rounding). Throws
/// Exception when the interpolated matrix is singular.
Mat3 InterpolateIdt(const IdtCalibration& c1, const IdtCalibration& c2, const IdtProblem& target,
                    bool extrapolate);

/// How far an as-shot neutral may stand from the light it is matched to:
/// the grey it stands for, under that light, at most this many ΔE00 from
/// the light's own white. A neutral further away is refused: no light
/// searched explains it (a fluorescent tube searched as daylight, a
/// neutral of 1,1,1 that no camera records under a real light).
constexpr double kAsShotLimitDeltaE = 2.0;

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
    std::string lightName;      ///< "daylight 5600K", "planckian 3200K", or a listed light's name
    /// ΔE00 of the grey the neutral stands for against the matched light's
    /// white (L*a*b* relative to that white): 0 for an exact match.
    double greyDeltaE = 0.0;
};

/// The lights an as-shot neutral is searched among: the daylight and
/// Planckian families ("daylight", "planckian", both by default) by
/// temperature, or a list of lights (fluorescent tubes, LED fixtures, a
/// user's own).
struct AsShotSearch
{
    bool daylight = true;
    bool planckian = true;
    std::vector<std::pair<std::string, Spectrum>> lights;  ///< when given: these alone
    std::string describe() const;  ///< "daylight or Planckian light", "F1, F2, ..."
};

/// The daylight (4000–25000 K) or Planckian (1000–25000 K) light whose raw
/// camera response has the chromaticity (R/G, B/G) of `neutral` (any
/// scale; every channel > 0 and finite, else Exception), searched in mired
/// and refined by golden section; the white it stands for is the neutral
/// carried through that light's white balance and first-order IDT back to
/// XYZ under the light (exactly the light's white when the response
/// matches), whose CCT and Duv are reported.
///
/// Refused (ParameterError naming the closest light and the distance, and
/// whether it lies at the end of its family's temperature range) when the
/// grey is more than kAsShotLimitDeltaE from the matched light's white.
AsShotEstimate EstimateAsShot(const SpectralCamera& camera, const Vec3& neutral,
                              const RgbSpace& working, AdaptationMethod adaptation,
                              Observer observer = Observer::CIE1931_2DEG,
                              const AsShotSearch& search = {});

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
