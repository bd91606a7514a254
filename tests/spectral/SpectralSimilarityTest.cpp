// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/SpectralSimilarity.h"
#include "spectral/SpectrumIO.h"

using namespace bandlight;

namespace
{

Spectrum Hmi()
{
    return ReadSpectraFile(std::string(BANDLIGHT_TEST_DATA) + "/ssi_hmi_1nm.csv").at(0).spectrum;
}

Spectrum Line(double centreNm, double fwhmNm)
{
    std::vector<double> v(501);
    const double sigma = fwhmNm / (2.0 * std::sqrt(2.0 * std::log(2.0)));
    for (size_t i = 0; i < v.size(); ++i)
    {
        const double d = (300.0 + double(i) - centreNm) / sigma;
        v[i] = std::exp(-0.5 * d * d);
    }
    return Spectrum(300.0, 1.0, std::move(v));
}

}  // namespace

TEST_CASE("SSI of colour-science's worked examples", "[spectral][ssi]")
{
    // colour-science's test_ssi.py and documentation: CIE C against D65 is
    // 94 (94.182 unrounded), its HMI spectrum against D50 is 72 (71.775).
    // These are colour-science's figures, not the Academy's: no published
    // SSI of a tabulated light was at hand. colour-science's C starts at
    // 300 nm; ours (colord-data's) at 380 nm, held at its 380 nm value over
    // 375–380 nm (CIE 15:2004 §7.2.1), which gives 94.203 against 94.182
    // (counted as zero there it would be 93.958). Its D50 comes from the daylight
    // basis at 300–830 nm, as Daylight() makes it; with it the unrounded
    // figure agrees to 0.001.
    CHECK(ComputeSsi(BuiltinIlluminant("C"), BuiltinIlluminant("D65")) == 94.0);
    const SpectralSimilarity c =
        ComputeSpectralSimilarity(BuiltinIlluminant("C"), BuiltinIlluminant("D65"), "D65");
    CHECK(c.unrounded == Approx(94.182).margin(0.025));
    CHECK(c.referenceName == "D65");
    CHECK(c.warnings.empty());
    // Data that stop 10 nm or more short are not held: counted as zero, and said.
    const SpectralSimilarity shortData = ComputeSpectralSimilarity(
        BuiltinIlluminant("D65").resampled(400.0, 5.0, 61), BuiltinIlluminant("D65"), "D65");
    CHECK(shortData.unrounded < 99.0);
    CHECK_THAT(shortData.warnings.at(0), Catch::Contains("400–700 nm"));
    const Spectrum d50 = Daylight(DaylightNominalCct(50.0));
    const SpectralSimilarity hmi = ComputeSpectralSimilarity(Hmi(), d50);
    CHECK(hmi.ssi == 72.0);
    CHECK(hmi.unrounded == Approx(71.775).margin(0.001));
    CHECK(hmi.warnings.empty());
    CHECK(ComputeSsi(Hmi(), BuiltinIlluminant("D50")) == 72.0);
}

TEST_CASE("SSI of a light against itself is 100, at any scale", "[spectral][ssi]")
{
    for (const Spectrum& s : {BuiltinIlluminant("F2"), BuiltinIlluminant("D65"), Hmi(),
                              Planckian(3200.0, 360.0, 1.0, 471)})
    {
        CHECK(ComputeSpectralSimilarity(s, s).unrounded == Approx(100.0).epsilon(1e-14));
        CHECK(ComputeSpectralSimilarity(s * 1000.0, s).unrounded == Approx(100.0).epsilon(1e-13));
        CHECK(ComputeSpectralSimilarity(s * 1e-9, s * 7.0).unrounded ==
              Approx(100.0).epsilon(1e-13));
    }
    const SpectralSimilarity a = ComputeSpectralSimilarity(BuiltinIlluminant("F11"));
    const SpectralSimilarity b = ComputeSpectralSimilarity(BuiltinIlluminant("F11") * 1e4);
    CHECK(a.unrounded == Approx(b.unrounded).epsilon(1e-12));
}

TEST_CASE("The default SSI reference follows the light's CCT", "[spectral][ssi]")
{
    // Academy S-2018-001: a Planckian radiator up to 4000 K, CIE daylight
    // from 5000 K, blended between. CIE A is a Planckian radiator (2856 K on
    // today's c2, CIE 15:2004 §3.1), D65 is the daylight of its CCT: both
    // score 100 to the rounding of their 5 nm tables.
    const SpectralSimilarity a = ComputeSpectralSimilarity(BuiltinIlluminant("A"));
    CHECK(a.cctK == Approx(2856.0).margin(1.0));
    CHECK_THAT(a.referenceName, Catch::StartsWith("Planckian 285"));
    CHECK(a.ssi == 100.0);
    const SpectralSimilarity d65 = ComputeSpectralSimilarity(BuiltinIlluminant("D65"));
    CHECK_THAT(d65.referenceName, Catch::StartsWith("CIE daylight 650"));
    CHECK(d65.ssi == 100.0);

    // The rule's three parts, each against its definition written out here:
    // shapes compared as ratios to 560 nm (SSI is blind to scale).
    const auto shape = [](const Spectrum& s, double nm) { return s(nm) / s(560.0); };
    const Spectrum p = SsiReference(4000.0);
    CHECK(p.start() == 375.0);
    CHECK(p.size() == 301);
    const Spectrum planck = Planckian(4000.0, 375.0, 1.0, 406);
    for (double nm : {375.0, 450.0, 675.0})
    {
        CHECK(shape(p, nm) == Approx(shape(planck, nm)).epsilon(1e-12));
    }
    const Spectrum d = SsiReference(5000.0);
    for (double nm : {375.0, 450.0, 675.0})
    {
        CHECK(shape(d, nm) == Approx(shape(Daylight(5000.0), nm)).epsilon(1e-12));
    }
    // 4250 K: a quarter of the way from 4000 K, so 3/4 Planckian and 1/4
    // daylight, each first brought to the same luminance (CIE 1931 Y over
    // 375–780 nm).
    const Spectrum b = SsiReference(4250.0);
    const Spectrum p4250 = Planckian(4250.0, 375.0, 1.0, 406);
    const Spectrum d4250 = Daylight(4250.0).resampled(375.0, 1.0, 406);
    const double yp = IntegrateXyz(p4250, Observer::CIE1931_2DEG).y();
    const double yd = IntegrateXyz(d4250, Observer::CIE1931_2DEG).y();
    const auto mix = [&](double nm) { return 0.75 * p4250(nm) / yp + 0.25 * d4250(nm) / yd; };
    for (double nm : {375.0, 420.0, 500.0, 600.0, 675.0})
    {
        CHECK(b(nm) / b(560.0) == Approx(mix(nm) / mix(560.0)).epsilon(1e-9));
    }
    // Neither end: the blend differs from both by more than rounding.
    CHECK(ComputeSpectralSimilarity(b, p4250).unrounded < 99.9);
    CHECK(ComputeSpectralSimilarity(b, d4250).unrounded < 99.9);
    CHECK(SsiReferenceName(3999.4) == "Planckian 3999 K");
    CHECK(SsiReferenceName(4250.0) == "blend at 4250 K: 75 % Planckian, 25 % CIE daylight");
    CHECK(SsiReferenceName(5600.0) == "CIE daylight 5600 K");
    CHECK_THROWS_WITH(SsiReference(30000.0), Catch::Contains("1000–25000 K"));
}

TEST_CASE("SSI stays finite for hard lights and refuses dark ones", "[spectral][ssi]")
{
    // A narrow line at 555 nm against daylight: all power in one band.
    const SpectralSimilarity line = ComputeSpectralSimilarity(Line(555.0, 2.0), Daylight(5600.0));
    CHECK(std::isfinite(line.unrounded));
    CHECK(line.ssi < 0.0);
    // Zero output below 450 nm, and data at 20 nm.
    Spectrum cut = Planckian(3200.0, 360.0, 5.0, 95);
    for (size_t i = 0; i < cut.size(); ++i)
    {
        if (cut.wavelength(i) < 450.0)
        {
            cut.values()[i] = 0.0;
        }
    }
    const double cutSsi = ComputeSpectralSimilarity(cut).unrounded;
    CHECK(std::isfinite(cutSsi));
    CHECK(cutSsi < 90.0);
    CHECK(ComputeSpectralSimilarity(Planckian(3200.0, 360.0, 20.0, 24)).ssi == 100.0);
    // Nothing in 375–675 nm: no SSI.
    CHECK_THROWS_WITH(ComputeSpectralSimilarity(Line(760.0, 2.0), Daylight(5600.0)),
                      Catch::Contains("375–675 nm"));
    CHECK_THROWS_WITH(ComputeSsi(Daylight(5600.0), Line(760.0, 2.0)), Catch::Contains("reference"));
}
