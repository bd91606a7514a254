// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace bandlight::cli
{

/// What a run prints on stderr, kept to the rule "a failed run prints one
/// line": from start-up until the run ends, file descriptor 2 is an
/// in-memory file, so notes, progress, and whatever libraries print on their
/// own (OpenColorIO's warnings, libpng's messages) are collected. A run that
/// succeeds passes them on to the real stderr when it ends; a run that fails
/// prints only its error line.
class StderrCapture
{
public:
    /// Starts capturing (does nothing when the in-memory file cannot be made).
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    /// Stops capturing; `success` says whether what was collected is passed
    /// on, and `line` (when not empty) is printed after it as the last line.
    void finish(bool success, const std::string& line);

private:
    int m_saved = -1;
    int m_memory = -1;
};

/// A progress line: shown at once when stderr is a terminal, otherwise
/// collected with the other notes (and shown only when the run succeeds).
void Progress(const std::string& line);

/// True when the run's real stderr is a terminal.
bool StderrIsTerminal();

/// A note on stderr ("note: ..."), shown when the run succeeds.
void Note(const std::string& line);

}  // namespace bandlight::cli
