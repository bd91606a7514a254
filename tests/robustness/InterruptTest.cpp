// SPDX-License-Identifier: BSD-3-Clause
// Nothing lost: a run killed in the middle of writing its output, or one
// that fails, leaves the previous output exactly as it was.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
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
    const std::string temp =
        out.substr(0, out.size() - 4) + ".tmp-" + std::to_string(pid) + ".exr";
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
