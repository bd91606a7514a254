// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Fits of models linear in their parameters that minimise the mean CIEDE2000
// of their predictions rather than a sum of squares: iteratively reweighted
// least squares, each residual seen as ΔE00 to first order at its target and
// weighted by the inverse of its current ΔE00, the plain least-squares fit
// and any other starts tried, the lowest mean ΔE00 on the data kept (never
// worse than the plain fit there). The root-polynomial plate method
// (transforms/methods/RootPolyPlate.cpp) and an LED wall's corrections
// (camera/WallFit.cpp) are fitted this way.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/Colorimetry.h"
#include "spectral/Metrics.h"
#include "spectral/Statistics.h"
#include "transforms/RootPolynomial.h"

namespace bandlight
{

/// ΔE00 (the metric registry's "de00") of an RGB colour against its target,
/// L*a*b* relative to `whiteXyz`.
class De00Distance
{
public:
    De00Distance(const Mat3& rgbToXyz, const Vec3& whiteXyz);
    double operator()(const Vec3& rgb, const Vec3& reference) const;

private:
    const MetricEntry& m_metric;
    MetricContext m_context;
};

/// A fit's ΔE00 on the data it was fitted on, against the plain
/// least-squares fit of the same form on the same data.
struct De00FitFigures
{
    /// Which fit won: "ciede2000" (the reweighted fit) or "least-squares"
    /// (when nothing beats the plain fit on the data).
    std::string fit;
    Statistics before;        ///< with all parameters 0 (the model's base alone)
    Statistics after;         ///< the fit returned
    Statistics leastSquares;  ///< the plain least-squares fit
};

/// CIEDE2000 to first order at a colour: d(L*a*b*) → (ΔL/S_L, ΔC/S_C,
/// ΔH/S_H) with the weighting functions at `lab` (CIE 15:2004 §8.3; the
/// rotation term and the a* rescaling G left out), so that the norm of the
/// image of a small L*a*b* difference is about its ΔE00.
Mat3 De00Jacobian(const Vec3& lab);

/// A model linear in its parameters θ, on its fitting data: sample i
/// predicts base_i + A_i θ (RGB) for target_i, seen in L*a*b* (through
/// `toXyz`) relative to white `whites[white_i]` (XYZ).
struct De00Model
{
    Eigen::Index parameters = 0;
    std::vector<Eigen::MatrixXd> a;  ///< 3 × parameters each
    std::vector<Vec3> base;
    std::vector<Vec3> target;
    std::vector<size_t> white;
    std::vector<Vec3> whites;
    Mat3 toXyz = Mat3::Identity();
    /// Linear constraints every fit keeps exactly, C θ = d (none when C has
    /// no rows): a white mapped onto a white.
    Eigen::MatrixXd constraints;
    Eigen::VectorXd constraintValues;

    void add(Eigen::MatrixXd ai, const Vec3& b, const Vec3& t, size_t w);
    Vec3 predict(size_t i, const Eigen::VectorXd& theta) const { return base[i] + a[i] * theta; }
    /// min Σ weight_i ‖W_i (base_i + A_i θ − target_i)‖², W_i CIEDE2000 to
    /// first order at the target (`perceptual`: De00Jacobian after the
    /// L*a*b* Jacobian) or the identity; the minimum-norm θ where the data
    /// leave directions free. With constraints, the constrained minimum (by
    /// the null-space method).
    Eigen::VectorXd solve(const std::vector<double>& weight, bool perceptual) const;
    /// ΔE00 (the metric registry's "de00") of each sample's prediction.
    std::vector<double> values(const Eigen::VectorXd& theta) const;
    Statistics errors(const Eigen::VectorXd& theta) const { return Summarise(values(theta)); }
};

/// The θ of least mean ΔE00 found from the plain least-squares fit and each
/// of `starts` by reweighting (see above); `figures` gets the error with
/// θ = 0, the plain fit's and the chosen one's. The starts must keep the
/// model's constraints (a start is a candidate as it is).
Eigen::VectorXd FitDe00(const De00Model& m, const std::vector<Eigen::VectorXd>& starts,
                        De00FitFigures& figures);

/// The model M · φ(input) of a root polynomial of `degree` (features per
/// channel; 1: a 3×3) on `data`'s pairs, L*a*b* relative to data.labWhite;
/// with `keepWhite`, constrained to map data.whiteIn exactly onto
/// data.whiteOut.
De00Model RootPolynomialModel(const ColourFit& data, int degree, bool keepWhite = false);

/// The rows of a 3 × k matrix as θ, and back.
Eigen::VectorXd RowsOf(const Eigen::MatrixXd& m);
Eigen::MatrixXd FromRows(const Eigen::VectorXd& v, Eigen::Index cols);

/// The root polynomial of `degree` (2 or 3) of least mean ΔE00 on `data` among those
/// that map data.whiteIn exactly onto data.whiteOut (FitDe00 on the
/// constrained model, started also from FitRootPolynomial's first-order
/// CIELAB fit); `figures` (when given) gets the fit's figures — its
/// `leastSquares` the plain least-squares fit under the same constraint,
/// `before` the inputs taken as they are.
RootPolynomial FitRootPolynomialDe00(const ColourFit& data, int degree,
                                     De00FitFigures* figures = nullptr);

}  // namespace bandlight
