// SPDX-License-Identifier: BSD-3-Clause
#include "luts/Shaper.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{
/// Parameters y = slope · log2(x) + offset above the break, derived so that
/// y(minLinear) = 0 on the linear extension and y(maxLinear) = 1.
struct LogParams
{
    double slope;
    double offset;
};

LogParams Params(const ShaperSpec& s)
{
    const double ln2 = std::log(2.0);
    // Below the break y is linear with the log side's slope at the break:
    // y(x) = y_b + (x - b) / (S ln2 b) with S the span in stops. Setting
    // y(minLinear) = 0 fixes the stop that y = 0 would have on the log side.
    const double b = s.breakLinear;
    const double stopsBelow = (b - s.minLinear) / (ln2 * b);
    const double s0 = std::log2(b) - stopsBelow;
    const double span = std::log2(s.maxLinear) - s0;
    return {1.0 / span, -s0 / span};
}
}  // namespace

ShaperSpec ShaperSpec::Parse(const std::string& text)
{
    ShaperSpec s;
    if (text == "log2")
    {
        s.kind = Kind::LOG2;
    }
    else if (text == "none")
    {
        s.kind = Kind::NONE;
    }
    else
    {
        throw Exception("unknown shaper '" + text + "' (log2 or none)");
    }
    return s;
}

std::string ShaperSpec::describe() const
{
    if (kind == Kind::NONE)
    {
        return "none: the LUT covers linear 0 to 1";
    }
    std::ostringstream o;
    o << "log2: linear " << minLinear << " to " << maxLinear << " mapped to 0 to 1, linear below "
      << breakLinear << ", log2 above; input outside " << minLinear << " to " << maxLinear
      << " is clamped to it, NaN to " << minLinear;
    return o.str();
}

ShaperSpec ShaperSpec::alignedTo(int size) const
{
    if (kind == Kind::NONE || size < 3 || !(minLinear < 0.0))
    {
        return *this;
    }
    // With u = -min / (ln2 · b) the stops of the linear toe below zero and
    // C = log2(max / b) + 1/ln2, zero encodes to u / (C + u). Choose u so
    // that this is k / (size - 1) for the nearest k >= 1.
    const double ln2 = std::log(2.0);
    const double b = breakLinear;
    const double c = std::log2(maxLinear / b) + 1.0 / ln2;
    const double u = -minLinear / (ln2 * b);
    const double n = double(size - 1);
    const double k = std::max(1.0, std::round(n * u / (c + u)));
    ShaperSpec out = *this;
    out.minLinear = -(k * c / (n - k)) * ln2 * b;
    return out;
}

OCIO::TransformRcPtr ShaperSpec::transform() const
{
    if (kind == Kind::NONE)
    {
        return nullptr;
    }
    const LogParams p = Params(*this);
    const double brk[3] = {breakLinear, breakLinear, breakLinear};
    OCIO::LogCameraTransformRcPtr t = OCIO::LogCameraTransform::Create(brk);
    t->setBase(2.0);
    const double slope[3] = {p.slope, p.slope, p.slope};
    const double offset[3] = {p.offset, p.offset, p.offset};
    t->setLogSideSlopeValue(slope);
    t->setLogSideOffsetValue(offset);
    return t;
}

double ShaperSpec::encode(double x) const noexcept
{
    if (kind == Kind::NONE)
    {
        return x;
    }
    const LogParams p = Params(*this);
    const double yb = p.slope * std::log2(breakLinear) + p.offset;
    if (x >= breakLinear)
    {
        return p.slope * std::log2(x) + p.offset;
    }
    return yb + (x - breakLinear) * p.slope / (std::log(2.0) * breakLinear);
}

double ShaperSpec::decode(double y) const noexcept
{
    if (kind == Kind::NONE)
    {
        return y;
    }
    const LogParams p = Params(*this);
    const double yb = p.slope * std::log2(breakLinear) + p.offset;
    if (y >= yb)
    {
        return std::exp2((y - p.offset) / p.slope);
    }
    return breakLinear + (y - yb) * std::log(2.0) * breakLinear / p.slope;
}

}  // namespace bandlight
