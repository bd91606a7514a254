// SPDX-License-Identifier: BSD-3-Clause
// FileError: a file that cannot be opened, read, created or written carries
// its path and errno, whatever the message says; content that was read and
// refused is an Exception, never a FileError.
// Covers, through the entry points it calls: spectral/TextFile.cpp.
#include "spectral/Exception.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <catch2/catch.hpp>

#include "FileErrorCheck.h"

#include "spectral/AtomicFile.h"
#include "spectral/CameraFile.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"

using namespace bandlight;
namespace fs = std::filesystem;

namespace
{

/// A fresh, empty folder in the temporary folder.
std::string FreshDir(const std::string& name)
{
    const char* tmp = std::getenv("TMPDIR");
    const std::string dir = std::string(tmp ? tmp : "/tmp") + "/bandlight_exception_" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void WriteText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

using test::CaughtFileError;

/// A folder this process cannot create files in, with EACCES: a folder
/// without write permission, or for root (whom permissions do not stop)
/// sysfs, which refuses to create files with EACCES. Empty when there is none.
std::string UnwritableFolder(const std::string& scratch)
{
    if (::geteuid() != 0)
    {
        ::chmod(scratch.c_str(), 0555);
        return scratch;
    }
    const std::string probe = "/sys/bandlight-probe";
    errno = 0;
    std::FILE* f = std::fopen(probe.c_str(), "w");
    const int error = errno;
    if (f)
    {
        std::fclose(f);
        std::remove(probe.c_str());
        return "";
    }
    return error == EACCES ? "/sys" : "";
}

}  // namespace

TEST_CASE("FileError names its path, an empty one as such, and keeps the errno",
          "[spectral][errors]")
{
    const FileError e("/x/lamp.csv", ENOENT, "cannot open spectrum file");
    CHECK(std::string(e.what()) == "/x/lamp.csv: cannot open spectrum file");
    CHECK(e.path() == "/x/lamp.csv");
    CHECK(e.error() == ENOENT);
    const FileError empty("", ENOENT, "cannot open spectrum file");
    CHECK(std::string(empty.what()) == "'' (an empty path): cannot open spectrum file");
    CHECK(empty.path().empty());
    const FileError passed = FileError::WithMessage("a.exr", EACCES, "a.exr: cannot read image: x");
    CHECK(std::string(passed.what()) == "a.exr: cannot read image: x");
    CHECK(passed.error() == EACCES);
    // A FileError is an Exception: the command's exit code 2 and one line.
    const Exception& base = passed;
    CHECK(std::string(base.what()) == "a.exr: cannot read image: x");
    CHECK(passed.spelled(Face::COMMAND) == "a.exr: cannot read image: x");
    // One that names a parameter spells it per face, as ParameterError does.
    const FileError named = FileError::ForParameter("/tmp", EISDIR, "{out} '/tmp' is a folder");
    CHECK(std::string(named.what()) == "out '/tmp' is a folder");
    CHECK(named.spelled(Face::COMMAND) == "--out '/tmp' is a folder");
    CHECK(named.spelled(Face::PYTHON) == "out '/tmp' is a folder");
    CHECK(named.error() == EISDIR);
    CHECK(named.path() == "/tmp");
}

TEST_CASE("Reading a file that is not there is a FileError ENOENT naming it", "[spectral][errors]")
{
    const std::string dir = FreshDir("missing");
    const std::string missing = dir + "/lamp.csv";
    FileError e = CaughtFileError([&] { ReadSpectraFile(missing); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == missing);
    CHECK(std::string(e.what()) == missing + ": cannot open spectrum file");

    e = CaughtFileError([&] { ReadCameraFile(dir + "/camera.json"); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == dir + "/camera.json");

    e = CaughtFileError([&] { ReadTextFile("", "scene file"); });
    CHECK(e.error() == ENOENT);
    CHECK(std::string(e.what()) == "'' (an empty path): cannot open scene file");

    // A folder on the way that is a file: ENOTDIR.
    WriteText(dir + "/plain", "x");
    e = CaughtFileError([&] { ReadSpectraFile(dir + "/plain/lamp.csv"); });
    CHECK(e.error() == ENOTDIR);
}

TEST_CASE("A directory where a file is expected is called a directory (EISDIR)",
          "[spectral][errors]")
{
    const std::string dir = FreshDir("isdir");
    const FileError e = CaughtFileError([&] { ReadSpectraFile(dir); });
    CHECK(e.error() == EISDIR);
    CHECK(std::string(e.what()) == dir + ": is a directory, not a spectrum file");
    CHECK(InputFileError(dir) == EISDIR);
    CHECK(InputFileError(dir + "/none") == ENOENT);
    WriteText(dir + "/ok.csv", "nm,a\n380,1\n780,1\n");
    CHECK(InputFileError(dir + "/ok.csv") == 0);
}

TEST_CASE("A file that cannot be opened for reading is a FileError EACCES", "[spectral][errors]")
{
    std::string unreadable;
    if (::geteuid() != 0)
    {
        unreadable = FreshDir("unreadable") + "/lamp.csv";
        WriteText(unreadable, "nm,a\n380,1\n780,1\n");
        ::chmod(unreadable.c_str(), 0200);
    }
    else if (::access("/sys/bus/pci/rescan", F_OK) == 0)
    {
        // Write-only in sysfs: root cannot open it for reading either.
        unreadable = "/sys/bus/pci/rescan";
    }
    if (unreadable.empty())
    {
        WARN("skipped: running as root without sysfs, no file here refuses to be read");
        return;
    }
    const FileError e = CaughtFileError([&] { ReadSpectraFile(unreadable); });
    CHECK(e.error() == EACCES);
    CHECK(e.path() == unreadable);
    CHECK(std::string(e.what()) == unreadable + ": cannot open spectrum file");
    CHECK(InputFileError(unreadable) == EACCES);
}

TEST_CASE("Malformed content is an Exception, not a FileError", "[spectral][errors]")
{
    const std::string dir = FreshDir("malformed");
    WriteText(dir + "/bad.csv", "nm,a\n380,0.1\n385,abc\n");
    try
    {
        ReadSpectraFile(dir + "/bad.csv");
        FAIL("accepted");
    }
    catch (const FileError& e)
    {
        FAIL("a FileError: " << e.what());
    }
    catch (const Exception& e)
    {
        CHECK(std::string(e.what()) ==
              dir + "/bad.csv:3: expected a number for a spectral value, got 'abc'");
    }
    // A device is read by no reader here: refused as what it is, not as a
    // file that cannot be opened.
    try
    {
        ReadSpectraFile("/dev/null");
        FAIL("accepted");
    }
    catch (const FileError& e)
    {
        FAIL("a FileError: " << e.what());
    }
    catch (const Exception& e)
    {
        CHECK(std::string(e.what()) ==
              "/dev/null: not a regular file (a spectrum file is a text file)");
    }
}

TEST_CASE("Writing into a folder that is not there is a FileError ENOENT naming the output",
          "[spectral][errors]")
{
    const std::string dir = FreshDir("nofolder");
    const std::string out = dir + "/none/x.clf";
    FileError e =
        CaughtFileError([&] { WriteFileAtomically(out, [](std::ostream& os) { os << 1; }); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == out);
    CHECK(std::string(e.what()) ==
          out + ": cannot create output file (" + std::strerror(ENOENT) + ")");

    OutputSet set;
    e = CaughtFileError([&] { set.add(out); });
    CHECK(e.error() == ENOENT);
    CHECK(e.path() == out);

    // An empty path is refused before anything is written.
    e = CaughtFileError([&] { WriteFileAtomically("", [](std::ostream& os) { os << 1; }); });
    CHECK(e.error() == ENOENT);
    CHECK(std::string(e.what()).rfind("'' (an empty path): cannot create output file", 0) == 0);

    // A folder on the way that is a file: ENOTDIR (holds for root too).
    WriteText(dir + "/plain", "x");
    e = CaughtFileError([&] { AtomicFile f(dir + "/plain/x.clf"); });
    CHECK(e.error() == ENOTDIR);
    CHECK(e.path() == dir + "/plain/x.clf");
}

TEST_CASE("Writing over a directory is a FileError EISDIR, the set left as it was",
          "[spectral][errors]")
{
    const std::string dir = FreshDir("overdir");
    fs::create_directories(dir + "/x.clf");
    WriteText(dir + "/shaper.spi1d", "old");
    OutputSet set;
    set.write(dir + "/shaper.spi1d", [](std::ostream& os) { os << "new"; });
    set.write(dir + "/x.clf", [](std::ostream& os) { os << "new"; });
    const FileError e = CaughtFileError([&] { set.commit(); });
    CHECK(e.error() == EISDIR);
    CHECK(e.path() == dir + "/x.clf");
    std::ifstream in(dir + "/shaper.spi1d");
    std::string text;
    in >> text;
    CHECK(text == "old");
}

TEST_CASE("Writing where files cannot be created is a FileError EACCES", "[spectral][errors]")
{
    const std::string scratch = FreshDir("readonly");
    const std::string folder = UnwritableFolder(scratch);
    if (folder.empty())
    {
        WARN(
            "skipped: running as root and sysfs creates files or is absent, so no folder "
            "here refuses a new file with EACCES");
        return;
    }
    const std::string out = folder + "/bandlight-x.clf";
    const FileError e =
        CaughtFileError([&] { WriteFileAtomically(out, [](std::ostream& os) { os << 1; }); });
    ::chmod(scratch.c_str(), 0755);
    CHECK(e.error() == EACCES);
    CHECK(e.path() == out);
    CHECK(std::string(e.what()) ==
          out + ": cannot create output file (" + std::strerror(EACCES) + ")");
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("ToLower lowers ASCII letters only, as names are compared", "[spectral]")
{
    CHECK(bandlight::ToLower("Rec709 ACEScg_Z") == "rec709 acescg_z");
    CHECK(bandlight::ToLower("@[`{") == "@[`{");  // the bytes beside A-Z and a-z
    // UTF-8 (here "Ä") is left as it is: no locale decides a name's case.
    CHECK(bandlight::ToLower("\xC3\x84X") == "\xC3\x84x");
    CHECK(bandlight::ToLower("").empty());
}

TEST_CASE("ListLines: one item a line, comments and blanks skipped, numbers kept", "[spectral]")
{
    // LF, CRLF and CR alone each end one line; a '#' after a space or at a
    // line's start begins a comment, one inside an item does not.
    const std::string text = "key=A:D65\r\n\n  # a comment\rfill=F11:D65#x  # tail\n\t \nlast";
    const std::vector<bandlight::ListLine> items = bandlight::ListLines(text);
    REQUIRE(items.size() == 3);
    CHECK(items[0].number == 1);
    CHECK(items[0].text == "key=A:D65");
    CHECK(items[1].number == 4);
    CHECK(items[1].text == "fill=F11:D65#x");
    CHECK(items[2].number == 6);
    CHECK(items[2].text == "last");
    CHECK(bandlight::ListLines("").empty());
    CHECK(bandlight::ListLines("# only\r\n\r\n").empty());
}
