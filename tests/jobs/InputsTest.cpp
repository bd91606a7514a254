// SPDX-License-Identifier: BSD-3-Clause
// The jobs' inputs: names or files, plates and cameras, the defaults table,
// and messages that name parameters as each face spells them.
// Covers, through the entry points it calls: farm/Reporter.cpp.
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "farm/Frames.h"
#include "requests/Inputs.h"
#include "spectral/Exception.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
/// Collects what a job reports.
struct Collect : jobs::Reporter
{
    std::vector<std::string> notes;
    void note(const std::string& line) override { notes.push_back(line); }
};
}  // namespace

TEST_CASE("ParameterError spells its parameters as each face does", "[jobs]")
{
    const ParameterError e(
        "method 'x' needs the camera ({camera=}FILE); give {working_space}, "
        "use {shaper=}none, drop {no_cost}; {src}/{dst}; "
        "render: {output: acescg}");
    CHECK(std::string(e.what()) ==
          "method 'x' needs the camera (camera = FILE); give working_space, use shaper = none, "
          "drop no_cost; src/dst; render: {output: acescg}");
    CHECK(e.spelled(Face::COMMAND) ==
          "method 'x' needs the camera (--camera FILE); give --working-space, use --shaper none, "
          "drop --no-cost; --from/--to; render: {output: acescg}");
    CHECK(e.spelled(Face::PYTHON) ==
          "method 'x' needs the camera (camera=FILE); give working_space, use shaper=none, "
          "drop cost=False; src/dst; render: {output: acescg}");
    // Braces that are not a parameter pass unchanged, unterminated ones too.
    CHECK(SpellParameters("{} {A} {a b} {x", Face::COMMAND) == "{} {A} {a b} {x");
}

TEST_CASE("illuminants resolve by built-in name or file, with notes on files", "[jobs]")
{
    const Light d65 = jobs::ResolveIlluminant("d65");
    CHECK(d65.name == "D65");
    CHECK(jobs::ResolveIlluminant("3200K").name == "3200K");
    CHECK_THROWS_WITH(jobs::ResolveIlluminant("no-such-light"), Contains("D65"));

    // A lamp measured from 400 nm only: usable, with a note that it stops short.
    const std::string file = test::TempPath("jobs_lamp.csv");
    {
        std::ofstream f(file);
        f << "wavelength,lamp\n";
        for (int nm = 400; nm <= 700; nm += 10)
        {
            f << nm << "," << 0.5 + nm / 1000.0 << "\n";
        }
    }
    Collect notes;
    const Light lamp = jobs::ResolveIlluminant(file, notes);
    CHECK(lamp.name == "lamp");
    // ... and one that it is sampled every 10 nm, coarser than the CIE's 5.
    REQUIRE(notes.notes.size() == 2);
    CHECK_THAT(notes.notes[0], Contains(file));
    CHECK_THAT(notes.notes[1], Contains(file) && Contains("every 10 nm"));
}

TEST_CASE("remittances resolve by test-colour name or file", "[jobs]")
{
    CHECK(jobs::ResolveReflectances("tcs03").at(0).name == "TCS03");
    CHECK(jobs::ResolveReflectances("TCS").size() == 15);
    CHECK_THROWS_WITH(jobs::ResolveReflectances("TCS99"), Contains("TCS01-TCS15"));
}

TEST_CASE("plates: the defaults table, both conventions, and rootpoly-camera's camera", "[jobs]")
{
    const jobs::PlatesRequest plates;
    CHECK(plates.plates == std::string(defaults::PLATES));
    CHECK(plates.parsed().balanced());
    CHECK(plates.parsed().adaptation == AdaptationMethod::CAT02);
    jobs::PlatesRequest both = plates;
    both.plates = "both";
    REQUIRE(both.all().size() == 2);
    CHECK(both.all()[0].balanced());
    CHECK_FALSE(both.all()[1].balanced());
    CHECK_THROWS_AS(both.parsed(), Exception);
    try
    {
        plates.apply(ParseMethod("rootpoly-camera"), nullptr);
        FAIL("rootpoly-camera without a camera was accepted");
    }
    catch (const ParameterError& e)
    {
        CHECK_THAT(e.spelled(Face::COMMAND), Contains("(--camera FILE)"));
        CHECK_THAT(e.spelled(Face::PYTHON), Contains("(camera=FILE)"));
    }
}

TEST_CASE("training remittances are for the fitted methods only", "[jobs]")
{
    const std::vector<NamedSpectrum> tcs = jobs::ResolveReflectances("TCS");
    CHECK(jobs::WithTraining(ParseMethod("fit3x3"), tcs).training.size() == 15);
    CHECK(jobs::WithTraining(ParseMethod("rootpoly3"), tcs).degree == 3);
    CHECK_THROWS_AS(jobs::WithTraining(ParseMethod("bradford"), tcs), ParameterError);
}

TEST_CASE("the defaults table is what the faces start from", "[jobs]")
{
    CHECK(std::string(defaults::VERSION) == BANDLIGHT_VERSION);
    CHECK(defaults::MIN_LUT_SIZE == 2);
    CHECK(defaults::MAX_LUT_SIZE == 129);
    CHECK(jobs::CheckedLutSize(defaults::CONFIG_LUT_SIZE, "lut_size") == 65);
    CHECK_THROWS_AS(jobs::CheckedLutSize(130, "lut_size"), ParameterError);
    CHECK(jobs::SplitList(defaults::CONFIG_ILLUMINANTS) ==
          std::vector<std::string>{"A", "C", "D65", "F2", "F11"});
    // The C++ types default as the table says: a MethodSpec is for balanced
    // plates, as the command's and Python's are.
    const Plates table = ParsePlates(defaults::PLATES, defaults::ADAPTATION);
    CHECK(Plates{}.convention == table.convention);
    CHECK(Plates{}.adaptation == table.adaptation);
    CHECK(ParseMethod("bradford").plates.balanced());
    CHECK_FALSE(Plates::Lit().balanced());
    const jobs::RelightRequest relight;
    CHECK(relight.method == "bradford");
    CHECK(relight.working().name == "acescg");
}

TEST_CASE("frame patterns and ranges", "[jobs]")
{
    CHECK(jobs::ExpandFramePattern("plate.####.exr", 1001) == "plate.1001.exr");
    CHECK(jobs::ExpandFramePattern("plate.%06d.exr", 7) == "plate.000007.exr");
    CHECK(jobs::ParseFrameRange("1001-1003") == std::vector<int>{1001, 1002, 1003});
    CHECK_THROWS_WITH(jobs::ParseFrameRange("3-1"), Contains("before the first"));
}
