// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/OcioTransforms.h"

#include <Eigen/LU>

#include "luts/LutWriter.h"
#include "spectral/Exception.h"

namespace bandlight
{

OCIO::MatrixTransformRcPtr MakeMatrixTransform(const Mat3& m)
{
    // clang-format off
    const double m44[16] = {m(0, 0), m(0, 1), m(0, 2), 0.0,
                            m(1, 0), m(1, 1), m(1, 2), 0.0,
                            m(2, 0), m(2, 1), m(2, 2), 0.0,
                            0.0,     0.0,     0.0,     1.0};
    // clang-format on
    OCIO::MatrixTransformRcPtr t = OCIO::MatrixTransform::Create();
    t->setMatrix(m44);
    return t;
}

OCIO::RangeTransformRcPtr InfinityGuard()
{
    OCIO::RangeTransformRcPtr r = OCIO::RangeTransform::Create();
    r->setStyle(OCIO::RANGE_CLAMP);
    r->setMinInValue(-INFINITY_GUARD);
    r->setMinOutValue(-INFINITY_GUARD);
    r->setMaxInValue(INFINITY_GUARD);
    r->setMaxOutValue(INFINITY_GUARD);
    return r;
}

OCIO::GroupTransformRcPtr GuardedMatrixTransform(const Mat3& m)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(InfinityGuard());
    g->appendTransform(MakeMatrixTransform(m));
    g->appendTransform(InfinityGuard());
    return g;
}

namespace
{
OCIO::GroupTransformRcPtr Group(const Mat3& m, const std::string& name,
                                const std::string& description)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    OCIO::FormatMetadata& md = g->getFormatMetadata();
    md.setName(name.c_str());
    md.setID(name.c_str());
    md.addChildElement(OCIO::METADATA_DESCRIPTION, description.c_str());
    g->appendTransform(InfinityGuard());
    g->appendTransform(MakeMatrixTransform(m));
    return g;
}
}  // namespace

OCIO::GroupTransformRcPtr IlluminantChangeTransform(const Light& from, const Light& to,
                                                    const MethodSpec& method,
                                                    const RgbSpace& working, Observer observer,
                                                    int lutSize)
{
    const std::string name = LookName(method.name, from.name, to.name);
    const std::string description = LookDescription(from, to, method, working, observer);
    auto relighter = std::make_shared<Relighter>(from, to, method, working, observer);
    if (relighter->isLinear())
    {
        return Group(relighter->matrix(), name, description);
    }
    const ShaperSpec shaper = ShaperSpec::ForNonLinear().alignedTo(lutSize);
    // upsample fits every pixel at one level: neighbouring lattice nodes on
    // one ray through black share their fit (the cache), so a 33^3 lattice
    // needs about a tenth of the fits.
    // For balanced plates the whole method is baked, balance included: a
    // balanced grey lies on the lattice's diagonal, where the log2 shaper
    // makes the exact transform linear and the LUT reproduces it to float
    // precision. For lit plates an input matrix (rootpoly-camera's way back
    // to the camera's record) stays exact in front of the LUT, which then
    // sees colours where plain lit looks' LUTs do: lit plates under a warm
    // light crowd the lattice's blue face, where the function's negative
    // neighbours are clamped.
    const Mat3* input = method.plates.balanced() ? nullptr : relighter->inputMatrix();
    OCIO::GroupTransformRcPtr g = LatticeTransform(
        [relighter, input](float* rgb, size_t count)
        { input ? relighter->applyAfterInput(rgb, count) : relighter->apply(rgb, count); },
        shaper, lutSize);
    if (input)
    {
        OCIO::GroupTransformRcPtr lattice = g;
        g = OCIO::GroupTransform::Create();
        g->appendTransform(InfinityGuard());
        g->appendTransform(MakeMatrixTransform(*input));
        for (int i = 0; i < lattice->getNumTransforms(); ++i)
        {
            g->appendTransform(lattice->getTransform(i)->createEditableCopy());
        }
    }
    OCIO::FormatMetadata& md = g->getFormatMetadata();
    md.setName(name.c_str());
    md.setID(name.c_str());
    md.addChildElement(OCIO::METADATA_DESCRIPTION, (description + " " + std::to_string(lutSize) +
                                                    "^3 LUT, shaper " + shaper.describe() + ".")
                                                       .c_str());
    return g;
}

OCIO::GroupTransformRcPtr BandSpaceTransform(const BandSet& bands, const RgbSpace& working,
                                             Observer observer)
{
    if (bands.size() != 3)
    {
        throw Exception("a band colour space needs three bands, got " +
                        std::to_string(bands.size()));
    }
    const Mat3 m = WorkingToBandMatrix(bands, working, observer);
    return Group(m, "bands_" + SafeName(bands.describe()),
                 "Working RGB to radiometric band values over " + bands.describe() + " nm");
}

OCIO::GroupTransformRcPtr MaterialTintTransform(const std::vector<double>& remittance,
                                                const BandSet& bands, const RgbSpace& working,
                                                Observer observer)
{
    const Mat3 m = MaterialTintMatrix(remittance, bands, working, observer);
    return Group(m, "material_tint",
                 "Band-space remittance (R_diff) over " + bands.describe() + " nm, in " +
                     working.displayName);
}

Mat3 MeasureMatrix(const OCIO::ConstProcessorRcPtr& processor)
{
    const OCIO::ConstCPUProcessorRcPtr cpu = processor->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
    Mat3 out;
    for (int c = 0; c < 3; ++c)
    {
        float rgb[3] = {0.0f, 0.0f, 0.0f};
        rgb[c] = 1.0f;
        cpu->applyRGB(rgb);
        for (int r = 0; r < 3; ++r)
        {
            out(r, c) = rgb[r];
        }
    }
    return out;
}

std::string SafeName(const std::string& text)
{
    std::string s = text;
    for (char& c : s)
    {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
        if (!ok)
        {
            c = '_';
        }
    }
    return s;
}

std::string LookName(const std::string& method, const std::string& from, const std::string& to)
{
    return SafeName(method) + "_" + SafeName(from) + "_to_" + SafeName(to);
}

}  // namespace bandlight
