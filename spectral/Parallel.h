// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace bandlight
{

/// At most this many threads for any one job: more than any machine
/// bandlight runs on has cores, and few enough that asking for them cannot
/// exhaust the process's thread or memory limits.
constexpr int kMaxThreads = 256;

/// The cores of this machine (at least 1): the one place bandlight asks.
inline int CoreCount()
{
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

/// The thread count a job actually uses: `requested` threads (0 or less:
/// one per core), at most kMaxThreads and at most `work` (one thread per
/// unit of work at most), at least 1.
inline int ThreadCount(int requested, size_t work)
{
    int n = requested > 0 ? requested : CoreCount();
    n = std::min(n, kMaxThreads);
    n = int(std::min<size_t>(size_t(n), std::max<size_t>(work, 1)));
    return std::max(n, 1);
}

namespace detail
{

/// Keeps the first exception thrown on any thread of a parallel loop, so the
/// loop joins every thread and rethrows it on the calling one: an exception
/// leaving a std::thread, or a joinable thread destroyed while one
/// propagates, would abort the process instead of reporting the error.
class FirstException
{
public:
    template <typename Fn>
    void run(Fn&& fn) noexcept
    {
        try
        {
            fn();
        }
        catch (...)
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            if (!m_error)
            {
                m_error = std::current_exception();
            }
        }
    }
    void rethrow() const
    {
        if (m_error)
        {
            std::rethrow_exception(m_error);
        }
    }

private:
    std::mutex m_mutex;
    std::exception_ptr m_error;
};

}  // namespace detail

/// Splits [0, count) into one contiguous range per thread and calls
/// `fn(begin, end)` for each, the last range on the calling thread. When
/// the system refuses a thread (std::system_error: resource limits), the
/// ranges it would have run are run on the calling thread instead: the
/// result is the same, only slower. When `fn` throws, every thread is
/// joined and the first exception is rethrown here.
template <typename RangeFn>
void ParallelFor(size_t count, int threads, RangeFn&& fn)
{
    const int n = ThreadCount(threads, count);
    if (n == 1 || count == 0)
    {
        fn(size_t(0), count);
        return;
    }
    const size_t chunk = (count + size_t(n) - 1) / size_t(n);
    detail::FirstException error;
    std::vector<std::thread> pool;
    std::vector<std::pair<size_t, size_t>> leftover;
    for (int t = 0; t < n; ++t)
    {
        const size_t b = chunk * size_t(t);
        const size_t e = std::min(count, b + chunk);
        if (b >= e)
        {
            continue;
        }
        if (t == n - 1)
        {
            leftover.push_back({b, e});
            continue;
        }
        try
        {
            pool.emplace_back([&fn, &error, b, e] { error.run([&] { fn(b, e); }); });
        }
        catch (const std::system_error&)
        {
            leftover.push_back({b, e});
        }
    }
    for (const std::pair<size_t, size_t>& range : leftover)
    {
        error.run([&] { fn(range.first, range.second); });
    }
    for (std::thread& th : pool)
    {
        th.join();
    }
    error.rethrow();
}

/// Runs `work()` on `threads` threads at once (including the calling one),
/// for jobs that take their own items from a shared counter. Threads the
/// system refuses are simply not started. When `work` throws, every thread
/// is joined and the first exception is rethrown here (the others' items
/// may have run or not: a job that throws has no partial result to keep).
template <typename WorkFn>
void ParallelRun(int threads, size_t items, WorkFn&& work)
{
    const int n = ThreadCount(threads, items);
    detail::FirstException error;
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t)
    {
        try
        {
            pool.emplace_back([&work, &error] { error.run(work); });
        }
        catch (const std::system_error&)
        {
            break;
        }
    }
    error.run(work);
    for (std::thread& th : pool)
    {
        th.join();
    }
    error.rethrow();
}

}  // namespace bandlight
