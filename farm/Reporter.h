// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace bandlight::jobs
{

/// What a job tells its caller while it runs, besides its result: notes
/// (what was assumed, what a file lacks) and progress. The command prints
/// them on stderr ("note: ..."), Python issues a bandlight.NoteWarning for
/// each note and calls its progress callback, a C++ host does what it likes.
/// Jobs may report from worker threads; a reporter serialises itself if it
/// must. The default reporter drops everything.
class Reporter
{
public:
    virtual ~Reporter() = default;
    /// A note on the input or on what the job assumed: one line. It may
    /// name parameters as ParameterError's templates do ({colorspace}); a
    /// face spells them (SpellParameters) as it spells its errors.
    virtual void note(const std::string& line) { (void)line; }
    /// A progress line, and how much of the job is done (0 to 1; negative
    /// when the line is not a fraction of the whole).
    virtual void progress(const std::string& line, double fraction = -1.0)
    {
        (void)line;
        (void)fraction;
    }
};

/// A reporter that drops everything (the default of every job).
Reporter& SilentReporter();

}  // namespace bandlight::jobs
