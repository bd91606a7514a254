// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/AtomicFile.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{
/// Temporary files in flight, for the signal handler: fixed slots of
/// heap-allocated C strings, claimed and released with atomic exchanges so
/// that the handler only reads them and calls unlink (async-signal-safe).
constexpr int kSlots = 256;
std::atomic<char*> g_inFlight[kSlots];

int Register(const std::string& temp)
{
    char* copy = strdup(temp.c_str());
    for (int i = 0; i < kSlots; ++i)
    {
        char* expected = nullptr;
        if (g_inFlight[i].compare_exchange_strong(expected, copy))
        {
            return i;
        }
    }
    std::free(copy);
    return -1;  // more files in flight than slots: this one is not cleaned on a signal
}

void Unregister(int slot)
{
    if (slot >= 0)
    {
        std::free(g_inFlight[slot].exchange(nullptr));
    }
}

using Cleanup = void (*)() noexcept;
std::atomic<Cleanup> g_moreCleanups[4];

extern "C" void RemoveTempsAndReraise(int sig)
{
    RemoveTemporaryFiles();
    for (auto& c : g_moreCleanups)
    {
        if (const Cleanup f = c.load())
        {
            f();
        }
    }
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

std::string TempName(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    const bool hasExt = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    const std::string stem = hasExt ? path.substr(0, dot) : path;
    const std::string ext = hasExt ? path.substr(dot) : "";
    return stem + ".tmp-" + std::to_string(::getpid()) + ext;
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)), m_temp(TempName(m_path))
{
    m_slot = Register(m_temp);
    m_stream.open(m_temp, std::ios::binary | std::ios::trunc);
    if (!m_stream)
    {
        const std::string reason = std::strerror(errno);
        Unregister(m_slot);
        throw Exception(m_path + ": cannot create output file (" + reason + ")");
    }
}

AtomicFile::~AtomicFile()
{
    if (!m_committed)
    {
        m_stream.close();
        std::remove(m_temp.c_str());
    }
    Unregister(m_slot);
}

void AtomicFile::commit()
{
    m_stream.flush();
    const bool ok = bool(m_stream);
    m_stream.close();
    if (!ok)
    {
        throw Exception(m_path + ": write failed (disk full?)");
    }
    if (std::rename(m_temp.c_str(), m_path.c_str()) != 0)
    {
        throw Exception(m_path + ": cannot replace output file (" + std::strerror(errno) + ")");
    }
    m_committed = true;
    Unregister(m_slot);
    m_slot = -1;
}

void RemoveTemporaryFiles() noexcept
{
    for (auto& slot : g_inFlight)
    {
        if (const char* p = slot.load())
        {
            ::unlink(p);
        }
    }
}

void AlsoOnInterrupt(void (*cleanup)() noexcept)
{
    for (auto& c : g_moreCleanups)
    {
        Cleanup expected = nullptr;
        if (c.load() == cleanup || c.compare_exchange_strong(expected, cleanup))
        {
            return;
        }
    }
}

void RemoveTemporaryFilesOnInterrupt()
{
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
    {
        std::signal(sig, RemoveTempsAndReraise);
    }
}

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill)
{
    AtomicFile f(path);
    fill(f.stream());
    f.commit();
}

}  // namespace bandlight
