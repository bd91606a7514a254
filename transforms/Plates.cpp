// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Plates.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/TextFile.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

std::string Plates::key() const
{
    return balanced() ? "balanced-" + AdaptationName(adaptation) : "lit";
}

namespace
{
/// What the description says of neutrals: generated from what the look
/// does to 0.18 grey, so it cannot claim what the look does not do.
std::string NeutralClause(const Vec3* grey)
{
    const bool neutral = !grey || (grey->minCoeff() > 0.0 &&
                                   grey->maxCoeff() / grey->minCoeff() - 1.0 < 1e-3);
    if (neutral)
    {
        return "so neutrals stay neutral.";
    }
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "but the method is not exact on white: 0.18 grey becomes (%.3f, %.3f, %.3f).",
                  grey->x(), grey->y(), grey->z());
    return buf;
}
}  // namespace

std::string Plates::describe(const std::string& workingSpaceName, const Vec3* grey) const
{
    if (!balanced())
    {
        return "For lit plates: images that carry the source light's cast, as the eye would "
               "record them without adapting.";
    }
    return std::string("For white-balanced plates (the ACES convention): images balanced to ") +
           workingSpaceName + "'s white by " +
           (adaptation == AdaptationMethod::BRADFORD ? "Bradford" : "CAT02") +
           "; the look undoes that balance, changes the light and balances again, " +
           NeutralClause(grey);
}

const std::vector<PlateConventionEntry>& PlateConventions()
{
    static const std::vector<PlateConventionEntry> table = {
        {PlateConvention::LIT, "lit",
         "carrying the source light's cast, which the look removes"},
        {PlateConvention::BALANCED, "balanced",
         "white-balanced to the working white, as every ACES IDT delivers them: the look keeps "
         "neutrals neutral and changes only the light's colour rendering"},
    };
    return table;
}

const std::vector<AdaptationEntry>& PlateAdaptations()
{
    // CAT02 is what rawtoaces balances with; Bradford is common in camera
    // vendors' IDTs and ICC profiles.
    static const std::vector<AdaptationEntry> table = []
    {
        std::vector<AdaptationEntry> t;
        for (const AdaptationMethod m : {AdaptationMethod::CAT02, AdaptationMethod::BRADFORD})
        {
            for (const AdaptationEntry& e : AdaptationMethods())
            {
                if (e.method == m)
                {
                    t.push_back(e);
                }
            }
        }
        return t;
    }();
    return table;
}

std::string PlateConventionChoices()
{
    std::string list;
    for (const PlateConventionEntry& e : PlateConventions())
    {
        list += (list.empty() ? "" : ", ") + std::string(e.key);
    }
    return list;
}

std::string PlateAdaptationChoices()
{
    std::string list;
    for (const AdaptationEntry& e : PlateAdaptations())
    {
        list += (list.empty() ? "" : ", ") + std::string(e.key);
    }
    return list;
}

Plates ParsePlates(const std::string& convention, const std::string& adaptation)
{
    Plates p;
    const std::string c = ToLower(convention);
    const auto conv = std::find_if(PlateConventions().begin(), PlateConventions().end(),
                                   [&](const PlateConventionEntry& e) { return c == e.key; });
    if (conv == PlateConventions().end())
    {
        throw Exception("unknown plates '" + convention + "' (" + PlateConventionChoices() + ")");
    }
    p.convention = conv->convention;
    const std::string a = ToLower(adaptation);
    const auto adapt = std::find_if(PlateAdaptations().begin(), PlateAdaptations().end(),
                                    [&](const AdaptationEntry& e) { return a == e.key; });
    if (adapt == PlateAdaptations().end())
    {
        throw Exception("unknown adaptation '" + adaptation + "' (" + PlateAdaptationChoices() +
                        ")");
    }
    p.adaptation = adapt->method;
    return p;
}

Vec3 WorkingWhiteXyz(const RgbSpace& working)
{
    return RgbToXyzMatrix(working.chromaticities) * Vec3::Ones();
}

Mat3 BalanceMatrix(const Spectrum& light, const RgbSpace& working, AdaptationMethod adaptation,
                   Observer observer)
{
    const SurfaceRenderer r(light, working, observer);
    const Vec3 white = r.rgbToXyz() * r.white();
    if (!(white.y() > 0.0) || !white.allFinite())
    {
        throw Exception("an illuminant with no luminance cannot be balanced");
    }
    return r.rgbToXyz().inverse() * AdaptationMatrix(white, WorkingWhiteXyz(working), adaptation) *
           r.rgbToXyz();
}

}  // namespace bandlight
