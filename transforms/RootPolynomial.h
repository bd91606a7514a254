// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include <Eigen/Core>

#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

/// Root-polynomial colour correction after G. D. Finlayson, M. Mackiewicz
/// and A. Hurlbert, "Color Correction Using Root-Polynomial Regression",
/// IEEE Trans. Image Processing 24(5), 2015: out = M · φ(rgb), where φ
/// holds the k-th roots of the degree-k monomials, so every term scales
/// with the pixel and the map is homogeneous of degree 1:
/// f(k·rgb) = k·f(rgb) for every k > 0 — exposure invariant, unlike a
/// plain polynomial. Degree 2: R, G, B, √(RG), √(GB), √(RB) (6 terms);
/// degree 3 adds ∛(RG²), ∛(GB²), ∛(RB²), ∛(GR²), ∛(BG²), ∛(BR²), ∛(RGB)
/// (13 terms). Roots take negative channels as 0 (a negative pixel has no
/// root; the linear terms keep it).
class RootPolynomial
{
public:
    RootPolynomial() = default;
    /// `m` is 3 × Terms(degree).
    RootPolynomial(int degree, Eigen::MatrixXd m);

    static int Terms(int degree);
    /// φ(rgb) for `degree` (2 or 3) into `out` (Terms(degree) values).
    static void Features(const Vec3& rgb, int degree, double* out) noexcept;

    int degree() const noexcept { return m_degree; }
    const Eigen::MatrixXd& matrix() const noexcept { return m_m; }
    /// The coefficients as floats, 3 × Terms(degree) (the rest zero).
    const float (&floats() const noexcept)[3][13] { return m_f; }

    /// One pixel (the scalar reference path).
    Vec3 apply(const Vec3& rgb) const noexcept;
    /// `count` interleaved float RGB triples in place: the fast path, blocks
    /// of 8 pixels de-interleaved so the roots and the products vectorise.
    void apply(float* rgb, size_t count) const noexcept;

private:
    int m_degree = 2;
    Eigen::MatrixXd m_m = Eigen::MatrixXd::Zero(3, 6);
    float m_f[3][13] = {};  ///< the matrix as floats, for the fast path
};

/// d(L*a*b*)/d(XYZ) at `xyz` relative to `white` (CIE 15:2004 §8.2.1): the
/// first-order weights of the fits below and the Jacobian of the exact one.
Mat3 LabJacobian(const Vec3& xyz, const Vec3& white);

/// What a fit is given: colours in and the colours they should become
/// (linear RGB), the white that must map exactly (whiteIn → whiteOut), and
/// how to see the targets in CIELAB (their RGB → XYZ and the reference
/// white's XYZ) for the error weights.
struct ColourFit
{
    std::vector<Vec3> input;
    std::vector<Vec3> target;
    Vec3 whiteIn = Vec3::Ones();
    Vec3 whiteOut = Vec3::Ones();
    Mat3 rgbToXyz = Mat3::Identity();
    Vec3 labWhite = Vec3::Ones();

    /// The training remittances' colours under `from` → under `to`, whites
    /// and L*a*b* those of `to`.
    static ColourFit Relight(const SurfaceRenderer& from, const SurfaceRenderer& to,
                             const std::vector<NamedSpectrum>& training);
};

/// Fits M minimising the squared CIELAB error of M·φ(input) against the
/// targets to first order (each residual weighted by the Jacobian of
/// L*a*b* at its target), with whiteIn mapped exactly onto whiteOut and a
/// ridge of `ridge` × the mean diagonal of the normal matrix.
RootPolynomial FitRootPolynomial(const ColourFit& data, int degree, double ridge = 1e-7);

/// The same for a plain 3×3, white preserved (degree 1, no ridge).
Mat3 FitLabMatrix(const ColourFit& data);

/// Fits the root polynomial that takes remittances' colours under `from`
/// to their colours under `to` (working RGB, white Y = 1), minimising the
/// squared CIELAB error to first order: each colour's residual is weighted
/// by the Jacobian of L*a*b* (relative to `to`'s white) at its target, a
/// closed-form weighted least squares. Constrained so that `from`'s white
/// maps exactly to `to`'s (the constraint is linear in M), and regularised
/// by a ridge of `ridge` × the mean diagonal of the normal matrix.
RootPolynomial FitRootPolynomial(const SurfaceRenderer& from, const SurfaceRenderer& to,
                                 const std::vector<NamedSpectrum>& training, int degree,
                                 double ridge = 1e-7);

/// The same for a plain 3×3 (degree 1: R, G, B), for the in-sample floor
/// of the accuracy report.
Mat3 FitLabMatrix(const SurfaceRenderer& from, const SurfaceRenderer& to,
                  const std::vector<NamedSpectrum>& training);

/// What rootpoly is fitted on by default: the 190 rawtoaces training
/// reflectances and TCS01–TCS15.
const std::vector<NamedSpectrum>& RootPolynomialTraining();

}  // namespace bandlight
