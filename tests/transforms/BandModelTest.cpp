// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("Matching-function band matrix reproduces the lecture's table", "[transforms][lecture]")
{
    // docs/science.md §1.2 acceptance table (the band model's, from the CIE 1931 5 nm table),
    // four decimals: the band model's rule reproduces it to 1e-4.
    // clang-format off
    const double expected[3][3] = {{0.1666, 0.4250, 0.4084},
                                   {0.0607, 0.7506, 0.1888},
                                   {0.9518, 0.0481, 0.0001}};
    // clang-format on
    const Eigen::MatrixXd m =
        MatchingBandMatrix(BandSet::Lecture(), MatchingSet::XYZ, Observer::CIE1931_2DEG);
    for (int k = 0; k < 3; ++k)
    {
        CHECK(m.row(k).sum() == Approx(1.0).epsilon(1e-14));
        for (int b = 0; b < 3; ++b)
        {
            INFO("row " << k << " band " << b);
            CHECK(m(k, b) == Approx(expected[k][b]).margin(1e-4));
        }
    }
}

TEST_CASE("Illuminant band means reproduce the lecture's table", "[transforms][lecture]")
{
    // docs/science.md §1.2 acceptance table: tolerance 0.001, except A's I_B (0.005).
    struct Row
    {
        const char* name;
        double b, g, r;
    };
    for (const Row& row : {Row{"D65", 1.0000, 0.9747, 0.7880}, Row{"A", 0.2050, 0.5631, 1.0000},
                           Row{"C", 1.0000, 0.9130, 0.7829}, Row{"F2", 0.6008, 1.0000, 0.4746},
                           Row{"F11", 0.7060, 1.0000, 0.8008}})
    {
        INFO(row.name);
        const std::vector<double> v =
            IlluminantBands(BuiltinIlluminant(row.name), BandSet::Lecture());
        CHECK(v[0] == Approx(row.b).margin(std::string(row.name) == "A" ? 0.005 : 0.001));
        CHECK(v[1] == Approx(row.g).margin(0.001));
        CHECK(v[2] == Approx(row.r).margin(0.001));
        CHECK(*std::max_element(v.begin(), v.end()) == 1.0);
    }
}

TEST_CASE("Remittance band means are raw averages in [0, 1]", "[transforms][lecture]")
{
    // TCS01 at 5 nm: the VB samples 400..495 nm average to 0.2300.
    const std::vector<double> o =
        RemittanceBands(TestColourSamples()[0].spectrum, BandSet::Lecture());
    CHECK(o[0] == Approx(0.2300).margin(1e-12));
    for (const NamedSpectrum& s : TestColourSamples())
    {
        for (double v : RemittanceBands(s.spectrum, BandSet::Lecture()))
        {
            CHECK(v >= 0.0);
            CHECK(v <= 1.0);
        }
    }
}

TEST_CASE("Equal energy on an ideal white gives the valence (1, 1, 1)", "[transforms]")
{
    for (MatchingSet set : {MatchingSet::XYZ, MatchingSet::EBU_RGB})
    {
        for (Observer obs : {Observer::CIE1931_2DEG, Observer::CIE1964_10DEG})
        {
            const BandMatrix3 m = BandToColourMatrix(BandSet::Lecture(), set, obs);
            CHECK((m.toColour * Vec3::Ones() - Vec3::Ones()).norm() < 1e-12);
            CHECK((m.toColour * m.fromColour - Mat3::Identity()).norm() < 1e-12);
            CHECK(m.conditionNumber > 1.0);
        }
    }
}

TEST_CASE("EBU RGB band rows have negative entries, as the lecture says", "[transforms]")
{
    const Eigen::MatrixXd m =
        MatchingBandMatrix(BandSet::Lecture(), MatchingSet::EBU_RGB, Observer::CIE1931_2DEG);
    CHECK(m.minCoeff() < 0.0);
    // r̄ is mostly red, ḡ green, b̄ blue.
    CHECK(m(0, 2) > 0.7);
    CHECK(m(1, 1) > 0.9);
    CHECK(m(2, 0) > 1.0);
}

TEST_CASE("The exact band rule integrates the interpolated spectrum", "[transforms]")
{
    // A linear ramp: the exact band mean is its value at the band centre; the
    // lecture's sample rule is the mean of 400..495, i.e. the value at 447.5.
    std::vector<double> v;
    for (int i = 0; i <= 80; ++i)
    {
        v.push_back(380.0 + 5.0 * i);
    }
    const Spectrum ramp(380.0, 5.0, v);
    const std::vector<double> exact = BandMeans(ramp, BandSet::Lecture(), BandRule::EXACT);
    const std::vector<double> lecture = BandMeans(ramp, BandSet::Lecture(), BandRule::SAMPLE_MEAN);
    CHECK(exact[0] == Approx(450.0));
    CHECK(exact[2] == Approx(650.0));
    CHECK(lecture[0] == Approx(447.5));
}

TEST_CASE("Line spectra count in the band that holds them", "[transforms]")
{
    const LineSpectrum lines({{435.8, 1.0}, {546.1, 2.0}, {599.99, 1.0}, {710.0, 5.0}});
    const std::vector<double> m = BandMeans(lines, BandSet::Lecture());
    CHECK(m[0] == Approx(0.01));
    CHECK(m[1] == Approx(0.03));
    CHECK(m[2] == Approx(0.0));
}

TEST_CASE("Band model errors are clear", "[transforms]")
{
    CHECK_THROWS_WITH(IlluminantBands(Spectrum::Constant(380.0, 5.0, 81, 0.0), BandSet::Lecture()),
                      Contains("no power in bands 400,500,600,700"));
    CHECK_THROWS_WITH(BandMeans(BuiltinIlluminant("F2"), BandSet::Parse("300,500,700")),
                      Contains("outside the 380–"));
    CHECK_THROWS_WITH(BandMeans(BuiltinIlluminant("F2"), BandSet::Parse("402,404,700")),
                      Contains("band B1 holds no sample"));
    CHECK_THROWS_WITH(
        BandToColourMatrix(BandSet::Equal(4, 400, 700), MatchingSet::XYZ, Observer::CIE1931_2DEG),
        Contains("needs three bands, got 4"));
    CHECK(ParseBandRule("EXACT") == BandRule::EXACT);
    CHECK_THROWS_AS(ParseBandRule("midpoint"), Exception);
}

TEST_CASE("Narrow bands make the band matrix ill-conditioned", "[transforms]")
{
    const BandMatrix3 good =
        BandToColourMatrix(BandSet::Lecture(), MatchingSet::XYZ, Observer::CIE1931_2DEG);
    // Below 440 nm x̄, ȳ and z̄ are nearly proportional: the columns of the band
    // matrix become nearly dependent (condition ≈ 1.6e4 against ≈ 4.3).
    const BandSet violet = BandSet::Parse("380,400,420,440");
    CHECK(good.conditionNumber == Approx(4.348).margin(0.01));
    CHECK(ConditionNumber(MatchingBandMatrix(violet, MatchingSet::XYZ, Observer::CIE1931_2DEG)) >
          1000.0 * good.conditionNumber);
    // Beyond MAX_BAND_CONDITION the band model refuses the set, naming the number.
    CHECK_THROWS_WITH(BandToColourMatrix(violet, MatchingSet::XYZ, Observer::CIE1931_2DEG),
                      Contains("is ill-conditioned: condition number 1.58e+04 exceeds the limit "
                               "1000"));
}
