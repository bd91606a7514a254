// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Frame sequences: patterns (plate.####.exr, plate.%04d.exr) and the frame
// ranges that name their frames.

#include <string>
#include <vector>

namespace bandlight::jobs
{

/// Expands a frame pattern: "plate.####.exr" (or "%04d") with frame 1001
/// gives "plate.1001.exr"; a name without a pattern is returned unchanged.
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

}  // namespace bandlight::jobs
