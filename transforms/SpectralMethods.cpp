// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/SpectralMethods.h"

#include <Eigen/LU>

#include "spectral/Exception.h"

namespace bandlight
{

Mat3 FitMatrix(const SurfaceRenderer& from, const SurfaceRenderer& to,
               const std::vector<NamedSpectrum>& training)
{
    if (training.size() < 3)
    {
        throw Exception("fit3x3 needs at least three training remittances, got " +
                        std::to_string(training.size()));
    }
    Eigen::Matrix<double, 3, Eigen::Dynamic> x1(3, training.size()), x2(3, training.size());
    for (size_t i = 0; i < training.size(); ++i)
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(training[i].spectrum);
        x1.col(Eigen::Index(i)) = from.render(r);
        x2.col(Eigen::Index(i)) = to.render(r);
    }
    const Mat3 gram = x1 * x1.transpose();
    const Eigen::FullPivLU<Mat3> lu(gram);
    if (!lu.isInvertible())
    {
        throw Exception("fit3x3: the training colours do not span three dimensions");
    }
    const Mat3 g = lu.inverse();
    const Mat3 m0 = x2 * x1.transpose() * g;
    // Each row m minimises |X1ᵀ m − x2|² with w1ᵀ m = w2_row: the
    // unconstrained solution moved along G·w1 until the constraint holds.
    const Vec3& w1 = from.white();
    const Vec3 gw1 = g * w1;
    const Vec3 lambda = (to.white() - m0 * w1) / w1.dot(gw1);
    return m0 + lambda * gw1.transpose();
}

namespace
{
constexpr int kN = SurfaceRenderer::kSamples;
using Kkt = Eigen::Matrix<double, kN + 3, kN + 3>;

/// Pixel RGB → its smoothest remittance (N × 3): the solution operator of
/// min |D r|² subject to A1 r = c, from the KKT system
/// [DᵀD A1ᵀ; A1 0] [r; λ] = [0; c]. DᵀD alone is singular (constants cost
/// nothing); the constraint fixes the level, so the system is not.
Eigen::Matrix<double, kN, 3> SmoothestOperator(const SurfaceRenderer& from)
{
    Kkt k = Kkt::Zero();
    for (int i = 0; i + 1 < kN; ++i)
    {
        k(i, i) += 1.0;
        k(i + 1, i + 1) += 1.0;
        k(i, i + 1) -= 1.0;
        k(i + 1, i) -= 1.0;
    }
    k.block<3, kN>(kN, 0) = from.matrix();
    k.block<kN, 3>(0, kN) = from.matrix().transpose();
    Eigen::Matrix<double, kN + 3, 3> rhs = Eigen::Matrix<double, kN + 3, 3>::Zero();
    rhs.block<3, 3>(kN, 0).setIdentity();
    const Eigen::Matrix<double, kN + 3, 3> sol = k.fullPivLu().solve(rhs);
    return sol.block<kN, 3>(0, 0);
}
}  // namespace

Mat3 MetamerMatrix(const SurfaceRenderer& from, const SurfaceRenderer& to)
{
    return to.matrix() * SmoothestOperator(from);
}

SurfaceRenderer::Samples SmoothestMetamer(const SurfaceRenderer& from, const Vec3& rgb)
{
    return SmoothestOperator(from) * rgb;
}

}  // namespace bandlight
