// SPDX-License-Identifier: BSD-3-Clause
// The wall as a light: the camera's errors on remittances lit by it against
// the light it shows, and the two corrections of them (the lighting
// content's drive, the plate), each beside the plain least-squares fit of
// its own form on the same data.
#include <memory>

#include <Eigen/LU>

#include "camera/Wall.h"
#include "transforms/De00Fit.h"
#include "transforms/IlluminantChange.h"
#include "transforms/Plates.h"
#include "transforms/RootPolynomial.h"

namespace bandlight::jobs
{

namespace
{

/// The post-camera data: plates under the wall → plates under the light,
/// L*a*b* relative to the light's white.
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

}  // namespace

Statistics WallErrors(const WallSetting& s, const Eigen::VectorXd& drive, const WallScene& scene,
                      const GridSpectra& set, const std::function<Vec3(const Vec3&)>& post)
{
    const Eigen::Matrix3Xd got = s.camera.plates(s.emitters * drive, set);
    const Eigen::Matrix3Xd want = s.camera.plates(scene.real, set);
    const De00Distance de(s.camera.rgbToXyz(), s.camera.rgbToXyz() * s.camera.plate(scene.real));
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
    De00Model m;
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
    const Eigen::VectorXd delta = FitDe00(m, {}, figures);
    return Eigen::MatrixXd::Identity(n, n) + Eigen::Map<const Eigen::MatrixXd>(delta.data(), n, n);
}

Mat3 FitPostMatrix(const WallSetting& s, const WallScene& scene, const GridSpectra& training,
                   WallFitFigures& figures)
{
    const ColourFit data = PostData(s, scene, training);
    // bandlight's 3×3 for a change of light (white kept, first-order CIELAB)
    // as one more start.
    const Eigen::VectorXd start = RowsOf(FitLabMatrix(data));
    const Eigen::VectorXd theta = FitDe00(RootPolynomialModel(data, 1), {start}, figures);
    // θ = 0 is no look at all: "before" is the identity's error.
    figures.before = WallErrors(s, scene.drive, scene, training);
    return FromRows(theta, 3);
}

void FitPostOp(const WallSetup& setup, const WallCamera& camera, const WallScene& scene,
               const Light& light, WallBalance& balance)
{
    const GridSpectrum wallSamples = setup.emitters * scene.drive;
    balance.postFrom = {
        "the wall showing " + light.name,
        Spectrum(SurfaceRenderer::kStartNm, SurfaceRenderer::kStepNm,
                 std::vector<double>(wallSamples.data(), wallSamples.data() + wallSamples.size()))};
    // The camera balanced once, for the light, and read through its IDT:
    // lit plates of rootpoly-plate with that light as the IDT's.
    MethodSpec method = WithCamera(ParseMethod(WallLookMethodName()),
                                   std::make_shared<const SpectralCamera>(setup.camera), light);
    method.training = setup.training;
    method.idt = camera.idt();
    method.plates = Plates{PlateConvention::LIT, setup.adaptation};
    balance.postTo = light;
    const Relighter op(balance.postFrom, light, method, setup.working, setup.observer);
    balance.postMethod = std::move(method);
    balance.postRootPolynomial = *op.rootPolynomial();
    // Its figures: the same fit on the wall's own plates (each light at the
    // wall's level; the op's at luminance 1, a scale the fit does not see)
    // gives the plain least-squares and identity figures; the error after
    // is the op's, measured on those plates.
    const WallSetting setting{camera, setup.emitters, setup.observer};
    const GridSpectra& training = setup.sets.front().second;
    FitRootPolynomialDe00(PostData(setting, scene, training), 2, &balance.postRootPolynomialFit);
    balance.postRootPolynomialFit.after = WallErrors(setting, scene.drive, scene, training,
                                                     [&](const Vec3& p) { return op.apply(p); });
}

Statistics RegistryPostErrors(const WallSetup& setup, const WallCamera& camera,
                              const WallScene& scene, const Light& light, const GridSpectra& set)
{
    const GridSpectrum wallSamples = setup.emitters * scene.drive;
    const Light wall{
        "the wall showing " + light.name,
        Spectrum(SurfaceRenderer::kStartNm, SurfaceRenderer::kStepNm,
                 std::vector<double>(wallSamples.data(), wallSamples.data() + wallSamples.size()))};
    MethodSpec method = WithCamera(ParseMethod(WallComparisonMethodName()),
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
