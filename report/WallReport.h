// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `wall`'s result as report.json, as the text the command prints, and as
// the descriptions its config's files carry.

#include <string>

#include "requests/Wall.h"

namespace bandlight::jobs
{

/// report.json: {"camera", "content_space", "working_space", "emitters",
/// "training", "test_set", "context_variable": {"name", "values",
/// "default"}, "config": {"drives", "note"}, "conventions", "depicted_lights",
/// "white_balances": [{"light", "key", "cct", "duv", "gains", "idt",
/// "in_frustum": {"solution", "drive_matrix", "exposure",
/// "condition_number", "residual", "corners", "negative_share"},
/// "pre_correction": {"matrix", "fit", "before", "after", "least_squares"},
/// "post_camera": {...}, "out_of_frustum": [{"shows", "drive",
/// "pre_corrected_drive", "negative_drive", "errors": {SET: {"before",
/// "pre_corrected", "post_corrected"}}}]}]}; every error a ΔE00 summary
/// {"count", "mean", "median", "p95", "max"}.
std::string WallDocument(const WallResult& result);

/// The text report of a result.
std::string WallReport(const WallResult& result);

/// What each of a white balance's files says it was made from: the
/// emitters, the camera, the white balance, the training set and the error.
struct WallDescriptions
{
    std::string idt;
    std::string inFrustum;
    std::string preCorrection;
    std::string postCamera;
    std::string postRootPolynomial;
};
WallDescriptions DescribeWallBalance(const WallResult& result, const WallBalance& balance);

/// The config's description.
std::string DescribeWallConfig(const WallResult& result);

}  // namespace bandlight::jobs
