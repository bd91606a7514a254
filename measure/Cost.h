// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "transforms/IlluminantChange.h"

namespace bandlight::jobs
{

/// How a method was applied when it was timed.
enum class CostForm
{
    OCIO_MATRIX,  ///< a linear method's OCIO processor
    OCIO_LUT,     ///< a non-linear method's OCIO processor, its LUT the size configs bake
    DIRECT_FIT,   ///< DirectForm::DIRECT_FIT
    NATIVE,       ///< DirectForm::NATIVE
    SPECTRAL,     ///< the 3 × 81 integration a spectral image needs per pixel
};

/// What applying a method to pixels costs on this machine.
struct CostRow
{
    std::string method;
    CostForm form = CostForm::OCIO_MATRIX;
    int threads = 1;
    double nsPerPixel = 0.0;

    /// The form's name in reports and JSON: "ocio-matrix", "ocio-lut65",
    /// "direct-fit", "native", "spectral-81".
    std::string formName() const;
};

/// One-off costs: fitting, LUT baking.
struct SetupCost
{
    std::string what;
    double seconds = 0.0;
};

/// Times every method applied to a float RGBA buffer of `pixels` pixels on
/// one thread and on all threads (best of three runs; `pixels` a multiple
/// of 1920, the rows of the buffer): linear methods and
/// upsample (as its 33³ LUT) through the OCIO CPU processor, upsample's
/// per-pixel fit directly, and `spectral` as the 3 × 81 integration a
/// spectral image would need per pixel.
/// rootpoly-camera is timed with `camera` and its IDT light (skipped
/// without a camera).
std::vector<CostRow> MeasureCost(const std::vector<std::string>& methods,
                                 const std::string& workingSpace, long pixels,
                                 const std::shared_ptr<const SpectralCamera>& camera = nullptr,
                                 const Light& idtLight = {});

/// Fitting fit3x3 and baking upsample LUTs at 17³, 33³ and 65³ (A → D65).
std::vector<SetupCost> MeasureSetupCost(const std::string& workingSpace);

}  // namespace bandlight::jobs
