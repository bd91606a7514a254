// SPDX-License-Identifier: BSD-3-Clause
#include "luts/LutEncoding.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{
// Academy S-2016-001 (ACEScct) and S-2014-003 (ACEScc): both are
// (log2 x + 9.72) / 17.52 above their toe.
constexpr double kLogOffset = 9.72;
constexpr double kLogScale = 17.52;
// ACEScct's linear toe below x = 2^-7, continuous with the log segment.
constexpr double kCctBreak = 0.0078125;
constexpr double kCctSlope = 10.5402377416545;
constexpr double kCctOffset = 0.0729055341958355;
constexpr double kCctEncodedBreak = 0.155251141552511;
// The largest half-float, where both specifications clamp their decoding.
constexpr double kHalfMax = 65504.0;
}  // namespace

LutEncoding ParseLutEncoding(const std::string& text)
{
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    if (t == "linear")
    {
        return LutEncoding::LINEAR;
    }
    if (t == "acescct")
    {
        return LutEncoding::ACESCCT;
    }
    if (t == "acescc")
    {
        return LutEncoding::ACESCC;
    }
    throw ParameterError("unknown LUT {encoding} '" + OneLine(text, 100) +
                         "' (linear, acescct, acescc)");
}

const char* LutEncodingName(LutEncoding encoding)
{
    switch (encoding)
    {
        case LutEncoding::LINEAR:
            return "linear";
        case LutEncoding::ACESCCT:
            return "acescct";
        case LutEncoding::ACESCC:
            return "acescc";
    }
    return "";
}

const char* LutEncodingTitle(LutEncoding encoding)
{
    switch (encoding)
    {
        case LutEncoding::LINEAR:
            return "linear";
        case LutEncoding::ACESCCT:
            return "ACEScct";
        case LutEncoding::ACESCC:
            return "ACEScc";
    }
    return "";
}

OCIO::TransformRcPtr LutEncodingTransform(LutEncoding encoding)
{
    switch (encoding)
    {
        case LutEncoding::LINEAR:
            return nullptr;
        case LutEncoding::ACESCCT:
        {
            OCIO::BuiltinTransformRcPtr t = OCIO::BuiltinTransform::Create();
            t->setStyle("CURVE - ACEScct-LOG_to_LINEAR");
            t->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
            return t;
        }
        case LutEncoding::ACESCC:
        {
            OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
            OCIO::BuiltinTransformRcPtr toAp0 = OCIO::BuiltinTransform::Create();
            toAp0->setStyle("ACEScg_to_ACES2065-1");
            g->appendTransform(toAp0);
            OCIO::BuiltinTransformRcPtr toCc = OCIO::BuiltinTransform::Create();
            toCc->setStyle("ACEScc_to_ACES2065-1");
            toCc->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
            g->appendTransform(toCc);
            return g;
        }
    }
    return nullptr;
}

double EncodeLut(LutEncoding encoding, double x) noexcept
{
    switch (encoding)
    {
        case LutEncoding::LINEAR:
            return x;
        case LutEncoding::ACESCCT:
            return x <= kCctBreak ? kCctSlope * x + kCctOffset
                                  : (std::log2(x) + kLogOffset) / kLogScale;
        case LutEncoding::ACESCC:
            if (x <= 0.0)
            {
                return (-16.0 + kLogOffset) / kLogScale;
            }
            if (x < std::exp2(-15.0))
            {
                return (std::log2(std::exp2(-16.0) + x * 0.5) + kLogOffset) / kLogScale;
            }
            return (std::log2(x) + kLogOffset) / kLogScale;
    }
    return x;
}

double DecodeLut(LutEncoding encoding, double y) noexcept
{
    const double top = (std::log2(kHalfMax) + kLogOffset) / kLogScale;
    switch (encoding)
    {
        case LutEncoding::LINEAR:
            return y;
        case LutEncoding::ACESCCT:
            if (y <= kCctEncodedBreak)
            {
                return (y - kCctOffset) / kCctSlope;
            }
            return y < top ? std::exp2(y * kLogScale - kLogOffset) : kHalfMax;
        case LutEncoding::ACESCC:
            if (y < (kLogOffset - 15.0) / kLogScale)
            {
                return (std::exp2(y * kLogScale - kLogOffset) - std::exp2(-16.0)) * 2.0;
            }
            return y < top ? std::exp2(y * kLogScale - kLogOffset) : kHalfMax;
    }
    return y;
}

std::string DescribeLutEncoding(LutEncoding encoding, const std::string& working)
{
    if (encoding == LutEncoding::LINEAR)
    {
        return "Input and output: " + working + " linear values.";
    }
    std::ostringstream o;
    o << std::setprecision(4) << "Input and output: " << LutEncodingTitle(encoding)
      << (encoding == LutEncoding::ACESCCT ? " (Academy S-2016-001)" : " (Academy S-2014-003)")
      << " of " << working << " linear values; encoded 0 to 1 is linear "
      << DecodeLut(encoding, 0.0) << " to " << DecodeLut(encoding, 1.0)
      << ", outside it the LUT clamps. No shaper.";
    return o.str();
}

}  // namespace bandlight
