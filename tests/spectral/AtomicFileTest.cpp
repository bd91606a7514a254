// SPDX-License-Identifier: BSD-3-Clause
// Outputs appear whole or not at all, under names no delivery script picks
// up, and what a killed process left behind is cleared by the next run.
#include "spectral/AtomicFile.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "FileErrorCheck.h"

using namespace bandlight;
namespace fs = std::filesystem;

namespace
{

std::string FreshDir(const std::string& name)
{
    const char* tmp = std::getenv("TMPDIR");
    const std::string dir = std::string(tmp ? tmp : "/tmp") + "/bandlight_atomic_" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void WriteText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

std::string ReadText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::set<std::string> Names(const std::string& dir)
{
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
    {
        names.insert(entry.path().filename().string());
    }
    return names;
}

/// The id of a process that has ended (a child that exited and was reaped).
pid_t GonePid()
{
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0)
    {
        ::_exit(0);
    }
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    return pid;
}

}  // namespace

TEST_CASE("Temporary outputs are hidden and do not end in the output's extension",
          "[spectral][atomic]")
{
    const std::string dir = FreshDir("names");
    AtomicFile file(dir + "/out.1008.exr");
    CHECK(file.tempPath() == dir + "/.out.1008.exr.tmp-" + std::to_string(::getpid()));
    file.stream() << "pixels";
    // A delivery script's "*.exr" sees nothing until the output is whole.
    for (const std::string& name : Names(dir))
    {
        CHECK(name.front() == '.');
        CHECK(name.substr(name.size() - 4) != ".exr");
    }
    file.commit();
    CHECK(Names(dir) == std::set<std::string>{"out.1008.exr"});
    CHECK(ReadText(dir + "/out.1008.exr") == "pixels");
}

TEST_CASE("A run clears the temporary files a process that is gone left for its outputs",
          "[spectral][atomic]")
{
    const std::string dir = FreshDir("stale");
    const std::string gone = std::to_string(GonePid());
    const std::string alive = std::to_string(::getppid());  // the test runner's parent lives
    // What a SIGKILLed run leaves: the image, gnuplot's script and log, a backup.
    for (const std::string& name :
         {".out.exr.tmp-" + gone, ".out.exr.tmp-" + gone + ".gp",
          ".out.exr.tmp-" + gone + ".err", ".out.exr.tmp-" + gone + ".previous"})
    {
        WriteText(dir + "/" + name, "left behind");
    }
    // Not ours to remove: a run still writing, another output's temporary,
    // names that only look alike, and the user's own files.
    const std::set<std::string> kept = {".out.exr.tmp-" + alive,
                                        ".other.exr.tmp-" + gone,
                                        ".out.exr.tmp-x" + gone,
                                        ".out.exr.tmp-" + gone + "x",
                                        "out.exr.tmp-" + gone,
                                        "notes.txt"};
    for (const std::string& name : kept)
    {
        WriteText(dir + "/" + name, "keep");
    }
    WriteFileAtomically(dir + "/out.exr", [](std::ostream& os) { os << "new"; });
    std::set<std::string> expected = kept;
    expected.insert("out.exr");
    CHECK(Names(dir) == expected);
    CHECK(ReadText(dir + "/out.exr") == "new");
}

TEST_CASE("A set whose second of three files fails leaves all three as they were",
          "[spectral][atomic]")
{
    const std::string dir = FreshDir("rollback");
    WriteText(dir + "/a.clf", "old a");
    fs::create_directories(dir + "/b.spi1d");  // a folder in the way: its rename fails
    WriteText(dir + "/c.ocio", "old c");
    {
        OutputSet set;
        set.write(dir + "/a.clf", [](std::ostream& os) { os << "new a"; });
        set.write(dir + "/b.spi1d", [](std::ostream& os) { os << "new b"; });
        set.write(dir + "/c.ocio", [](std::ostream& os) { os << "new c"; });
        set.write(dir + "/d.txt", [](std::ostream& os) { os << "new d"; });
        const FileError e = test::CaughtFileError([&] { set.commit(); });
        CHECK(e.path() == dir + "/b.spi1d");
    }  // a failed run ends: its set goes
    CHECK(ReadText(dir + "/a.clf") == "old a");  // replaced, then given back
    CHECK(fs::is_directory(dir + "/b.spi1d"));
    CHECK(ReadText(dir + "/c.ocio") == "old c");  // never touched
    CHECK_FALSE(fs::exists(dir + "/d.txt"));      // had no previous file: none now
    // Nothing else is left: no backup, no temporary file.
    CHECK(Names(dir) == std::set<std::string>{"a.clf", "b.spi1d", "c.ocio"});
}

TEST_CASE("A scratch file of a writer lives beside its output's temporary name",
          "[spectral][atomic]")
{
    const std::string dir = FreshDir("scratch");
    {
        AtomicFile image(dir + "/plot.png");
        AtomicFile script(image.tempPath() + ".gp", AtomicFile::Scratch{});
        CHECK(script.tempPath() == image.tempPath() + ".gp");
        script.stream() << "plot 1";
        script.stream().flush();
        CHECK(ReadText(script.tempPath()) == "plot 1");
    }
    CHECK(Names(dir).empty());
}
