// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The one table of bandlight's library defaults: the parameters of the
// transforms and measurements themselves. The jobs add the defaults of what
// a run writes and how it runs (requests/Defaults.h). The C++ request structs
// (jobs/), the command's options (cli/) and the Python module's keywords
// (python/) all take their defaults from these two files, so the three faces
// cannot drift apart; tests/python/test_defaults.py holds Python to them.

#include <cstddef>

#include "transforms/Version.h"

namespace bandlight::defaults
{

/// What a pipeline's images are: white-balanced to the working white, as
/// every ACES IDT delivers them (docs/plates.md). "lit" is the other choice.
inline constexpr const char* PLATES = "balanced";
/// The adaptation balanced plates were balanced with: rawtoaces uses CAT02.
inline constexpr const char* ADAPTATION = "cat02";
/// The light a camera's one fixed IDT was fitted for (rootpoly-camera).
inline constexpr const char* IDT_LIGHT = "D55";

/// The working space camera input transforms land in: ACES2065-1, as IDTs do.
inline constexpr const char* IDT_WORKING_SPACE = "aces2065-1";
/// The second set an IDT's error is measured on (beside its training set,
/// rawtoaces' 190): the CIE 13.3 test colour samples, fitted on by no IDT.
inline constexpr const char* IDT_TEST_SET = "TCS";
/// The degree of the root polynomial a chart IDT also fits: 0, none (2 or 3).
inline constexpr int IDT_CHART_ROOTPOLY = 0;
/// The colour temperatures `idt --interpolate` measures the interpolated
/// IDT at: 2800–6500 K every 100 K (tungsten to daylight).
inline constexpr double IDT_SWEEP_MIN_K = 2800.0;
inline constexpr double IDT_SWEEP_MAX_K = 6500.0;
inline constexpr double IDT_SWEEP_STEP_K = 100.0;

/// `wall`: the OCIO context variable that selects the transforms of the
/// camera's white balance, as FileTransform paths read it (wall/${WALL_WB}/...).
inline constexpr const char* WALL_CONTEXT_VARIABLE = "WALL_WB";
/// `wall`: emitters whose responses in the camera are this close to
/// collinear (the condition number of the camera's 3×N response, each
/// emitter's column scaled to unit length) are refused: a drive solved
/// through them can move by 100 % for a 1 % error in the measured spectra
/// or sensitivities. RGB and RGBW walls of distinct LEDs lie near 2–3; two
/// greens 2 nm apart beside a red reach 185.
inline constexpr double WALL_MAX_CONDITION = 100.0;
/// `wall`: the most emitters a wall may have. The in-frustum drive of more
/// than three is found by trying every set of emitters (2^N − 1 small
/// solves a content primary: 0.2 s at 16); fixtures and walls have 3–7.
inline constexpr size_t WALL_MAX_EMITTERS = 16;
/// `wall`: the lights the wall's content depicts when its lighting
/// pre-correction is fitted, beside the white-balance lights: Planckian
/// below 4000 K, CIE daylight from 4000 K (IdtLightForCct), 2800–10000 K.
inline constexpr double WALL_DEPICTED_K[] = {2800.0, 3200.0, 4000.0, 4500.0, 5000.0,
                                             5600.0, 6500.0, 8000.0, 10000.0};
/// `wall`: the second set the out-of-frustum errors are measured on, fitted
/// on by no correction.
inline constexpr const char* WALL_TEST_SET = "TCS";

/// The linear working space of images, configs and LUTs.
inline constexpr const char* WORKING_SPACE = "acescg";
/// The illuminant-change method of `apply`, `lut` and Python's relighters.
inline constexpr const char* METHOD = "bradford";
/// The CIE standard observer: 1931 (2°).
inline constexpr const char* OBSERVER = "1931";
/// The three bands VB, VG, VR, edges in nm.
inline constexpr const char* BANDS = "400,500,600,700";
/// N equal bands span 400–700 nm by default.
inline constexpr double EQUAL_BANDS_MIN_NM = 400.0;
inline constexpr double EQUAL_BANDS_MAX_NM = 700.0;
/// How band means are taken: "lecture" (the average of the 5 nm samples
/// inside the band, docs/science.md) or "exact" (the interpolated spectrum
/// integrated).
inline constexpr const char* BAND_RULE = "lecture";
/// The matching functions band matrices are made of: "xyz" (CIE) or "ebu".
inline constexpr const char* MATCHING_SET = "xyz";
/// The chromatic adaptation of a white-point change (adaptation_matrix).
inline constexpr const char* WHITE_ADAPTATION = "bradford";
/// The CIEDE2000 parametric factors kL, kC, kH (CIE 142-2001: 1 for the
/// reference conditions).
inline constexpr double CIEDE2000_K = 1.0;
/// The remittances named when none are: the CIE 13.3 test colour samples.
inline constexpr const char* REFLECTANCES = "TCS";
/// A Planckian spectrum's grid when none is given: 300–830 nm at 5 nm.
inline constexpr double PLANCK_START_NM = 300.0;
inline constexpr double PLANCK_STEP_NM = 5.0;
inline constexpr int PLANCK_COUNT = 107;
/// What a spectral image holds when its channels do not say: radiance.
inline constexpr const char* SPECTRAL_KIND = "emissive";
/// How spectral channels are read: "auto" (point samples, or buckets where
/// the layout says so), "points" or "buckets".
inline constexpr const char* SPECTRAL_SAMPLING = "auto";
/// The illuminants a config gets looks between (the band model's five).
inline constexpr const char* CONFIG_ILLUMINANTS = "A,C,D65,F2,F11";

/// 3D LUT size of a config's non-linear looks: 65³ keeps the LUT's own
/// error near 0.05 ΔE00 where 33³ adds up to 0.25 (docs/accuracy.md); a 65³
/// CLF file is about 12 MB.
inline constexpr int CONFIG_LUT_SIZE = 65;
/// 3D LUT size of a `lut` file: 65³, where OpenColorIO 2.1's GPU shader
/// agrees with its CPU to 1e-5 of the pixel even when a host filters the LUT
/// texture GL_LINEAR (OCIO's own apps and Blender do); a 33³ shaper LUT is
/// off by up to 7 % there on saturated HDR pixels (docs/luts.md, "On the
/// GPU"). A 65³ .cube is about 7 MB, a CLF about 12 MB.
inline constexpr int LUT_SIZE = 65;
/// 3D LUT size of the non-linear transforms made in process for the CPU
/// (apply --method upsample, IlluminantChangeTransform's default).
inline constexpr int TRANSFORM_LUT_SIZE = 33;
/// The LUT sizes accepted anywhere: OCIO's Lut3D takes 2 to 129 points.
inline constexpr int MIN_LUT_SIZE = 2;
inline constexpr int MAX_LUT_SIZE = 129;
/// The shaper of HDR LUT files.
inline constexpr const char* LUT_SHAPER = "log2";
/// What a `lut` file takes and returns: "linear" (the working space's linear
/// values, through the shaper), or "acescct" / "acescc" (those encodings of
/// them, as log-grading hosts hand them over; no shaper).
inline constexpr const char* LUT_ENCODING = "linear";
/// "bandlight 0.1.0": the version CMake's project() states.
inline constexpr const char* VERSION = BANDLIGHT_VERSION;

}  // namespace bandlight::defaults
