// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/LightScores.h"

#include <cmath>

#include "spectral/Colorimetry.h"
#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/TelevisionLighting.h"

namespace bandlight
{

namespace
{

ScoreField Value(const char* name, double v)
{
    return {name, {v}, false, {}};
}

ScoreField List(const char* name, std::vector<double> v, std::vector<std::string> labels = {})
{
    return {name, std::move(v), true, std::move(labels)};
}

Score CctScore(const Spectrum& light, const ScoreContext&)
{
    const CctDuv c = ComputeCct(IntegrateXyz(light, Observer::CIE1931_2DEG));
    Score s{"cct", {Value("cct", c.cctK), Value("duv", c.duv)}, "", {}};
    if (std::abs(c.duv) > 0.05)
    {
        s.warnings.push_back("|Duv| " + std::to_string(std::abs(c.duv)).substr(0, 6) +
                             " > 0.05: CIE 15:2004 §9.5 says a CCT should not be given this far "
                             "from the Planckian locus");
    }
    return s;
}

Score CriScore(const Spectrum& light, const ScoreContext&)
{
    Score s{"cri", {}, "", {}};
    ColourRendering cr;
    try
    {
        cr = ComputeColourRendering(light);
    }
    catch (const Exception& e)
    {
        s.warnings.push_back(std::string("no value: ") + e.what());
        return s;
    }
    std::vector<std::string> labels;
    for (size_t i = 0; i < cr.r.size(); ++i)
    {
        labels.push_back("R" + std::to_string(i + 1));
    }
    s.fields = {Value("Ra", cr.ra), List("R", {cr.r.begin(), cr.r.end()}, labels)};
    s.reference = cr.cctK < 5000.0 ? "Planckian" : "CIE daylight";
    s.reference += " at " + std::to_string(std::lround(cr.cctK)) + " K";
    if (cr.outsideTolerance)
    {
        s.warnings.push_back(
            "|Duv| > 5.4e-3: CIE 13.3 does not consider Ra meaningful this far from the "
            "Planckian locus");
    }
    return s;
}

/// A TLCI or TLMF result as a score: Qa (TLCI) or the factor (TLMF), ΔEa,
/// and ΔE00 per chart patch (null where Tech 3355 leaves a patch out).
Score TelevisionScore(const char* key, const char* value, const TelevisionLightingScore& t)
{
    Score s{key, {Value(value, t.qa), Value("delta_Ea", t.deltaEa)}, t.referenceName, t.warnings};
    std::vector<std::string> labels;
    for (size_t i = 0; i < t.deltaE.size(); ++i)
    {
        labels.push_back("delta_E" + std::to_string(i + 1));
    }
    s.fields.push_back(List("delta_E", t.deltaE, labels));
    return s;
}

/// A score that needs a white balance a light cannot give (a red line)
/// has no value; the reason is its warning.
template <typename Compute>
Score Guarded(const char* key, Compute&& compute)
{
    try
    {
        return compute();
    }
    catch (const Exception& e)
    {
        return {key, {}, "", {std::string("no value: ") + e.what()}};
    }
}

Score TlciScore(const Spectrum& light, const ScoreContext&)
{
    return Guarded("tlci", [&] { return TelevisionScore("tlci", "Qa", ComputeTlci(light)); });
}

Score TlmfScore(const Spectrum& light, const ScoreContext& context)
{
    return Guarded("tlmf",
                   [&]
                   {
                       return TelevisionScore(
                           "tlmf", "value",
                           ComputeTlmf(light, *context.reference, context.referenceName));
                   });
}

// clang-format off
const std::vector<LightScoreEntry> kScores = {
    {"cct", "CCT", "Correlated colour temperature and Duv", "CIE 15:2004 §9.5",
     "The temperature of the Planckian radiator nearest in CIE 1960 (u, v), and the signed "
     "distance from it (positive above the locus, towards green), CIE 1931 observer.",
     "cct=CCT K:0,duv=Duv:4", false, true, CctScore},
    {"cri", "CRI", "Colour rendering index", "CIE 13.3-1995 (R15: JIS Z 8726)",
     "Ra, the mean of R1-R8, and R1-R15: 100 - 4.6 ΔE in CIE 1964 U*V*W* of the test colour "
     "samples under the light against a Planckian (< 5000 K) or daylight reference at its CCT.",
     "Ra,R9", false, false, CriScore},
    {"tlci", "TLCI", "Television lighting consistency index", "EBU Tech 3355 (TLCI-2012)",
     "Qa = 100 / (1 + (ΔEa / 3.16)^2.4): ΔE00 of the 18 coloured ColorChecker patches seen by "
     "the EBU standard camera (balanced on each light) and shown on a BT.709 display, under the "
     "light against Tech 3355's Planckian/daylight reference at its CCT.",
     "Qa=TLCI", false, false, TlciScore},
    {"tlmf", "TLMF", "Television luminaire matching factor", "EBU Tech 3355 (TLMF-2013), EBU R 137",
     "TLCI's camera and display with the reference light the user names: the camera balanced "
     "on the reference, the light seen through that balance at matched exposure, all 24 "
     "patches scored.",
     "value=TLMF", true, false, TlmfScore},
};
// clang-format on

}  // namespace

const ScoreField* Score::field(const std::string& name) const
{
    for (const ScoreField& f : fields)
    {
        if (f.name == name)
        {
            return &f;
        }
    }
    return nullptr;
}

const Score* LightQuality::score(const std::string& key) const
{
    for (const Score& s : scores)
    {
        if (s.key == key)
        {
            return &s;
        }
    }
    return nullptr;
}

const std::vector<LightScoreEntry>& LightScores()
{
    return kScores;
}

const LightScoreEntry& FindLightScore(const std::string& key)
{
    std::string keys;
    for (const LightScoreEntry& e : kScores)
    {
        if (key == e.key)
        {
            return e;
        }
        keys += (keys.empty() ? "" : ", ") + std::string(e.key);
    }
    throw ParameterError("unknown light score '" + OneLine(key, 40) + "' (the scores: " + keys +
                         ")");
}

LightQuality ScoreLight(const std::string& name, const Spectrum& light, const ScoreContext& context)
{
    LightQuality q;
    q.light = name;
    const Vec3 xyz = IntegrateXyz(light, Observer::CIE1931_2DEG);
    if (!(xyz.y() > 0.0) || !xyz.allFinite())
    {
        throw Exception("light '" + OneLine(name, 80) +
                        "' has no power in the visible range: no score can be given");
    }
    for (const LightScoreEntry& e : kScores)
    {
        if (e.needsReference && !context.reference)
        {
            continue;
        }
        q.scores.push_back(e.compute(light, context));
        q.scores.back().key = e.key;
    }
    return q;
}

}  // namespace bandlight
