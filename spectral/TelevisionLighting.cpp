// SPDX-License-Identifier: BSD-3-Clause
// TLCI-2012 and TLMF-2013 (EBU Tech 3355): the camera, the display and the
// score. The light's side (CCT, reference) is TelevisionLightingReference.cpp.
#include "spectral/TelevisionLighting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/detail/TelevisionLightingDetail.h"

namespace bandlight
{

namespace
{

using detail::TLCI_SAMPLES;
using detail::TLCI_START_NM;
using detail::TLCI_STEP_NM;
using detail::TlciSamples;

constexpr int PATCHES = 24;
constexpr int TLCI_PATCHES = 18;  // the coloured ones: TLCI leaves the greys out (§1.5.1)
constexpr int CAMERA_ROWS = 3 * PATCHES + 3;

/// The flat reflector the camera is white-balanced on (Tech 3355 §1.3.1):
/// 90 %, so that the chart's white patch (about 0.9) makes peak white.
constexpr double BALANCE_REFLECTANCE = 0.9;

/// Tech 3355 §2, eq. [61]: camera signals map to 8-bit studio codes as
/// 16 + 219 E'; above nominal white they are kept up to code 255.
constexpr double SIGNAL_CEILING = (255.0 - 16.0) / (235.0 - 16.0);

/// Tech 3355 §1.3.2: the saturation control at S = 90 %.
constexpr double SATURATION = 0.90;

/// Tech 3355 §1.4.1: the display's gamma.
constexpr double DISPLAY_GAMMA = 2.4;

/// Tech 3355 Appendix 5 (eqs. [20]–[22]): the standard camera's linear
/// matrix, applied to white-balanced R, G, B. Each row sums to 1: greys stay grey.
const Mat3& CameraMatrix()
{
    // clang-format off
    static const Mat3 m = (Mat3() << 1.182, -0.209, 0.027,
                                     0.107,  0.890, 0.003,
                                     0.040, -0.134, 1.094).finished();
    // clang-format on
    return m;
}

/// Tech 3355 eqs. [23]–[25]: S on the diagonal plus (1 − S) / 3 everywhere.
const Mat3& SaturationMatrix()
{
    static const Mat3 m = SATURATION * Mat3::Identity() + Mat3::Constant((1.0 - SATURATION) / 3.0);
    return m;
}

/// The display of Tech 3355 §1.4.2: its RGB → XYZ matrix as eq. [29] prints
/// it (BT.709 primaries, D65), and the white CIELAB is relative to, D65 of
/// Table 1 (x = 0.3127, y = 0.3290) at Y = 1. The printed matrix, not one
/// derived from the primaries, is the standard's definition: derived, it
/// moves F2's TLCI by 6e-6.
struct Display
{
    Mat3 toXyz;
    Vec3 white;
};

const Display& GetDisplay()
{
    static const Display d = []
    {
        // clang-format off
        const Mat3 m = (Mat3() << 0.412391, 0.357584, 0.180481,
                                  0.212639, 0.715169, 0.072192,
                                  0.019331, 0.119195, 0.950532).finished();
        // clang-format on
        return Display{m, WhiteXyz(0.3127, 0.3290)};
    }();
    return d;
}

/// Rows 3j..3j+2: r̄, ḡ, b̄ times patch j's reflectance; the last three rows:
/// r̄, ḡ, b̄ times the balance reflector. Computed once, so that what the
/// camera sees of the whole chart under a light is one matrix product.
const Eigen::MatrixXd& CameraChartWeights()
{
    static const Eigen::MatrixXd w = []
    {
        const auto& camera = detail::TlciCameraSensitivities();
        const auto& chart = detail::TlciChartReflectances();
        Eigen::MatrixXd m(CAMERA_ROWS, TLCI_SAMPLES);
        for (int j = 0; j < PATCHES; ++j)
        {
            for (int c = 0; c < 3; ++c)
            {
                m.row(3 * j + c) = camera.col(c).cwiseProduct(chart.col(j)).transpose();
            }
        }
        m.bottomRows(3) = BALANCE_REFLECTANCE * camera.transpose();
        return m;
    }();
    return w;
}

/// CIE 1931 x̄, ȳ, z̄ on the TLCI grid (rows), for the light's chromaticity (§1.1.1).
const Eigen::Matrix<double, 3, TLCI_SAMPLES>& MatchingFunctionsOnGrid()
{
    static const Eigen::Matrix<double, 3, TLCI_SAMPLES> m = []
    {
        const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
        Eigen::Matrix<double, 3, TLCI_SAMPLES> out;
        for (int i = 0; i < TLCI_SAMPLES; ++i)
        {
            const double l = TLCI_START_NM + TLCI_STEP_NM * i;
            out.col(i) = Vec3(cmf.x(l), cmf.y(l), cmf.z(l));
        }
        return out;
    }();
    return m;
}

/// The camera's raw signals under one light: each patch (columns) and the
/// balance reflector.
struct CameraSignals
{
    Eigen::Matrix<double, 3, PATCHES> patches;
    Vec3 white;
};

CameraSignals SeeChart(const TlciSamples& light)
{
    const Eigen::VectorXd s = CameraChartWeights() * light;
    CameraSignals out;
    for (int j = 0; j < PATCHES; ++j)
    {
        out.patches.col(j) = s.segment<3>(3 * j);
    }
    out.white = s.tail<3>();
    return out;
}

/// Throws when the camera cannot be white-balanced on a light: a channel
/// sees none of it.
void RequireBalance(const CameraSignals& s, const char* which)
{
    if (!(s.white.minCoeff() > 0.0))
    {
        static const char* channel[3] = {"red", "green", "blue"};
        int c = 0;
        s.white.minCoeff(&c);
        throw Exception(std::string("TLCI/TLMF: the standard camera's ") + channel[c] +
                        " channel sees nothing of " + which +
                        ", so it cannot be white-balanced on it (EBU Tech 3355 §1.3.1)");
    }
}

/// BT.709 OETF (Tech 3355 §1.3.3, eq. [26]) on a signal clipped at 0 below
/// and at code 255 above.
double Oetf(double l) noexcept
{
    l = std::max(l, 0.0);
    const double v = l < 0.018 ? 4.5 * l : 1.099 * std::pow(l, 0.45) - 0.099;
    return std::min(v, SIGNAL_CEILING);
}

/// CIELAB on the display of a white-balanced camera signal; `clipped` is set
/// when a matrixed signal went negative (the patch leaves the score, §1.5.1).
Vec3 DisplayedLab(const Vec3& balanced, bool& clipped)
{
    const Vec3 matrixed = CameraMatrix() * balanced;
    const Vec3 saturated = SaturationMatrix() * matrixed;
    clipped = matrixed.minCoeff() < 0.0 || saturated.minCoeff() < 0.0;
    Vec3 shown;
    for (int c = 0; c < 3; ++c)
    {
        shown[c] = std::pow(Oetf(saturated[c]), DISPLAY_GAMMA);
    }
    const Display& d = GetDisplay();
    return XyzToLab(d.toXyz * shown, d.white);
}

/// Scores balanced test signals against balanced reference signals over the
/// first `patches` patches.
TelevisionLightingScore Score(const Eigen::Matrix<double, 3, PATCHES>& test,
                              const Eigen::Matrix<double, 3, PATCHES>& reference, int patches,
                              std::vector<std::string> warnings)
{
    TelevisionLightingScore out;
    std::string excluded;
    for (int j = 0; j < patches; ++j)
    {
        bool clippedTest = false, clippedRef = false;
        const Vec3 labTest = DisplayedLab(test.col(j), clippedTest);
        const Vec3 labRef = DisplayedLab(reference.col(j), clippedRef);
        if (clippedTest || clippedRef)
        {
            out.deltaE.push_back(NAN);
            excluded += (excluded.empty() ? "" : ", ") + std::to_string(j + 1) + " (" +
                        detail::TlciChartNames()[size_t(j)] + ")";
            continue;
        }
        out.deltaE.push_back(DeltaE2000(labTest, labRef));
    }
    if (!excluded.empty())
    {
        warnings.push_back(
            "patches left out of the score, a camera signal having gone negative "
            "(EBU Tech 3355 §1.5.1): " +
            excluded);
    }
    const detail::TlciQuality q = detail::TlciQualityOf(out.deltaE);
    out.qa = q.qa;
    out.deltaEa = q.deltaEa;
    out.warnings = std::move(warnings);
    return out;
}

std::string Fixed2(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", v);
    return text;
}

/// CCT and d of a light on the TLCI grid.
struct LightOnLocus
{
    detail::TlciLocusMatch match;
    double d = 0.0;
};

LightOnLocus Locate(const TlciSamples& light, const char* which)
{
    const Vec3 xyz = MatchingFunctionsOnGrid() * light;
    if (!(xyz.x() + 15.0 * xyz.y() + 3.0 * xyz.z() > 0.0) || !(xyz.y() > 0.0))
    {
        throw Exception(std::string("TLCI/TLMF: ") + which +
                        " has no luminance over 380–760 nm, so no chromaticity");
    }
    const Eigen::Vector2d uv = XyzToUv1960(xyz);
    LightOnLocus out;
    out.match = detail::FindTlciLocus(uv);
    out.d = detail::TlciDistance(uv, out.match);
    return out;
}

Eigen::Matrix<double, 3, PATCHES> Balanced(const CameraSignals& s, const Vec3& white)
{
    return (s.patches.array().colwise() / white.array()).matrix();
}

}  // namespace

TelevisionLightingScore ComputeTlci(const Spectrum& light)
{
    std::vector<std::string> warnings;
    const TlciSamples samples = detail::TlciGridLight(light, warnings);
    const LightOnLocus where = Locate(samples, "the light");
    if (!where.match.onNormal)
    {
        warnings.push_back(
            "no normal from EBU Tech 3355's loci reaches the light's chromaticity: "
            "the nearest tabulated point, " +
            std::to_string(std::lround(where.match.cctK)) + " K, was taken");
    }
    if (std::abs(where.d) > 1.0)
    {
        warnings.push_back("the light is far from the locus (d = " + Fixed2(where.d) +
                           ", beyond ±1, EBU Tech 3355 §1.1.1): its CCT, and so TLCI's "
                           "reference, are uncertain");
    }
    const detail::TlciReference reference = detail::TlciReferenceLight(where.match);
    const CameraSignals test = SeeChart(samples);
    const CameraSignals ref = SeeChart(reference.spd);
    RequireBalance(test, "the light");
    RequireBalance(ref, "the reference");
    // TLCI balances the camera on each light (§1.3.1).
    TelevisionLightingScore out = Score(Balanced(test, test.white), Balanced(ref, ref.white),
                                        TLCI_PATCHES, std::move(warnings));
    out.cctK = where.match.cctK;
    out.d = where.d;
    out.referenceName = reference.name;
    return out;
}

TelevisionLightingScore ComputeTlmf(const Spectrum& test, const Spectrum& reference,
                                    const std::string& referenceName)
{
    std::vector<std::string> testNotes, referenceNotes, warnings;
    const TlciSamples testSamples = detail::TlciGridLight(test, testNotes);
    const TlciSamples refSamples = detail::TlciGridLight(reference, referenceNotes);
    for (const std::string& n : testNotes)
    {
        warnings.push_back("test light: " + n);
    }
    for (const std::string& n : referenceNotes)
    {
        warnings.push_back(referenceName + ": " + n);
    }
    const LightOnLocus where = Locate(testSamples, "the test light");
    const CameraSignals t = SeeChart(testSamples);
    const CameraSignals r = SeeChart(refSamples);
    // Balanced on the reference; the test light seen through that balance
    // (it need not be balanceable itself), its exposure matched by the luma
    // of the balance reflector (§1.3.1).
    RequireBalance(r, "the reference light");
    const Vec3 testWhite = (t.white.array() / r.white.array()).matrix();
    const double luma = GetDisplay().toXyz.row(1).dot(CameraMatrix() * testWhite);
    if (!(luma > 0.0))
    {
        throw Exception("TLMF: the test light gives no luma through the reference's balance");
    }
    TelevisionLightingScore out =
        Score(Balanced(t, r.white) / luma, Balanced(r, r.white), PATCHES, std::move(warnings));
    out.cctK = where.match.cctK;
    out.d = where.d;
    out.referenceName = referenceName;
    return out;
}

const std::vector<std::string>& TelevisionChartPatchNames()
{
    return detail::TlciChartNames();
}

}  // namespace bandlight
