// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The outputs of one run, checked together before any work: a run that will
// fail to write its result fails in the first second, not after the work,
// and no run writes over one of its own inputs.

#include <string>
#include <vector>

namespace bandlight::jobs
{

/// How a path reads in a message: the path in quotes, or "'' (an empty path)".
std::string ShowPath(const std::string& path);

/// The output paths of one run and the files it reads. check() refuses,
/// naming the parameter and the path:
/// - an empty path (ParameterError);
/// - a file output that is an existing directory, or a folder output that
///   is an existing file (FileError EISDIR, ENOTDIR, naming the parameter);
/// - a file output whose folder does not exist, is not a folder, or cannot
///   be written (FileError ENOENT, ENOTDIR, EACCES, naming the folder);
/// - a folder output none of whose existing ancestors can be written;
/// - a file output that is one of the inputs (the same file, by device and
///   inode, or the same path), unless it was added with `mayReplaceInput`;
/// - two outputs that are the same file.
class OutputPlan
{
public:
    /// A file the run writes; `param` names it in messages ("{out}", "{json}").
    OutputPlan& file(const std::string& param, const std::string& path,
                     bool mayReplaceInput = false);
    /// A folder the run writes into (created when missing); `contents` are
    /// the names it will write there (config.ocio, ...), checked as files.
    OutputPlan& folder(const std::string& param, const std::string& path,
                       const std::vector<std::string>& contents = {});
    /// A file the run reads.
    OutputPlan& input(const std::string& path);

    /// Throws at the first problem (see above); does nothing on disk.
    void check() const;

private:
    struct Output
    {
        std::string param;
        std::string path;
        bool folder;
        bool mayReplaceInput;
    };
    std::vector<Output> m_outputs;
    std::vector<std::string> m_inputs;
};

/// Whether `a` and `b` name the same existing file (device and inode), or,
/// when either does not exist, the same absolute, normalised path.
bool SameFile(const std::string& a, const std::string& b);

}  // namespace bandlight::jobs
