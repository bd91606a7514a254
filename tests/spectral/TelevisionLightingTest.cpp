// SPDX-License-Identifier: BSD-3-Clause
// TLCI-2012 and TLMF-2013 (spectral/TelevisionLighting.h) against EBU Tech
// 3355's published tables and colour-science's figures, and the invariants
// every light must keep.
//
// Figures marked "colour-science" come from colour-science's implementation
// (BSD-3-Clause; colour/quality/tlci.py and tests/test_tlci.py at commit
// 5551cb071ac3a1442b9706dcad6af7dbba6c3cff): its docstrings and tests give
// them as its own output, without naming EBU's TLCI application as their
// source. They check this implementation against an independent reading of
// Tech 3355, not against EBU's calculator.
// Covers, through the entry points it calls: spectral/TelevisionLightingReference.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/TelevisionLighting.h"
#include "spectral/detail/TelevisionLightingDetail.h"

using namespace bandlight;
using Catch::Contains;

namespace
{

Spectrum OnTlciGrid(const detail::TlciSamples& s)
{
    return Spectrum(380.0, 5.0, std::vector<double>(s.data(), s.data() + s.size()));
}

struct Lobe
{
    double centre, width, amplitude;
};

/// A sum of Gaussian lobes on [380, 760] at `stepNm`, as colour-science's
/// tests build their LED spectra.
Spectrum Lobes(std::initializer_list<Lobe> lobes, double stepNm = 5.0)
{
    std::vector<double> v;
    for (double l = 380.0; l <= 760.0 + 1e-9; l += stepNm)
    {
        double s = 0.0;
        for (const Lobe& b : lobes)
        {
            s += b.amplitude * std::exp(-0.5 * std::pow((l - b.centre) / b.width, 2.0));
        }
        v.push_back(s);
    }
    return Spectrum(380.0, stepNm, v);
}

/// CIE daylight (CIE 15:2004, the CIE basis) on the TLCI grid, as
/// colour-science's tests make their daylight lights.
Spectrum CieDaylight(double cct)
{
    return Daylight(cct).resampled(380.0, 5.0, 77);
}

/// colour-science's "mixed reference" test light: Planckian 3400 K (Tech 3355
/// eq. 9) blended with CIE daylight 5000 K in proportion to the CCT.
Spectrum Blend(double cct)
{
    const double w = (cct - 3400.0) / 1600.0;
    const Spectrum p = OnTlciGrid(detail::TlciPlanckian(3400.0));
    Spectrum d = CieDaylight(5000.0);
    d *= 100.0 / d(560.0);
    return p * (1.0 - w) + d * w;
}

bool Mentions(const TelevisionLightingScore& s, const std::string& text)
{
    return std::any_of(s.warnings.begin(), s.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("Tech 3355's tables have the sizes and sums it publishes", "[spectral][tlci][published]")
{
    // EBU Tech 3355 Appendix 2 prints the column sums of its locus tables and
    // Appendix 3 those of its daylight vectors (as colour-science's
    // TestDatasetsTLCI2012 quotes them); a row mistyped would show here.
    auto sums = [](const std::vector<detail::TlciLocusEntry>& t)
    {
        double x = 0.0, y = 0.0;
        for (const auto& e : t)
        {
            x += e.x;
            y += e.y;
        }
        return std::make_pair(x, y);
    };
    REQUIRE(detail::TlciPlanckianLocus().size() == 152);
    REQUIRE(detail::TlciDaylightLocus().size() == 104);
    CHECK(sums(detail::TlciPlanckianLocus()).first == Approx(74.357659).margin(5e-7));
    CHECK(sums(detail::TlciPlanckianLocus()).second == Approx(60.180968).margin(5e-7));
    CHECK(sums(detail::TlciDaylightLocus()).first == Approx(31.602241).margin(5e-7));
    CHECK(sums(detail::TlciDaylightLocus()).second == Approx(33.132636).margin(5e-7));
    CHECK(detail::TlciPlanckianLocus()[150].cctK == 4999.0);
    CHECK(detail::TlciDaylightLocus()[1].cctK == 5001.0);
    CHECK(detail::TlciDaylightLocus().back().cctK == 25000.0);

    const auto basisSums = detail::TlciDaylightBasis().colwise().sum();
    CHECK(basisSums[0] == Approx(7140.45).margin(1e-9));
    CHECK(basisSums[1] == Approx(545.05).margin(1e-9));
    CHECK(basisSums[2] == Approx(201.55).margin(1e-9));
    // Tech 3355 Appendix 3 differs from CIE 15's Table T.2 at 385 nm (62.45, not 64.6).
    CHECK(detail::TlciDaylightBasis()(1, 0) == 62.45);

    // Appendix 5: each camera curve sums to 1 (to the six decimals printed).
    for (int c = 0; c < 3; ++c)
    {
        CHECK(detail::TlciCameraSensitivities().col(c).sum() == Approx(1.0).margin(5e-7));
    }

    // Appendix 4: 24 patches; values where Tech 3355 departs from BBC R&D
    // Report 1988/2 (foliage at 725 nm, 0.445 not 0.455; green at 430 nm,
    // 0.054 not 0.064) are Tech 3355's.
    REQUIRE(TelevisionChartPatchNames().size() == 24);
    CHECK(TelevisionChartPatchNames()[3] == "foliage");
    CHECK(TelevisionChartPatchNames()[18] == "white 9.5");
    const auto& chart = detail::TlciChartReflectances();
    CHECK(chart((725 - 380) / 5, 3) == 0.445);
    CHECK(chart((430 - 380) / 5, 13) == 0.054);
    CHECK(chart(0, 0) == 0.054);
    CHECK(chart(76, 18) == 0.898);
}

TEST_CASE("Tech 3355's Planckian and daylight references", "[spectral][tlci]")
{
    // Both are 100 at 560 nm by construction (eq. [9]; S0 = 100, S1 = S2 = 0 there).
    for (double t : {1500.0, 3200.0, 4000.0})
    {
        CHECK(detail::TlciPlanckian(t)[36] == Approx(100.0).epsilon(1e-12));
    }
    for (double t : {5000.0, 6500.0, 20000.0})
    {
        CHECK(detail::TlciDaylight(t)[36] == Approx(100.0).epsilon(1e-12));
    }
    // colour-science (sd_planckian_TLCI2012's docstring): P3200 at 600 nm = 120.81916…
    CHECK(detail::TlciPlanckian(3200.0)[44] == Approx(120.81916).margin(1e-5));
    // colour-science (TestSdDaylightTLCI2012): D6500 at 400 nm = 82.423248.
    CHECK(detail::TlciDaylight(6500.0)[4] == Approx(82.423248).margin(1e-6));
}

TEST_CASE("CCT is found against Tech 3355's own loci", "[spectral][tlci]")
{
    // colour-science (TestUvToCCTTLCI2012): figures of its uv_to_CCT_TLCI2012.
    const detail::TlciLocusMatch warm = detail::FindTlciLocus({0.26, 0.35});
    CHECK(warm.cctK == Approx(2755.437250).margin(1e-6));
    CHECK_FALSE(warm.daylight);
    const detail::TlciLocusMatch cool = detail::FindTlciLocus({0.19, 0.31});
    CHECK(cool.cctK == Approx(7255.262985).margin(1e-6));
    CHECK(cool.daylight);
    // Beyond the tables no normal reaches: the nearest row, 25000 K daylight.
    const detail::TlciLocusMatch far = detail::FindTlciLocus({0.18, 0.20});
    CHECK(far.cctK == 25000.0);
    CHECK(far.daylight);
    CHECK_FALSE(far.onNormal);
    // The first daylight row is found as itself, not on the Planckian table.
    const auto& d5000 = detail::TlciDaylightLocus().front();
    const double den = -2.0 * d5000.x + 12.0 * d5000.y + 3.0;
    const detail::TlciLocusMatch first =
        detail::FindTlciLocus({4.0 * d5000.x / den, 6.0 * d5000.y / den});
    CHECK(first.cctK == Approx(5000.0).margin(1e-9));
    CHECK(first.daylight);

    // colour-science (TestSdReferenceIlluminantTLCI2012): CIE A is 2848.132209 K
    // and D65 6505.096585 K by this method; both within 0.015 of the locus.
    const TelevisionLightingScore a = ComputeTlci(BuiltinIlluminant("A"));
    CHECK(a.cctK == Approx(2848.132209).margin(1e-6));
    CHECK(std::abs(a.d) < 1.5e-2);
    CHECK(a.referenceName.find("Planckian 2848 K") == 0);
    const TelevisionLightingScore d65 = ComputeTlci(BuiltinIlluminant("D65"));
    CHECK(d65.cctK == Approx(6505.096585).margin(1e-6));
    CHECK(std::abs(d65.d) < 1.5e-2);
    CHECK(d65.referenceName.find("daylight 6505 K") == 0);
}

TEST_CASE("Qa is 50 at the watershed ΔEa = 3.16", "[spectral][tlci]")
{
    // Tech 3355 §1.5.1, eq. [59]: 3.16 is the ΔEa that scores 50.
    const detail::TlciQuality q = detail::TlciQualityOf({3.16, NAN});
    CHECK(q.deltaEa == Approx(3.16).epsilon(1e-12));
    CHECK(q.qa == Approx(50.0).epsilon(1e-12));
    CHECK(detail::TlciQualityOf({1.0, 2.0}).deltaEa == Approx(std::pow(8.5, 0.25)));
    CHECK_THROWS_WITH(detail::TlciQualityOf({NAN, NAN}), Contains("every patch was excluded"));
}

TEST_CASE("TLCI and TLMF of CIE F2 match colour-science", "[spectral][tlci]")
{
    // colour-science: television_lighting_consistency_index(FL2) =
    // 29.492541753138433 and television_luminaire_matching_factor(FL2, D65) =
    // 5.376079603398939 (its tests, to 1e-7). bandlight's F2 and D65 are
    // CIE 15's tables, as colour-science's are (F2 stored in units of 1/100);
    // the two agree to 1e-13.
    const TelevisionLightingScore tlci = ComputeTlci(BuiltinIlluminant("F2"));
    CHECK(tlci.qa == Approx(29.492541753138433).margin(1e-9));
    CHECK(tlci.deltaE.size() == 18);
    CHECK(tlci.referenceName.find("blend for") == 0);  // F2 is 4230 K: the 3400–5000 K blend
    const TelevisionLightingScore tlmf =
        ComputeTlmf(BuiltinIlluminant("F2"), BuiltinIlluminant("D65"), "D65");
    CHECK(tlmf.qa == Approx(5.376079603398939).margin(1e-9));
    CHECK(tlmf.deltaE.size() == 24);
    CHECK(tlmf.referenceName == "D65");
}

TEST_CASE("A light that is its own reference scores 100", "[spectral][tlci]")
{
    // Through Tech 3355's own formulas the reference is the light itself, up
    // to the CCT the Appendix 2 tables give back (a fraction of a kelvin).
    const TelevisionLightingScore p = ComputeTlci(OnTlciGrid(detail::TlciPlanckian(3000.0)));
    CHECK(p.cctK == Approx(3000.0).margin(1.0));
    CHECK(p.qa == Approx(100.0).margin(1e-4));
    CHECK(std::abs(p.d) < 0.01);
    CHECK(p.warnings.empty());
    const TelevisionLightingScore d = ComputeTlci(OnTlciGrid(detail::TlciDaylight(6500.0)));
    CHECK(d.cctK == Approx(6500.0).margin(1.0));
    CHECK(d.qa == Approx(100.0).margin(1e-4));
    // colour-science (TestTelevisionLightingConsistencyIndex): CIE A and D65
    // score 100 to 5e-4.
    CHECK(ComputeTlci(BuiltinIlluminant("A")).qa == Approx(100.0).margin(5e-4));
    CHECK(ComputeTlci(BuiltinIlluminant("D65")).qa == Approx(100.0).margin(5e-4));
}

TEST_CASE("TLMF of a light against itself is 100", "[spectral][tlci]")
{
    for (const Spectrum& s : {BuiltinIlluminant("F2"), BuiltinIlluminant("D65"),
                              Lobes({{450, 10, 1.0}, {545, 75, 0.82}, {610, 35, 0.22}}, 1.0)})
    {
        const TelevisionLightingScore m = ComputeTlmf(s, s);
        CHECK(m.qa == Approx(100.0).margin(1e-9));
        CHECK(m.deltaEa < 1e-6);
    }
}

TEST_CASE("Scores do not depend on the light's scale", "[spectral][tlci]")
{
    const Spectrum led = Lobes({{455, 12, 0.85}, {600, 80, 1.0}, {630, 25, 0.18}});
    const Spectrum f2 = BuiltinIlluminant("F2");
    for (double k : {1e-3, 1000.0})
    {
        const TelevisionLightingScore a = ComputeTlci(led), b = ComputeTlci(led * k);
        CHECK(b.qa == Approx(a.qa).epsilon(1e-12));
        CHECK(b.cctK == Approx(a.cctK).epsilon(1e-12));
        CHECK(b.d == Approx(a.d).epsilon(1e-9));
        CHECK(ComputeTlmf(led * k, f2 * (1.0 / k)).qa ==
              Approx(ComputeTlmf(led, f2).qa).epsilon(1e-12));
    }
}

TEST_CASE("colour-science's generated lights score as there", "[spectral][tlci]")
{
    // colour-science (test_television_lighting_consistency_index_regression_spectra
    // and its TLMF twin): generated spectra and the scores its implementation
    // gives, rounded, checked there to ±0.5. Its daylight lights use the CIE
    // basis (sd_CIE_illuminant_D_series), as Daylight() does.
    const Spectrum warm = Lobes({{455, 12, 0.85}, {600, 80, 1.0}, {630, 25, 0.18}});
    const Spectrum cool = Lobes({{450, 10, 1.0}, {545, 75, 0.82}, {610, 35, 0.22}});
    const Spectrum rgb = Lobes({{455, 14, 0.72}, {535, 18, 1.0}, {625, 18, 0.86}});
    const Spectrum p3000 = OnTlciGrid(detail::TlciPlanckian(3000.0));
    const Spectrum p3400 = OnTlciGrid(detail::TlciPlanckian(3400.0));
    const std::pair<Spectrum, double> tlci[] = {{p3000, 100.0},
                                                {OnTlciGrid(detail::TlciPlanckian(4000.0)), 100.0},
                                                {CieDaylight(5600.0), 100.0},
                                                {Blend(4500.0), 100.0},
                                                {warm, 88.0},
                                                {cool, 77.0},
                                                {rgb, 58.0}};
    for (const auto& [light, qa] : tlci)
    {
        CHECK(ComputeTlci(light).qa == Approx(qa).margin(0.5));
    }
    const TelevisionLightingScore blend = ComputeTlci(Blend(4500.0));
    CHECK(blend.cctK > 4000.0);
    CHECK(blend.cctK < 5000.0);
    CHECK(std::abs(ComputeTlci(OnTlciGrid(detail::TlciPlanckian(4000.0))).d) < 2e-2);

    const std::tuple<Spectrum, Spectrum, double> tlmf[] = {
        {warm, p3000, 3.5},
        {cool, CieDaylight(5600.0), 61.0},
        {rgb, CieDaylight(5600.0), 4.0},
        {Blend(4000.0), p3400, 18.0},
        {Blend(4990.0), CieDaylight(5000.0), 100.0}};
    for (const auto& [test, reference, qa] : tlmf)
    {
        CHECK(ComputeTlmf(test, reference).qa == Approx(qa).margin(0.5));
    }
}

TEST_CASE("d is negative towards green, positive towards magenta, widened at 4000-5000 K",
          "[spectral][tlci]")
{
    // Tech 3355 §1.1.1 and eqs. [16]-[17] (colour-science's sign test).
    const Spectrum d65 = BuiltinIlluminant("D65").resampled(380.0, 5.0, 77);
    const double peak = d65.maxValue();
    CHECK(ComputeTlci(d65 + Lobes({{545, 20, 0.2 * peak}})).d < -0.5);
    CHECK(ComputeTlci(d65 + Lobes({{450, 15, 0.1 * peak}, {650, 20, 0.1 * peak}})).d > 0.5);

    // Eqs. [16]-[17] as colour-science reads them: |d| grows by
    // 0.9 (5000 - CCT) / 1000 on the magenta side and by 0.9 (CCT - 4000) /
    // 1000 on the green side; at 4500 K both add 0.45.
    detail::TlciLocusMatch m;
    m.cctK = 4500.0;
    m.uv = {0.22, 0.33};
    m.tangent = Eigen::Vector2d(-0.6, -0.8);  // towards higher CCT: u and v fall
    const Eigen::Vector2d below(0.8, -0.6);   // magenta
    CHECK(detail::TlciDistance(m.uv + 0.0054 * below, m) == Approx(1.45).epsilon(1e-12));
    CHECK(detail::TlciDistance(m.uv - 0.0054 * below, m) == Approx(-1.45).epsilon(1e-12));
    m.cctK = 3999.0;
    CHECK(detail::TlciDistance(m.uv + 0.0054 * below, m) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("Hard lights give finite scores, or say why there is none", "[spectral][tlci]")
{
    auto finite = [](const TelevisionLightingScore& s)
    { return std::isfinite(s.qa) && s.qa >= 0.0 && s.qa <= 100.0 && std::isfinite(s.d); };

    // A monochromatic line at 552 nm sampled every 1 nm: its power lands on
    // the 5 nm grid; far from any locus, so warned about.
    std::vector<double> line(401, 0.0);
    line[552 - 380] = 1.0;
    const TelevisionLightingScore mono = ComputeTlci(Spectrum(380.0, 1.0, line));
    CHECK(finite(mono));
    CHECK(mono.qa < 50.0);
    CHECK(Mentions(mono, "far from the locus"));

    // No output below 500 nm (blue channel still sees 500–520 nm).
    Spectrum cut = OnTlciGrid(detail::TlciPlanckian(3000.0));
    for (size_t i = 0; i < 24; ++i)
    {
        cut.values()[i] = 0.0;
    }
    const TelevisionLightingScore noBlue = ComputeTlci(cut);
    CHECK(finite(noBlue));
    CHECK(noBlue.qa < 100.0);

    // Every 20 nm: interpolated, with a warning; a smooth light still scores ~100.
    std::vector<double> coarse;
    for (double l = 380.0; l <= 760.0; l += 20.0)
    {
        coarse.push_back(detail::TlciPlanckian(3000.0)[int((l - 380.0) / 5.0)]);
    }
    const TelevisionLightingScore twenty = ComputeTlci(Spectrum(380.0, 20.0, coarse));
    CHECK(finite(twenty));
    CHECK(twenty.qa > 99.0);
    CHECK(Mentions(twenty, "coarser than EBU Tech 3355's 5 nm"));

    // Data that stop at 700 nm: zero beyond, said so.
    const TelevisionLightingScore shortData =
        ComputeTlci(OnTlciGrid(detail::TlciPlanckian(3000.0)).resampled(400.0, 5.0, 61));
    CHECK(finite(shortData));
    CHECK(Mentions(shortData, "400–700 nm"));

    // Far off the locus (a strong green hump): scored, with |d| > 1 flagged.
    const TelevisionLightingScore greenish =
        ComputeTlci(OnTlciGrid(detail::TlciPlanckian(4000.0)) + Lobes({{530, 25, 150.0}}));
    CHECK(finite(greenish));
    CHECK(greenish.d < -1.0);
    CHECK(Mentions(greenish, "far from the locus"));

    // A red line: the camera's green and blue see nothing, no balance exists.
    std::vector<double> red(401, 0.0);
    red[680 - 380] = 1.0;
    CHECK_THROWS_WITH(ComputeTlci(Spectrum(380.0, 1.0, red)),
                      Contains("cannot be white-balanced") && Contains("green"));
    CHECK_THROWS_WITH(ComputeTlci(Spectrum::Constant(380.0, 5.0, 77, 0.0)),
                      Contains("no luminance"));
    CHECK_THROWS_WITH(ComputeTlci(Spectrum(380.0, 5.0, {1.0, NAN, 1.0})), Contains("not finite"));
    CHECK_THROWS_WITH(ComputeTlmf(BuiltinIlluminant("D65"), Spectrum(380.0, 1.0, red)),
                      Contains("cannot be white-balanced"));
    // As a TLMF test light it is seen through the reference's balance: scored.
    const TelevisionLightingScore redTest =
        ComputeTlmf(Spectrum(380.0, 1.0, red), BuiltinIlluminant("D65"));
    CHECK(finite(redTest));
    CHECK(redTest.qa < 1.0);
}

TEST_CASE("A light on a finer grid is measured through a 5 nm bandpass", "[spectral][tlci]")
{
    // Independently of TlciGridLight: each 5 nm sample is the light's
    // interpolant weighted by a triangle of ±5 nm, integrated by the
    // trapezoid rule every 0.01 nm; the score of those samples is the score
    // of the 1 nm light.
    const Spectrum rgb1 = Lobes({{455, 14, 0.72}, {535, 18, 1.0}, {625, 18, 0.86}}, 1.0);
    std::vector<double> measured;
    for (int i = 0; i < 77; ++i)
    {
        const double c = 380.0 + 5.0 * i;
        double sum = 0.0;
        for (int k = -500; k <= 500; ++k)
        {
            const double l = c + 0.01 * k;
            sum += (std::abs(k) == 500 ? 0.5 : 1.0) * rgb1(l) * (1.0 - std::abs(l - c) / 5.0);
        }
        measured.push_back(sum * 0.01 / 5.0);
    }
    const TelevisionLightingScore direct = ComputeTlci(rgb1);
    CHECK(direct.qa == Approx(ComputeTlci(Spectrum(380.0, 5.0, measured)).qa).margin(1e-4));
    // Resampled onto the 5 nm grid first, the 1 nm light scores as its 5 nm twin.
    const Spectrum rgb5 = Lobes({{455, 14, 0.72}, {535, 18, 1.0}, {625, 18, 0.86}}, 5.0);
    CHECK(ComputeTlci(rgb1.resampled(380.0, 5.0, 77)).qa ==
          Approx(ComputeTlci(rgb5).qa).epsilon(1e-12));
    // For a phosphor white the bandpass hardly matters.
    const Spectrum warm1 = Lobes({{455, 12, 0.85}, {600, 80, 1.0}, {630, 25, 0.18}}, 1.0);
    const Spectrum warm5 = Lobes({{455, 12, 0.85}, {600, 80, 1.0}, {630, 25, 0.18}}, 5.0);
    CHECK(ComputeTlci(warm1).qa == Approx(ComputeTlci(warm5).qa).margin(0.1));
    CHECK(ComputeTlci(warm1).cctK == Approx(ComputeTlci(warm5).cctK).margin(1.0));
}

TEST_CASE("A hundred lights score in well under two seconds", "[spectral][tlci]")
{
    std::vector<Spectrum> lights;
    for (int i = 0; i < 100; ++i)
    {
        lights.push_back(
            Lobes({{440.0 + i * 0.3, 12, 1.0}, {560.0 + i, 70, 1.2}}, i % 2 ? 1.0 : 5.0));
    }
    ComputeTlci(lights[0]);  // tables loaded once, outside the timing
    const auto start = std::chrono::steady_clock::now();
    double sum = 0.0;
    for (const Spectrum& s : lights)
    {
        sum += ComputeTlci(s).qa + ComputeTlmf(s, lights[0]).qa;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(std::isfinite(sum));
    CHECK(seconds < 2.0);
}
