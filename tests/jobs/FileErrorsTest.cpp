// SPDX-License-Identifier: BSD-3-Clause
// Files the jobs cannot use are FileError with the errno that says why, also
// those OpenImageIO and OpenColorIO open (the image module reports a file
// error as such across its boundary); images and configs that open but are
// malformed are Exception.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <catch2/catch.hpp>

#include "spectral/FileErrorCheck.h"

#include "cli/RunCommand.h"
#include "jobs/ApplyJob.h"
#include "imaging/ImageApply.h"
#include "requests/Inputs.h"
#include "jobs/SpectralJob.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"

using namespace bandlight;
namespace fs = std::filesystem;

namespace
{
/// The image module is found beside the bandlight executable; this test
/// program lives elsewhere, so it says where.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

std::string FreshDir(const std::string& name)
{
    const std::string dir = test::TempPath("file_errors_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// A 4x2 RGBA float EXR.
void WritePlate(const std::string& path)
{
    const std::vector<float> px(4 * 2 * 4, 0.25f);
    WriteImage(path, px.data(), 4, 2, 4, {"R", "G", "B", "A"},
                     LinearImageDescription(FindRgbSpace("acescg"), "ACEScg"),
                     PixelType::FLOAT);
}

jobs::ApplyRequest Relight(const std::string& in, const std::string& out)
{
    jobs::ApplyRequest r;
    r.input = in;
    r.output = out;
    jobs::RelightRequest relight;
    relight.src = jobs::ResolveIlluminant("A");
    relight.dst = jobs::ResolveIlluminant("D65");
    r.relight = relight;
    return r;
}

using test::CaughtFileError;

/// The message of the Exception `fn` throws, FAILing when it is a FileError.
std::string CaughtContentError(const std::function<void()>& fn)
{
    try
    {
        fn();
    }
    catch (const FileError& e)
    {
        FAIL("a FileError: " << e.what());
    }
    catch (const Exception& e)
    {
        return e.what();
    }
    FAIL("nothing thrown");
    return "";
}
}  // namespace

TEST_CASE("an image that is not there is a FileError ENOENT, for every job that reads one",
          "[jobs][errors]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = FreshDir("missing");
    const std::string missing = dir + "/missing.exr";
    FileError e = CaughtFileError([&] { jobs::ApplyImages(Relight(missing, dir + "/o.exr")); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == missing);
    // OpenImageIO's words after the path, as the command has always printed them.
    CHECK_THAT(e.what(), Catch::StartsWith(missing + ": cannot read image: "));
    CHECK_FALSE(fs::exists(dir + "/o.exr"));

    e = CaughtFileError([&] { jobs::ReadSpectralImage(missing); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == missing);

    e = CaughtFileError([&] { jobs::ApplyImages(Relight("", dir + "/o.exr")); });
    CHECK(e.error() == ENOENT);
    CHECK_THAT(e.what(), Catch::StartsWith("'' (an empty path): cannot read image"));

    // A folder given as the input image: refused before any work, or by the
    // image module when it is asked to read one.
    fs::create_directories(dir + "/plate.exr");
    e = CaughtFileError([&] { jobs::ApplyImages(Relight(dir + "/plate.exr", dir + "/o.exr")); });
    CHECK(e.error() == EISDIR);
    CHECK(e.path() == dir + "/plate.exr");
    CHECK_THAT(e.what(), Catch::Contains("is a folder, not an image file"));
    e = CaughtFileError([&] { jobs::ReadSpectralImage(dir + "/plate.exr"); });
    CHECK(e.error() == EISDIR);
    CHECK(std::string(e.what()) == dir + "/plate.exr: is a directory, not an image file");
}

TEST_CASE("an image written into a folder that is not there is a FileError ENOENT",
          "[jobs][errors]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = FreshDir("nofolder");
    WritePlate(dir + "/plate.exr");
    const std::string out = dir + "/none/o.exr";
    // Refused before any work, by the run's output plan.
    FileError e = CaughtFileError([&] { jobs::ApplyImages(Relight(dir + "/plate.exr", out)); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == out);
    CHECK(std::string(e.what()) ==
          out + ": cannot write there: the folder '" + dir + "/none' does not exist");

    // Written without a plan: the output file itself cannot be created.
    e = CaughtFileError([&] { WritePlate(out); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == out);
    CHECK_THAT(e.what(), Catch::StartsWith(out + ": cannot create output file"));

    // Under a file: ENOTDIR, whoever runs the test.
    std::ofstream(dir + "/plain") << "x";
    e = CaughtFileError([&] { WritePlate(dir + "/plain/o.exr"); });
    CHECK(e.error() == ENOTDIR);
    e = CaughtFileError([&]
                        { jobs::ApplyImages(Relight(dir + "/plate.exr", dir + "/plain/o.exr")); });
    CHECK(e.error() == ENOTDIR);
    // Over a folder: EISDIR, the message naming the parameter per face.
    fs::create_directories(dir + "/folder.exr");
    e = CaughtFileError([&]
                        { jobs::ApplyImages(Relight(dir + "/plate.exr", dir + "/folder.exr")); });
    CHECK(e.error() == EISDIR);
    CHECK(e.path() == dir + "/folder.exr");
    CHECK(e.spelled(Face::COMMAND) == "--output '" + dir + "/folder.exr' is a folder, not a file");
    CHECK(e.spelled(Face::PYTHON) == "output '" + dir + "/folder.exr' is a folder, not a file");

    OutputSet set;
    e = CaughtFileError(
        [&] { WriteImage(out, nullptr, 0, 0, 3, {}, {}, PixelType::FLOAT, &set); });
    CHECK(e.error() == ENOENT);
}

TEST_CASE("an image written where files cannot be created is a FileError EACCES", "[jobs][errors]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = FreshDir("readonly");
    WritePlate(dir + "/plate.exr");
    std::string folder;
    if (::geteuid() != 0)
    {
        fs::create_directories(dir + "/locked");
        ::chmod((dir + "/locked").c_str(), 0555);
        folder = dir + "/locked";
    }
    else if (std::FILE* f = std::fopen("/sys/bandlight-probe", "w"))
    {
        std::fclose(f);  // sysfs that creates files: nowhere refuses root
        std::remove("/sys/bandlight-probe");
    }
    else if (errno == EACCES)
    {
        folder = "/sys";  // sysfs refuses to create files even for root
    }
    if (folder.empty())
    {
        WARN("skipped: running as root without sysfs, no folder refuses a new file with EACCES");
        return;
    }
    const std::string out = folder + "/bandlight-o.exr";
    const FileError e =
        CaughtFileError([&] { jobs::ApplyImages(Relight(dir + "/plate.exr", out)); });
    CHECK(e.error() == EACCES);
    CHECK(e.path() == out);
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("an image file that opens but is no image is an Exception, not a FileError",
          "[jobs][errors]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = FreshDir("malformed");
    std::ofstream(dir + "/text.exr") << "not an image\n";
    const std::string message =
        CaughtContentError([&] { jobs::ApplyImages(Relight(dir + "/text.exr", dir + "/o.exr")); });
    CHECK_THAT(message, Catch::StartsWith(dir + "/text.exr: cannot read image: "));
    CaughtContentError([&] { jobs::ReadSpectralImage(dir + "/text.exr"); });
    CHECK_FALSE(fs::exists(dir + "/o.exr"));
}

TEST_CASE("a config that is not there is a FileError; a malformed one an Exception",
          "[jobs][errors]")
{
    const std::string dir = FreshDir("config");
    const FileError e = CaughtFileError([&] { jobs::ReadConfigFile(dir + "/none/config.ocio"); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == dir + "/none/config.ocio");
    CHECK_THAT(e.what(), Catch::StartsWith(dir + "/none/config.ocio: cannot read the config: "));
    CHECK(CaughtFileError([&] { jobs::ReadConfigFile(dir); }).error() == EISDIR);
    std::ofstream(dir + "/bad.ocio") << "ocio_profile_version: 2\nroles: [\n";
    const std::string message =
        CaughtContentError([&] { jobs::ReadConfigFile(dir + "/bad.ocio"); });
    CHECK_THAT(message, Catch::StartsWith(dir + "/bad.ocio:"));
}
