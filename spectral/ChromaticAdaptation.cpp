// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/ChromaticAdaptation.h"

#include <algorithm>
#include <cctype>

#include <Eigen/LU>

#include "spectral/Exception.h"

namespace bandlight
{

const std::vector<AdaptationEntry>& AdaptationMethods()
{
    static const std::vector<AdaptationEntry> methods = {
        {AdaptationMethod::XYZ_SCALING, "vonkries", {"von-kries", "xyz", "xyz-scaling"}},
        {AdaptationMethod::BRADFORD, "bradford", {}},
        {AdaptationMethod::CAT02, "cat02", {}},
        {AdaptationMethod::SHARP, "sharp", {}},
    };
    return methods;
}

AdaptationMethod ParseAdaptationMethod(const std::string& text)
{
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    std::string names;
    for (const AdaptationEntry& e : AdaptationMethods())
    {
        if (t == e.key || std::find(e.aliases.begin(), e.aliases.end(), t) != e.aliases.end())
        {
            return e.method;
        }
        names += (names.empty() ? "" : ", ") + std::string(e.key);
    }
    throw Exception("unknown chromatic adaptation '" + text + "' (" + names + ")");
}

std::string AdaptationName(AdaptationMethod method)
{
    for (const AdaptationEntry& e : AdaptationMethods())
    {
        if (e.method == method)
        {
            return e.key;
        }
    }
    throw Exception("adaptation method " + std::to_string(int(method)) + " is not in the table");
}

Mat3 ConeResponseMatrix(AdaptationMethod method)
{
    Mat3 m;
    switch (method)
    {
        case AdaptationMethod::XYZ_SCALING:
            m.setIdentity();
            break;
        case AdaptationMethod::BRADFORD:
            // clang-format off
            m <<  0.8951,  0.2664, -0.1614,
                 -0.7502,  1.7135,  0.0367,
                  0.0389, -0.0685,  1.0296;
            break;
        case AdaptationMethod::CAT02:
            m <<  0.7328,  0.4296, -0.1624,
                 -0.7036,  1.6975,  0.0061,
                  0.0030,  0.0136,  0.9834;
            break;
        case AdaptationMethod::SHARP:
            // S. Süsstrunk, J. Holm, G. D. Finlayson, "Chromatic adaptation
            // performance of different RGB sensors", Proc. SPIE 4300 (2001).
            m <<  1.2694, -0.0988, -0.1706,
                 -0.8364,  1.8006,  0.0357,
                  0.0297, -0.0315,  1.0018;
            // clang-format on
            break;
    }
    return m;
}

Mat3 AdaptationMatrix(const Vec3& srcWhiteXyz, const Vec3& dstWhiteXyz, AdaptationMethod method)
{
    const Mat3 m = ConeResponseMatrix(method);
    const Vec3 src = m * srcWhiteXyz;
    const Vec3 dst = m * dstWhiteXyz;
    if ((src.array() == 0.0).any() || !src.allFinite() || !dst.allFinite())
    {
        throw Exception("chromatic adaptation: the source white has a zero cone response");
    }
    return m.inverse() * dst.cwiseQuotient(src).asDiagonal() * m;
}

}  // namespace bandlight
