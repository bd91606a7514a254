// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Idt.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>

#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/GoldenSection.h"
#include "spectral/Illuminants.h"
#include "transforms/Accuracy.h"
#include "transforms/Plates.h"
#include "transforms/detail/IdtParts.h"

namespace bandlight
{

namespace detail
{

/// The raw response of the camera (on SurfaceRenderer's grid, the units
/// CameraShot balances) to a light's white.
Vec3 Response(const SpectralCamera& camera, const Spectrum& light)
{
    SurfaceRenderer::Samples s;
    for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
    {
        s(i) = light(SurfaceRenderer::Wavelength(i));
    }
    return camera.sensitivities() * s;
}

/// (log R/G, log B/G): what a neutral says about the light, any scale.
Eigen::Vector2d LogChromaticity(const Vec3& rgb)
{
    return {std::log(rgb.x() / rgb.y()), std::log(rgb.z() / rgb.y())};
}

}  // namespace detail

using detail::kDaylightFromK;
using detail::kHighestCctK;
using detail::kLowestCctK;

namespace
{

/// The six free parameters of a matrix whose rows are fixed by
/// M·whiteIn = whiteOut: the first two columns; the third follows.
using Params = Eigen::Matrix<double, 6, 1>;

Params ToParams(const Mat3& m)
{
    Params p;
    for (int k = 0; k < 3; ++k)
    {
        p(2 * k) = m(k, 0);
        p(2 * k + 1) = m(k, 1);
    }
    return p;
}

Mat3 FromParams(const Params& p, const ColourFit& d)
{
    Mat3 m;
    for (int k = 0; k < 3; ++k)
    {
        m(k, 0) = p(2 * k);
        m(k, 1) = p(2 * k + 1);
        m(k, 2) = (d.whiteOut(k) - m(k, 0) * d.whiteIn(0) - m(k, 1) * d.whiteIn(1)) / d.whiteIn(2);
    }
    return m;
}

}  // namespace

Spectrum IdtLightForCct(double kelvin)
{
    if (!(kelvin >= kLowestCctK && kelvin <= kHighestCctK))
    {
        throw Exception("a colour temperature for an IDT lies in 1000-25000 K, not " +
                        std::to_string(kelvin) + " K");
    }
    return kelvin >= kDaylightFromK ? Daylight(kelvin) : Planckian(kelvin);
}

bool ParseCct(const std::string& text, double& kelvin)
{
    if (text.size() < 2 || !std::isdigit(static_cast<unsigned char>(text.front())) ||
        (text.back() != 'K' && text.back() != 'k'))
    {
        return false;
    }
    const std::string number = text.substr(0, text.size() - 1);
    bool dot = false;
    for (const char c : number)
    {
        if (c == '.' && !dot)
        {
            dot = true;
        }
        else if (!std::isdigit(static_cast<unsigned char>(c)))
        {
            throw Exception("'" + OneLine(text, 80) +
                            "' is not a colour temperature: write it as digits then K (3200K)");
        }
    }
    kelvin = std::stod(number);
    return true;
}

double LabObjective(const ColourFit& d, const Mat3& m)
{
    double sum = 0.0;
    for (size_t i = 0; i < d.input.size(); ++i)
    {
        const Vec3 lab = XyzToLab(d.rgbToXyz * (m * d.input[i]), d.labWhite);
        const Vec3 ref = XyzToLab(d.rgbToXyz * d.target[i], d.labWhite);
        sum += (lab - ref).squaredNorm();
    }
    return sum;
}

Mat3 OptimiseLabMatrix(const ColourFit& d, const Mat3& start, int* iterations)
{
    if (d.input.size() != d.target.size() || !(std::abs(d.whiteIn(2)) > 0.0))
    {
        throw Exception("IDT fit: as many inputs as targets and a white with a blue are needed");
    }
    std::vector<Vec3> refs;
    for (const Vec3& t : d.target)
    {
        refs.push_back(XyzToLab(d.rgbToXyz * t, d.labWhite));
    }
    // Gauss–Newton's normal equations and gradient at p.
    const auto linearise = [&](const Params& p, Eigen::Matrix<double, 6, 6>& jtj, Params& jtr)
    {
        const Mat3 m = FromParams(p, d);
        jtj.setZero();
        jtr.setZero();
        double sum = 0.0;
        for (size_t i = 0; i < d.input.size(); ++i)
        {
            const Vec3& c = d.input[i];
            const Vec3 xyz = d.rgbToXyz * (m * c);
            const Vec3 r = XyzToLab(xyz, d.labWhite) - refs[i];
            const Mat3 ja = LabJacobian(xyz, d.labWhite) * d.rgbToXyz;
            Eigen::Matrix<double, 3, 6> j;
            for (int k = 0; k < 3; ++k)
            {
                for (int col = 0; col < 2; ++col)
                {
                    // m(k, 2) moves with m(k, col) to keep the white.
                    const double dc = c(col) - c(2) * d.whiteIn(col) / d.whiteIn(2);
                    j.col(2 * k + col) = ja.col(k) * dc;
                }
            }
            jtj += j.transpose() * j;
            jtr += j.transpose() * r;
            sum += r.squaredNorm();
        }
        return sum;
    };
    Params p = ToParams(start);
    Eigen::Matrix<double, 6, 6> jtj;
    Params jtr;
    double cost = linearise(p, jtj, jtr);
    double lambda = 1e-6;
    int it = 0;
    constexpr int kMaxIterations = 200;
    for (; it < kMaxIterations; ++it)
    {
        if (jtr.norm() <= 1e-13 * (1.0 + cost))
        {
            break;
        }
        Eigen::Matrix<double, 6, 6> a = jtj;
        a.diagonal() += lambda * jtj.diagonal();
        const Params step = a.ldlt().solve(-jtr);
        const Params trial = p + step;
        Eigen::Matrix<double, 6, 6> jtjTrial;
        Params jtrTrial;
        const double trialCost = linearise(trial, jtjTrial, jtrTrial);
        if (std::isfinite(trialCost) && trialCost <= cost)
        {
            const bool converged =
                step.norm() <= 1e-13 * (1.0 + p.norm()) || cost - trialCost <= 1e-15 * cost;
            p = trial;
            cost = trialCost;
            jtj = jtjTrial;
            jtr = jtrTrial;
            lambda = std::max(lambda * 0.1, 1e-12);
            if (converged)
            {
                ++it;
                break;
            }
        }
        else
        {
            lambda *= 10.0;
            if (lambda > 1e12)
            {
                break;  // no step lowers the cost: p is the optimum to rounding
            }
        }
    }
    if (iterations)
    {
        *iterations = it;
    }
    return FromParams(p, d);
}

IdtProblem::IdtProblem(const SpectralCamera& camera, const Spectrum& light, const RgbSpace& working,
                       AdaptationMethod adaptation, Observer observer)
    : m_shot(camera, light),
      m_eye(light, working, observer),
      m_balance(BalanceMatrix(light, working, adaptation, observer)),
      m_adaptation(adaptation),
      m_labWhite(WorkingWhiteXyz(working)),
      m_whiteXyz(m_eye.rgbToXyz() * m_eye.white())
{
}

Vec3 IdtProblem::gains() const
{
    return m_shot.gains() / m_shot.gains().y();
}

ColourFit IdtProblem::data(const std::vector<NamedSpectrum>& set) const
{
    ColourFit fit;
    for (const NamedSpectrum& t : set)
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        fit.input.push_back(m_shot.record(r));
        fit.target.push_back(m_balance * m_eye.render(r));
    }
    fit.whiteIn = Vec3::Ones();
    fit.whiteOut = Vec3::Ones();
    fit.rgbToXyz = m_eye.rgbToXyz();
    fit.labWhite = m_labWhite;
    return fit;
}

Vec3 IdtProblem::raw(const Spectrum& remittance) const
{
    return m_shot.record(SurfaceRenderer::Sample(remittance)).cwiseQuotient(m_shot.gains());
}

IdtError IdtProblem::errors(const Mat3& idt, const std::vector<NamedSpectrum>& set,
                            const std::string& name) const
{
    const ColourFit d = data(set);
    std::vector<double> de;
    for (size_t i = 0; i < d.input.size(); ++i)
    {
        const Vec3 lab = XyzToLab(d.rgbToXyz * (idt * d.input[i]), d.labWhite);
        const Vec3 ref = XyzToLab(d.rgbToXyz * d.target[i], d.labWhite);
        de.push_back(DeltaE2000(lab, ref));
    }
    IdtError e = IdtError::Of(Summarise(std::move(de)));
    e.set = name;
    e.count = int(set.size());
    return e;
}

namespace
{
IdtFit FitOn(const ColourFit& d, const Vec3& gains, const std::string& cameraLabel)
{
    IdtFit f;
    f.gains = gains;
    try
    {
        f.firstOrder = FitLabMatrix(d);
    }
    catch (const Exception&)
    {
        f.firstOrder = Mat3::Zero();  // refused below, naming the camera
    }
    const auto singular = [](const Mat3& m)
    { return !m.allFinite() || std::abs(m.determinant()) < 1e-12; };
    if (singular(f.firstOrder))
    {
        throw Exception(cameraLabel +
                        ": its channels do not separate colours (the fitted input transform is "
                        "singular)");
    }
    f.matrix = OptimiseLabMatrix(d, f.firstOrder, &f.iterations);
    if (singular(f.matrix))
    {
        throw Exception(cameraLabel + ": the fitted input transform is singular");
    }
    const double n = double(std::max<size_t>(d.input.size(), 1));
    f.rmsDe76 = std::sqrt(LabObjective(d, f.matrix) / n);
    f.firstOrderRmsDe76 = std::sqrt(LabObjective(d, f.firstOrder) / n);
    return f;
}
}  // namespace

IdtFit FitIdtOptimal(const IdtProblem& problem, const std::vector<NamedSpectrum>& training,
                     const std::string& cameraLabel)
{
    return FitOn(problem.data(training.empty() ? Rawtoaces190() : training), problem.gains(),
                 cameraLabel);
}

double MiredWeight(double cct1, double cct2, double cct, bool extrapolate)
{
    const double g1 = 1.0 / cct1, g2 = 1.0 / cct2, g = 1.0 / cct;
    const double line = std::abs(g1 - g2) < 1e-15 ? 1.0 : (g - g2) / (g1 - g2);
    return extrapolate ? line : std::clamp(line, 0.0, 1.0);
}

IdtCalibration CalibrationOf(const IdtProblem& problem, const IdtFit& fit)
{
    // Raw → XYZ under the light: the fit lands balanced colours in working
    // RGB; BalanceMatrix's CAT undone gives the colour under the light.
    const Mat3 cat =
        AdaptationMatrix(problem.whiteXyz(), problem.workingWhiteXyz(), problem.adaptation());
    const Mat3 rawToXyz = cat.inverse() * problem.rgbToXyz() * fit.matrix * fit.gains.asDiagonal();
    if (!rawToXyz.allFinite() || std::abs(rawToXyz.determinant()) < 1e-12)
    {
        throw Exception("an IDT to interpolate is singular: its camera has no colour matrix");
    }
    IdtCalibration c;
    c.cct = ComputeCct(problem.whiteXyz()).cctK;
    c.colorMatrix = rawToXyz.inverse();
    // DNG SDK, NormalizeColorMatrix: the connection space's white → a
    // camera neutral whose largest channel is 1.
    c.colorMatrix /= (c.colorMatrix * problem.workingWhiteXyz()).maxCoeff();
    return c;
}

Mat3 InterpolateIdt(const IdtCalibration& c1, const IdtCalibration& c2, const IdtProblem& target,
                    bool extrapolate)
{
    const double cct = ComputeCct(target.whiteXyz()).cctK;
    const double w = MiredWeight(c1.cct, c2.cct, cct, extrapolate);
    const Mat3 colorMatrix = w * c1.colorMatrix + (1.0 - w) * c2.colorMatrix;
    if (!colorMatrix.allFinite() || std::abs(colorMatrix.determinant()) < 1e-12)
    {
        throw Exception("the colour matrix interpolated to " + std::to_string(std::lround(cct)) +
                        " K is singular");
    }
    const Mat3 cameraToXyz = colorMatrix.inverse();
    // The raw neutral of the target light (balanced (1, 1, 1) undone), the
    // white it stands for through the interpolated matrix, and that white
    // adapted to the working white: white in, working white out.
    const Vec3 neutral = target.gains().cwiseInverse();
    const Vec3 white = cameraToXyz * neutral;
    const Mat3 cat = AdaptationMatrix(white, target.workingWhiteXyz(), target.adaptation());
    return target.rgbToXyz().inverse() * cat * cameraToXyz * neutral.asDiagonal();
}

size_t FlattestRemittance(const std::vector<NamedSpectrum>& set)
{
    size_t best = 0;
    double bestSpread = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < set.size(); ++i)
    {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (double l = 400.0; l <= 700.0; l += 5.0)
        {
            lo = std::min(lo, set[i].spectrum(l));
            hi = std::max(hi, set[i].spectrum(l));
        }
        const double spread = hi > 0.0 ? (hi - lo) / hi : std::numeric_limits<double>::infinity();
        if (spread < bestSpread)
        {
            bestSpread = spread;
            best = i;
        }
    }
    return best;
}

ColourFit ChartFitData(const std::vector<Vec3>& raw, const std::vector<NamedSpectrum>& chart,
                       const Spectrum& light, const RgbSpace& working, AdaptationMethod adaptation,
                       Observer observer, Vec3* gainsOut)
{
    if (raw.size() != chart.size() || chart.empty())
    {
        throw Exception("a chart IDT needs one camera RGB per patch (" +
                        std::to_string(raw.size()) + " RGB for " + std::to_string(chart.size()) +
                        " patches)");
    }
    const SurfaceRenderer eye(light, working, observer);
    const Mat3 balance = BalanceMatrix(light, working, adaptation, observer);
    const size_t grey = FlattestRemittance(chart);
    // The neutral patch's raw RGB is its luminance factor times the raw
    // white's: the gains that make the white (1, 1, 1).
    const SurfaceRenderer::Samples g = SurfaceRenderer::Sample(chart[grey].spectrum);
    const double y = (eye.rgbToXyz() * eye.render(g)).y();
    Vec3 gains;
    for (int c = 0; c < 3; ++c)
    {
        if (!(raw[grey][c] > 0.0) || !(y > 0.0))
        {
            throw Exception("the chart's neutral patch (" + chart[grey].name +
                            ") records nothing in a channel: no white balance exists");
        }
        gains[c] = y / raw[grey][c];
    }
    ColourFit fit;
    for (size_t i = 0; i < chart.size(); ++i)
    {
        fit.input.push_back(raw[i].cwiseProduct(gains));
        fit.target.push_back(balance * eye.render(SurfaceRenderer::Sample(chart[i].spectrum)));
    }
    fit.rgbToXyz = eye.rgbToXyz();
    fit.labWhite = WorkingWhiteXyz(working);
    if (gainsOut)
    {
        *gainsOut = gains / gains.y();
    }
    return fit;
}

IdtFit FitChartIdt(const std::vector<Vec3>& raw, const std::vector<NamedSpectrum>& chart,
                   const Spectrum& light, const RgbSpace& working, AdaptationMethod adaptation,
                   Observer observer)
{
    Vec3 gains;
    const ColourFit d = ChartFitData(raw, chart, light, working, adaptation, observer, &gains);
    return FitOn(d, gains, "the chart");
}

std::string IdtColorSpaceName(const std::string& camera, const std::string& light)
{
    return "Input - " + camera + " - " + light;
}

}  // namespace bandlight
