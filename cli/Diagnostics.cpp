// SPDX-License-Identifier: BSD-3-Clause
#include "cli/Diagnostics.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <iostream>

#include "spectral/Exception.h"

namespace bandlight::cli
{

namespace
{
/// The real stderr while a capture is running (-1: none).
std::atomic<int> g_realStderr{-1};

void WriteAll(int fd, const char* data, size_t size)
{
    while (size > 0)
    {
        const ssize_t n = ::write(fd, data, size);
        if (n <= 0)
        {
            return;
        }
        data += n;
        size -= size_t(n);
    }
}
}  // namespace

StderrCapture::StderrCapture()
{
    std::cerr.flush();
    m_memory = ::memfd_create("bandlight-stderr", MFD_CLOEXEC);
    if (m_memory < 0)
    {
        return;
    }
    m_saved = ::fcntl(2, F_DUPFD_CLOEXEC, 3);
    if (m_saved < 0 || ::dup2(m_memory, 2) < 0)
    {
        ::close(m_memory);
        m_memory = -1;
        return;
    }
    g_realStderr.store(m_saved);
}

StderrCapture::~StderrCapture()
{
    finish(false, "");
}

void StderrCapture::finish(bool success, const std::string& line)
{
    std::cerr.flush();
    std::fflush(stderr);
    if (m_memory >= 0)
    {
        ::dup2(m_saved, 2);
        g_realStderr.store(-1);
        if (success)
        {
            char buf[65536];
            ::lseek(m_memory, 0, SEEK_SET);
            for (ssize_t n; (n = ::read(m_memory, buf, sizeof buf)) > 0;)
            {
                WriteAll(2, buf, size_t(n));
            }
        }
        ::close(m_memory);
        ::close(m_saved);
        m_memory = m_saved = -1;
    }
    if (!line.empty())
    {
        const std::string text = line + "\n";
        WriteAll(2, text.data(), text.size());
    }
}

void Progress(const std::string& line)
{
    const int real = g_realStderr.load();
    if (real >= 0 && ::isatty(real))
    {
        const std::string text = OneLine(line) + "\n";
        WriteAll(real, text.data(), text.size());
        return;
    }
    std::cerr << OneLine(line) << "\n";
}

bool StderrIsTerminal()
{
    const int real = g_realStderr.load();
    return ::isatty(real >= 0 ? real : 2) != 0;
}

void Note(const std::string& line)
{
    std::cerr << "note: " << OneLine(line) << "\n";
}

}  // namespace bandlight::cli
