// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Frame sequences: patterns (plate.####.exr, plate.%04d.exr) and the frame
// ranges that name their frames.

#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "farm/Reporter.h"

namespace bandlight::jobs
{

/// Expands a frame pattern: "plate.####.exr" (or "%04d") with frame 1001
/// gives "plate.1001.exr", every field of it ("a.##.##.exr": "a.1001.1001.exr");
/// a name without a pattern is returned unchanged.
std::string ExpandFramePattern(const std::string& pattern, int frame);
bool HasFramePattern(const std::string& pattern);

/// Frame numbers are at most this wide in a pattern ("%09d", "#########").
constexpr int kMaxFrameWidth = 9;
/// At most this many frames in one call: a farm splits longer ranges.
constexpr long kMaxFramesPerCall = 1000000;

/// Parses a frame set as render farms hand them out: ranges "1001-1100",
/// ranges with a step "1001-1100x2", single frames, and lists of them
/// "1001-1010,1020" (OpenCue's and Deadline's syntax), into the frames it
/// names, in the order given, each once; at most kMaxFramesPerCall, numbers
/// of at most 9 digits. Throws Exception with one line naming the text.
std::vector<int> ParseFrameRange(const std::string& text);

/// A frame that could not be done, and why.
struct FrameFailure
{
    int frame = 0;
    std::string error;
};

/// What a run over one image or a frame set did.
struct FrameRun
{
    size_t frames = 0;                 ///< frames written (1 for a single image)
    size_t skipped = 0;                ///< frames whose output existed (skipExisting)
    std::vector<FrameFailure> failed;  ///< keepGoing: the frames that failed, in order
    double seconds = 0.0;              ///< wall time of the frames
    bool sequence = false;
};

/// How a job walks its inputs: one image, or the frames of a pattern.
struct FrameSetRequest
{
    std::string input;   ///< an image, or a pattern such as plate.####.exr
    std::string output;  ///< an image, or a pattern
    std::string frames;  ///< with patterns: the frames, "1001-1100"
    /// Frames whose output exists are skipped (outputs are written
    /// atomically, so an existing file is a complete one).
    bool skipExisting = false;
    /// A frame that fails does not stop the others; the run lists it.
    bool keepGoing = false;
    /// An output may be its own input (apply in place: the result keeps what
    /// the run carries); otherwise such a run is refused before any work.
    bool mayReplaceInput = false;
    /// Frames read, worked and written at once (0: as many as there are
    /// cores, at most 4, fewer when their pixels would not fit in half the
    /// machine's memory).
    int inFlight = 0;
};

/// Checks every input and output path (CheckImageInput, OutputPlan: an
/// output is never an input unless mayReplaceInput), then calls
/// `one(in, out)` for the image, or for each frame of the set: frames
/// start in order, `inFlight` of them at once on their own threads (`one`
/// must be safe to call so), reporting progress as each finishes. Without
/// keepGoing no frame starts after one fails, and the first failing frame
/// (in order) throws once those in flight are done (the frames before it,
/// and any in flight beside it, are written). Throws ParameterError for a
/// pattern without frames or frames without patterns.
/// Whether `path` is a finished frame for --skip-existing: a regular,
/// readable file (outputs are renamed into place whole), not a folder.
bool IsFinishedFrame(const std::string& path);

/// Refuses (ParameterError) an image input that exists but is not a regular
/// file (a FIFO, a device such as /dev/zero, a folder): reading one blocks
/// or never ends. A missing input is left to the reader.
void CheckImageInput(const std::string& path);

/// The path checks RunFrameSet starts with, for a job to run before its own
/// set-up work: every frame's input (CheckImageInput) and output
/// (OutputPlan). Throws ParameterError for a pattern without frames or
/// frames without patterns.
void CheckFrameSetPaths(const FrameSetRequest& request);

FrameRun RunFrameSet(const FrameSetRequest& request, Reporter& reporter,
                     const std::function<void(const std::string& in, const std::string& out)>& one);

/// The first input of a request that is there: the image, or the first
/// frame whose input exists ("" when none is).
std::string FirstExistingInput(const FrameSetRequest& frames);

/// Each note of a frame set's frames said once, the frame's file names
/// given as the set's patterns (a note per frame would repeat itself).
class FrameNotes
{
public:
    FrameNotes(std::string inputPattern, std::string outputPattern, Reporter& reporter)
        : m_input(std::move(inputPattern)), m_output(std::move(outputPattern)), m_reporter(reporter)
    {
    }
    void add(const std::vector<std::string>& notes, const std::string& in, const std::string& out)
    {
        std::lock_guard<std::mutex> lock(m_mu);
        for (std::string n : notes)
        {
            for (const auto& [name, pattern] :
                 {std::pair{in, m_input}, std::pair{out, m_output}})
            {
                for (size_t at = n.find(name); !name.empty() && at != std::string::npos;
                     at = n.find(name, at + pattern.size()))
                {
                    n.replace(at, name.size(), pattern);
                }
            }
            if (m_noted.insert(n).second)
            {
                m_reporter.note(n);
            }
        }
    }

private:
    std::string m_input;
    std::string m_output;
    Reporter& m_reporter;
    std::set<std::string> m_noted;
    std::mutex m_mu;
};

}  // namespace bandlight::jobs
