// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "farm/Frames.h"
#include "imaging/SpectralImages.h"

namespace bandlight::jobs
{

/// `spectral`: spectral images integrated (and relit) to RGB EXRs.
struct SpectralRequest
{
    FrameSetRequest files;
    SpectralOptions options;
    int threads = 0;  ///< 0: all cores
};

struct SpectralResult
{
    FrameRun run;
    std::string layout;   ///< the first frame's layout, described
    std::string applied;  ///< what was done
};

/// Converts every image of `request`: each output is an RGB EXR (R, G, B
/// and any alpha), tagged with its colour space, written atomically.
SpectralResult ConvertSpectralImages(const SpectralRequest& request,
                                     Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
