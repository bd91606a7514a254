// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>

#include "jobs/Inputs.h"

namespace bandlight::jobs
{

/// `apply`: a look of a config, or an illuminant change, applied to an
/// image file or a frame sequence through OpenImageIO.
struct ApplyRequest
{
    std::string input;   ///< an image, or a pattern such as plate.####.exr
    std::string output;  ///< an image, or a pattern
    std::string frames;  ///< with patterns: the frames, "1001-1100"
    /// A look of a config (folder or .ocio file), applied in `colorspace`
    /// (empty: the config's scene_linear role).
    std::string look;
    std::string config;
    std::string colorspace;
    /// Without a look: the illuminant change (rootpoly applies natively,
    /// the other methods through their OCIO transform).
    std::optional<RelightRequest> relight;
    int threads = 0;  ///< 0: all cores
};

struct ApplyResult
{
    std::string applied;  ///< what was applied: "look band3_A_to_D65", a look name
    size_t frames = 0;    ///< frames written (1 for a single image)
    /// Applied by bandlight's own kernel (a clamp-and-matrix processor,
    /// rootpoly) rather than by OpenColorIO's CPU processor.
    bool native = false;
    bool sequence = false;
};

/// Applies `request`: every output is complete or absent (written to a
/// temporary file, then renamed); alpha and other channels pass through.
ApplyResult ApplyImages(const ApplyRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
