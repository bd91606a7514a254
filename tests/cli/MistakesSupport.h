// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the tests of users' mistakes share: a fresh folder per test, and the
// rule every mistake follows (one line on stderr, exit code 2).

#include <algorithm>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"

namespace bandlight::test
{

/// A fresh folder for one test.
inline std::string Folder(const std::string& name)
{
    const std::string dir = TempPath("mistakes_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// One line on stderr: the mistake is named, nothing else is printed.
inline void CheckOneLine(const Result& r, const std::string& mentions)
{
    CHECK(r.code == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Catch::Matchers::Contains(mentions));
}

}  // namespace bandlight::test
