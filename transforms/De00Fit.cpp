// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/De00Fit.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/QR>

#include "spectral/Colorimetry.h"
#include "spectral/Metrics.h"

namespace bandlight
{

namespace
{

/// How many reweightings the CIELAB fit takes at most: the mean error
/// settles within a few (the best iterate is kept).
constexpr int kReweightings = 12;

}  // namespace

De00Distance::De00Distance(const Mat3& rgbToXyz, const Vec3& whiteXyz)
    : m_metric(FindMetric("de00"))
{
    m_context.rgbToXyz = rgbToXyz;
    m_context.whiteXyz = whiteXyz;
}

double De00Distance::operator()(const Vec3& rgb, const Vec3& reference) const
{
    return m_metric.compute(rgb, reference, m_context);
}

Mat3 De00Jacobian(const Vec3& lab)
{
    const double c = std::hypot(lab.y(), lab.z());
    const double l50 = (lab.x() - 50.0) * (lab.x() - 50.0);
    const double sl = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
    const double h = std::atan2(lab.z(), lab.y());
    const double deg = kPi / 180.0;
    const double t = 1.0 - 0.17 * std::cos(h - 30.0 * deg) + 0.24 * std::cos(2.0 * h) +
                     0.32 * std::cos(3.0 * h + 6.0 * deg) - 0.20 * std::cos(4.0 * h - 63.0 * deg);
    const double sc = 1.0 + 0.045 * c;
    const double sh = 1.0 + 0.015 * c * t;
    // Chroma along (a, b)/C, hue across it; a neutral has no direction: any.
    const double ca = c > 1e-9 ? lab.y() / c : 1.0;
    const double cb = c > 1e-9 ? lab.z() / c : 0.0;
    Mat3 j;
    // clang-format off
    j << 1.0 / sl, 0.0,     0.0,
         0.0,      ca / sc, cb / sc,
         0.0,     -cb / sh, ca / sh;
    // clang-format on
    return j;
}

void De00Model::add(Eigen::MatrixXd ai, const Vec3& b, const Vec3& t, size_t w)
{
    a.push_back(std::move(ai));
    base.push_back(b);
    target.push_back(t);
    white.push_back(w);
}

Eigen::VectorXd De00Model::solve(const std::vector<double>& weight, bool perceptual) const
{
    Eigen::MatrixXd m(3 * Eigen::Index(a.size()), parameters);
    Eigen::VectorXd rhs(m.rows());
    for (size_t i = 0; i < a.size(); ++i)
    {
        Mat3 w = Mat3::Identity() * std::sqrt(weight[i]);
        if (perceptual)
        {
            const Vec3 xyz = toXyz * target[i];
            const Vec3& reference = whites[white[i]];
            w *= De00Jacobian(XyzToLab(xyz, reference)) * LabJacobian(xyz, reference) * toXyz;
        }
        m.middleRows(3 * Eigen::Index(i), 3) = w * a[i];
        rhs.segment<3>(3 * Eigen::Index(i)) = w * (target[i] - base[i]);
    }
    if (constraints.rows() == 0)
    {
        return m.completeOrthogonalDecomposition().solve(rhs);
    }
    // min ‖m θ − rhs‖² subject to C θ = d, by the null-space method (no
    // normal equations, so as well conditioned as the unconstrained
    // solve): θ = θ0 + N z with θ0 the least-norm solution of the
    // constraints and N a basis of C's null space, z by least squares.
    // Cᵀ = Q R (column pivoting): Q's first `rank` columns span C's rows,
    // the rest its null space.
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(constraints.transpose());
    const Eigen::Index rank = qr.rank();
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(parameters, parameters);
    const Eigen::MatrixXd n = q.rightCols(parameters - rank);
    const Eigen::VectorXd theta0 =
        constraints.completeOrthogonalDecomposition().solve(constraintValues);
    const Eigen::VectorXd z = (m * n).completeOrthogonalDecomposition().solve(rhs - m * theta0);
    return theta0 + n * z;
}

std::vector<double> De00Model::values(const Eigen::VectorXd& theta) const
{
    std::vector<De00Distance> de;
    for (const Vec3& w : whites)
    {
        de.emplace_back(toXyz, w);
    }
    std::vector<double> v;
    for (size_t i = 0; i < a.size(); ++i)
    {
        v.push_back(de[white[i]](predict(i, theta), target[i]));
    }
    return v;
}

Eigen::VectorXd FitDe00(const De00Model& m, const std::vector<Eigen::VectorXd>& starts,
                        De00FitFigures& figures)
{
    const std::vector<double> ones(m.a.size(), 1.0);
    const Eigen::VectorXd plain = m.solve(ones, false);
    figures.before = m.errors(Eigen::VectorXd::Zero(m.parameters));
    figures.leastSquares = m.errors(plain);
    figures.after = figures.leastSquares;
    figures.fit = "least-squares";
    Eigen::VectorXd best = plain;
    std::vector<Eigen::VectorXd> from = starts;
    from.insert(from.begin(), plain);
    for (Eigen::VectorXd theta : from)
    {
        for (int k = 0; k <= kReweightings; ++k)
        {
            if (k > 0)
            {
                std::vector<double> w = m.values(theta);
                for (double& e : w)
                {
                    e = 1.0 / std::max(e, 0.05);  // a perfect sample does not take over
                }
                theta = m.solve(w, true);
            }
            const Statistics s = m.errors(theta);
            if (s.mean < figures.after.mean)
            {
                figures.after = s;
                figures.fit = "ciede2000";
                best = theta;
            }
        }
    }
    return best;
}

De00Model RootPolynomialModel(const ColourFit& data, int degree, bool keepWhite)
{
    const Eigen::Index features = degree == 1 ? 3 : RootPolynomial::Terms(degree);
    // θ holds the rows of M: φ(x) in row r's block predicts channel r.
    const auto design = [&](const Vec3& x)
    {
        Eigen::VectorXd f(features);
        if (degree == 1)
        {
            f = x;
        }
        else
        {
            RootPolynomial::Features(x, degree, f.data());
        }
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3 * features);
        for (Eigen::Index r = 0; r < 3; ++r)
        {
            a.block(r, r * features, 1, features) = f.transpose();
        }
        return a;
    };
    De00Model m;
    m.parameters = 3 * features;
    m.toXyz = data.rgbToXyz;
    m.whites = {data.labWhite};
    for (size_t i = 0; i < data.input.size(); ++i)
    {
        m.add(design(data.input[i]), Vec3::Zero(), data.target[i], 0);
    }
    if (keepWhite)
    {
        m.constraints = design(data.whiteIn);
        m.constraintValues = data.whiteOut;
    }
    return m;
}

Eigen::VectorXd RowsOf(const Eigen::MatrixXd& m)
{
    Eigen::VectorXd v(m.size());
    for (Eigen::Index r = 0; r < m.rows(); ++r)
    {
        v.segment(r * m.cols(), m.cols()) = m.row(r).transpose();
    }
    return v;
}
Eigen::MatrixXd FromRows(const Eigen::VectorXd& v, Eigen::Index cols)
{
    Eigen::MatrixXd m(3, cols);
    for (Eigen::Index r = 0; r < 3; ++r)
    {
        m.row(r) = v.segment(r * cols, cols).transpose();
    }
    return m;
}

RootPolynomial FitRootPolynomialDe00(const ColourFit& data, int degree, De00FitFigures* figures)
{
    const De00Model m = RootPolynomialModel(data, degree, true);
    De00FitFigures own;
    De00FitFigures& f = figures ? *figures : own;
    const RootPolynomial start = FitRootPolynomial(data, degree);
    const Eigen::VectorXd theta = FitDe00(m, {RowsOf(start.matrix())}, f);
    // θ = 0 is no map at all: "before" is the inputs as they are.
    const De00Distance de(data.rgbToXyz, data.labWhite);
    std::vector<double> before;
    for (size_t i = 0; i < data.input.size(); ++i)
    {
        before.push_back(de(data.input[i], data.target[i]));
    }
    f.before = Summarise(std::move(before));
    return RootPolynomial(degree, FromRows(theta, RootPolynomial::Terms(degree)));
}

}  // namespace bandlight
