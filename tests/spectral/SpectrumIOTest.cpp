// SPDX-License-Identifier: BSD-3-Clause
#include <sstream>

#include <catch2/catch.hpp>

#include "spectral/Exception.h"
#include "spectral/SpectrumIO.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
std::vector<NamedSpectrum> Csv(const std::string& text)
{
    std::istringstream in(text);
    return ReadCsvSpectra(in, "test.csv");
}

std::vector<NamedSpectrum> Cgats(const std::string& text)
{
    std::istringstream in(text);
    return ReadCgatsSpectra(in, "test.sp");
}
}  // namespace

TEST_CASE("CSV spectra: header, comments, several columns", "[spectral][io]")
{
    const auto s = Csv("# a comment\nwavelength,red,blue\n400,0.1,0.9\n410,0.2,0.8\n420,0.3,0.7\n");
    REQUIRE(s.size() == 2);
    CHECK(s[0].name == "red");
    CHECK(s[1].name == "blue");
    CHECK(s[0].spectrum.start() == 400.0);
    CHECK(s[0].spectrum.step() == Approx(10.0));
    CHECK(s[1].spectrum[2] == Approx(0.7));
}

TEST_CASE("CSV spectra: no header, tab or space separated", "[spectral][io]")
{
    const auto t = Csv("400\t1\n405\t2\n");
    REQUIRE(t.size() == 1);
    CHECK(t[0].name == "1");
    const auto s = Csv("400 1 5\n405 2 6\n410 3 7\n");
    REQUIRE(s.size() == 2);
    CHECK(s[1].spectrum[2] == 7.0);
}

TEST_CASE("CSV spectra: an irregular grid is resampled onto its smallest step", "[spectral][io]")
{
    const auto s = Csv("400,0\n410,10\n415,15\n");
    REQUIRE(s.size() == 1);
    CHECK(s[0].spectrum.step() == Approx(5.0));
    CHECK(s[0].spectrum.size() == 4);
    CHECK(s[0].spectrum[1] == Approx(5.0));
}

TEST_CASE("CSV spectra: errors name the file, the line and the value", "[spectral][io]")
{
    CHECK_THROWS_WITH(Csv("w,a\n400,0.1\n405,abc\n"),
                      "test.csv:3: expected a number for a spectral value, got 'abc'");
    CHECK_THROWS_WITH(Csv("w,a\n400,0.1\n405,nan\n"),
                      "test.csv:3: NaN ('nan') is not allowed for a spectral value");
    CHECK_THROWS_WITH(Csv("w,a\n400,0.1\n405,1e999\n"), Contains("test.csv:3: value out of range"));
    CHECK_THROWS_WITH(Csv("w,a\n400,0.1\n405\n"), "test.csv:3: expected 2 columns, got 1 in '405'");
    CHECK_THROWS_WITH(Csv("w,a\n400,0.1\n400,0.2\n"),
                      Contains("test.csv:3: wavelengths must increase"));
    CHECK_THROWS_WITH(Csv("w,a\n400,0.1\n"), Contains("fewer than two wavelength rows"));
    CHECK_THROWS_WITH(Csv(""), Contains("fewer than two wavelength rows"));
}

TEST_CASE("CGATS spectra as colord and ArgyllCMS write them", "[spectral][io]")
{
    const std::string sp = R"(SPECT
DESCRIPTOR "test"  # a comment
SPECTRAL_START_NM	400.0
SPECTRAL_END_NM	420.0
SPECTRAL_BANDS	3
NUMBER_OF_FIELDS	4
NUMBER_OF_SETS	2
BEGIN_DATA_FORMAT
SAMPLE_ID SPEC_400 SPEC_410 SPEC_420
END_DATA_FORMAT
BEGIN_DATA
one 0.1 0.2 0.3
two 0.4 0.5
0.6
END_DATA
)";
    const auto s = Cgats(sp);
    REQUIRE(s.size() == 2);
    CHECK(s[0].name == "one");
    CHECK(s[1].name == "two");
    CHECK(s[1].spectrum[2] == Approx(0.6));
    CHECK(s[0].spectrum.step() == Approx(10.0));
}

TEST_CASE("CGATS .ti3 remittances are in percent unless SPECTRAL_NORM says", "[spectral][io]")
{
    const std::string ti3 = R"(CTI3
DEVICE_CLASS "OUTPUT"
SPECTRAL_BANDS "2"
SPECTRAL_START_NM "400"
SPECTRAL_END_NM "700"
NUMBER_OF_FIELDS 4
BEGIN_DATA_FORMAT
SAMPLE_ID RGB_R SPEC_400 SPEC_700
END_DATA_FORMAT
NUMBER_OF_SETS 1
BEGIN_DATA
A1 100 50.0 25.0
END_DATA
)";
    const auto s = Cgats(ti3);
    REQUIRE(s.size() == 1);
    CHECK(s[0].spectrum[0] == Approx(0.5));
    CHECK(s[0].spectrum[1] == Approx(0.25));
    CHECK(s[0].spectrum.step() == Approx(300.0));
}

TEST_CASE("CGATS errors name the file, the line and the value", "[spectral][io]")
{
    const std::string head =
        "SPECT\nSPECTRAL_START_NM 400\nSPECTRAL_END_NM 410\nSPECTRAL_BANDS 2\n"
        "BEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\nEND_DATA_FORMAT\n";
    CHECK_THROWS_WITH(Cgats(head + "BEGIN_DATA\n0.1 x\nEND_DATA\n"),
                      "test.sp:9: expected a number for SPEC_410, got 'x'");
    CHECK_THROWS_WITH(Cgats(head + "BEGIN_DATA\n0.1 0.2\n0.3\nEND_DATA\n"),
                      Contains("test.sp:10: data has 3 values, not a multiple of the 2 fields"));
    CHECK_THROWS_WITH(Cgats(head + "BEGIN_DATA\n0.1 0.2\n"),
                      Contains("test.sp:9: BEGIN_DATA without END_DATA"));
    CHECK_THROWS_WITH(Cgats(head + "NUMBER_OF_SETS 2\nBEGIN_DATA\n0.1 0.2\nEND_DATA\n"),
                      "test.sp:8: NUMBER_OF_SETS says 2 but the data has 1 sets");
    CHECK_THROWS_WITH(Cgats("SPECT\nSPECTRAL_BANDS 3\nBEGIN_DATA_FORMAT\nSPEC_400 SPEC_410\n"
                            "END_DATA_FORMAT\nBEGIN_DATA\n1 2\nEND_DATA\n"),
                      "test.sp:2: SPECTRAL_BANDS says 3 but the format has 2 SPEC_ fields");
    CHECK_THROWS_WITH(Cgats("CTI3\nBEGIN_DATA_FORMAT\nRGB_R\nEND_DATA_FORMAT\nBEGIN_DATA\n1\n"
                            "END_DATA\n"),
                      Contains("test.sp: no spectral data"));
    CHECK_THROWS_WITH(Cgats(""), "test.sp: empty file: not a CGATS file");
}

TEST_CASE("A missing spectrum file is reported by name", "[spectral][io]")
{
    CHECK_THROWS_WITH(ReadSpectraFile("/nonexistent/lamp.csv"),
                      "/nonexistent/lamp.csv: cannot open spectrum file");
}
