// SPDX-License-Identifier: BSD-3-Clause
// What the jobs' tests share: a fresh scratch folder per test and a file's
// bytes, to compare what a job writes with what the command writes.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/RunCommand.h"

namespace bandlight::test
{

/// A file's bytes ("" when it cannot be read).
inline std::string ReadAll(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// A scratch path for a job's test, emptied of what an earlier run left.
inline std::string Fresh(const std::string& name)
{
    const std::string dir = TempPath("jobs_" + name);
    std::filesystem::remove_all(dir);
    return dir;
}

}  // namespace bandlight::test
