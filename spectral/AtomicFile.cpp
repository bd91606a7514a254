// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/AtomicFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{
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
    m_stream.open(m_temp, std::ios::binary | std::ios::trunc);
    if (!m_stream)
    {
        throw Exception(m_path + ": cannot create output file (" + std::strerror(errno) + ")");
    }
}

AtomicFile::~AtomicFile()
{
    if (!m_committed)
    {
        m_stream.close();
        std::remove(m_temp.c_str());
    }
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
}

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill)
{
    AtomicFile f(path);
    fill(f.stream());
    f.commit();
}

}  // namespace bandlight
