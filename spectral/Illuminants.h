// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/Spectrum.h"

namespace bandlight
{

/// Second radiation constant c2 = hc/k (CODATA 2018), m·K.
constexpr double kPlanckC2 = 1.438776877e-2;
/// Wien's displacement constant b = λ_max·T (CODATA 2018), m·K.
constexpr double kWienB = 2.897771955e-3;

/// Spectral radiance of a black body (Planck's law), W·sr⁻¹·m⁻²·nm⁻¹, at
/// wavelength lambdaNm (in vacuum) and temperature kelvin > 0.
double PlanckRadiance(double lambdaNm, double kelvin) noexcept;

/// Relative spectral power of a Planckian radiator at `kelvin`, 300–830 nm
/// (or the given grid), normalised to 100 at 560 nm as CIE tables are.
/// Throws Exception for temperatures outside (0, 1e6] K.
Spectrum Planckian(double kelvin, double startNm = 300.0, double stepNm = 5.0, size_t count = 107);

/// Chromaticity (x, y) of CIE daylight at correlated colour temperature
/// `cct` in 4000–25000 K (CIE 15:2004 eq. 3.3–3.4); throws outside.
Eigen::Vector2d DaylightChromaticity(double cct);

/// Relative SPD of CIE daylight at `cct` (4000–25000 K), 300–830 nm at 5 nm:
/// S0 + M1·S1 + M2·S2 with M1, M2 rounded to three decimals as CIE 15:2004
/// §3.1 prescribes, so the tabulated D-illuminants are reproduced.
Spectrum Daylight(double cct);

/// The nominal CCT of a D-illuminant named for `hundreds` (65 for D65):
/// the value of the old second radiation constant 1.4380e-2 corrected to
/// 1.4388e-2 (CIE 15:2004 §3.1): 6500 K → 6504 K.
double DaylightNominalCct(double hundreds) noexcept;

/// A built-in illuminant by case-insensitive name: the tabulated A, C, D50,
/// D55, D65, E, F1–F12; D75 and any other "Dnn" derived from the daylight
/// basis; "3200K" / "BB3200" / "planck:3200" a Planckian radiator;
/// "daylight:5600" CIE daylight at exactly that CCT. Throws Exception naming
/// the choices when the name is unknown.
Spectrum BuiltinIlluminant(const std::string& name);

/// True when name is understood by BuiltinIlluminant.
bool IsBuiltinIlluminant(const std::string& name);

/// An illuminant taken from data, made safe to integrate. Its scale never
/// matters (colours are relative to its white), so it is scaled by a power
/// of two — exactly — until its largest |value| lies in [0.5, 1): values
/// near the double range (1e308) or denormal ones then integrate like any
/// other. It must have a white: a luminance (CIE 1931 ȳ) of at least 1e-6
/// of an equal-energy light of the same peak over 380–780 nm. Throws Exception
/// naming `source` for an illuminant with no power, only non-finite or
/// negative luminance, power only where the eye sees nothing, or a white
/// whose X or Z is zero (a red laser: nothing to relate L*a*b* to).
Spectrum UsableIlluminant(const Spectrum& illuminant, const std::string& source);

/// The canonical spelling of a built-in illuminant name ("d65" → "D65").
std::string CanonicalIlluminantName(const std::string& name);

/// The standard set, in table order: A, C, D50, D55, D65, D75, E, F1–F12.
const std::vector<std::string>& StandardIlluminantNames();

}  // namespace bandlight
