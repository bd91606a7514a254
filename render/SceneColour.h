// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The colour side of scene rendering, shared by the planner and the
// renderer: light scaling, spectral grids, matching-function weights, and
// light × remittance products in the output's channels.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "render/Scene.h"

namespace bandlight::detail
{

/// The output name that asks for the spectral radiance itself (spectral
/// mode): one channel per grid sample, Fichet 2021 names.
inline constexpr const char* SPECTRUM_OUTPUT = "spectrum";

struct Output
{
    bool bands = false;
    /// Spectral radiance on the grid, scaled so that XYZ = Σ v·cmf·Δλ /
    /// Σ ȳ·Δλ over the grid (pbrt-v4's convention) is the RGB render's XYZ.
    bool spectrum = false;
    int channels = 3;
    std::vector<std::string> names;
    Mat3 xyzToRgb = Mat3::Identity();
};

/// The output's channels: a working space's RGB, (band mode) the bands, or
/// (spectral mode, SPECTRUM_OUTPUT) the grid's samples.
Output MakeOutput(const Scene& s);

/// Band means of a light or remittance (lines count in their band).
std::vector<double> Means(const SceneSpectrum& s, const BandSet& bands);

/// 1 / the light's largest band mean (the band model's normalisation).
double LightScale(const SceneSpectrum& s, const BandSet& bands);

/// A spectral sampling grid: `count` samples from `start` nm, `step` apart,
/// the last at most `end`; emission lines count inside [start, end].
struct Grid
{
    double start;
    double end;
    double step;
    int count;
    double wavelength(int i) const { return start + step * i; }
    bool contains(double nm) const { return nm >= start && nm <= end; }
};
/// The grid of `step` nm over the scene's integration range; throws
/// Exception for a step outside 0.1–50 nm or a range outside 360–830 nm.
Grid MakeGrid(const RenderSettings& settings, double step);

/// "81 samples at 5 nm over 380-780 nm (as the scene sets)": the grid and
/// where its range comes from.
std::string DescribeRange(const RenderSettings& settings, const Grid& grid);

/// The spectral grid step both render paths use: the scene's, or the
/// planner's choice (ChooseStep); `why` says which, in words.
double GridStep(const Scene& s, std::string& why);

/// Matching functions on a grid, as weights cmf(λ_i)·Δλ / N_y, and the
/// band integrals N_k of each.
struct Cmf
{
    std::vector<Vec3> weight;
    Vec3 norm;
};
Cmf MakeCmf(const Grid& g, const BandSet& bands);

std::vector<double> Sample(const Spectrum& s, const Grid& g);

/// diag(N) / N_y · B: band values → XYZ on the scene's scale.
Eigen::MatrixXd BandToXyz(const BandSet& bands);

std::vector<double> ToChannels(const Output& out, const Vec3& xyz);

/// One unit of `light` on `remittance`, in the output's channels, in the
/// scene's mode.
std::vector<double> ProductColour(const Scene& s, const Output& out, const SceneSpectrum& light,
                                  const Spectrum& remittance, const Grid& grid, const Cmf& cmf);

/// The coarsest of 20, 10, 5 and 2 nm that reproduces every light ×
/// remittance product of the scene to 1e-4 of white, 1 nm (the reference
/// grid) when none does (see docs/scenes.md); `why` says so in words, and
/// names the product that needs the finer grid.
double ChooseStep(const Scene& s, std::string& why);

/// Throws Exception for material indices out of range or an empty image.
void CheckScene(const Scene& s);

}  // namespace bandlight::detail
