// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/AtomicFile.h"

#include <dirent.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
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

/// "dir/.name.tmp-": the start of every temporary name of `path`'s outputs.
/// Hidden, and the output's extension is not the end of the name, so a
/// delivery script's `*.exr` never picks a temporary file up.
std::string TempPrefix(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + name + ".tmp-";
}

std::string TempName(const std::string& path)
{
    return TempPrefix(path) + std::to_string(::getpid());
}

/// Removes the temporary files a process that is gone left for `path`
/// (killed by SIGKILL, or a Python or Dask worker killed without our
/// handlers): ".name.tmp-<pid>" and names that continue it (".gp", ".err",
/// ".previous"), when no process <pid> exists. A live process's files, and
/// anything not of this form, are left alone.
void RemoveStaleTemporaries(const std::string& path)
{
    const std::string prefix = TempPrefix(path);
    const size_t slash = prefix.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : prefix.substr(0, slash);
    const std::string start = slash == std::string::npos ? prefix : prefix.substr(slash + 1);
    DIR* folder = ::opendir(dir.empty() ? "/" : dir.c_str());
    if (!folder)
    {
        return;
    }
    std::vector<std::string> stale;
    while (const dirent* entry = ::readdir(folder))
    {
        const std::string name = entry->d_name;
        if (name.compare(0, start.size(), start) != 0)
        {
            continue;
        }
        size_t end = start.size();
        while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end])))
        {
            ++end;
        }
        if (end == start.size() || end - start.size() > 9 ||
            (end < name.size() && name[end] != '.'))
        {
            continue;
        }
        const long pid = std::strtol(name.c_str() + start.size(), nullptr, 10);
        if (pid > 0 && pid != long(::getpid()) && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
        {
            stale.push_back((slash == std::string::npos ? "" : dir + "/") + name);
        }
    }
    ::closedir(folder);
    for (const std::string& file : stale)
    {
        ::unlink(file.c_str());
    }
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : m_path(std::move(path)), m_temp(TempName(m_path))
{
    if (m_path.empty())
    {
        // The temporary name would be a file in the current folder, and the
        // rename would fail only after the whole output had been written.
        throw FileError(m_path, ENOENT,
                        std::string("cannot create output file (") + std::strerror(ENOENT) + ")");
    }
    RemoveStaleTemporaries(m_path);
    open("cannot create output file");
}

AtomicFile::AtomicFile(std::string path, Scratch) : m_path(std::move(path)), m_temp(m_path)
{
    open("cannot create a working file");
}

void AtomicFile::open(const char* failure)
{
    m_slot = Register(m_temp);
    errno = 0;
    m_stream.open(m_temp, std::ios::binary | std::ios::trunc);
    if (!m_stream)
    {
        const int error = errno;
        Unregister(m_slot);
        throw FileError(m_path, error, std::string(failure) + " (" + std::strerror(error) + ")");
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

void AtomicFile::finishWriting()
{
    if (m_stream.is_open())
    {
        errno = 0;
        m_stream.flush();
        const bool ok = bool(m_stream);
        m_stream.close();
        if (!ok)
        {
            // errno as the failed write left it (ENOSPC, EIO, ...), or 0.
            const int error = errno;
            throw FileError(m_path, error, "write failed (disk full?)");
        }
    }
    // A writer that used tempPath() directly must have left a file there.
    if (::access(m_temp.c_str(), F_OK) != 0)
    {
        const int error = errno;
        throw FileError(m_path, error, "the output was not written");
    }
}

void AtomicFile::commit()
{
    finishWriting();
    if (std::rename(m_temp.c_str(), m_path.c_str()) != 0)
    {
        const int error = errno;
        throw FileError(m_path, error,
                        std::string("cannot replace output file (") + std::strerror(error) + ")");
    }
    m_committed = true;
    Unregister(m_slot);
    m_slot = -1;
}

AtomicFile& OutputSet::add(const std::string& path)
{
    for (const auto& f : m_files)
    {
        if (f->path() == path)
        {
            throw Exception(path + ": the same output is written twice");
        }
    }
    m_files.push_back(std::make_unique<AtomicFile>(path));
    return *m_files.back();
}

void OutputSet::write(const std::string& path, const std::function<void(std::ostream&)>& fill)
{
    AtomicFile& f = add(path);
    fill(f.stream());
    f.finishWriting();
}

void OutputSet::commit()
{
    for (const auto& f : m_files)
    {
        f->finishWriting();
    }
    // Backups of the destinations that exist, as hard links (same folder,
    // no copy); where a link cannot be made there is no rollback for it.
    std::vector<std::string> backups(m_files.size());
    for (size_t i = 0; i < m_files.size(); ++i)
    {
        const std::string backup = m_files[i]->m_temp + ".previous";
        if (::link(m_files[i]->m_path.c_str(), backup.c_str()) == 0)
        {
            backups[i] = backup;
        }
    }
    size_t done = 0;
    int failure = 0;  // errno of the rename that failed
    for (; done < m_files.size(); ++done)
    {
        AtomicFile& f = *m_files[done];
        if (std::rename(f.m_temp.c_str(), f.m_path.c_str()) != 0)
        {
            failure = errno ? errno : EIO;
            break;
        }
        f.m_committed = true;
    }
    for (size_t i = 0; i < m_files.size(); ++i)
    {
        if (failure != 0 && i < done)
        {
            // Put the previous file back, or remove the new one if there was none.
            if (!backups[i].empty())
            {
                std::rename(backups[i].c_str(), m_files[i]->m_path.c_str());
            }
            else
            {
                std::remove(m_files[i]->m_path.c_str());
            }
        }
        else if (!backups[i].empty())
        {
            std::remove(backups[i].c_str());
        }
    }
    if (failure != 0)
    {
        throw FileError(m_files[done]->m_path, failure,
                        std::string("cannot replace output file (") + std::strerror(failure) +
                            "); the other outputs of the set were left as they were");
    }
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
