// SPDX-License-Identifier: BSD-3-Clause
// hueplane: hue-plane preserving colour correction (Andersen & Hardeberg,
// "Colorimetric characterization of digital cameras preserving hue
// planes", Proc. 13th Color Imaging Conference, IS&T 2005, pp. 141-146).
//
// Planes through the neutral axis divide the source RGB space into hue
// sectors; inside each sector the change of light is one 3×3, and
// neighbouring 3×3s agree on the plane between them, so the map is
// continuous, keeps every hue plane's colours on one plane, maps white
// exactly and is exposure invariant (f(k·x) = k·f(x) for k > 0: a sector is
// a cone from black). A sector j between the planes at hue angles θj and
// θj+1 maps the source white w, and the unit hue directions dj, dj+1 of its
// planes, to the target white w' and to bj', bj+1':
//     Mj = [w', bj', bj+1'] · [w, dj, dj+1]⁻¹.
// The planes sit at quantiles of the training colours' hues (so each sector
// holds as many of them), with more planes where the colours leave a gap
// wider than kMaxGap; the images bj' of the planes are fitted by weighted
// least squares (each colour weighted by 1 / its target luminance, so dark
// and light colours count alike) on the training remittances, with a slight
// ridge towards the least-squares 3×3 so that a plane few colours are near
// stays where that 3×3 puts it. Andersen & Hardeberg place their planes at
// chosen training colours and fit with white and those colours kept; the
// structure (continuous, hue-plane preserving, white exact) is theirs, the
// quantile planes and the ridge are this implementation's choices.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"
#include "transforms/RootPolynomial.h"
#include "transforms/SurfaceRenderer.h"
#include "transforms/detail/MethodFits.h"
#include "transforms/methods/PixelOp.h"

namespace bandlight
{

namespace
{

/// Planes at the training hues' quantiles; more where a gap is wider.
constexpr int kPlanes = 6;
constexpr double kMaxGap = 100.0 * kPi / 180.0;
/// The ridge towards the least-squares 3×3, relative to the mean diagonal
/// of the normal equations.
constexpr double kRidge = 1e-3;

/// Hue angles about the neutral axis of a source white.
struct HueFrame
{
    Vec3 u, v;  ///< orthonormal, both orthogonal to the white

    explicit HueFrame(const Vec3& white)
    {
        const Vec3 n = white.normalized();
        Vec3 axis = Vec3::UnitX() - n.x() * n;
        if (axis.norm() < 1e-6)
        {
            axis = Vec3::UnitY() - n.y() * n;
        }
        u = axis.normalized();
        v = n.cross(u);
    }
    double angle(const Vec3& x) const { return std::atan2(v.dot(x), u.dot(x)); }
    Vec3 direction(double angle) const { return std::cos(angle) * u + std::sin(angle) * v; }
};

/// The planes' angles, ascending in (−π, π]: kPlanes quantiles of `hues`,
/// then the widest gaps halved until none is wider than kMaxGap.
std::vector<double> PlaneAngles(std::vector<double> hues)
{
    std::sort(hues.begin(), hues.end());
    std::vector<double> planes;
    for (int j = 0; j < kPlanes && !hues.empty(); ++j)
    {
        const double a = hues[std::min(hues.size() - 1, size_t((j + 0.5) * hues.size() / kPlanes))];
        if (planes.empty() || a - planes.back() > 1e-6)
        {
            planes.push_back(a);
        }
    }
    if (planes.empty())
    {
        planes.push_back(0.0);
    }
    for (;;)
    {
        size_t widest = 0;
        double gap = 0.0;
        for (size_t j = 0; j < planes.size(); ++j)
        {
            const double next = j + 1 < planes.size() ? planes[j + 1] : planes[0] + 2.0 * kPi;
            if (next - planes[j] > gap)
            {
                gap = next - planes[j];
                widest = j;
            }
        }
        if (gap <= kMaxGap)
        {
            return planes;
        }
        double mid = planes[widest] + gap / 2.0;
        mid = mid > kPi ? mid - 2.0 * kPi : mid;
        planes.insert(std::upper_bound(planes.begin(), planes.end(), mid), mid);
    }
}

class HuePlane final : public PixelOp
{
public:
    HuePlane(const HueFrame& frame, std::vector<double> planes, std::vector<Mat3> sectors)
        : m_frame(frame), m_planes(std::move(planes)), m_sectors(std::move(sectors))
    {
    }

    Vec3 apply(const Vec3& in) const override { return m_sectors[sector(in)] * in; }

    void applyAfterInput(float* rgb, size_t count, int threads) const override
    {
        ParallelFor(count, count < 4096 ? 1 : threads,
                    [&](size_t begin, size_t end)
                    {
                        for (size_t i = begin; i < end; ++i)
                        {
                            float* p = rgb + 3 * i;
                            const Vec3 out = apply(GuardPixel(Vec3(p[0], p[1], p[2])));
                            p[0] = float(out.x());
                            p[1] = float(out.y());
                            p[2] = float(out.z());
                        }
                    });
    }

private:
    /// The sector of a colour: the last plane at or below its hue, the last
    /// sector below the first plane (it wraps round). Colours on the neutral
    /// axis take any sector: every one maps them alike.
    size_t sector(const Vec3& x) const
    {
        const double a = m_frame.angle(x);
        const auto above = std::upper_bound(m_planes.begin(), m_planes.end(), a);
        return above == m_planes.begin() ? m_planes.size() - 1
                                         : size_t(above - m_planes.begin()) - 1;
    }

    HueFrame m_frame;
    std::vector<double> m_planes;
    std::vector<Mat3> m_sectors;
};

/// [w, dj, dj+1]: a sector's source basis.
Mat3 SectorBasis(const Vec3& white, const HueFrame& frame, const std::vector<double>& planes,
                 size_t j)
{
    Mat3 s;
    s.col(0) = white;
    s.col(1) = frame.direction(planes[j]);
    s.col(2) = frame.direction(planes[(j + 1) % planes.size()]);
    return s;
}

/// The sectors' 3×3s (lit plates) fitted on `input` → `target`, weights
/// `weight`, white → white exactly.
std::vector<Mat3> FitSectors(const std::vector<Vec3>& input, const std::vector<Vec3>& target,
                             const std::vector<double>& weight, const Vec3& whiteIn,
                             const Vec3& whiteOut, const HueFrame& frame,
                             const std::vector<double>& planes)
{
    const size_t k = planes.size(), n = input.size();
    std::vector<Mat3> inverse(k);
    for (size_t j = 0; j < k; ++j)
    {
        inverse[j] = SectorBasis(whiteIn, frame, planes, j).inverse();
    }
    // The prior: the weighted least-squares 3×3, M0 = (Σ s² y xᵀ)(Σ s² x xᵀ)⁻¹.
    Mat3 xx = Mat3::Zero(), yx = Mat3::Zero();
    for (size_t i = 0; i < n; ++i)
    {
        const double s2 = weight[i] * weight[i];
        xx += s2 * input[i] * input[i].transpose();
        yx += s2 * target[i] * input[i].transpose();
    }
    const Mat3 prior = yx * xx.inverse();
    // One linear least-squares problem per output channel: the planes'
    // images are the unknowns, a colour of sector j gives α1·bj + α2·bj+1 =
    // y − α0·w' with α = [w, dj, dj+1]⁻¹ x.
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(k));
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(k), 3);
    for (size_t i = 0; i < n; ++i)
    {
        const double a = frame.angle(input[i]);
        const auto above = std::upper_bound(planes.begin(), planes.end(), a);
        const size_t j =
            above == planes.begin() ? k - 1 : size_t(above - planes.begin()) - 1;
        const size_t j1 = (j + 1) % k;
        const Vec3 alpha = inverse[j] * input[i];
        const double s2 = weight[i] * weight[i];
        const Vec3 t = target[i] - alpha[0] * whiteOut;
        normal(Eigen::Index(j), Eigen::Index(j)) += s2 * alpha[1] * alpha[1];
        normal(Eigen::Index(j1), Eigen::Index(j1)) += s2 * alpha[2] * alpha[2];
        normal(Eigen::Index(j), Eigen::Index(j1)) += s2 * alpha[1] * alpha[2];
        normal(Eigen::Index(j1), Eigen::Index(j)) += s2 * alpha[1] * alpha[2];
        rhs.row(Eigen::Index(j)) += s2 * alpha[1] * t.transpose();
        rhs.row(Eigen::Index(j1)) += s2 * alpha[2] * t.transpose();
    }
    const double lambda = kRidge * std::max(normal.trace() / double(k), 1e-12);
    for (size_t j = 0; j < k; ++j)
    {
        normal(Eigen::Index(j), Eigen::Index(j)) += lambda;
        rhs.row(Eigen::Index(j)) += lambda * (prior * frame.direction(planes[j])).transpose();
    }
    const Eigen::MatrixXd images = normal.ldlt().solve(rhs);
    if (!images.allFinite())
    {
        throw Exception("hueplane: the fit on the training remittances has no solution");
    }
    std::vector<Mat3> sectors(k);
    for (size_t j = 0; j < k; ++j)
    {
        Mat3 out;
        out.col(0) = whiteOut;
        out.col(1) = images.row(Eigen::Index(j)).transpose();
        out.col(2) = images.row(Eigen::Index((j + 1) % k)).transpose();
        sectors[j] = out * inverse[j];
    }
    return sectors;
}

std::unique_ptr<PixelOp> MakeOp(const Light& from, const Light& to, const MethodSpec& method,
                                const RgbSpace& working, Observer observer)
{
    const SurfaceRenderer r1(from.spectrum, working, observer);
    const SurfaceRenderer r2(to.spectrum, working, observer);
    const std::vector<NamedSpectrum>& training = TrainingOf(method);
    std::vector<Vec3> input, target;
    std::vector<double> weight, hues;
    const HueFrame frame(r1.white());
    for (const NamedSpectrum& t : training)
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        input.push_back(r1.render(r));
        target.push_back(r2.render(r));
        weight.push_back(1.0 / std::max((r2.rgbToXyz() * target.back()).y(), 1e-3));
        hues.push_back(frame.angle(input.back()));
    }
    const std::vector<double> planes = PlaneAngles(hues);
    std::vector<Mat3> sectors =
        FitSectors(input, target, weight, r1.white(), r2.white(), frame, planes);
    const detail::PlateBalance balance = detail::BalanceOf(from, to, method, working, observer);
    for (Mat3& m : sectors)
    {
        m = balance.to * m;
    }
    auto op = std::make_unique<HuePlane>(frame, planes, std::move(sectors));
    op->hasInput = balance.balanced;
    op->input = balance.from.inverse();
    return op;
}

bool Parse(const std::string& name, MethodSpec&)
{
    return name == "hueplane";
}

std::string Describe(const MethodSpec&)
{
    return "Hue-plane preserving colour correction (Andersen & Hardeberg 2005): one 3x3 "
           "between neighbouring planes through the neutral axis (6 at the training colours' "
           "hue quantiles), continuous across them, exact on white and exposure invariant, "
           "fitted on 205 measured remittances (rawtoaces' 190 and the 15 TCS): not linear, "
           "baked into a 3D LUT with a log2 shaper.";
}

}  // namespace

MethodEntry HuePlaneMethod(ChangeMethod key)
{
    MethodEntry e;
    e.methods = {key};
    e.syntax = "hueplane";
    e.exactness = MethodExactness::NONLINEAR;
    e.parse = &Parse;
    e.describe = &Describe;
    e.makeOp = &MakeOp;
    e.native = true;
    e.directForm = DirectForm::NATIVE;
    e.defaultTraining = &RootPolynomialTraining;
    e.takesTraining = true;
    e.accuracyDefaults = {"hueplane"};
    return e;
}

}  // namespace bandlight
