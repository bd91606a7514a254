// SPDX-License-Identifier: BSD-3-Clause
// Running the bandlight command (or a host tool) from a test.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

namespace bandlight::test
{

struct Result
{
    int code = -1;
    std::string out;
    std::string err;
};

/// A path in the temporary folder, prefixed so tests do not collide.
inline std::string TempPath(const std::string& name)
{
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir ? dir : "/tmp") + "/bandlight_test_" + name;
}

/// Runs a shell command line; captures stdout, stderr and the exit code.
inline Result Sh(const std::string& command)
{
    // One file per test process: ctest runs test processes in parallel.
    const std::string errFile = TempPath("stderr." + std::to_string(::getpid()) + ".txt");
    Result r;
#ifdef BANDLIGHT_SANITIZED_TESTS
    // The commands a test runs do not end with LeakSanitizer's leak check:
    // its exit-time tracer itself crashes now and then (SIGSEGV in the
    // tracer, "LeakSanitizer has encountered a fatal error") while
    // OpenImageIO's and OpenEXR's worker threads are alive, failing a run
    // whose work was right. ASan and UBSan stay on in them; the library's
    // leaks are checked in process by the other suites.
    const std::string run = "export ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\"; " + command;
#else
    const std::string& run = command;
#endif
    FILE* p = popen((run + " 2>'" + errFile + "'").c_str(), "r");
    REQUIRE(p);
    char buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;)
    {
        r.out.append(buf, n);
    }
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(errFile);
    std::stringstream s;
    s << e.rdbuf();
    r.err = s.str();
    return r;
}

/// A file's bytes ("" when it cannot be read).
inline std::string Slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Runs bandlight with the given arguments.
inline Result Bandlight(const std::string& args)
{
    return Sh(std::string("'") + BANDLIGHT_EXE + "' " + args);
}

}  // namespace bandlight::test
