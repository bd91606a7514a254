// SPDX-License-Identifier: BSD-3-Clause
// The wall in the frustum (the drive that makes the camera record the
// content as intended) and one white balance's work from end to end.
#include "camera/Wall.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "plugin/Names.h"
#include "spectral/CieData.h"
#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::jobs
{

GridSpectrum EmissionOnGrid(const Spectrum& s)
{
    GridSpectrum g;
    for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
    {
        g(i) = s(SurfaceRenderer::Wavelength(i));
    }
    return g;
}

GridSpectra RemittancesOnGrid(const std::vector<NamedSpectrum>& set)
{
    GridSpectra g(SurfaceRenderer::kSamples, Eigen::Index(set.size()));
    for (size_t i = 0; i < set.size(); ++i)
    {
        g.col(Eigen::Index(i)) = SurfaceRenderer::Sample(set[i].spectrum);
    }
    return g;
}

double GridLuminance(const GridSpectrum& light, Observer observer)
{
    return EmissionOnGrid(GetMatchingFunctions(observer).y).dot(light);
}

WallCamera::WallCamera(const SpectralCamera& camera, const Spectrum& whiteBalance, const Mat3& idt,
                       const Mat3& rgbToXyz)
    : m_idt(idt), m_rgbToXyz(rgbToXyz)
{
    // CameraShot's gains: the perfect reflector under the white-balance
    // light records (1, 1, 1); it refuses a light a channel does not see.
    const CameraShot shot(camera, whiteBalance);
    m_gains = shot.gains();
    m_balanced = m_gains.asDiagonal() * camera.sensitivities();
}

Eigen::Matrix3Xd WallCamera::plates(const GridSpectrum& light, const GridSpectra& set) const
{
    return m_idt * ((m_balanced.array().rowwise() * light.transpose().array()).matrix() * set);
}

Eigen::Matrix3Xd WallCamera::plateByDrive(const GridSpectrum& remittance,
                                          const GridSpectra& emitters) const
{
    return m_idt *
           ((m_balanced.array().rowwise() * remittance.transpose().array()).matrix() * emitters);
}

namespace
{

/// The content cube's corners but black, and its white: where a gamut's
/// drives are most extreme (the drive is linear in the content).
const std::vector<std::pair<const char*, Vec3>>& Corners()
{
    static const std::vector<std::pair<const char*, Vec3>> corners = {
        {"red", {1, 0, 0}},     {"green", {0, 1, 0}},  {"blue", {0, 0, 1}}, {"cyan", {0, 1, 1}},
        {"magenta", {1, 0, 1}}, {"yellow", {1, 1, 0}}, {"white", {1, 1, 1}}};
    return corners;
}

bool HasNegative(const Eigen::VectorXd& drive)
{
    const double scale = drive.cwiseAbs().maxCoeff();
    return (drive.array() < -1e-9 * scale).any();
}

/// The two emitters whose responses in the camera point most nearly the
/// same way (unit columns' largest |cosine|), for the refusal's message.
std::string MostCollinear(const Eigen::Matrix3Xd& unit, const std::vector<std::string>& names)
{
    double best = -1.0;
    std::string pair;
    for (Eigen::Index a = 0; a < unit.cols(); ++a)
    {
        for (Eigen::Index b = a + 1; b < unit.cols(); ++b)
        {
            const double c = std::abs(unit.col(a).dot(unit.col(b)));
            if (c > best)
            {
                best = c;
                pair = names[size_t(a)] + " and " + names[size_t(b)];
            }
        }
    }
    return pair;
}

/// A drive "exact" to this relative residual over the content cube's corners.
constexpr double kExactDriveResidual = 1e-9;

/// The Moore–Penrose inverse of a symmetric 3×3 (eigenvalues below 1e-14
/// of the largest taken as zero): with rsᵀ in front, the least-norm
/// least-squares solution of rs · y = t for any rank of rs.
Mat3 PseudoInverse(const Mat3& symmetric)
{
    const Eigen::SelfAdjointEigenSolver<Mat3> e(symmetric);
    const Vec3 lambda = e.eigenvalues();
    Vec3 inverse = Vec3::Zero();
    for (int i = 0; i < 3; ++i)
    {
        inverse(i) = lambda(i) > 1e-14 * lambda(2) ? 1.0 / lambda(i) : 0.0;
    }
    return e.eigenvectors() * inverse.asDiagonal() * e.eigenvectors().transpose();
}

/// For more than three emitters: per content primary (a column of
/// `target`), the non-negative drive whose record is closest to it, and
/// among equally close ones the least (Euclidean) drive; D ≥ 0 then drives
/// every colour of the content cube non-negatively, since the drive is
/// linear in the content. Found exactly: by the Karush–Kuhn–Tucker
/// conditions the optimum drives some set S of emitters and is there the
/// least-squares, least-norm drive of those emitters alone, so every set's
/// is computed (through the pseudo-inverse of its Gram matrix) and the best
/// non-negative one kept — 2^N − 1 small solves, which bounds N
/// (defaults::WALL_MAX_EMITTERS). Closeness and size are compared
/// relative to the target, so the emitter files' units change nothing.
Eigen::MatrixXd NonNegativeDrive(const Eigen::Matrix3Xd& response, const Mat3& target)
{
    const Eigen::Index n = response.cols();
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, 3);
    for (int c = 0; c < 3; ++c)
    {
        const Vec3 t = target.col(c);
        const double scale = t.norm();
        if (!(scale > 0.0))
        {
            continue;  // black: no drive
        }
        double bestResidual = INFINITY;
        double bestNorm = INFINITY;
        for (unsigned long set = 1; set < (1ul << n); ++set)
        {
            std::vector<Eigen::Index> members;
            for (Eigen::Index j = 0; j < n; ++j)
            {
                if (set & (1ul << j))
                {
                    members.push_back(j);
                }
            }
            Eigen::Matrix3Xd rs(3, Eigen::Index(members.size()));
            for (size_t k = 0; k < members.size(); ++k)
            {
                rs.col(Eigen::Index(k)) = response.col(members[k]);
            }
            const Eigen::VectorXd y = rs.transpose() * PseudoInverse(rs * rs.transpose()) * t;
            if (!((y.array() >= -1e-12 * y.cwiseAbs().maxCoeff()).all()))
            {
                continue;  // asks an emitter of the set for less than nothing
            }
            const Eigen::VectorXd drive = y.cwiseMax(0.0);
            const double residual = (rs * drive - t).norm() / scale;
            const double norm = drive.norm();
            // Closer by more than rounding; or as close, and smaller.
            const bool closer = residual < bestResidual - 1e-12;
            const bool asClose = std::abs(residual - bestResidual) <= 1e-12;
            if (closer || (asClose && norm < bestNorm))
            {
                bestResidual = residual;
                bestNorm = norm;
                d.col(c).setZero();
                for (size_t k = 0; k < members.size(); ++k)
                {
                    d(members[k], c) = drive(Eigen::Index(k));
                }
            }
        }
    }
    return d;
}

}  // namespace

WallInFrustum SolveInFrustum(const Eigen::Matrix3Xd& response, const Mat3& contentToRecord,
                             const std::vector<std::string>& names, const std::string& cameraLabel,
                             double maxCondition)
{
    WallInFrustum f;
    const Eigen::Index n = response.cols();
    Eigen::Matrix3Xd unit = response;
    for (Eigen::Index k = 0; k < n; ++k)
    {
        const double norm = response.col(k).norm();
        if (!(norm > 0.0) || !std::isfinite(norm))
        {
            throw Exception(cameraLabel + " does not see emitter " + names[size_t(k)] +
                            ": its drive could show the camera nothing");
        }
        unit.col(k) /= norm;
    }
    // The collinearity of the emitters as the camera sees them, whatever
    // their power: a drive solved through a condition number κ turns a
    // relative error ε in the data into up to κ·ε in the drive.
    // Singular values: the square roots of the Gram matrix's eigenvalues.
    const Eigen::SelfAdjointEigenSolver<Mat3> gram(unit * unit.transpose(), Eigen::EigenvaluesOnly);
    const Vec3 lambda = gram.eigenvalues();  // ascending
    f.condition = lambda(0) > 0.0 ? std::sqrt(lambda(2) / lambda(0)) : INFINITY;
    if (!(f.condition <= maxCondition))
    {
        char figure[64];
        std::snprintf(figure, sizeof figure, "%.4g", f.condition);
        throw Exception(cameraLabel +
                        ": the emitters are nearly collinear for this camera "
                        "(condition number " +
                        figure + ", above " + std::to_string(int(maxCondition)) +
                        "; most alike: " + MostCollinear(unit, names) +
                        "): no drive shows it colours reliably; leave one of them out");
    }
    // Three emitters: D = R⁻¹ · C, exact (a corner outside the emitters'
    // gamut asks for a negative drive, which the report counts). More: the
    // exact equations R · D = C have an (N − 3)-dimensional family of
    // solutions, most of them asking some emitter for less than nothing;
    // bandlight takes the non-negative one of least error, the least drive
    // among equals (NonNegativeDrive).
    const Eigen::MatrixXd d0 = n == 3 ? Eigen::MatrixXd(Mat3(response).inverse() * contentToRecord)
                                      : NonNegativeDrive(response, contentToRecord);
    const double peak = (d0 * Vec3::Ones()).maxCoeff();
    if (!(peak > 0.0))
    {
        throw Exception(cameraLabel +
                        ": the content's white drives no emitter positively: "
                        "this wall cannot show white to this camera");
    }
    f.exposure = 1.0 / peak;
    f.drive = d0 * f.exposure;
    for (const auto& [name, c] : Corners())
    {
        WallCorner corner{name, c, f.drive * c, false};
        corner.negative = HasNegative(corner.drive);
        f.negativeCorners += corner.negative ? 1 : 0;
        const Vec3 want = f.exposure * (contentToRecord * c);
        const Vec3 got = response * corner.drive;
        f.residual = std::max(f.residual, (got - want).norm() / want.norm());
        f.corners.push_back(std::move(corner));
    }
    f.solution = n == 3                              ? "exact"
                 : f.residual <= kExactDriveResidual ? "non-negative minimum-norm"
                                                     : "non-negative least-squares";
    return f;
}

Eigen::VectorXd DepictedDrive(const WallInFrustum& f, const WallCamera& camera,
                              const Mat3& workingToContent, const GridSpectrum& light,
                              const std::string& lightName)
{
    const Vec3 content = workingToContent * camera.plate(light);
    const Eigen::VectorXd drive = f.drive * content;
    const double peak = drive.maxCoeff();
    if (!(peak > 0.0))
    {
        throw Exception("the wall cannot show " + lightName +
                        " to this camera: no emitter is "
                        "driven for its white");
    }
    return drive / peak;
}

WallScene WallSetting::scene(const Eigen::VectorXd& drive, const GridSpectrum& light) const
{
    const GridSpectrum wall = emitters * drive;
    return {drive, light * (GridLuminance(wall, observer) / GridLuminance(light, observer))};
}

WallBalance SolveWallBalance(const WallSetup& s, size_t b)
{
    const Light& wb = s.depicted[b];
    WallBalance out;
    out.light = wb.name;
    out.key = SafeName(wb.name);
    const IdtProblem problem(s.camera, wb.spectrum, s.working, s.adaptation, s.observer);
    const CctDuv cd = ComputeCct(problem.whiteXyz());
    out.cct = cd.cctK;
    out.duv = cd.duv;
    out.idt = FitIdtOptimal(problem, s.training, s.camera.label());
    const WallCamera camera(s.camera, wb.spectrum, out.idt.matrix, problem.rgbToXyz());

    // In the frustum: the content, carried into the working space as the
    // config carries it, is what the plate must be.
    const Mat3 contentToWorking = SpaceToSpace(s.content, s.working);
    out.inFrustum =
        SolveInFrustum(camera.response(s.emitters), out.idt.matrix.inverse() * contentToWorking,
                       s.names, s.camera.label());

    // Out of the frustum: the wall showing each depicted light.
    const WallSetting setting{camera, s.emitters, s.observer};
    const Mat3 workingToContent = contentToWorking.inverse();
    std::vector<WallScene> scenes;
    for (const Light& l : s.depicted)
    {
        const GridSpectrum light = EmissionOnGrid(l.spectrum);
        scenes.push_back(setting.scene(
            DepictedDrive(out.inFrustum, camera, workingToContent, light, l.name), light));
    }
    const GridSpectra& training = s.sets.front().second;
    out.preCorrection = FitPreCorrection(setting, scenes, training, out.preFit);
    out.post = FitPostMatrix(setting, scenes[b], training, out.postFit);
    FitPostOp(s, camera, scenes[b], wb, out);
    out.postRegistry = RegistryPostErrors(s, camera, scenes[b], wb, training);

    const Mat3 post = out.post;
    for (size_t k = 0; k < s.balances; ++k)
    {
        WallShown shown;
        shown.light = s.depicted[k].name;
        shown.drive = scenes[k].drive;
        shown.preDrive = out.preCorrection * shown.drive;
        shown.negative = HasNegative(shown.drive) || HasNegative(shown.preDrive);
        shown.scores = ScoreWallLight(s, shown.drive, "wall showing " + shown.light);
        shown.preScores =
            ScoreWallLight(s, shown.preDrive, "wall showing " + shown.light + ", pre-corrected");
        for (const auto& [name, set] : s.sets)
        {
            WallSetErrors e;
            e.set = name;
            e.before = WallErrors(setting, shown.drive, scenes[k], set);
            e.preCorrected = WallErrors(setting, shown.preDrive, scenes[k], set);
            e.postCorrected = WallErrors(setting, shown.drive, scenes[k], set,
                                         [&post](const Vec3& p) { return Vec3(post * p); });
            shown.errors.push_back(e);
        }
        out.shown.push_back(std::move(shown));
    }
    out.whiteScores =
        ScoreWallLight(s, out.inFrustum.drive * Vec3::Ones(), "wall white (content 1, 1, 1)");
    return out;
}

std::optional<LightQuality> ScoreWallLight(const WallSetup& setup, const Eigen::VectorXd& drive,
                                           const std::string& name)
{
    if (HasNegative(drive) || setup.emitterSpectra.size() != size_t(drive.size()))
    {
        return std::nullopt;
    }
    Spectrum light = Spectrum::Constant(360.0, 1.0, 471, 0.0);
    for (size_t k = 0; k < setup.emitterSpectra.size(); ++k)
    {
        Spectrum e = setup.emitterSpectra[k];
        e *= drive[Eigen::Index(k)];
        light += e;
    }
    try
    {
        return ScoreLight(name, light);
    }
    catch (const Exception&)
    {
        return std::nullopt;  // no power where the eye sees
    }
}

}  // namespace bandlight::jobs
