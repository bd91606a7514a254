// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <fstream>
#include <functional>
#include <string>

namespace bandlight
{

/// An output file that appears whole or not at all: it is written to a
/// temporary file in the destination directory and renamed over the
/// destination by commit(). Destroyed without commit(), it removes the
/// temporary file and the previous output stays as it was.
class AtomicFile
{
public:
    /// Throws Exception when the temporary file cannot be created.
    explicit AtomicFile(std::string path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// The temporary path, for writers that want a file name (OIIO); keeps
    /// the destination's extension so format detection still works.
    const std::string& tempPath() const noexcept { return m_temp; }
    /// A stream on the temporary file.
    std::ofstream& stream() noexcept { return m_stream; }

    /// Flushes and renames the temporary file over the destination; throws
    /// Exception naming the file on any write or rename failure.
    void commit();

private:
    std::string m_path;
    std::string m_temp;
    std::ofstream m_stream;
    bool m_committed = false;
    int m_slot = -1;  ///< registration for RemoveTemporaryFilesOnInterrupt()
};

/// Installs SIGINT, SIGTERM and SIGHUP handlers that remove the temporary
/// files of every AtomicFile not yet committed, then end the process with
/// the signal's default action. The previous outputs stay as they were.
/// (SIGKILL cannot be caught: it leaves a "<stem>.tmp-<pid><ext>" beside
/// the untouched output.) Call once, early in main().
void RemoveTemporaryFilesOnInterrupt();

/// Removes the temporary files of every AtomicFile not yet committed
/// (async-signal-safe: what the interrupt handlers call).
void RemoveTemporaryFiles() noexcept;

/// Registers one more cleanup for the interrupt handlers: a loaded module's
/// own RemoveTemporaryFiles (a module linking this library has its own
/// registry). At most a few; async-signal-safe functions only.
void AlsoOnInterrupt(void (*cleanup)() noexcept);

/// Writes a file through AtomicFile with a callback that fills the stream.
void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

}  // namespace bandlight
