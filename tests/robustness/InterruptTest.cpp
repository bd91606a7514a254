// SPDX-License-Identifier: BSD-3-Clause
// Nothing lost: a run killed in the middle of writing its output, or one
// that fails, leaves the previous output exactly as it was.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"
#include "robustness/HardValues.h"

using namespace bandlight::test;

namespace
{

bool Exists(const std::string& path)
{
    return ::access(path.c_str(), F_OK) == 0;
}

/// A scene big enough that writing its 4000×3000 float EXR takes a while.
std::string BigScene()
{
    const std::string path = TempFile("big_scene.yaml");
    std::ofstream(path) << R"(
camera: {position: [0, 1.2, 7.5], look_at: [0, 0.2, 0], fov: 40, width: 4000, height: 3000}
render: {mode: band3}
lights:
  - {type: point, position: [3, 5, 6], spectrum: D65}
materials:
  gold: {lecture: gold}
  floor: {diffuse: TCS05}
objects:
  - {sphere: {center: [0, 0.5, 0], radius: 1.5}, material: gold}
  - {plane: {point: [0, -1, 0], normal: [0, 1, 0]}, material: floor}
)";
    return path;
}

struct Interrupted
{
    bool tempSeen = false;
    bool killedBySignal = false;
};

/// Starts `bandlight render`, waits until its temporary output file appears
/// (the write has begun), lets it write for a moment and sends `sig`.
Interrupted RenderAndInterrupt(const std::string& scene, const std::string& out, int sig)
{
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0)
    {
        ::execl(BANDLIGHT_EXE, BANDLIGHT_EXE, "render", scene.c_str(), "-o", out.c_str(),
                "--threads", "2", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    const size_t slash = out.find_last_of('/');
    const std::string temp =
        out.substr(0, slash + 1) + "." + out.substr(slash + 1) + ".tmp-" + std::to_string(pid);
    Interrupted r;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline)
    {
        if (Exists(temp))
        {
            r.tempSeen = true;
            std::this_thread::sleep_for(std::chrono::milliseconds(30));
            ::kill(pid, sig);
            break;
        }
        if (::waitpid(pid, &status, WNOHANG) == pid)
        {
            return r;  // finished (or failed) before it could be interrupted
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    r.killedBySignal = WIFSIGNALED(status) && WTERMSIG(status) == sig;
    if (sig == SIGKILL)
    {
        std::remove(temp.c_str());  // SIGKILL cannot be caught: the temporary stays
    }
    else
    {
        CHECK_FALSE(Exists(temp));  // the handler removed it
    }
    return r;
}

}  // namespace

TEST_CASE("A render killed mid-write leaves the previous output intact",
          "[robustness][atomic]")
{
    const std::string scene = BigScene();
    for (int sig : {SIGTERM, SIGINT, SIGKILL})
    {
        INFO("signal " << sig);
        const std::string out = TempFile("interrupted.exr");
        const std::string png = TempFile("interrupted.png");
        std::ofstream(out) << "previous EXR";
        std::ofstream(png) << "previous PNG";
        const Interrupted r = RenderAndInterrupt(scene, out, sig);
        REQUIRE(r.tempSeen);
        REQUIRE(r.killedBySignal);
        CHECK(Slurp(out) == "previous EXR");
        CHECK(Slurp(png) == "previous PNG");
    }
}

TEST_CASE("A failing run leaves the previous outputs intact", "[robustness][atomic]")
{
    // An image whose look cannot be built, a config over an existing one, a LUT.
    const std::string out = TempFile("kept.exr");
    std::ofstream(out) << "previous EXR";
    const std::string in = TempFile("kept_in.exr");
    WriteFloatImage(in, std::vector<float>(12, 0.5f), 2, 2, 3);
    Result r = Bandlight("apply '" + in + "' '" + out + "' --from A --to D65 --method bands380-390-400-780");
    CHECK(r.code == 2);
    CHECK(Slurp(out) == "previous EXR");

    const std::string dir = TempFile("kept_config");
    REQUIRE(Bandlight("config --out '" + dir + "'").code == 0);
    const std::string before = Slurp(dir + "/config.ocio");
    r = Bandlight("config --out '" + dir + "' --methods bands380-390-400-780");
    CHECK(r.code == 2);
    CHECK(Slurp(dir + "/config.ocio") == before);

    // An output directory that cannot be written: a clear error, nothing half-made.
    r = Bandlight("lut --from A --to D65 --method bradford --format clf -o /proc/bandlight.clf");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::StartsWith("bandlight: /proc/bandlight.clf: cannot create output file"));
}

TEST_CASE("apply killed by SIGKILL over a sequence resumes with --skip-existing, exactly",
          "[robustness][atomic][farm]")
{
    // A farm task killed mid-write (SIGKILL: no handler runs) and re-queued
    // with --skip-existing: the folder must hold exactly the outputs,
    // pixel-exact, and no temporary file.
    const std::string dir = TempFile("killed_sequence");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const int width = 1600, height = 1200, frames = 6;
    for (int f = 1; f <= frames; ++f)
    {
        std::vector<float> pixels(size_t(width) * height * 3);
        for (size_t i = 0; i < pixels.size(); ++i)
        {
            pixels[i] = float((i * 7919 + size_t(f) * 104729) % 1000) / 400.0f;
        }
        WriteFloatImage(dir + "/in.100" + std::to_string(f) + ".exr", pixels, width, height, 3);
    }
    const std::string in = dir + "/in.####.exr", out = dir + "/out.####.exr";
    const std::string ref = dir + "/ref";
    std::filesystem::create_directories(ref);
    const std::string options = " --frames 1001-100" + std::to_string(frames) +
                                " --from A --to D65 --method rootpoly --threads 1";
    REQUIRE(Bandlight("apply '" + in + "' '" + ref + "/out.####.exr'" + options).code == 0);

    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0)
    {
        ::execl(BANDLIGHT_EXE, BANDLIGHT_EXE, "apply", in.c_str(), out.c_str(), "--frames",
                ("1001-100" + std::to_string(frames)).c_str(), "--from", "A", "--to", "D65",
                "--method", "rootpoly", "--threads", "1", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Kill it while it writes the third frame.
    const std::string temp = dir + "/.out.1003.exr.tmp-" + std::to_string(pid);
    bool killed = false;
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline)
    {
        if (Exists(temp))
        {
            ::kill(pid, SIGKILL);
            killed = true;
            break;
        }
        if (::waitpid(pid, &status, WNOHANG) == pid)
        {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    REQUIRE(killed);
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    REQUIRE(WIFSIGNALED(status));
    CHECK(Exists(temp));  // SIGKILL cannot be caught: the temporary stays ...

    const Result r = Bandlight("apply '" + in + "' '" + out + "'" + options + " --skip-existing");
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_FALSE(Exists(temp));  // ... until the rerun clears it
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
    {
        names.insert(entry.path().filename().string());
    }
    std::set<std::string> expected = {"ref"};
    for (int f = 1; f <= frames; ++f)
    {
        expected.insert("in.100" + std::to_string(f) + ".exr");
        expected.insert("out.100" + std::to_string(f) + ".exr");
    }
    CHECK(names == expected);
    for (int f = 1; f <= frames; ++f)
    {
        const std::string name = "/out.100" + std::to_string(f) + ".exr";
        INFO(name);
        CHECK(ReadFloatImage(dir + name, width, height, 3) ==
              ReadFloatImage(ref + name, width, height, 3));
    }
}
