// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The science of `wall`: an LED wall or fixture of N emitters as a camera
// sees it in the frustum (the drive that makes the camera record the
// content as intended) and as a light outside it (reflectances lit by the
// wall showing a light against the same under that light, and the two
// corrections of it: of the lighting content, and of the plate). Plain
// matrices: the job (jobs/WallJob.cpp) orchestrates, plugin/WallConfig.h
// turns the results into an OCIO config. docs/wall.md states the
// conventions.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "requests/Wall.h"
#include "transforms/Camera.h"
#include "transforms/Methods.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight::jobs
{

/// Spectra on SurfaceRenderer's grid (380–780 nm at 5 nm), one a column.
using GridSpectra = Eigen::Matrix<double, SurfaceRenderer::kSamples, Eigen::Dynamic>;
using GridSpectrum = SurfaceRenderer::Samples;

/// A light or an emission on the grid as bandlight samples lights
/// (CameraShot): its linear interpolant at each wavelength, zero outside
/// its data; its scale kept.
GridSpectrum EmissionOnGrid(const Spectrum& spectrum);

/// Remittances on the grid (SurfaceRenderer::Sample: edge-extended), one a column.
GridSpectra RemittancesOnGrid(const std::vector<NamedSpectrum>& set);

/// ȳ · light on the grid: the luminance, in the units of the spectrum,
/// that "the same luminance" compares.
double GridLuminance(const GridSpectrum& light, Observer observer);

/// A camera white-balanced for one light and read through the IDT fitted
/// for that light: light reaching the sensor → a plate in the working space.
class WallCamera
{
public:
    /// `idt`: balanced camera RGB → working RGB (IdtFit::matrix); `rgbToXyz`:
    /// working RGB → CIE XYZ as the observer sees the working primaries.
    WallCamera(const SpectralCamera& camera, const Spectrum& whiteBalance, const Mat3& idt,
               const Mat3& rgbToXyz);

    /// Balanced camera RGB of the light reaching the sensor: the perfect
    /// reflector under the white-balance light records (1, 1, 1).
    Vec3 record(const GridSpectrum& light) const { return m_balanced * light; }
    /// The same through the IDT: the plate, working RGB.
    Vec3 plate(const GridSpectrum& light) const { return m_idt * record(light); }
    /// The plates of remittances (columns of `set`) lit by `light`, 3 × n.
    Eigen::Matrix3Xd plates(const GridSpectrum& light, const GridSpectra& set) const;
    /// The plate of one remittance as a linear map of the N emitters' drives
    /// (3 × N): what the remittance gives lit by each emitter at drive 1.
    Eigen::Matrix3Xd plateByDrive(const GridSpectrum& remittance,
                                  const GridSpectra& emitters) const;
    /// Balanced camera RGB of each emitter at drive 1 seen directly, 3 × N.
    Eigen::Matrix3Xd response(const GridSpectra& emitters) const { return m_balanced * emitters; }
    /// Raw → balanced: the perfect reflector under the white-balance light
    /// records (1, 1, 1).
    const Vec3& gains() const noexcept { return m_gains; }
    const Mat3& idt() const noexcept { return m_idt; }
    const Mat3& rgbToXyz() const noexcept { return m_rgbToXyz; }

private:
    Eigen::Matrix<double, 3, SurfaceRenderer::kSamples> m_balanced;
    Vec3 m_gains;
    Mat3 m_idt;
    Mat3 m_rgbToXyz;
};

/// The in-frustum transform for a camera's response to the emitters
/// (3 × N, balanced camera RGB per unit drive) and the record the content
/// asks for (`contentToRecord`: content RGB → balanced camera RGB, the
/// IDT's inverse after content → working): the drive D (N × 3) with
/// response · D = exposure · contentToRecord, exactly for three emitters;
/// for more, the non-negative D (so every colour of the content cube gets a
/// drive a wall can emit) of least error, the least drive among equals —
/// exact whenever a non-negative exact solution exists;
/// `exposure` scales content white's largest drive to 1. Throws Exception
/// naming the two most collinear emitters when the response's condition
/// number (unit columns) exceeds `maxCondition`, and an emitter the camera
/// does not see.
WallInFrustum SolveInFrustum(const Eigen::Matrix3Xd& response, const Mat3& contentToRecord,
                             const std::vector<std::string>& names, const std::string& cameraLabel,
                             double maxCondition = defaults::WALL_MAX_CONDITION);

/// The drive of the wall showing `light` (largest channel 1): the content
/// that shows the camera `light`'s white as the camera records a white card
/// under it (its plate, working → content by `workingToContent`), through
/// the in-frustum drive. Throws Exception when no emitter is driven.
Eigen::VectorXd DepictedDrive(const WallInFrustum& inFrustum, const WallCamera& camera,
                              const Mat3& workingToContent, const GridSpectrum& light,
                              const std::string& lightName);

/// The wall showing a light, and that light.
struct WallScene
{
    Eigen::VectorXd drive;  ///< the wall's drive
    GridSpectrum real;      ///< the light itself, at the wall's luminance
};

/// What the out-of-frustum work of one white balance shares.
struct WallSetting
{
    const WallCamera& camera;
    const GridSpectra& emitters;
    Observer observer;

    /// The wall driven by `drive` and `light` scaled to its luminance.
    WallScene scene(const Eigen::VectorXd& drive, const GridSpectrum& light) const;
};

/// ΔE00 (the metric registry's "de00") of each remittance of `set` lit by
/// the wall at `drive` — its plate through `post` when given — against the
/// same lit by `scene.real`, L*a*b* relative to the plate of a white card
/// under `scene.real`.
Statistics WallErrors(const WallSetting& setting, const Eigen::VectorXd& drive,
                      const WallScene& scene, const GridSpectra& set,
                      const std::function<Vec3(const Vec3&)>& post = {});

/// The lighting pre-correction: P (N × N) on the drive, fitted over the
/// scenes (the wall showing each depicted light) and the training
/// remittances so that their plates under the wall at P · drive are those
/// under the real light. The plates are linear in P = I + Δ: the plain
/// least-squares Δ, then bandlight's fit (iteratively reweighted least
/// squares on CIEDE2000 to first order, which minimises the mean ΔE00),
/// each the minimum-norm Δ (drives span three dimensions: P is the
/// identity off them); the one of the lower mean ΔE00 on the data is
/// returned, so never worse than the plain fit there. `figures` gets both.
Eigen::MatrixXd FitPreCorrection(const WallSetting& setting, const std::vector<WallScene>& scenes,
                                 const GridSpectra& training, WallFitFigures& figures);

/// The post-camera look for `scene`: the 3×3 (working RGB) from the plates
/// under the wall to those under the real light, fitted as the
/// pre-correction is (plain least squares, then bandlight's CIEDE2000 fit,
/// also started from FitLabMatrix, the 3×3 bandlight fits for a change of
/// light: white kept, CIELAB to first order), the lower mean ΔE00 on the
/// training set kept.
Mat3 FitPostMatrix(const WallSetting& setting, const WallScene& scene, const GridSpectra& training,
                   WallFitFigures& figures);

struct WallSetup;

/// The post-camera look's non-linear form as the method registry's op:
/// rootpoly-plate (a degree-2 root polynomial of least mean ΔE00 from the
/// camera's plates under one light to its plates under another) from the
/// wall showing `scene` — its spectrum as a light — to `light`, lit plates
/// through the white balance's IDT, fitted on the training set: the same
/// data the 3×3 is fitted on. Sets balance.postFrom, postMethod,
/// postRootPolynomial (the op's) and postRootPolynomialFit (the op's fit's
/// figures, FitRootPolynomialDe00 on those plates).
void FitPostOp(const WallSetup& setup, const WallCamera& camera, const WallScene& scene,
               const Light& light, WallBalance& balance);

/// The method registry's rootpoly-camera op for the same change of light,
/// beside the post-camera look: the op of rootpoly-camera (Relighter, the
/// camera set, its one IDT the white balance's) from the wall showing
/// `scene` to `light`, on the plates of `set` under the wall, carried from
/// the white balance's gains to the wall's own as the op expects; ΔE00
/// against the plates under the light as WallErrors measures. The op is
/// fitted to the observer's colours under the light, not to this camera's
/// plate of them: its floor is the camera's IDT error there.
Statistics RegistryPostErrors(const WallSetup& setup, const WallCamera& camera,
                              const WallScene& scene, const Light& light, const GridSpectra& set);

/// Everything `wall` needs beside a white balance, resolved.
struct WallSetup
{
    const SpectralCamera& camera;
    std::vector<std::string> names;  ///< the emitters'
    GridSpectra emitters;
    const RgbSpace& content;
    const RgbSpace& working;
    AdaptationMethod adaptation;
    Observer observer;
    std::vector<NamedSpectrum> training;
    std::vector<std::pair<std::string, GridSpectra>> sets;  ///< training, then the test set
    std::vector<Light> depicted;                            ///< the white balances first
    size_t balances = 0;  ///< how many of `depicted` are white balances
    /// The emitters' spectra as their files give them (any grid): the
    /// wall's light, scored as `quality` scores a light.
    std::vector<Spectrum> emitterSpectra;
};

/// One white balance: its IDT, the in-frustum transform, the wall showing
/// every depicted light, the pre-correction fitted over them, the
/// post-camera look fitted for the wall showing the white-balance light,
/// and the errors of the wall showing each white-balance light.
WallBalance SolveWallBalance(const WallSetup& setup, size_t balance);

/// The light the wall emits at `drive` (Σ drive_k × emitter_k, on 1 nm over
/// 360–830 nm), scored by every entry of the light-score registry, named
/// `name`; nullopt when a drive is negative (no light to score: the
/// report says so) or no score can be given.
std::optional<LightQuality> ScoreWallLight(const WallSetup& setup, const Eigen::VectorXd& drive,
                                           const std::string& name);

}  // namespace bandlight::jobs
