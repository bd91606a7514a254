// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/LutJob.h"

#include <memory>

#include "farm/OutputPaths.h"
#include "plugin/OcioTransforms.h"

namespace bandlight::jobs
{

LutResult MakeLut(const LutRequest& r, Reporter& reporter)
{
    OutputPlan().file("{out}", r.out).check();
    LutResult result;
    LutOptions options;
    options.format = LutFormatForPath(r.out, r.format);
    options.size = r.size.value_or(defaults::LUT_SIZE);
    options.forceLattice = r.size.has_value();
    options.shaper = ShaperSpec::Parse(r.shaper);
    options.encoding = ParseLutEncoding(r.encoding);
    const MethodSpec method = r.relight.methodSpec(reporter);
    const RgbSpace& working = r.relight.working();
    const Observer observer = ParseObserver(r.relight.observer);
    result.encodingDescription = DescribeLutEncoding(options.encoding, working.displayName);
    if (options.encoding != LutEncoding::LINEAR && working.name != "acescg")
    {
        // ACEScct and ACEScc are defined on AP1: the curve applied to another
        // space's linear values is that space's own log encoding.
        reporter.note(std::string("the LUT's ") + LutEncodingTitle(options.encoding) +
                      " curve encodes " + working.displayName + " linear values, not " +
                      LutEncodingTitle(options.encoding) +
                      "'s ACEScg (AP1); with the working space acescg it is " +
                      LutEncodingTitle(options.encoding) + " itself");
    }
    if (method.isLinear())
    {
        const OCIO_NAMESPACE::GroupTransformRcPtr exact =
            IlluminantChangeTransform(r.relight.src, r.relight.dst, method, working, observer);
        if (options.encoding != LutEncoding::LINEAR)
        {
            options.description = TransformDescription(exact) + " " + result.encodingDescription;
        }
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
        options.description =
            LookDescription(r.relight.src, r.relight.dst, method, working, observer);
        if (options.encoding != LutEncoding::LINEAR)
        {
            options.description += " " + result.encodingDescription;
        }
        result.files = WriteLut([relighter](float* rgb, size_t n) { relighter->apply(rgb, n); },
                                options, r.out);
    }
    result.size = options.size;
    result.shaper = options.shaper.alignedTo(options.size);
    return result;
}

}  // namespace bandlight::jobs
