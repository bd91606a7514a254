// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bandlight
{

/// An output file that appears whole or not at all: it is written to a
/// temporary file in the destination directory and renamed over the
/// destination by commit(). Destroyed without commit(), it removes the
/// temporary file and the previous output stays as it was.
class AtomicFile
{
public:
    /// Throws FileError when the temporary file cannot be created (its
    /// folder is missing or not writable, or `path` is empty).
    explicit AtomicFile(std::string path);
    /// A working file of a writer (a script, a log) at exactly `path`,
    /// registered for removal on interrupt like a temporary file and removed
    /// when destroyed; never committed. Name it after an output's tempPath()
    /// (tempPath() + ".gp") so that a later run clears it with the output's
    /// stale temporaries.
    struct Scratch
    {
    };
    AtomicFile(std::string path, Scratch);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// The temporary path, for writers that want a file name: "dir/.name.tmp-<pid>"
    /// for "dir/name", hidden and not ending in the output's extension (a
    /// writer that picks a format by name is given the destination's name
    /// for that). Creating an AtomicFile removes the temporary files that a
    /// process that is gone left for the same destination.
    const std::string& tempPath() const noexcept { return m_temp; }
    /// A stream on the temporary file.
    std::ofstream& stream() noexcept { return m_stream; }

    /// Flushes and renames the temporary file over the destination; throws
    /// FileError naming the file on any write or rename failure.
    void commit();

    /// The destination path.
    const std::string& path() const noexcept { return m_path; }

    /// The first half of commit(): flushes and closes the temporary file and
    /// throws FileError naming the file when anything written failed. The
    /// destination is not touched yet (OutputSet renames a set together).
    void finishWriting();

private:
    friend class OutputSet;
    /// Registers the temporary file for interrupts and creates it; throws
    /// FileError "<failure> (<strerror>)" naming the destination.
    void open(const char* failure);
    std::string m_path;
    std::string m_temp;
    std::ofstream m_stream;
    bool m_committed = false;
    int m_slot = -1;  ///< registration for RemoveTemporaryFilesOnInterrupt()
};

/// A set of outputs that belong together (a config and its LUTs, a LUT and
/// its shaper, an image and its preview) and are replaced together or not
/// at all: every file is written to its temporary name; commit() renames
/// them over their destinations only once every one of them was written
/// completely. If a rename fails part-way (the destination folder vanished,
/// a permission changed), the destinations already replaced get their
/// previous contents back from hard-linked backups, so a failing run never
/// leaves a mixed set. Destroyed without commit(), it removes every
/// temporary file.
class OutputSet
{
public:
    OutputSet() = default;
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    /// Adds an output to the set; the reference stays valid for the set's
    /// life. Throws FileError when its temporary file cannot be created,
    /// Exception when the same path is added twice.
    AtomicFile& add(const std::string& path);

    /// Writes a whole file of the set through a callback that fills it.
    void write(const std::string& path, const std::function<void(std::ostream&)>& fill);

    /// Renames every file of the set over its destination (see above);
    /// throws FileError naming the file that could not be written or renamed.
    void commit();

    size_t size() const noexcept { return m_files.size(); }

private:
    std::vector<std::unique_ptr<AtomicFile>> m_files;
};

/// Installs SIGINT, SIGTERM and SIGHUP handlers that remove the temporary
/// files of every AtomicFile not yet committed, then end the process with
/// the signal's default action. The previous outputs stay as they were.
/// (SIGKILL cannot be caught: it leaves a hidden ".<name>.tmp-<pid>" beside
/// the untouched output, which the next run writing that output removes.)
/// Call once, early in main().
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
