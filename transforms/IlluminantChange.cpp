// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/IlluminantChange.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <sstream>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"
#include "transforms/BandModel.h"
#include "transforms/Idt.h"
#include "transforms/Methods.h"
#include "transforms/SpectralMethods.h"
#include "transforms/Upsampler.h"
#include "transforms/detail/MethodFits.h"
#include "transforms/methods/PixelOp.h"

#include <thread>

namespace bandlight
{

namespace
{

/// Band model matrix B (3 × N, rows normalised) and its Moore–Penrose
/// pseudo-inverse (the ordinary inverse for three bands).
struct BandBasis
{
    Eigen::MatrixXd b;
    Eigen::MatrixXd pinv;
};

BandBasis MakeBandBasis(const BandSet& bands, Observer observer)
{
    BandBasis out;
    out.b = MatchingBandMatrix(bands, MatchingSet::XYZ, observer);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(out.b, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const auto& s = svd.singularValues();
    CheckBandCondition(bands, s(s.size() - 1) > 0.0 ? s(0) / s(s.size() - 1)
                                                    : std::numeric_limits<double>::infinity());
    out.pinv = svd.matrixV() * s.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
    return out;
}

/// XYZ (Y = 1) of a light's white as every method sees it: the perfect
/// reflector rendered on SurfaceRenderer's grid (380–780 nm at 5 nm), so
/// that white-preserving methods agree with the spectral reference exactly.
Vec3 WhiteOf(const Light& light, Observer observer)
{
    const SurfaceRenderer r(light.spectrum, AcesCgSpace(), observer);
    const Vec3 w = r.rgbToXyz() * r.white();
    if (!(w.y() > 0.0) || !w.allFinite())
    {
        throw Exception("illuminant " + light.name + " has no luminance: no white to adapt from");
    }
    return w / w.y();
}

}  // namespace

Eigen::MatrixXd WorkingToBandMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer)
{
    return MakeBandBasis(bands, observer).pinv * RgbToXyzMatrix(working.chromaticities);
}

Eigen::MatrixXd BandToWorkingMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer)
{
    return RgbToXyzMatrix(working.chromaticities).inverse() *
           MatchingBandMatrix(bands, MatchingSet::XYZ, observer);
}

Mat3 MaterialTintMatrix(const std::vector<double>& remittance, const BandSet& bands,
                        const RgbSpace& working, Observer observer)
{
    if (remittance.size() != bands.size())
    {
        throw Exception("material tint: " + std::to_string(remittance.size()) +
                        " remittance values for " + std::to_string(bands.size()) + " bands");
    }
    const Eigen::VectorXd r =
        Eigen::Map<const Eigen::VectorXd>(remittance.data(), Eigen::Index(remittance.size()));
    return BandToWorkingMatrix(bands, working, observer) * r.asDiagonal() *
           WorkingToBandMatrix(bands, working, observer);
}

namespace detail
{

Mat3 IdentityFit(const Light&, const Light&, const MethodSpec&, const RgbSpace&, Observer)
{
    return Mat3::Identity();
}

Mat3 AdaptationFit(const Light& from, const Light& to, const MethodSpec& method,
                   const RgbSpace& working, Observer observer)
{
    const Mat3 m = RgbToXyzMatrix(working.chromaticities);
    const AdaptationMethod cat = method.entry().adaptation;
    return m.inverse() * AdaptationMatrix(WhiteOf(from, observer), WhiteOf(to, observer), cat) * m;
}

Mat3 LeastSquaresFit(const Light& from, const Light& to, const MethodSpec& method,
                     const RgbSpace& working, Observer observer)
{
    const SurfaceRenderer r1(from.spectrum, working, observer);
    const SurfaceRenderer r2(to.spectrum, working, observer);
    return FitMatrix(r1, r2, TrainingOf(method));
}

Mat3 MetamerFit(const Light& from, const Light& to, const MethodSpec&, const RgbSpace& working,
                Observer observer)
{
    return MetamerMatrix(SurfaceRenderer(from.spectrum, working, observer),
                         SurfaceRenderer(to.spectrum, working, observer));
}

Mat3 BandFit(const Light& from, const Light& to, const MethodSpec& method, const RgbSpace& working,
             Observer observer)
{
    const Mat3 m = RgbToXyzMatrix(working.chromaticities);
    const Mat3 mInv = m.inverse();
    const BandSet& bands = method.bands;
    const BandBasis basis = MakeBandBasis(bands, observer);
    Eigen::VectorXd ratio(Eigen::Index(bands.size()));
    if (!method.whitePreserving)
    {
        const std::vector<double> i1 = IlluminantBands(from.spectrum, bands);
        const std::vector<double> i2 = IlluminantBands(to.spectrum, bands);
        Eigen::VectorXd e1(ratio.size()), e2(ratio.size());
        for (size_t b = 0; b < bands.size(); ++b)
        {
            if (!(i1[b] > 0.0))
            {
                throw Exception("illuminant " + from.name + " has no power in band " +
                                bands[b].name + ": the band ratio " + to.name + "/" + from.name +
                                " is undefined");
            }
            ratio(Eigen::Index(b)) = i2[b] / i1[b];
            e1(Eigen::Index(b)) = i1[b];
            e2(Eigen::Index(b)) = i2[b];
        }
        // Keep the exposure: the band model's white under `from` keeps its Y.
        const double y1 = (basis.b * e1)(1);
        const double y2 = (basis.b * e2)(1);
        if (!(y1 > 0.0) || !(y2 > 0.0))
        {
            throw Exception("band model: " + std::string(y1 > 0.0 ? to.name : from.name) +
                            " has no luminance in bands " + bands.describe() +
                            " nm: the exposure cannot be kept");
        }
        ratio *= y1 / y2;
    }
    else
    {
        const Eigen::VectorXd c1 = basis.pinv * WhiteOf(from, observer);
        const Eigen::VectorXd c2 = basis.pinv * WhiteOf(to, observer);
        for (Eigen::Index b = 0; b < ratio.size(); ++b)
        {
            if (!(c1(b) > 0.0) || !(c2(b) > 0.0))
            {
                throw Exception("band-wp: a white has a non-positive band coordinate in band " +
                                bands[size_t(b)].name + " (" + from.name + " → " + to.name +
                                "): no white-preserving band ratio exists");
            }
            ratio(b) = c2(b) / c1(b);
        }
    }
    return mInv * basis.b * ratio.asDiagonal() * basis.pinv * m;
}

}  // namespace detail

namespace
{
/// The lit 3×3 of a linear method, through its registry entry.
Mat3 LitChangeMatrix(const Light& from, const Light& to, const MethodSpec& method,
                     const RgbSpace& working, Observer observer)
{
    const MethodEntry& entry = FindMethod(method.method);
    if (!entry.litMatrix)
    {
        throw Exception("method '" + method.name +
                        "' is not one 3x3 matrix: apply it through a Relighter (upsample, "
                        "rootpoly) or to spectra (spectral)");
    }
    return entry.litMatrix(from, to, method, working, observer);
}
}  // namespace

Mat3 IlluminantChangeMatrix(const Light& from, const Light& to, const MethodSpec& method,
                            const RgbSpace& working, Observer observer)
{
    const Mat3 lit = LitChangeMatrix(from, to, method, working, observer);
    if (!method.plates.balanced() || method.entry().identity)
    {
        return lit;
    }
    const AdaptationMethod a = method.plates.adaptation;
    return BalanceMatrix(to.spectrum, working, a, observer) * lit *
           BalanceMatrix(from.spectrum, working, a, observer).inverse();
}

Relighter::Relighter(const Light& from, const Light& to, const MethodSpec& method,
                     const RgbSpace& working, Observer observer)
{
    build(from, to, method, working, observer);
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
        {
            m_matrixF.m[3 * r + c] = float(m_matrix(r, c));
        }
    }
}

void Relighter::build(const Light& from, const Light& to, const MethodSpec& method,
                      const RgbSpace& working, Observer observer)
{
    const MethodEntry& entry = method.entry();
    if (entry.isReference())
    {
        throw Exception(
            "method '" + method.name +
            "' needs the spectra of the surfaces: it is the "
            "reference `bandlight accuracy` measures against, not an image transform");
    }
    if (method.isLinear())
    {
        m_matrix = IlluminantChangeMatrix(from, to, method, working, observer);
        return;
    }
    m_op = entry.makeOp(from, to, method, working, observer);
    m_matrix = m_op->linearPart();
}

namespace detail
{

PlateBalance BalanceOf(const Light& from, const Light& to, const MethodSpec& method,
                       const RgbSpace& working, Observer observer)
{
    PlateBalance b{method.plates.balanced()};
    if (b.balanced)
    {
        b.from = BalanceMatrix(from.spectrum, working, method.plates.adaptation, observer);
        b.to = BalanceMatrix(to.spectrum, working, method.plates.adaptation, observer);
    }
    return b;
}

}  // namespace detail

std::string LookDescription(const Light& from, const Light& to, const MethodSpec& method,
                            const RgbSpace& working, Observer observer)
{
    std::string text = "Relight from " + from.name + " to " + to.name + " in " +
                       working.displayName + ". " + DescribeMethod(method) + " ";
    if (method.entry().needsCamera && method.camera)
    {
        // The plates it expects come through the camera's one fixed IDT:
        // the input colour space `bandlight idt` writes for that light.
        text += "Expects plates read through the input colour space '" +
                IdtColorSpaceName(method.camera->name(), method.idtLightName) +
                "' (bandlight idt --camera ... --lights " + method.idtLightName + "). ";
    }
    if (!method.plates.balanced() || method.entry().isReference())
    {
        return text + method.plates.describe(working.displayName);
    }
    const Vec3 grey = Relighter(from, to, method, working, observer).apply(Vec3::Constant(0.18));
    return text + method.plates.describe(working.displayName, &grey);
}

Relighter::~Relighter() = default;
Relighter::Relighter(Relighter&&) noexcept = default;

Vec3 GuardPixel(const Vec3& rgb) noexcept
{
    Vec3 out;
    for (int c = 0; c < 3; ++c)
    {
        out[c] = std::isnan(rgb[c]) ? -PIXEL_GUARD : std::clamp(rgb[c], -PIXEL_GUARD, PIXEL_GUARD);
    }
    return out;
}

const RootPolynomial* Relighter::rootPolynomial() const noexcept
{
    return m_op ? m_op->rootPolynomial() : nullptr;
}

const Mat3* Relighter::inputMatrix() const noexcept
{
    return m_op && m_op->hasInput ? &m_op->input : nullptr;
}

Vec3 Relighter::apply(const Vec3& rgb) const
{
    const Vec3 in = GuardPixel(rgb);
    if (!m_op)
    {
        return m_matrix * in;
    }
    return m_op->apply(m_op->hasInput ? Vec3(m_op->input * in) : in);
}

void Relighter::apply(Vec3* rgb, size_t count) const
{
    if (!m_op)
    {
        for (size_t i = 0; i < count; ++i)
        {
            rgb[i] = apply(rgb[i]);
        }
        return;
    }
    for (size_t i = 0; i < count; ++i)
    {
        const Vec3 guarded = GuardPixel(rgb[i]);
        rgb[i] = m_op->hasInput ? Vec3(m_op->input * guarded) : guarded;
    }
    m_op->apply(rgb, count);
}

void Relighter::apply(float* rgb, size_t count, int threads) const
{
    apply(rgb, count, 3, threads);
}

void Relighter::apply(float* pixels, size_t count, size_t stride, int threads) const
{
    if (stride < 3)
    {
        throw Exception("Relighter: pixels of " + std::to_string(stride) +
                        " channels (at least R, G, B)");
    }
    if (!m_op)
    {
        // The guarded 3×3: bound by memory, so threads only for big buffers.
        ParallelFor(count, count < 65536 ? 1 : threads,
                    [&](size_t begin, size_t end)
                    { GuardedMatrix(m_matrixF, pixels + begin * stride, end - begin, stride); });
        return;
    }
    if (m_op->applyWhole(pixels, count, stride, threads))
    {
        return;
    }
    if (stride != 3)
    {
        // The op works on packed triples: gather, relight, scatter.
        ParallelFor(count, count < 1024 ? 1 : threads,
                    [&](size_t begin, size_t end)
                    {
                        std::vector<float> rgb(3 * (end - begin));
                        for (size_t i = begin; i < end; ++i)
                        {
                            std::copy_n(pixels + i * stride, 3, &rgb[3 * (i - begin)]);
                        }
                        apply(rgb.data(), end - begin, 3, 1);
                        for (size_t i = begin; i < end; ++i)
                        {
                            std::copy_n(&rgb[3 * (i - begin)], 3, pixels + i * stride);
                        }
                    });
        return;
    }
    float* rgb = pixels;
    // The guard (written so NaN goes to the lower bound: (-G < NaN) is
    // false, and the loop vectorises), the input matrix, then the op.
    ParallelFor(count, count < 1024 ? 1 : threads,
                [&](size_t begin, size_t end)
                {
                    const float lo = float(-PIXEL_GUARD), hi = float(PIXEL_GUARD);
                    for (size_t i = 3 * begin; i < 3 * end; ++i)
                    {
                        const float v = lo < rgb[i] ? rgb[i] : lo;
                        rgb[i] = hi < v ? hi : v;
                    }
                    if (m_op->hasInput)
                    {
                        const Eigen::Matrix3f pre = m_op->input.cast<float>();
                        for (size_t i = begin; i < end; ++i)
                        {
                            Eigen::Map<Eigen::Vector3f> p(rgb + 3 * i);
                            p = pre * Eigen::Vector3f(p);
                        }
                    }
                    m_op->applyAfterInput(rgb + 3 * begin, end - begin, 1);
                });
}

void Relighter::applyAfterInput(float* rgb, size_t count, int threads) const
{
    if (m_op)
    {
        m_op->applyAfterInput(rgb, count, threads);
        return;
    }
    auto run = [&](size_t begin, size_t end)
    {
        for (size_t i = begin; i < end; ++i)
        {
            float* p = rgb + 3 * i;
            const Vec3 out = m_matrix * GuardPixel(Vec3(p[0], p[1], p[2]));
            p[0] = float(out.x());
            p[1] = float(out.y());
            p[2] = float(out.z());
        }
    };
    // Below 1024 pixels a thread costs more than it saves.
    ParallelFor(count, count < 1024 ? 1 : threads, run);
}

void PixelOp::apply(Vec3* rgb, size_t count) const
{
    for (size_t i = 0; i < count; ++i)
    {
        rgb[i] = apply(rgb[i]);
    }
}

bool PixelOp::applyWhole(float*, size_t, size_t, int) const
{
    return false;
}

}  // namespace bandlight
