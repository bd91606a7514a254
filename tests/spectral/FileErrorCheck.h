// SPDX-License-Identifier: BSD-3-Clause
// The FileError a call throws, for tests of file errors (spectral and jobs).
#pragma once

#include <exception>
#include <functional>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "spectral/Exception.h"

namespace bandlight::test
{

/// The FileError `fn` throws (FAILs when it throws none, or another type).
inline FileError CaughtFileError(const std::function<void()>& fn)
{
    try
    {
        fn();
    }
    catch (const FileError& e)
    {
        return e;
    }
    catch (const std::exception& e)
    {
        FAIL("not a FileError: " << e.what());
    }
    FAIL("nothing thrown");
    throw std::logic_error("unreachable");
}

}  // namespace bandlight::test
