// SPDX-License-Identifier: BSD-3-Clause
// The wall as a light: the camera's errors on remittances lit by it against
// the light it shows, and the two corrections of them (the lighting
// content's drive, the plate), each beside the plain least-squares fit of
// its own form on the same data.
#include <algorithm>
#include <cmath>

#include <memory>

#include <Eigen/LU>
#include <Eigen/QR>

#include "camera/Wall.h"
#include "spectral/Metrics.h"
#include "transforms/IlluminantChange.h"
#include "transforms/Plates.h"
#include "transforms/RootPolynomial.h"

namespace bandlight::jobs
{

namespace
{

/// ΔE00 (the registry's "de00") of a colour against its target, L*a*b*
/// relative to `whiteXyz`.
class De00
{
public:
    De00(const Mat3& rgbToXyz, const Vec3& whiteXyz) : m_metric(FindMetric("de00"))
    {
        m_context.rgbToXyz = rgbToXyz;
        m_context.whiteXyz = whiteXyz;
    }
    double operator()(const Vec3& rgb, const Vec3& reference) const
    {
        return m_metric.compute(rgb, reference, m_context);
    }

private:
    const MetricEntry& m_metric;
    MetricContext m_context;
};

/// CIEDE2000 to first order at a colour: d(L*a*b*) → (ΔL/S_L, ΔC/S_C,
/// ΔH/S_H) with the weighting functions at `lab` (CIE 15:2004 §8.3; the
/// rotation term and the a* rescaling G left out), so that the norm of the
/// image of a small L*a*b* difference is about its ΔE00.
Mat3 De00Jacobian(const Vec3& lab)
{
    constexpr double kPi = 3.14159265358979323846;
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

/// A correction linear in its parameters θ, on its fitting data: sample i
/// predicts base_i + A_i θ (working RGB) for target_i, seen in L*a*b*
/// relative to white `whites[white_i]`.
struct LinearModel
{
    Eigen::Index parameters = 0;
    std::vector<Eigen::MatrixXd> a;  ///< 3 × parameters each
    std::vector<Vec3> base;
    std::vector<Vec3> target;
    std::vector<size_t> white;
    std::vector<Vec3> whites;  ///< XYZ
    Mat3 toXyz = Mat3::Identity();

    void add(Eigen::MatrixXd ai, const Vec3& b, const Vec3& t, size_t w)
    {
        a.push_back(std::move(ai));
        base.push_back(b);
        target.push_back(t);
        white.push_back(w);
    }
    Vec3 predict(size_t i, const Eigen::VectorXd& theta) const { return base[i] + a[i] * theta; }

    /// min Σ weight_i ‖W_i (base_i + A_i θ − target_i)‖², W_i CIEDE2000 to
    /// first order at the target (`perceptual`: De00Jacobian after the
    /// L*a*b* Jacobian) or the identity; the minimum-norm θ where the data
    /// leave directions free.
    Eigen::VectorXd solve(const std::vector<double>& weight, bool perceptual) const
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
        return m.completeOrthogonalDecomposition().solve(rhs);
    }

    /// ΔE00 of each sample's prediction.
    std::vector<double> values(const Eigen::VectorXd& theta) const
    {
        std::vector<De00> de;
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
    Statistics errors(const Eigen::VectorXd& theta) const { return Summarise(values(theta)); }
};

/// How many reweightings the CIELAB fit takes at most: the mean error
/// settles within a few (the best iterate is kept).
constexpr int kReweightings = 12;

/// The plain least-squares θ, and bandlight's: iteratively reweighted least
/// squares in CIEDE2000 from the plain fit and from each of `starts` — each
/// residual seen as ΔE00 to first order at its target (De00Jacobian) and
/// weighted by the inverse of its current ΔE00, which minimises the sum of
/// the errors (their mean) rather than of their squares — keeping the θ of
/// the lowest mean ΔE00 on the data (the plain fit's when nothing beats it:
/// never worse). `figures` gets the
/// error with θ = 0, the plain fit's and the chosen one's.
Eigen::VectorXd FitModel(const LinearModel& m, const std::vector<Eigen::VectorXd>& starts,
                         WallFitFigures& figures)
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

/// The post-camera data: plates under the wall → plates under the light,
/// L*a*b* relative to the light's white, for a model of `features` terms a
/// channel (3: the 3×3; the root polynomial's terms).
template <typename Features>
LinearModel PostModel(const WallSetting& s, const WallScene& scene, const GridSpectra& training,
                      Eigen::Index features, const Features& phi)
{
    const Eigen::Matrix3Xd in = s.camera.plates(s.emitters * scene.drive, training);
    const Eigen::Matrix3Xd out = s.camera.plates(scene.real, training);
    LinearModel m;
    m.parameters = 3 * features;
    m.toXyz = s.camera.rgbToXyz();
    m.whites = {m.toXyz * s.camera.plate(scene.real)};
    for (Eigen::Index i = 0; i < in.cols(); ++i)
    {
        const Eigen::VectorXd f = phi(Vec3(in.col(i)));
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, m.parameters);
        for (Eigen::Index r = 0; r < 3; ++r)
        {
            a.block(r, r * features, 1, features) = f.transpose();  // θ: the rows of M
        }
        m.add(std::move(a), Vec3::Zero(), out.col(i), 0);
    }
    return m;
}

ColourFit PostData(const WallSetting& s, const WallScene& scene, const GridSpectra& training)
{
    const GridSpectrum wall = s.emitters * scene.drive;
    const Eigen::Matrix3Xd in = s.camera.plates(wall, training);
    const Eigen::Matrix3Xd out = s.camera.plates(scene.real, training);
    ColourFit d;
    for (Eigen::Index i = 0; i < in.cols(); ++i)
    {
        d.input.push_back(in.col(i));
        d.target.push_back(out.col(i));
    }
    d.whiteIn = s.camera.plate(wall);
    d.whiteOut = s.camera.plate(scene.real);
    d.rgbToXyz = s.camera.rgbToXyz();
    d.labWhite = d.rgbToXyz * d.whiteOut;
    return d;
}

/// The rows of a 3 × k matrix as θ, and back.
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

}  // namespace

Statistics WallErrors(const WallSetting& s, const Eigen::VectorXd& drive, const WallScene& scene,
                      const GridSpectra& set, const std::function<Vec3(const Vec3&)>& post)
{
    const Eigen::Matrix3Xd got = s.camera.plates(s.emitters * drive, set);
    const Eigen::Matrix3Xd want = s.camera.plates(scene.real, set);
    const De00 de(s.camera.rgbToXyz(), s.camera.rgbToXyz() * s.camera.plate(scene.real));
    std::vector<double> v;
    for (Eigen::Index i = 0; i < set.cols(); ++i)
    {
        const Vec3 p = got.col(i);
        v.push_back(de(post ? post(p) : p, want.col(i)));
    }
    return Summarise(std::move(v));
}

Eigen::MatrixXd FitPreCorrection(const WallSetting& s, const std::vector<WallScene>& scenes,
                                 const GridSpectra& training, WallFitFigures& figures)
{
    const Eigen::Index n = s.emitters.cols();
    // Each remittance's plate is linear in the drive (A_i · drive), and
    // A_i (I + Δ) d_j is linear in vec(Δ): A_i d_j + (d_jᵀ ⊗ A_i) vec(Δ).
    std::vector<Eigen::Matrix3Xd> byDrive;
    for (Eigen::Index i = 0; i < training.cols(); ++i)
    {
        byDrive.push_back(s.camera.plateByDrive(training.col(i), s.emitters));
    }
    LinearModel m;
    m.parameters = n * n;
    m.toXyz = s.camera.rgbToXyz();
    for (size_t j = 0; j < scenes.size(); ++j)
    {
        const Eigen::VectorXd& d = scenes[j].drive;
        const Eigen::Matrix3Xd targets = s.camera.plates(scenes[j].real, training);
        m.whites.push_back(m.toXyz * s.camera.plate(scenes[j].real));
        for (size_t i = 0; i < byDrive.size(); ++i)
        {
            Eigen::MatrixXd a(3, n * n);
            for (Eigen::Index c = 0; c < n; ++c)
            {
                a.middleCols(c * n, n) = d(c) * byDrive[i];
            }
            m.add(std::move(a), byDrive[i] * d, targets.col(Eigen::Index(i)), j);
        }
    }
    // Minimum norm: the drives of all scenes lie in the in-frustum
    // transform's three-dimensional range, so Δ is determined there only
    // and P is the identity off it.
    const Eigen::VectorXd delta = FitModel(m, {}, figures);
    return Eigen::MatrixXd::Identity(n, n) + Eigen::Map<const Eigen::MatrixXd>(delta.data(), n, n);
}

Mat3 FitPostMatrix(const WallSetting& s, const WallScene& scene, const GridSpectra& training,
                   WallFitFigures& figures)
{
    const LinearModel m =
        PostModel(s, scene, training, 3, [](const Vec3& p) { return Eigen::VectorXd(p); });
    // bandlight's 3×3 for a change of light (white kept, first-order CIELAB)
    // as one more start.
    const Eigen::VectorXd start = RowsOf(FitLabMatrix(PostData(s, scene, training)));
    const Eigen::VectorXd theta = FitModel(m, {start}, figures);
    // θ = 0 is no look at all: "before" is the identity's error.
    figures.before = WallErrors(s, scene.drive, scene, training);
    return FromRows(theta, 3);
}

RootPolynomial FitPostRootPolynomial(const WallSetting& s, const WallScene& scene,
                                     const GridSpectra& training, WallFitFigures& figures)
{
    constexpr int kDegree = 2;
    const int terms = RootPolynomial::Terms(kDegree);
    const LinearModel m = PostModel(s, scene, training, terms,
                                    [terms](const Vec3& p)
                                    {
                                        Eigen::VectorXd f(terms);
                                        RootPolynomial::Features(p, kDegree, f.data());
                                        return f;
                                    });
    const RootPolynomial rootpoly = FitRootPolynomial(PostData(s, scene, training), kDegree);
    const Eigen::VectorXd theta = FitModel(m, {RowsOf(rootpoly.matrix())}, figures);
    figures.before = WallErrors(s, scene.drive, scene, training);
    return RootPolynomial(kDegree, FromRows(theta, terms));
}

Statistics RegistryPostErrors(const WallSetup& setup, const WallCamera& camera,
                              const WallScene& scene, const Light& light, const GridSpectra& set)
{
    const GridSpectrum wallSamples = setup.emitters * scene.drive;
    const Light wall{
        "the wall showing " + light.name,
        Spectrum(SurfaceRenderer::kStartNm, SurfaceRenderer::kStepNm,
                 std::vector<double>(wallSamples.data(), wallSamples.data() + wallSamples.size()))};
    MethodSpec method = WithCamera(ParseMethod("rootpoly-camera"),
                                   std::make_shared<const SpectralCamera>(setup.camera), light);
    method.training = setup.training;
    method.plates = Plates{PlateConvention::BALANCED, setup.adaptation};
    const Relighter relight(wall, light, method, setup.working, setup.observer);
    // The op expects the camera balanced for the light it is under (the
    // wall), read through the one IDT (the white balance's); the plates are
    // balanced for the white balance.
    const Vec3 wallGains = CameraShot(setup.camera, wall.spectrum).gains();
    const Mat3 toOp = camera.idt() * wallGains.cwiseQuotient(camera.gains()).asDiagonal() *
                      camera.idt().inverse();
    // The op works in relative units (its white of Y = 1); the plates are at
    // the light's level: one scale, the white card's.
    const Vec3 wallWhite = camera.plate(wallSamples);
    const double level = (camera.rgbToXyz() * camera.plate(scene.real)).y() /
                         (camera.rgbToXyz() * relight.apply(Vec3(toOp * wallWhite))).y();
    const WallSetting setting{camera, setup.emitters, setup.observer};
    return WallErrors(setting, scene.drive, scene, set,
                      [&](const Vec3& p) { return Vec3(level * relight.apply(Vec3(toOp * p))); });
}

}  // namespace bandlight::jobs
