// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/LutJob.h"

#include <memory>

#include "plugin/OcioTransforms.h"

namespace bandlight::jobs
{

LutResult MakeLut(const LutRequest& r, Reporter& reporter)
{
    LutResult result;
    LutOptions options;
    options.format = ParseLutFormat(r.format);
    options.size = r.size.value_or(defaults::LUT_SIZE);
    options.forceLattice = r.size.has_value();
    options.shaper = ShaperSpec::Parse(r.shaper);
    const MethodSpec method = r.relight.methodSpec(reporter);
    const RgbSpace& working = r.relight.working();
    const Observer observer = ParseObserver(r.relight.observer);
    if (method.isLinear())
    {
        const OCIO_NAMESPACE::GroupTransformRcPtr exact =
            IlluminantChangeTransform(r.relight.src, r.relight.dst, method, working, observer);
        result.files = WriteLut(exact, true, options, r.out);
    }
    else
    {
        // Baked straight from the per-pixel spectral fit, not from a lattice.
        const auto relighter =
            std::make_shared<Relighter>(r.relight.src, r.relight.dst, method, working, observer);
        if (options.shaper.kind == ShaperSpec::Kind::LOG2)
        {
            options.shaper = ShaperSpec::ForNonLinear();
        }
        options.description = "Relight from " + r.relight.src.name + " to " + r.relight.dst.name +
                              " in " + working.displayName + ". " + DescribeMethod(method) + " " +
                              method.plates.describe(working.displayName);
        result.files = WriteLut([relighter](float* rgb, size_t n) { relighter->apply(rgb, n); },
                                options, r.out);
    }
    result.size = options.size;
    result.shaper = options.shaper.alignedTo(options.size);
    return result;
}

}  // namespace bandlight::jobs
