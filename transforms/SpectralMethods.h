// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

/// `fit3x3`: the 3×3 M minimising Σ |M·c1_i − c2_i|² over training
/// remittances (c_k their RGB under S_k), subject to M·w1 = w2 (S1's white
/// maps exactly to S2's) — least squares with one linear constraint per
/// row, in the manner of camera IDT fitting.
Mat3 FitMatrix(const SurfaceRenderer& from, const SurfaceRenderer& to,
               const std::vector<NamedSpectrum>& training);

/// `metamer`: for a pixel c, the smoothest remittance r (least Σ (r_{i+1} −
/// r_i)²) with A1·r = c, re-lit under S2: c2 = A2·r. Linear in c, so one
/// 3×3 (the KKT solution operator of the constrained least squares).
/// Reproduces the input under S1 exactly (A1·r = c) and, since the flat
/// remittance is the smoothest, maps S1's white exactly to S2's.
Mat3 MetamerMatrix(const SurfaceRenderer& from, const SurfaceRenderer& to);

/// The smoothest remittance of MetamerMatrix for one pixel (for tests and plots).
SurfaceRenderer::Samples SmoothestMetamer(const SurfaceRenderer& from, const Vec3& rgb);

}  // namespace bandlight
