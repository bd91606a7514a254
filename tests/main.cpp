// SPDX-License-Identifier: BSD-3-Clause
// The Catch2 main of every test program. Before any test runs, TMPDIR is
// pointed at this build's own temporary folder, so the fixed names the tests
// use (TempPath, temp_directory_path) never meet those of another build's
// suite running on the same machine at the same time.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

int main(int argc, char* argv[])
{
#ifdef BANDLIGHT_TEST_TMPDIR
    std::error_code ec;
    std::filesystem::create_directories(BANDLIGHT_TEST_TMPDIR, ec);
    ::setenv("TMPDIR", BANDLIGHT_TEST_TMPDIR, 1);
#endif
    return Catch::Session().run(argc, argv);
}
