// SPDX-License-Identifier: BSD-3-Clause
// End-to-end tests of the bandlight command: output shapes, exit codes, errors,
// and agreement with ArgyllCMS spec2cie.
// Covers, through the entry points it calls: cli/main.cpp, cli/Common.cpp, cli/Diagnostics.cpp,
// cli/CommandAccuracy.cpp, cli/CommandConfig.cpp, cli/CommandCri.cpp, cli/CommandLut.cpp,
// cli/CommandMethods.cpp, cli/CommandPackage.cpp, cli/CommandTables.cpp, cli/CommandXyz.cpp,
// jobs/PackageJob.cpp.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli/RunCommand.h"
#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"

using namespace bandlight;
using Catch::Matchers::Contains;

using test::Bandlight;
using test::Result;
using test::Sh;
using test::TempPath;

namespace
{
Result Run(const std::string& args)
{
    return Bandlight(args);
}
}  // namespace

TEST_CASE("tables --json has the documented shape", "[cli]")
{
    const Result r = Run("tables --json");
    REQUIRE(r.code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    REQUIRE(j["bands"].size() == 3);
    CHECK(j["bands"][0]["name"] == "VB");
    CHECK(j["bands"][0]["min_nm"] == 400);
    CHECK(j["bands"][2]["max_nm"] == 700);
    CHECK(j["matching_functions"]["cie1931_xyz"]["y"][1].get<double>() ==
          Approx(0.7506).margin(1e-4));
    CHECK(j["matching_functions"]["ebu_rgb"]["r"].size() == 3);
    CHECK(j["illuminants"]["F11"][1] == 1.0);
    CHECK(j["illuminants"].contains("D75"));
    CHECK(j["remittances"].size() == 15);
    CHECK(j["remittances"]["TCS01"][0].get<double>() == Approx(0.23));
}

TEST_CASE("tables accepts other bands and observers", "[cli]")
{
    const Result r = Run("tables --bands 400,450,500,550,600,650,700 --observer 1964 --json");
    REQUIRE(r.code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["bands"].size() == 6);
    CHECK(j["matching_functions"].contains("cie1964_xyz"));
    CHECK(j["illuminants"]["D65"].size() == 6);
}

TEST_CASE("xyz: one row per sample in file order, keyed by sample id", "[cli]")
{
    const std::string path = TempPath("two.csv");
    std::ofstream(path) << "wavelength,grey50,white\n380,0.5,1\n780,0.5,1\n";
    const Result r = Run("xyz --illuminant d65 --reflectance '" + path + "' --json");
    REQUIRE(r.code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["illuminant"] == "D65");
    REQUIRE(j["samples"].size() == 2);
    CHECK(j["samples"][0]["id"] == "grey50");
    CHECK(j["samples"][0]["XYZ"][1].get<double>() == Approx(50.0));
    CHECK(j["samples"][1]["Lab"][0].get<double>() == Approx(100.0));
    CHECK(j["samples"][1]["xy"][0].get<double>() == Approx(0.31272).margin(1e-4));
}

TEST_CASE("cri --json has the documented shape", "[cli]")
{
    const Result r = Run("cri --illuminant F11 --json");
    REQUIRE(r.code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["illuminant"] == "F11");
    CHECK(j["cct_K"].get<double>() == Approx(4000).margin(15));
    CHECK(std::lround(j["Ra"].get<double>()) == 83);  // CIE 15:2004 Table T.8.2
    CHECK(j["R"].size() == 15);  // R1–R15
    CHECK(j.contains("duv"));
}

TEST_CASE("methods lists the registry as each method describes itself", "[cli]")
{
    const Result r = Run("methods --json");
    REQUIRE(r.code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    REQUIRE(j.size() >= 13);
    int references = 0;
    for (const auto& m : j)
    {
        INFO(m["names"]);
        const std::string exactness = m["exactness"];
        CHECK((exactness == "linear" || exactness == "non-linear" || exactness == "reference"));
        references += exactness == "reference";
        // Only an op can run natively; a 3x3 always goes through OCIO.
        CHECK((!m["native"].get<bool>() || exactness == "non-linear"));
        CHECK(m["description"].get<std::string>().size() > 20);
        if (m["names"] == "hueplane")
        {
            CHECK(exactness == "non-linear");
            CHECK(m["native"].get<bool>());
            CHECK(m["training_size"] == 205);
            CHECK(m["default_in"] == nlohmann::json::array({"accuracy"}));
        }
        if (m["names"] == "bradford")
        {
            CHECK(exactness == "linear");
            CHECK(m["default_in"] == nlohmann::json::array({"config", "accuracy"}));
        }
    }
    CHECK(references == 1);
    CHECK(j.back()["names"] == "spectral");
    // The text form names every method once.
    const Result text = Run("methods");
    REQUIRE(text.code == 0);
    CHECK_THAT(text.out, Contains("hueplane (non-linear, native in apply, fitted on 205"));
}

TEST_CASE("Bad input: one line on stderr and exit code 2", "[cli]")
{
    Result r = Run("xyz --illuminant Tungsten");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("unknown illuminant 'Tungsten'"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);

    const std::string bad = TempPath("bad.csv");
    std::ofstream(bad) << "wavelength,x\n400,0.1\n410,oops\n";
    r = Run("xyz --illuminant D65 --reflectance '" + bad + "'");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(bad + ":3: expected a number for a spectral value, got 'oops'"));

    r = Run("cri --illuminant '" + bad + "'");
    CHECK(r.code == 2);
    r = Run("tables --bands 500,400");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("empty or not increasing"));
    r = Run("tables --observer 1951");
    CHECK(r.code == 2);
    r = Run("frobnicate");
    CHECK(r.code == 2);
}

TEST_CASE("--help works on every command", "[cli]")
{
    for (const char* cmd : {"", "tables ", "xyz ", "cri ", "config ", "lut ", "apply ", "package "})
    {
        const Result r = Run(std::string(cmd) + "--help");
        INFO(cmd);
        CHECK(r.code == 0);
        CHECK_THAT(r.out, Contains("Usage"));
    }
}

#ifdef SPEC2CIE_EXE
TEST_CASE("xyz agrees with ArgyllCMS spec2cie on the TCS under D65 and A", "[cli][argyll]")
{
    // A .ti3 of TCS01–TCS14 in percent, as ArgyllCMS stores remittances.
    const std::string ti3 = TempPath("tcs.ti3");
    {
        std::ofstream f(ti3);
        const Spectrum& s0 = TestColourSamples()[0].spectrum;
        f << "CTI3\n\nDESCRIPTOR \"CIE 13.3 test colour samples\"\nDEVICE_CLASS \"OUTPUT\"\n"
          << "SPECTRAL_BANDS \"" << s0.size() << "\"\nSPECTRAL_START_NM \"" << s0.start()
          << "\"\nSPECTRAL_END_NM \"" << s0.end() << "\"\n\nNUMBER_OF_FIELDS " << s0.size() + 1
          << "\nBEGIN_DATA_FORMAT\nSAMPLE_ID";
        for (size_t i = 0; i < s0.size(); ++i)
        {
            f << " SPEC_" << int(s0.wavelength(i));
        }
        f << "\nEND_DATA_FORMAT\n\nNUMBER_OF_SETS 14\nBEGIN_DATA\n";
        for (size_t k = 0; k < 14; ++k)
        {
            f << TestColourSamples()[k].name;
            for (double v : TestColourSamples()[k].spectrum.values())
            {
                f << " " << std::fixed << std::setprecision(4) << v * 100.0;
            }
            f << "\n";
        }
        f << "END_DATA\n";
    }
    for (const char* illuminant : {"D65", "A"})
    {
        const std::string out = TempPath(std::string("tcs_") + illuminant + ".ti3");
        std::remove(out.c_str());
        const Result argyll = Sh(std::string("'") + SPEC2CIE_EXE + "' -n -i " + illuminant +
                                 " -o 1931_2 '" + ti3 + "' '" + out + "'");
        REQUIRE(argyll.code == 0);
        // Pull SAMPLE_ID and XYZ_X/Y/Z out of spec2cie's CGATS output.
        std::ifstream in(out);
        std::string line;
        std::vector<std::string> fields;
        std::vector<std::vector<std::string>> rows;
        bool inFormat = false, inData = false;
        while (std::getline(in, line))
        {
            std::istringstream t(line);
            std::vector<std::string> tok;
            for (std::string w; t >> w;)
            {
                tok.push_back(w);
            }
            if (tok.empty())
            {
                continue;
            }
            if (tok[0] == "BEGIN_DATA_FORMAT" || tok[0] == "BEGIN_DATA")
            {
                (tok[0] == "BEGIN_DATA" ? inData : inFormat) = true;
            }
            else if (tok[0] == "END_DATA_FORMAT" || tok[0] == "END_DATA")
            {
                inFormat = inData = false;
            }
            else if (inFormat)
            {
                fields.insert(fields.end(), tok.begin(), tok.end());
            }
            else if (inData)
            {
                rows.push_back(tok);
            }
        }
        auto column = [&](const std::string& name)
        { return size_t(std::find(fields.begin(), fields.end(), name) - fields.begin()); };
        REQUIRE(rows.size() == 14);
        REQUIRE(column("XYZ_X") < fields.size());

        const Result ours = Run(std::string("xyz --illuminant ") + illuminant + " --reflectance '" +
                                ti3 + "' --json");
        REQUIRE(ours.code == 0);
        const nlohmann::json j = nlohmann::json::parse(ours.out);
        REQUIRE(j["samples"].size() == 14);
        const Vec3 white(j["white_XYZ"][0], j["white_XYZ"][1], j["white_XYZ"][2]);
        double worstXyz = 0.0, worstDe = 0.0;
        for (size_t k = 0; k < 14; ++k)
        {
            const Vec3 a(std::stod(rows[k][column("XYZ_X")]), std::stod(rows[k][column("XYZ_Y")]),
                         std::stod(rows[k][column("XYZ_Z")]));
            const Vec3 b(j["samples"][k]["XYZ"][0], j["samples"][k]["XYZ"][1],
                         j["samples"][k]["XYZ"][2]);
            INFO(illuminant << " " << rows[k][column("SAMPLE_ID")] << ": spec2cie " << a.transpose()
                            << ", bandlight " << b.transpose());
            CHECK(j["samples"][k]["id"] == rows[k][column("SAMPLE_ID")]);
            worstXyz = std::max(worstXyz, (a - b).cwiseAbs().maxCoeff());
            worstDe = std::max(worstDe, DeltaE2000(XyzToLab(a, white), XyzToLab(b, white)));
        }
        // spec2cie resamples spectra and tables onto its own finer grid before
        // summing; bandlight sums the 5 nm tables as CIE 15:2004 §7.1 does. The
        // two agree within 0.05 in XYZ (white Y = 100) and 0.075 ΔE00 (measured:
        // D65 0.044 / 0.049, A 0.017 / 0.036).
        INFO(illuminant << ": worst |ΔXYZ| " << worstXyz << ", worst ΔE00 " << worstDe);
        CHECK(worstXyz < 0.05);
        CHECK(worstDe < 0.075);
    }
}
#endif

namespace
{
/// The pixel `ociochecklut FILE r g b` prints.
std::vector<double> CheckLut(const std::string& file, double r, double g, double b)
{
    std::ostringstream args;
    args << std::setprecision(9) << "ociochecklut '" << file << "' " << r << " " << g << " " << b;
    const Result out = Sh(args.str());
    INFO(args.str() << "\n" << out.out << out.err);
    REQUIRE(out.code == 0);
    std::istringstream in(out.out);
    std::vector<double> v(3);
    in >> v[0] >> v[1] >> v[2];
    REQUIRE_FALSE(in.fail());
    return v;
}

/// ACEScct, Academy S-2016-001: the toe below 2^-7, log2 above.
double Acescct(double x)
{
    return x <= 0.0078125 ? 10.5402377416545 * x + 0.0729055341958355
                          : (std::log2(x) + 9.72) / 17.52;
}
double AcescctToLinear(double y)
{
    return y <= 0.155251141552511 ? (y - 0.0729055341958355) / 10.5402377416545
                                  : std::exp2(y * 17.52 - 9.72);
}
}  // namespace

TEST_CASE("lut --encoding acescct: one file for Resolve, cinespace and Houdini", "[cli]")
{
    // The exact transform: the linear method's CLF is its matrix.
    const std::string exact = TempPath("encoding_exact.clf");
    REQUIRE(Run("lut --from A --to D65 -o '" + exact + "'").code == 0);
    for (const char* format : {"resolve_cube", "csp", "houdini"})
    {
        const std::string ext = std::string(format) == "resolve_cube" ? "cube" : format;
        const std::string path = TempPath(std::string("encoding_") + format + "." +
                                          (std::string(format) == "houdini" ? "lut" : ext));
        const Result r = Run("lut --from A --to D65 --format " + std::string(format) +
                             " --encoding acescct -o '" + path + "'");
        INFO(format << ": " << r.out << r.err);
        REQUIRE(r.code == 0);
        CHECK_THAT(r.out, Contains("Input and output: ACEScct (Academy S-2016-001) of ACEScg"));
        CHECK_FALSE(r.out.find(".shaper.clf") != std::string::npos);  // one file
        // ACEScct in, ACEScct out: a grey and a colour against the matrix
        // (ociochecklut interpolates trilinearly, hence a little slack).
        for (const std::vector<double>& px :
             {std::vector<double>{0.18, 0.18, 0.18}, std::vector<double>{8.0, 8.0, 8.0},
              std::vector<double>{0.9, 0.3, 0.05}})
        {
            const std::vector<double> e = CheckLut(exact, px[0], px[1], px[2]);
            const std::vector<double> l =
                CheckLut(path, Acescct(px[0]), Acescct(px[1]), Acescct(px[2]));
            const double scale = std::max({e[0], e[1], e[2]});
            for (int c = 0; c < 3; ++c)
            {
                INFO(format << " pixel " << px[0] << " channel " << c);
                CHECK(std::fabs(AcescctToLinear(l[c]) - e[c]) < 2e-2 * scale);
            }
        }
    }
    // Another working space: the note says what the curve encodes.
    const Result rec709 =
        Run("lut --from A --to D65 --format cube --encoding acescct "
            "--working-space rec709 -o '" +
            TempPath("encoding_709.cube") + "'");
    CHECK(rec709.code == 0);
    CHECK_THAT(rec709.err, Contains("curve encodes"));
    CHECK_THAT(rec709.err, Contains("not ACEScct's ACEScg (AP1)"));
    // --help states the encodings.
    const Result help = Run("lut --help");
    CHECK_THAT(help.out, Contains("--encoding"));
    CHECK_THAT(help.out, Contains("S-2016-001"));
    // Bad values: one line, exit 2, nothing written.
    struct Bad
    {
        std::string args;
        std::string message;
    };
    for (const Bad& b :
         {Bad{"--encoding log", "unknown LUT --encoding 'log' (linear, acescct, acescc)"},
          Bad{"--encoding acescc --shaper log2", "--shaper is for --encoding linear"}})
    {
        const std::string path = TempPath("encoding_bad.cube");
        const Result r =
            Run("lut --from A --to D65 --format cube " + b.args + " -o '" + path + "'");
        INFO(b.args << ": " << r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains(b.message));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK_FALSE(std::ifstream(path).good());
    }
}
