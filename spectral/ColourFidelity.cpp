// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/ColourFidelity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Core>

#include "spectral/Cam02Ucs.h"
#include "spectral/CieData.h"
#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

namespace bandlight
{

namespace
{

// CIE 224:2017: the evaluation range and the range of CCT with a reference.
constexpr double kFirstNm = 380.0;
constexpr double kLastNm = 780.0;
constexpr double kMinCct = 1000.0;
constexpr double kMaxCct = 25000.0;
// CIE 224:2017 / TM-30-18: where the reference blends from
// Planckian to daylight.
constexpr double kPlanckianBelow = 4000.0;
constexpr double kDaylightAbove = 5000.0;
/// CIE 224:2017, TM-30-18: the scale factor c_f of ΔE' in Rf.
constexpr double kCf = 6.73;
/// |Duv| beyond which the light is taken to be too far from the locus for a
/// same-CCT reference to mean much (see ColourFidelity::outsideTolerance).
constexpr double kDuvTolerance = 0.02;

/// The observers and the 99 CES on one working grid, as one matrix: rows
/// 0–2 hold x̄, ȳ, z̄ (CIE 1931, for the CCT), rows 3–5 x̄10, ȳ10, z̄10 and rows
/// 6 + 3i … 8 + 3i R_i·x̄10, R_i·ȳ10, R_i·z̄10, so that everything taken from
/// a light is one matrix–vector product (the grid's Δλ cancels in each
/// normalisation).
struct WorkingGrid
{
    double step = 1.0;
    size_t count = 0;
    Eigen::MatrixXd weights;
};

constexpr Eigen::Index kWhiteRow = 3;
constexpr Eigen::Index kFirstSampleRow = 6;

WorkingGrid MakeGrid(double step)
{
    WorkingGrid g;
    g.step = step;
    g.count = size_t(std::lround((kLastNm - kFirstNm) / step)) + 1;
    const MatchingFunctions& cmf2 = GetMatchingFunctions1nm(Observer::CIE1931_2DEG);
    const MatchingFunctions& cmf10 = GetMatchingFunctions1nm(Observer::CIE1964_10DEG);
    const std::vector<NamedSpectrum>& ces = ColourEvaluationSamples();
    if (ces.size() != CES_COUNT)
    {
        throw Exception("embedded data/ref/cie224_ces.csv holds " + std::to_string(ces.size()) +
                        " samples, not 99");
    }
    g.weights.resize(kFirstSampleRow + 3 * Eigen::Index(CES_COUNT), Eigen::Index(g.count));
    for (size_t j = 0; j < g.count; ++j)
    {
        // Whole nanometres: the 1 nm tables' own values, no interpolation.
        const double l = kFirstNm + step * double(j);
        const Eigen::Index c = Eigen::Index(j);
        g.weights.block<3, 1>(0, c) = Vec3(cmf2.x(l), cmf2.y(l), cmf2.z(l));
        const Vec3 xyz10(cmf10.x(l), cmf10.y(l), cmf10.z(l));
        g.weights.block<3, 1>(kWhiteRow, c) = xyz10;
        for (size_t i = 0; i < CES_COUNT; ++i)
        {
            g.weights.block<3, 1>(kFirstSampleRow + 3 * Eigen::Index(i), c) =
                ces[i].spectrum(l) * xyz10;
        }
    }
    return g;
}

const WorkingGrid& Grid(bool fiveNm)
{
    static const WorkingGrid oneNm = MakeGrid(1.0);
    static const WorkingGrid five = MakeGrid(5.0);
    return fiveNm ? five : oneNm;
}

/// The products of the working grid's weights with a light sampled on it.
Eigen::VectorXd Integrate(const WorkingGrid& g, const Spectrum& light)
{
    return g.weights *
           Eigen::Map<const Eigen::VectorXd>(light.values().data(), Eigen::Index(g.count));
}

/// CAM02-UCS (J', a', b') of the 99 CES from a light's integrals: CIECAM02
/// with the light's white at Y = 100 (CIE 224:2017).
std::array<Vec3, CES_COUNT> Appearance(const Eigen::VectorXd& v)
{
    const double k = 100.0 / v[kWhiteRow + 1];
    const Cam02 cam(k * v.segment<3>(kWhiteRow));
    std::array<Vec3, CES_COUNT> jab;
    for (size_t i = 0; i < CES_COUNT; ++i)
    {
        jab[i] = cam.ucs(k * v.segment<3>(kFirstSampleRow + 3 * Eigen::Index(i)));
    }
    return jab;
}

/// The light on its working grid, scaled by a power of two (exact) so that
/// any scale integrates alike.
struct WorkingLight
{
    const WorkingGrid* grid = nullptr;
    Spectrum light;
};

WorkingLight OnWorkingGrid(const Spectrum& light, FidelityMethod method)
{
    // CIE 224: a 5 nm light aligned to 380 nm is used as given, at 5 nm; any
    // other light is brought onto 1 nm through its linear interpolant. Zero
    // outside the data.
    const double offset = (light.start() - kFirstNm) / 5.0;
    const bool fiveNm = method == FidelityMethod::CIE_224 && std::abs(light.step() - 5.0) < 1e-9 &&
                        std::abs(offset - std::round(offset)) < 1e-9;
    WorkingLight w;
    w.grid = &Grid(fiveNm);
    w.light = light.resampled(kFirstNm, w.grid->step, w.grid->count);
    double peak = 0.0;
    for (double v : w.light.values())
    {
        peak = std::isfinite(v) ? std::max(peak, std::abs(v)) : HUGE_VAL;
    }
    if (!(peak > 0.0) || !std::isfinite(peak))
    {
        throw Exception("colour fidelity: the light has no finite power in 380–780 nm");
    }
    int exponent = 0;
    std::frexp(peak, &exponent);
    w.light *= std::ldexp(1.0, -exponent);
    return w;
}

/// Rf of a colour difference ΔE' (CIE 224:2017): 10 ln(exp((100 − c_f ΔE')/10) + 1).
double FidelityOf(double deltaE) noexcept
{
    return 10.0 * std::log1p(std::exp((100.0 - kCf * deltaE) / 10.0));
}

/// Signed area of the closed polygon through the bins that hold samples, in
/// bin order (shoelace formula).
double PolygonArea(const std::array<std::array<double, 2>, HUE_BIN_COUNT>& p,
                   const std::array<int, HUE_BIN_COUNT>& n) noexcept
{
    std::vector<std::array<double, 2>> v;
    for (size_t j = 0; j < HUE_BIN_COUNT; ++j)
    {
        if (n[j] > 0)
        {
            v.push_back(p[j]);
        }
    }
    double twice = 0.0;
    for (size_t j = 0; j < v.size(); ++j)
    {
        const auto& a = v[j];
        const auto& b = v[(j + 1) % v.size()];
        twice += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * twice;
}

double LuminanceY(const Spectrum& s)
{
    return IntegrateXyz(s, Observer::CIE1931_2DEG).y();
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0)
{
    char text[160];
    std::snprintf(text, sizeof(text), format, a, b, c);
    return text;
}

/// TM-30-18: the 16 hue-bin figures from the samples' (J', a', b').
void HueBins(const std::array<Vec3, CES_COUNT>& test, const std::array<Vec3, CES_COUNT>& ref,
             const std::array<double, CES_COUNT>& deltaE, ColourFidelity& out)
{
    std::array<int, HUE_BIN_COUNT> n{};
    std::array<double, HUE_BIN_COUNT> sumDeltaE{};
    for (size_t i = 0; i < CES_COUNT; ++i)
    {
        // The bin of a sample is that of its hue under the reference.
        double h = std::atan2(ref[i].z(), ref[i].y());
        if (h < 0.0)
        {
            h += 2.0 * kPi;
        }
        const size_t j = std::min(HUE_BIN_COUNT - 1, size_t(h / (2.0 * kPi / HUE_BIN_COUNT)));
        ++n[j];
        sumDeltaE[j] += deltaE[i];
        out.testBinAb[j][0] += test[i].y();
        out.testBinAb[j][1] += test[i].z();
        out.referenceBinAb[j][0] += ref[i].y();
        out.referenceBinAb[j][1] += ref[i].z();
    }
    for (size_t j = 0; j < HUE_BIN_COUNT; ++j)
    {
        if (n[j] == 0)
        {
            // Only below about 1150 K do the reference's hues leave a bin empty.
            const double nan = std::numeric_limits<double>::quiet_NaN();
            out.rfHue[j] = out.chromaShift[j] = out.hueShift[j] = nan;
            out.testBinAb[j] = out.referenceBinAb[j] = {nan, nan};
            out.warnings.push_back("hue bin " + std::to_string(j + 1) +
                                   " holds no sample under the reference: its figures are NaN "
                                   "and Rg spans the other bins");
            continue;
        }
        for (int k = 0; k < 2; ++k)
        {
            out.testBinAb[j][size_t(k)] /= n[j];
            out.referenceBinAb[j][size_t(k)] /= n[j];
        }
        out.rfHue[j] = FidelityOf(sumDeltaE[j] / n[j]);
        // Components of the mean's shift along and across the bin's middle
        // hue, over the reference mean's chroma (TM-30-18).
        const double theta = (double(j) + 0.5) * 2.0 * kPi / HUE_BIN_COUNT;
        const double da = out.testBinAb[j][0] - out.referenceBinAb[j][0];
        const double db = out.testBinAb[j][1] - out.referenceBinAb[j][1];
        const double chroma = std::hypot(out.referenceBinAb[j][0], out.referenceBinAb[j][1]);
        out.chromaShift[j] = (da * std::cos(theta) + db * std::sin(theta)) / chroma;
        out.hueShift[j] = (-da * std::sin(theta) + db * std::cos(theta)) / chroma;
    }
    out.rg = 100.0 * PolygonArea(out.testBinAb, n) / PolygonArea(out.referenceBinAb, n);
}

}  // namespace

Spectrum ColourFidelityReference(double cctK, double startNm, double stepNm, size_t count)
{
    if (!(cctK >= kMinCct && cctK <= kMaxCct))
    {
        throw Exception("colour fidelity: CCT " + Format("%.0f", cctK) +
                        " K is outside 1000–25000 K, where CIE 224:2017 defines a reference");
    }
    Spectrum planck;
    Spectrum daylight;
    if (cctK < kDaylightAbove)
    {
        planck = Planckian(cctK, startNm, stepNm, count);
    }
    if (cctK > kPlanckianBelow)
    {
        daylight = Daylight(cctK).resampled(startNm, stepNm, count);
    }
    Spectrum reference;
    if (cctK <= kPlanckianBelow)
    {
        reference = planck;
    }
    else if (cctK >= kDaylightAbove)
    {
        reference = daylight;
    }
    else
    {
        // Both normalised to the same luminance, then mixed in proportion to
        // the CCT's place between 4000 K and 5000 K.
        const double m = (cctK - kPlanckianBelow) / (kDaylightAbove - kPlanckianBelow);
        reference = planck * ((1.0 - m) / LuminanceY(planck));
        reference += daylight * (m / LuminanceY(daylight));
    }
    return reference * (100.0 / LuminanceY(reference));
}

std::string ColourFidelityReferenceName(double cctK)
{
    if (cctK <= kPlanckianBelow)
    {
        return Format("Planckian %.0f K", cctK);
    }
    if (cctK >= kDaylightAbove)
    {
        return Format("CIE daylight %.0f K", cctK);
    }
    const double m = (cctK - kPlanckianBelow) / (kDaylightAbove - kPlanckianBelow);
    return Format("blend at %.0f K: %.0f %% Planckian, %.0f %% CIE daylight", cctK,
                  100.0 * (1.0 - m), 100.0 * m);
}

CctDuv ColourFidelityCct(const Spectrum& light, FidelityMethod method)
{
    const WorkingLight w = OnWorkingGrid(light, method);
    const Eigen::Map<const Eigen::VectorXd> v(w.light.values().data(), Eigen::Index(w.grid->count));
    return ComputeCct(w.grid->weights.topRows<3>() * v);
}

ColourFidelity ComputeColourFidelity(const Spectrum& light, FidelityMethod method)
{
    ColourFidelity out;
    out.method = method;
    const WorkingLight w = OnWorkingGrid(light, method);
    const WorkingGrid& grid = *w.grid;
    if (light.start() > kFirstNm + 1e-9 || light.end() < kLastNm - 1e-9)
    {
        const char* text = "the data cover %.0f–%.0f nm; the rest of 380–780 nm counts as zero";
        out.warnings.push_back(Format(text, light.start(), light.end()));
    }
    if (light.step() > 5.0 + 1e-9)
    {
        const char* text =
            "the data are %g nm apart; CIE 224:2017 asks for 5 nm or finer "
            "(they were interpolated linearly to 1 nm)";
        out.warnings.push_back(Format(text, light.step()));
    }

    const Eigen::VectorXd integrals = Integrate(grid, w.light);
    const CctDuv cct = ComputeCct(integrals.head<3>());
    out.cctK = cct.cctK;
    out.duv = cct.duv;
    out.outsideTolerance = std::abs(cct.duv) > kDuvTolerance;
    if (out.outsideTolerance)
    {
        const char* text =
            "Duv %.4f: the light is more than 0.02 from the Planckian locus, so a "
            "reference of its CCT says little";
        out.warnings.push_back(Format(text, cct.duv));
    }
    const Spectrum reference = ColourFidelityReference(cct.cctK, kFirstNm, grid.step, grid.count);
    out.referenceName = ColourFidelityReferenceName(cct.cctK);

    const std::array<Vec3, CES_COUNT> test = Appearance(integrals);
    const std::array<Vec3, CES_COUNT> ref = Appearance(Integrate(grid, reference));
    std::array<double, CES_COUNT> deltaE{};
    double sum = 0.0;
    for (size_t i = 0; i < CES_COUNT; ++i)
    {
        deltaE[i] = DeltaECam02Ucs(test[i], ref[i]);
        out.rfSample[i] = FidelityOf(deltaE[i]);
        sum += deltaE[i];
    }
    out.rf = FidelityOf(sum / double(CES_COUNT));
    HueBins(test, ref, deltaE, out);
    return out;
}

}  // namespace bandlight
