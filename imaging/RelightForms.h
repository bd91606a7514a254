// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A change of light or a look of a config as an image's pixels get it:
// natively (a method's own op, the guarded 3×3 of a linear one, a config's
// look that optimises to a clamp and a matrix) or through its OCIO
// processor. `apply`, its mattes and light groups, and the light-group
// accuracy all take their pixels' work from here.

#include <functional>
#include <optional>
#include <string>

#include <OpenColorIO/OpenColorIO.h>

#include "farm/Reporter.h"
#include "imaging/ImageApply.h"
#include "requests/Apply.h"

namespace bandlight::jobs
{

/// A change of light as the pixels get it: natively (rootpoly, the
/// guarded 3×3 of the linear methods) or through its OCIO processor.
struct RelightForm
{
    OCIO::ConstProcessorRcPtr processor;
    std::function<void(float*, size_t)> native;
    std::optional<ClampMatrixKernel> kernel;
    std::string applied;

    BufferWork work(int threads) const
    {
        return kernel   ? KernelWork(*kernel, threads)
               : native ? RgbWork(native, threads)
                        : ProcessorWork(processor->getOptimizedCPUProcessor(
                                            OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                            OCIO::OPTIMIZATION_DEFAULT),
                                        threads);
    }
};

RelightForm MakeRelightForm(const RelightRequest& relight, Reporter& reporter);

/// The colour space of `config` a look is applied in: {colorspace}, or
/// scene_linear. Throws Exception when the config has no such space.
std::string LookSpace(const ApplyRequest& request, const OCIO::ConstConfigRcPtr& config);

/// A look of the request's config as the pixels get it, as `apply --look`
/// applies it: from LookSpace to itself through the config's own
/// processor; natively when that optimises to a clamp and a matrix (any
/// config's, read back from OCIO). Throws Exception when the config has no
/// such look (checked first) or colour space.
RelightForm MakeLookForm(const ApplyRequest& request, const OCIO::ConstConfigRcPtr& config,
                         const std::string& look);

/// The linear space an image is converted to for a config's looks: the
/// config's scene_linear, whose primaries the config shows; nullptr (the
/// pixels go to the looks as they are) when the user named the image's
/// colour space in the config, or when scene_linear's primaries are
/// unknown (`unknown` then says why).
const RgbSpace* LookWorkingSpace(const ApplyRequest& request, const OCIO::ConstConfigRcPtr& config,
                                 std::string& unknown);

}  // namespace bandlight::jobs
