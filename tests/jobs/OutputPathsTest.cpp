// SPDX-License-Identifier: BSD-3-Clause
// The output plan: every output path of a run checked before any work.
// Covers, through the entry points it calls: farm/Frames.cpp.
#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include "farm/Frames.h"
#include "farm/OutputPaths.h"
#include "spectral/Exception.h"

using namespace bandlight;
using namespace bandlight::jobs;
using Catch::Matchers::Contains;

namespace fs = std::filesystem;

namespace
{
std::string Fresh(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("bandlight_outputs_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}
}  // namespace

TEST_CASE("An empty output path is refused by name", "[jobs][outputs]")
{
    CHECK_THROWS_WITH(OutputPlan().file("{json}", "").check(),
                      Contains("json is '' (an empty path)"));
    CHECK_THROWS_AS(OutputPlan().folder("{out}", "").check(), ParameterError);
    CHECK(ShowPath("") == "'' (an empty path)");
}

TEST_CASE("Files, folders and their parents", "[jobs][outputs]")
{
    const std::string dir = Fresh("kinds");
    std::ofstream(dir + "/file.txt") << "x";
    OutputPlan().file("{out}", dir + "/new.exr").check();  // a new file in a folder: fine
    OutputPlan().folder("{out}", dir + "/a/b/c").check();  // created when missing
    CHECK_THROWS_WITH(OutputPlan().file("{out}", dir).check(), Contains("is a folder, not a file"));
    CHECK_THROWS_WITH(OutputPlan().folder("{out}", dir + "/file.txt").check(),
                      Contains("is a file, not a folder"));
    CHECK_THROWS_WITH(OutputPlan().file("{out}", dir + "/missing/x.exr").check(),
                      Contains("does not exist"));
    CHECK_THROWS_WITH(OutputPlan().file("{out}", dir + "/file.txt/x.exr").check(),
                      Contains("is not a folder"));
    // A folder under a regular file cannot be created.
    CHECK_THROWS_WITH(OutputPlan().folder("{out}", dir + "/file.txt/sub").check(),
                      Contains("is not a folder"));
}

TEST_CASE("An output is never one of the run's inputs unless it may be", "[jobs][outputs]")
{
    const std::string dir = Fresh("inputs");
    const std::string in = dir + "/in.exr";
    std::ofstream(in) << "x";
    CHECK_THROWS_WITH(OutputPlan().input(in).file("{out}", in).check(), Contains("is the input"));
    // Another name of the same file: a dot segment, a hard link.
    CHECK_THROWS_AS(OutputPlan().input(in).file("{out}", dir + "/./in.exr").check(),
                    ParameterError);
    fs::create_hard_link(in, dir + "/link.exr");
    CHECK_THROWS_AS(OutputPlan().input(in).file("{out}", dir + "/link.exr").check(),
                    ParameterError);
    OutputPlan().input(in).file("{out}", in, true).check();  // apply in place
    // Two outputs of one run that are one file.
    CHECK_THROWS_WITH(
        OutputPlan().file("{json}", dir + "/a.json").file("{plot}", dir + "/./a.json").check(),
        Contains("name the same file"));
}

TEST_CASE("Frame patterns expand every field and finished frames are regular files",
          "[jobs][outputs]")
{
    CHECK(ExpandFramePattern("out.##.##.exr", 7) == "out.07.07.exr");
    CHECK(ExpandFramePattern("out.%04d.####.exr", 1008) == "out.1008.1008.exr");
    CHECK(ExpandFramePattern("plain.exr", 3) == "plain.exr");
    const std::string dir = Fresh("frames");
    fs::create_directories(dir + "/f.1001.exr");
    std::ofstream(dir + "/f.1002.exr") << "x";
    CHECK_FALSE(IsFinishedFrame(dir + "/f.1001.exr"));
    CHECK(IsFinishedFrame(dir + "/f.1002.exr"));
    CHECK_FALSE(IsFinishedFrame(dir + "/f.1003.exr"));
    CHECK_THROWS_WITH(CheckImageInput("/dev/zero"), Contains("a device"));
    CheckImageInput(dir + "/f.1002.exr");
    CheckImageInput(dir + "/missing.exr");  // left to the reader
}

TEST_CASE("A frame set's outputs are all checked before the first frame", "[jobs][outputs]")
{
    const std::string dir = Fresh("set");
    for (int f : {1, 2, 3})
    {
        std::ofstream(dir + "/in." + std::to_string(f) + ".exr") << "x";
    }
    FrameSetRequest r;
    r.input = dir + "/in.#.exr";
    r.output = dir + "/in.#.exr";  // every frame its own input
    r.frames = "1-3";
    CHECK_THROWS_WITH(CheckFrameSetPaths(r), Contains("is the input"));
    r.output = dir + "/missing/out.#.exr";
    CHECK_THROWS_WITH(CheckFrameSetPaths(r), Contains("does not exist"));
    r.output = dir + "/out.#.exr";
    CheckFrameSetPaths(r);
}
