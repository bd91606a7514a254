// SPDX-License-Identifier: BSD-3-Clause
// Malformed CSV, CGATS, YAML scenes and OCIO configs through the command:
// each gives exactly one line "bandlight: FILE:LINE: what", exit code 2,
// and no output file.
#include <fstream>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "robustness/HardValues.h"

using namespace bandlight::test;

namespace
{

const std::string kDir = std::string(ROBUSTNESS_DATA) + "/malformed/";

struct Case
{
    const char* file;
    const char* command;  ///< %s is replaced by the file's path
    const char* message;  ///< after "bandlight: <path>"
};

std::string Expand(const std::string& command, const std::string& path)
{
    std::string out = command;
    out.replace(out.find("%s"), 2, "'" + path + "'");
    return out;
}

}  // namespace

TEST_CASE("Malformed files: one line naming file and line, exit 2, nothing written",
          "[robustness][files][cli]")
{
    const char* xyz = "xyz --illuminant D65 --reflectance %s";
    const std::string out = TempFile("malformed_out.exr");
    const std::string render = "render %s -o '" + out + "'";
    const std::string configOut = TempFile("malformed_config");
    const std::string config = "config --base %s --out '" + configOut + "'";
    const std::vector<Case> cases = {
        {"truncated.csv", xyz, ":4: expected a number for a spectral value, got ''"},
        {"wrong_count.csv", xyz, ":3: expected 3 columns, got 2 in '385,0.2'"},
        {"non_numeric.csv", xyz, ":3: expected a number for a spectral value, got 'abc'"},
        {"nan_token.csv", xyz, ":3: NaN ('nan') is not allowed for a spectral value"},
        {"huge.csv", xyz, ":3: value out of range for a spectral value: '1e999'"},
        {"decreasing.csv", xyz, ":3: wavelengths must increase: 375 nm follows 380 nm"},
        {"latin1.csv", xyz,
         ":1: byte 0xE9 is not UTF-8 (Latin-1 or another legacy encoding?); save the file as "
         "UTF-8"},
        {"utf16.csv", xyz,
         ":1: UTF-16/UTF-32 text (byte-order mark); save the file as UTF-8 or ASCII"},
        {"empty.csv", xyz, ": fewer than two wavelength rows: not a spectrum"},
        {"truncated.sp", xyz, ":9: BEGIN_DATA without END_DATA (truncated file?)"},
        {"wrong_sets.sp", xyz, ":5: NUMBER_OF_SETS says 3 but the data has 2 sets"},
        {"nan_value.sp", xyz, ":6: NaN ('NaN') is not allowed for SPEC_385"},
        {"no_sets.sp", xyz,
         ": the spectral table holds no data sets (empty BEGIN_DATA ... END_DATA)"},
        {"bad_bands.sp", xyz, ":2: SPECTRAL_BANDS says 1e300 but the format has 3 SPEC_ fields"},
        {"truncated.yaml", render.c_str(), ":3: end of map flow not found"},
        {"non_numeric.yaml", render.c_str(), ":4: intensity must be a number, got 'lots'"},
        {"nan.yaml", render.c_str(), ":4: intensity must be finite, got '.nan'"},
        {"wrong_count.yaml", render.c_str(),
         ":4: light position must be a list of three numbers [x, y, z]"},
        {"wrong_type.yaml", render.c_str(),
         ":2: expected a single value (a name or a number) here, not a list or mapping"},
        {"latin1.yaml", render.c_str(),
         ":2: byte 0xE9 is not UTF-8 (Latin-1 or another legacy encoding?); save the file as "
         "UTF-8"},
        {"truncated.ocio", config.c_str(),
         ":8: cannot read the config: yaml-cpp: error at line 8, column 1: end of sequence flow "
         "not found"},
        {"wrong_count.ocio", config.c_str(),
         ":6: cannot read the config: At line 6, the value parsing of the key 'matrix' from "
         "'MatrixTransform' failed: 'matrix' values must be 16 numbers. Found '5'."},
    };
    std::remove(out.c_str());
    for (const Case& c : cases)
    {
        const std::string path = kDir + c.file;
        INFO(c.file);
        const Result r = Bandlight(Expand(c.command, path));
        CHECK(r.code == 2);
        CHECK(r.err == "bandlight: " + path + c.message + "\n");
        CHECK_FALSE(std::ifstream(out).good());
        CHECK_FALSE(std::ifstream(configOut + "/config.ocio").good());
    }
}

TEST_CASE("A byte-order mark and CRLF line ends are read as plain text", "[robustness][files]")
{
    const Result r = Bandlight("xyz --illuminant D65 --reflectance '" + kDir + "bom_crlf.csv' --json");
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Catch::Contains("\"a\""));
}

TEST_CASE("Paths that are not text files are refused before reading", "[robustness][files]")
{
    Result r = Bandlight("xyz --illuminant /dev/zero");
    CHECK(r.code == 2);
    CHECK(r.err == "bandlight: /dev/zero: not a regular file (a spectrum file is a text file)\n");
    const std::string dir = kDir.substr(0, kDir.size() - 1);
    r = Bandlight("render '" + dir + "' -o '" + TempFile("dir.exr") + "'");
    CHECK(r.code == 2);
    CHECK(r.err == "bandlight: " + dir + ": is a directory, not a scene file\n");
}

TEST_CASE("An empty file name is named as such, not left as ': cannot ...'; directories as such",
          "[robustness][files][cli]")
{
    Result r = Bandlight("apply '' '" + TempFile("empty_name.exr") + "' --from A --to D65");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::StartsWith("bandlight: '' (an empty path): cannot read image"));
    r = Bandlight("spectral '' '" + TempFile("empty_name.exr") + "'");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::StartsWith("bandlight: '' (an empty path): cannot read image"));
    r = Bandlight("package --out ''");
    CHECK(r.code == 2);
    CHECK_THAT(r.err,
               Catch::StartsWith("bandlight: '' (an empty path): cannot create the directory"));
    // Directories where a file belongs.
    r = Bandlight("lut --from A --to D65 -o /tmp");
    CHECK(r.code == 2);
    CHECK(r.err == "bandlight: --out '/tmp' is a folder, not a file\n");
    r = Bandlight("apply /tmp '" + TempFile("dir_in.exr") + "' --from A --to D65");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::StartsWith("bandlight: '/tmp' is a folder, not an image file"));
    // A missing file keeps the message it has always had.
    r = Bandlight("config --base '/nonexistent/config.ocio' --out '" + TempFile("empty_name") +
                  "'");
    CHECK(r.code == 2);
    CHECK(r.err ==
          "bandlight: /nonexistent/config.ocio: cannot read the config: Error could not "
          "read '/nonexistent/config.ocio' OCIO profile.\n");
}
