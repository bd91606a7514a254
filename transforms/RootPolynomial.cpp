// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/RootPolynomial.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "spectral/Exception.h"

namespace bandlight
{

Mat3 LabJacobian(const Vec3& xyz, const Vec3& white)
{
    constexpr double kDelta = 6.0 / 29.0;
    const auto fPrime = [](double t)
    {
        return t > kDelta * kDelta * kDelta ? 1.0 / (3.0 * std::cbrt(t * t))
                                            : 1.0 / (3.0 * kDelta * kDelta);
    };
    const double fx = fPrime(xyz.x() / white.x()) / white.x();
    const double fy = fPrime(xyz.y() / white.y()) / white.y();
    const double fz = fPrime(xyz.z() / white.z()) / white.z();
    Mat3 j;
    // clang-format off
    j << 0.0,        116.0 * fy,  0.0,
         500.0 * fx, -500.0 * fy, 0.0,
         0.0,        200.0 * fy,  -200.0 * fz;
    // clang-format on
    return j;
}

namespace
{

Eigen::MatrixXd Fit(const ColourFit& data, int degree, double ridge)
{
    if (data.input.size() != data.target.size())
    {
        throw Exception("root-polynomial fit: as many inputs as targets are needed");
    }
    const int t = degree == 1 ? 3 : RootPolynomial::Terms(degree);
    const int n = 3 * t;  // unknowns: M row by row
    Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd atb = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd phi(t);
    for (size_t i = 0; i < data.input.size(); ++i)
    {
        const Vec3& c1 = data.input[i];
        const Vec3& c2 = data.target[i];
        if (degree == 1)
        {
            phi = c1;
        }
        else
        {
            RootPolynomial::Features(c1, degree, phi.data());
        }
        // Residual in L*a*b*: J · (M φ − c2), J = dLab/dXYZ · RGB→XYZ.
        const Mat3 j = LabJacobian(data.rgbToXyz * c2, data.labWhite) * data.rgbToXyz;
        Eigen::MatrixXd a(3, n);  // J · (I3 ⊗ φᵀ)
        for (int row = 0; row < 3; ++row)
        {
            for (int k = 0; k < 3; ++k)
            {
                a.block(row, k * t, 1, t) = j(row, k) * phi.transpose();
            }
        }
        ata += a.transpose() * a;
        atb += a.transpose() * (j * c2);
    }
    ata.diagonal().array() += ridge * ata.diagonal().mean();
    // White preserved exactly: M φ(w1) = w2, three linear constraints.
    Eigen::VectorXd phiW(t);
    if (degree == 1)
    {
        phiW = data.whiteIn;
    }
    else
    {
        RootPolynomial::Features(data.whiteIn, degree, phiW.data());
    }
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + 3, n + 3);
    Eigen::VectorXd rhs(n + 3);
    kkt.topLeftCorner(n, n) = ata;
    rhs.head(n) = atb;
    for (int k = 0; k < 3; ++k)
    {
        kkt.block(n + k, k * t, 1, t) = phiW.transpose();
        kkt.block(k * t, n + k, t, 1) = phiW;
        rhs(n + k) = data.whiteOut(k);
    }
    const Eigen::VectorXd x = kkt.fullPivLu().solve(rhs);
    if (!x.allFinite())
    {
        throw Exception("root-polynomial fit: the training set does not determine the map");
    }
    Eigen::MatrixXd m(3, t);
    for (int k = 0; k < 3; ++k)
    {
        m.row(k) = x.segment(k * t, t).transpose();
    }
    return m;
}

}  // namespace

RootPolynomial::RootPolynomial(int degree, Eigen::MatrixXd m) : m_degree(degree), m_m(std::move(m))
{
    if ((degree != 2 && degree != 3) || m_m.rows() != 3 || m_m.cols() != Terms(degree))
    {
        throw Exception("root polynomial: degree 2 or 3 with a 3 x " +
                        std::to_string(Terms(degree == 3 ? 3 : 2)) + " matrix");
    }
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < m_m.cols(); ++c)
        {
            m_f[r][c] = float(m_m(r, c));
        }
    }
}

int RootPolynomial::Terms(int degree)
{
    return degree == 3 ? 13 : 6;
}

void RootPolynomial::Features(const Vec3& rgb, int degree, double* out) noexcept
{
    const double r = std::max(rgb.x(), 0.0), g = std::max(rgb.y(), 0.0), b = std::max(rgb.z(), 0.0);
    out[0] = rgb.x();
    out[1] = rgb.y();
    out[2] = rgb.z();
    out[3] = std::sqrt(r * g);
    out[4] = std::sqrt(g * b);
    out[5] = std::sqrt(r * b);
    if (degree == 3)
    {
        out[6] = std::cbrt(r * g * g);
        out[7] = std::cbrt(g * b * b);
        out[8] = std::cbrt(r * b * b);
        out[9] = std::cbrt(g * r * r);
        out[10] = std::cbrt(b * g * g);
        out[11] = std::cbrt(b * r * r);
        out[12] = std::cbrt(r * g * b);
    }
}

Vec3 RootPolynomial::apply(const Vec3& rgb) const noexcept
{
    double phi[13];
    Features(rgb, m_degree, phi);
    const Eigen::Map<const Eigen::VectorXd> f(phi, Terms(m_degree));
    return m_m * f;
}

void RootPolynomial::apply(float* rgb, size_t count) const noexcept
{
    if (m_degree != 2)
    {
        for (size_t i = 0; i < count; ++i)
        {
            float* p = rgb + 3 * i;
            const Vec3 o = apply(Vec3(p[0], p[1], p[2]));
            p[0] = float(o.x());
            p[1] = float(o.y());
            p[2] = float(o.z());
        }
        return;
    }
    // Coefficients in registers; each block de-interleaved into channel
    // arrays so the clamp, the three roots and the 18 products are plain
    // loops over 8 lanes (SSE/AVX without intrinsics).
    const float m00 = m_f[0][0], m01 = m_f[0][1], m02 = m_f[0][2], m03 = m_f[0][3], m04 = m_f[0][4],
                m05 = m_f[0][5];
    const float m10 = m_f[1][0], m11 = m_f[1][1], m12 = m_f[1][2], m13 = m_f[1][3], m14 = m_f[1][4],
                m15 = m_f[1][5];
    const float m20 = m_f[2][0], m21 = m_f[2][1], m22 = m_f[2][2], m23 = m_f[2][3], m24 = m_f[2][4],
                m25 = m_f[2][5];
    constexpr size_t kBlock = 8;
    size_t i = 0;
    for (; i < count; i += kBlock)
    {
        const size_t n = std::min(kBlock, count - i);
        float* p = rgb + 3 * i;
        float r[kBlock] = {}, g[kBlock] = {}, b[kBlock] = {};
        for (size_t k = 0; k < n; ++k)
        {
            r[k] = p[3 * k];
            g[k] = p[3 * k + 1];
            b[k] = p[3 * k + 2];
        }
        float o0[kBlock], o1[kBlock], o2[kBlock];
        for (size_t k = 0; k < kBlock; ++k)
        {
            const float rp = std::max(r[k], 0.0f), gp = std::max(g[k], 0.0f),
                        bp = std::max(b[k], 0.0f);
            const float rg = std::sqrt(rp * gp), gb = std::sqrt(gp * bp), rb = std::sqrt(rp * bp);
            o0[k] = m00 * r[k] + m01 * g[k] + m02 * b[k] + m03 * rg + m04 * gb + m05 * rb;
            o1[k] = m10 * r[k] + m11 * g[k] + m12 * b[k] + m13 * rg + m14 * gb + m15 * rb;
            o2[k] = m20 * r[k] + m21 * g[k] + m22 * b[k] + m23 * rg + m24 * gb + m25 * rb;
        }
        for (size_t k = 0; k < n; ++k)
        {
            p[3 * k] = o0[k];
            p[3 * k + 1] = o1[k];
            p[3 * k + 2] = o2[k];
        }
    }
}

ColourFit ColourFit::Relight(const SurfaceRenderer& from, const SurfaceRenderer& to,
                             const std::vector<NamedSpectrum>& training)
{
    ColourFit d;
    for (const NamedSpectrum& s : training)
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(s.spectrum);
        d.input.push_back(from.render(r));
        d.target.push_back(to.render(r));
    }
    d.whiteIn = from.white();
    d.whiteOut = to.white();
    d.rgbToXyz = to.rgbToXyz();
    d.labWhite = to.rgbToXyz() * to.white();
    return d;
}

RootPolynomial FitRootPolynomial(const ColourFit& data, int degree, double ridge)
{
    if (degree != 2 && degree != 3)
    {
        throw Exception("root polynomial: degree must be 2 or 3");
    }
    return RootPolynomial(degree, Fit(data, degree, ridge));
}

Mat3 FitLabMatrix(const ColourFit& data)
{
    return Fit(data, 1, 0.0);
}

RootPolynomial FitRootPolynomial(const SurfaceRenderer& from, const SurfaceRenderer& to,
                                 const std::vector<NamedSpectrum>& training, int degree,
                                 double ridge)
{
    return FitRootPolynomial(ColourFit::Relight(from, to, training), degree, ridge);
}

Mat3 FitLabMatrix(const SurfaceRenderer& from, const SurfaceRenderer& to,
                  const std::vector<NamedSpectrum>& training)
{
    return FitLabMatrix(ColourFit::Relight(from, to, training));
}

const std::vector<NamedSpectrum>& RootPolynomialTraining()
{
    static const std::vector<NamedSpectrum> set = []
    {
        std::vector<NamedSpectrum> s = Rawtoaces190();
        for (const NamedSpectrum& t : TestColourSamples())
        {
            s.push_back(t);
        }
        return s;
    }();
    return set;
}

}  // namespace bandlight
