// SPDX-License-Identifier: BSD-3-Clause
#include <atomic>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "spectral/Parallel.h"

using namespace bandlight;

TEST_CASE("ParallelFor covers every index once, on every thread count", "[spectral][parallel]")
{
    for (int threads : {1, 2, 3, 7})
    {
        std::vector<std::atomic<int>> seen(1000);
        ParallelFor(seen.size(), threads,
                    [&](size_t b, size_t e)
                    {
                        for (size_t i = b; i < e; ++i)
                        {
                            ++seen[i];
                        }
                    });
        for (const auto& s : seen)
        {
            REQUIRE(s.load() == 1);
        }
    }
}

TEST_CASE("An exception on any thread of a parallel loop reaches the caller",
          "[spectral][parallel]")
{
    // Thrown on a worker thread and on the calling one: both must come back
    // as the exception, after every thread is joined, not abort the process.
    for (int threads : {1, 2, 4})
    {
        for (size_t bad : {size_t(0), size_t(999)})
        {
            CHECK_THROWS_WITH(
                ParallelFor(1000, threads,
                            [&](size_t b, size_t e)
                            {
                                if (b <= bad && bad < e)
                                {
                                    throw std::runtime_error("item " + std::to_string(bad));
                                }
                            }),
                "item " + std::to_string(bad));
        }
        std::atomic<int> next{0};
        std::atomic<int> done{0};
        CHECK_THROWS_WITH(ParallelRun(threads, 100,
                                      [&]
                                      {
                                          for (int i; (i = next++) < 100;)
                                          {
                                              if (i == 50)
                                              {
                                                  throw std::runtime_error("row 50");
                                              }
                                              ++done;
                                          }
                                      }),
                          "row 50");
        CHECK(done.load() <= 99);
    }
}
