// SPDX-License-Identifier: BSD-3-Clause
#include "farm/Frames.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>
#include <unordered_set>

#include "farm/OutputPaths.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"

namespace bandlight::jobs
{

namespace
{
/// A printf-style frame field "%d", "%4d" or "%04d" in a pattern: where it
/// starts, how long it is and its width. Scanned by hand (no regex: a
/// recursive matcher overflows the stack on long names).
struct PrintfField
{
    size_t pos = std::string::npos;
    size_t length = 0;
    int width = 1;
};

PrintfField FindPrintfField(const std::string& pattern)
{
    for (size_t i = pattern.find('%'); i != std::string::npos; i = pattern.find('%', i + 1))
    {
        size_t j = i + 1;
        while (j < pattern.size() && pattern[j] >= '0' && pattern[j] <= '9')
        {
            ++j;
        }
        if (j < pattern.size() && pattern[j] == 'd')
        {
            PrintfField f{i, j + 1 - i, 1};
            const std::string digits = pattern.substr(i + 1, j - i - 1);
            const size_t first = digits.find_first_not_of('0');
            const std::string value = first == std::string::npos ? "" : digits.substr(first);
            if (value.size() > 2 || (!value.empty() && std::stoi(value) > kMaxFrameWidth))
            {
                throw Exception("frame pattern '" + OneLine(pattern, 80) +
                                "': the frame number's width is at most " +
                                std::to_string(kMaxFrameWidth) + " digits");
            }
            f.width = value.empty() ? 1 : std::stoi(value);
            return f;
        }
    }
    return {};
}

/// Parses an optionally signed decimal integer of at most 9 digits at
/// text[i...], skipping spaces before it; advances i. False when absent.
bool ParseFrameNumber(const std::string& text, size_t& i, long& value)
{
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
    {
        ++i;
    }
    const bool negative = i < text.size() && text[i] == '-';
    size_t j = i + (negative ? 1 : 0);
    const size_t digitsStart = j;
    value = 0;
    while (j < text.size() && text[j] >= '0' && text[j] <= '9')
    {
        if (j - digitsStart >= 9)
        {
            return false;
        }
        value = value * 10 + (text[j] - '0');
        ++j;
    }
    if (j == digitsStart)
    {
        return false;
    }
    value = negative ? -value : value;
    i = j;
    return true;
}
}  // namespace

bool HasFramePattern(const std::string& pattern)
{
    return pattern.find('#') != std::string::npos ||
           FindPrintfField(pattern).pos != std::string::npos;
}

namespace
{
/// The pattern with its first frame field replaced by `frame`; the pattern
/// itself when it has none.
std::string ExpandFirstField(const std::string& pattern, int frame)
{
    const size_t hash = pattern.find('#');
    if (hash != std::string::npos)
    {
        size_t end = hash;
        while (end < pattern.size() && pattern[end] == '#')
        {
            ++end;
        }
        if (end - hash > size_t(kMaxFrameWidth))
        {
            throw Exception("frame pattern '" + OneLine(pattern, 80) +
                            "': the frame number's width is at most " +
                            std::to_string(kMaxFrameWidth) + " digits");
        }
        char buf[32];
        std::snprintf(buf, sizeof buf, "%0*d", int(end - hash), frame);
        return pattern.substr(0, hash) + buf + pattern.substr(end);
    }
    const PrintfField f = FindPrintfField(pattern);
    if (f.pos != std::string::npos)
    {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%0*d", f.width, frame);
        return pattern.substr(0, f.pos) + buf + pattern.substr(f.pos + f.length);
    }
    return pattern;
}
}  // namespace

std::string ExpandFramePattern(const std::string& pattern, int frame)
{
    // Every field gets the frame ("out.##.##.exr", "out.%04d.####.exr"):
    // a name whose second field stayed a pattern would name no frame.
    std::string out = pattern;
    for (int fields = 0; HasFramePattern(out); ++fields)
    {
        if (fields == 8)
        {
            throw Exception("frame pattern '" + OneLine(pattern, 80) +
                            "' has more than 8 frame fields");
        }
        out = ExpandFirstField(out, frame);
    }
    return out;
}

bool IsFinishedFrame(const std::string& path)
{
    struct stat st{};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
           ::access(path.c_str(), R_OK) == 0;
}

void CheckImageInput(const std::string& path)
{
    struct stat st{};
    if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode))
    {
        return;  // missing: the reader says so, frame by frame
    }
    if (S_ISDIR(st.st_mode))
    {
        // A directory where a file belongs: EISDIR, as opening it to read would say.
        throw FileError::WithMessage(
            path, EISDIR,
            ShowPath(path) + " is a folder, not an image file: images are read from regular files");
    }
    throw ParameterError(ShowPath(path) + " is " +
                         (S_ISFIFO(st.st_mode)                         ? "a FIFO"
                          : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                          : S_ISSOCK(st.st_mode)                       ? "a socket"
                                                                       : "not a regular file") +
                         ", not an image file: images are read from regular files");
}

std::vector<int> ParseFrameRange(const std::string& text)
{
    const std::string shown = OneLine(text, 80);
    const auto fail = [&]
    {
        return Exception("frame range '" + shown +
                         "': expected FIRST-LAST, FIRST-LASTxSTEP or FRAME, separated by commas, "
                         "e.g. 1001-1100, 1001-1100x2 or 1001-1010,1020 (frame numbers of at "
                         "most 9 digits)");
    };
    const auto skipSpaces = [&](size_t& i)
    {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
        {
            ++i;
        }
    };
    struct Item
    {
        long first, last, step;
    };
    std::vector<Item> items;
    long total = 0;
    size_t i = 0;
    for (;;)
    {
        long first = 0, last = 0, step = 1;
        if (!ParseFrameNumber(text, i, first))
        {
            throw fail();
        }
        last = first;
        skipSpaces(i);
        if (i < text.size() && text[i] == '-')
        {
            ++i;
            if (!ParseFrameNumber(text, i, last))
            {
                throw fail();
            }
            skipSpaces(i);
            if (i < text.size() && (text[i] == 'x' || text[i] == 'X'))
            {
                ++i;
                if (!ParseFrameNumber(text, i, step) || step < 1)
                {
                    throw Exception("frame range '" + shown +
                                    "': the step after x is a whole number of at least 1");
                }
                skipSpaces(i);
            }
        }
        if (last < first)
        {
            throw Exception("frame range '" + shown + "': the last frame comes before the first");
        }
        total += (last - first) / step + 1;
        if (total > kMaxFramesPerCall)
        {
            throw Exception("frame range '" + shown + "': " + std::to_string(total) +
                            " frames; at most " + std::to_string(kMaxFramesPerCall) +
                            " per call (split the range)");
        }
        items.push_back({first, last, step});
        if (i == text.size())
        {
            break;
        }
        if (text[i] != ',')
        {
            throw fail();
        }
        ++i;
    }
    // In the order given, each frame once.
    std::vector<int> frames;
    frames.reserve(size_t(total));
    std::unordered_set<long> seen;
    for (const Item& item : items)
    {
        for (long f = item.first; f <= item.last; f += item.step)
        {
            if (seen.insert(f).second)
            {
                frames.push_back(int(f));
            }
        }
    }
    return frames;
}

namespace
{
/// Frames whose pixels (four floats a channel value, the first frame's file
/// size times four as an estimate of its decoded size) fit in half the
/// machine's memory, at most the cores and at most 4.
size_t FramesInFlight(const std::string& first)
{
    const size_t cores = size_t(CoreCount());
    std::error_code ec;
    const double bytes = double(std::filesystem::file_size(first, ec));
    const double pages = double(::sysconf(_SC_PHYS_PAGES));
    const double page = double(::sysconf(_SC_PAGESIZE));
    const double budget = pages > 0 && page > 0 ? 0.5 * pages * page : 8.0 * double(1 << 30);
    const size_t fit = ec || bytes <= 0.0 ? cores : size_t(budget / (4.0 * bytes));
    return std::max<size_t>(1, std::min({cores, size_t(4), fit}));
}
}  // namespace

void CheckFrameSetPaths(const FrameSetRequest& r)
{
    if (r.frames.empty())
    {
        if (HasFramePattern(r.input))
        {
            throw ParameterError("'" + OneLine(r.input, 200) +
                                 "' is a frame pattern: give {frames=}FIRST-LAST");
        }
        CheckImageInput(r.input);
        OutputPlan().input(r.input).file("{output}", r.output, r.mayReplaceInput).check();
        return;
    }
    if (!HasFramePattern(r.input) || !HasFramePattern(r.output))
    {
        throw ParameterError("{frames} needs frame patterns such as plate.####.exr for IN and OUT");
    }
    OutputPlan plan;
    for (const int f : ParseFrameRange(r.frames))
    {
        const std::string in = ExpandFramePattern(r.input, f);
        CheckImageInput(in);
        plan.input(in).file("{output}", ExpandFramePattern(r.output, f), r.mayReplaceInput);
    }
    plan.check();
}

namespace
{

using FrameWork = std::function<void(const std::string& in, const std::string& out)>;

/// What became of one frame of a set.
struct FrameOutcome
{
    enum class State
    {
        NOT_RUN,  ///< left when an earlier failure stopped the set
        DONE,
        SKIPPED,  ///< its output exists (--skip-existing)
        FAILED
    };
    State state = State::NOT_RUN;
    std::exception_ptr error;
};

const char* StateText(FrameOutcome::State state)
{
    switch (state)
    {
    case FrameOutcome::State::DONE:
        return "done";
    case FrameOutcome::State::SKIPPED:
        return "skipped (exists)";
    case FrameOutcome::State::FAILED:
        return "failed";
    case FrameOutcome::State::NOT_RUN:
        break;
    }
    return "not run";
}

/// One image, no frame set: checked, then worked.
FrameRun RunSingleImage(const FrameSetRequest& r, Reporter& reporter, const FrameWork& one)
{
    if (HasFramePattern(r.input))
    {
        throw ParameterError("'" + OneLine(r.input, 200) +
                             "' is a frame pattern: give {frames=}FIRST-LAST");
    }
    CheckFrameSetPaths(r);
    if (r.mayReplaceInput && SameFile(r.input, r.output))
    {
        reporter.note(ShowPath(r.output) + " is the input: it is replaced by the result");
    }
    one(r.input, r.output);
    FrameRun run;
    run.frames = 1;
    return run;
}

/// Runs the frames, `inFlight` at once: each reads, works and writes on its
/// own thread, so one frame's reading and writing overlap another's. A
/// failure stops the frames not yet started unless `keepGoing`.
std::vector<FrameOutcome> RunFrames(const FrameSetRequest& r, Reporter& reporter,
                                    const FrameWork& one, const std::vector<int>& frames,
                                    size_t inFlight)
{
    std::mutex mu;
    size_t next = 0, finished = 0;
    bool stop = false;
    std::vector<FrameOutcome> outcomes(frames.size());
    const auto worker = [&]
    {
        for (;;)
        {
            size_t i;
            {
                std::lock_guard<std::mutex> lock(mu);
                if (stop || next == frames.size())
                {
                    return;
                }
                i = next++;
            }
            const int f = frames[i];
            const std::string out = ExpandFramePattern(r.output, f);
            FrameOutcome o;
            o.state = FrameOutcome::State::DONE;
            if (r.skipExisting && IsFinishedFrame(out))
            {
                o.state = FrameOutcome::State::SKIPPED;
            }
            else
            {
                try
                {
                    one(ExpandFramePattern(r.input, f), out);
                }
                catch (const std::exception& e)
                {
                    o.error = std::current_exception();
                    o.state = FrameOutcome::State::FAILED;
                }
            }
            std::lock_guard<std::mutex> lock(mu);
            outcomes[i] = o;
            stop = stop || (o.state == FrameOutcome::State::FAILED && !r.keepGoing);
            ++finished;
            reporter.progress("frame " + std::to_string(f) + " " + StateText(o.state) + " (" +
                                  std::to_string(finished) + " of " +
                                  std::to_string(frames.size()) + ")",
                              double(finished) / double(frames.size()));
        }
    };
    // The one pool (spectral/Parallel.h): threads the system refuses are not
    // started, and the calling thread works too.
    ParallelRun(int(std::min<size_t>(inFlight, size_t(kMaxThreads))), frames.size(), worker);
    return outcomes;
}

/// Counts the outcomes into `run`. Without `keepGoing` the first failing
/// frame, in order, is thrown again; with it, each failure is listed.
void Tally(const std::vector<int>& frames, const std::vector<FrameOutcome>& outcomes,
           bool keepGoing, FrameRun& run)
{
    for (size_t i = 0; i < frames.size(); ++i)
    {
        const FrameOutcome& o = outcomes[i];
        if (o.state == FrameOutcome::State::DONE)
        {
            ++run.frames;
        }
        else if (o.state == FrameOutcome::State::SKIPPED)
        {
            ++run.skipped;
        }
        else if (o.error)
        {
            if (!keepGoing)
            {
                std::rethrow_exception(o.error);
            }
            try
            {
                std::rethrow_exception(o.error);
            }
            catch (const std::exception& e)
            {
                run.failed.push_back({frames[i], e.what()});
            }
        }
    }
}

}  // namespace

FrameRun RunFrameSet(const FrameSetRequest& r, Reporter& reporter, const FrameWork& one)
{
    if (r.frames.empty())
    {
        return RunSingleImage(r, reporter, one);
    }
    if (!HasFramePattern(r.input) || !HasFramePattern(r.output))
    {
        throw ParameterError("{frames} needs frame patterns such as plate.####.exr for IN and OUT");
    }
    const std::vector<int> frames = ParseFrameRange(r.frames);
    CheckFrameSetPaths(r);
    const auto t0 = std::chrono::steady_clock::now();
    // As many frames in flight as there are cores (at most 4), fewer when
    // their pixels would not fit in half the machine's memory.
    const size_t inFlight = std::min(
        frames.size(), r.inFlight > 0 ? size_t(r.inFlight)
                                      : FramesInFlight(ExpandFramePattern(r.input, frames[0])));
    const std::vector<FrameOutcome> outcomes = RunFrames(r, reporter, one, frames, inFlight);
    FrameRun run;
    Tally(frames, outcomes, r.keepGoing, run);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.sequence = true;
    return run;
}

std::string FirstExistingInput(const FrameSetRequest& f)
{
    std::error_code ec;
    if (f.frames.empty())
    {
        return std::filesystem::is_regular_file(f.input, ec) ? f.input : "";
    }
    for (const int frame : ParseFrameRange(f.frames))
    {
        const std::string in = ExpandFramePattern(f.input, frame);
        if (std::filesystem::is_regular_file(in, ec))
        {
            return in;
        }
    }
    return "";
}


}  // namespace bandlight::jobs
