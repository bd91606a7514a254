// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The colour side of scene rendering, shared by the planner and the
// renderer: light scaling, spectral grids, matching-function weights, and
// light × remittance products in the output's channels.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "transforms/Scene.h"

namespace bandlight::detail
{

struct Output
{
    bool bands = false;
    int channels = 3;
    std::vector<std::string> names;
    Mat3 xyzToRgb = Mat3::Identity();
};

/// The output's channels: a working space's RGB, or (band mode) the bands.
Output MakeOutput(const Scene& s);

/// Band means of a light or remittance (lines count in their band).
std::vector<double> Means(const SceneSpectrum& s, const BandSet& bands);

/// 1 / the light's largest band mean (the lecture's normalisation).
double LightScale(const SceneSpectrum& s, const BandSet& bands);

/// A spectral sampling grid from 360 nm to 830 nm.
struct Grid
{
    double step;
    int count;
    double wavelength(int i) const { return 360.0 + step * i; }
};
Grid MakeGrid(double step);

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

/// The coarsest grid that reproduces every product of the scene (see
/// docs/scenes.md); `why` says so in words.
double ChooseStep(const Scene& s, std::string& why);

/// Throws Exception for material indices out of range or an empty image.
void CheckScene(const Scene& s);

}  // namespace bandlight::detail
