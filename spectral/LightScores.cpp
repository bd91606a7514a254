// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/LightScores.h"

#include <cmath>

#include "spectral/Colorimetry.h"
#include "spectral/ColourFidelity.h"
#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/SpectralSimilarity.h"
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

/// Labels "<name>1"… for a list of `n`.
std::vector<std::string> Numbered(const std::string& name, size_t n)
{
    std::vector<std::string> labels;
    for (size_t i = 0; i < n; ++i)
    {
        labels.push_back(name + std::to_string(i + 1));
    }
    return labels;
}

/// A score that needs a value a light cannot give (a CCT outside a
/// standard's range, a white balance on a red line) has no value; the
/// reason is its warning.
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

Score CriScore(const Spectrum& light, const ScoreContext&)
{
    return Guarded("cri",
                   [&]
                   {
                       const ColourRendering cr = ComputeColourRendering(light);
                       Score s{"cri",
                               {Value("Ra", cr.ra),
                                List("R", {cr.r.begin(), cr.r.end()}, Numbered("R", cr.r.size()))},
                               std::string(cr.cctK < 5000.0 ? "Planckian" : "CIE daylight") +
                                   " at " + std::to_string(std::lround(cr.cctK)) + " K",
                               {}};
                       if (cr.outsideTolerance)
                       {
                           s.warnings.push_back(
                               "|Duv| > 5.4e-3: CIE 13.3 does not consider Ra meaningful this "
                               "far from the Planckian locus");
                       }
                       return s;
                   });
}

Score Cie2017Score(const Spectrum& light, const ScoreContext&)
{
    return Guarded(
        "cie2017",
        [&]
        {
            // As the CIE 224:2017 calculator computes it (5 nm data
            // at 5 nm).
            const ColourFidelity f = ComputeColourFidelity(light, FidelityMethod::CIE_224);
            return Score{"cie2017",
                         {Value("Rf", f.rf), List("Rf_i", {f.rfSample.begin(), f.rfSample.end()},
                                                  Numbered("Rf_", CES_COUNT))},
                         f.referenceName,
                         f.warnings};
        });
}

Score Tm30Score(const Spectrum& light, const ScoreContext&)
{
    return Guarded("tm30",
                   [&]
                   {
                       // As the ANSI/IES TM-30 calculator computes it (every
                       // grid brought to 1 nm); the same Rf as CIE 224 for
                       // data at 1 nm.
                       const ColourFidelity f = ComputeColourFidelity(light, FidelityMethod::TM_30);
                       return Score{"tm30",
                                    {Value("Rf", f.rf), Value("Rg", f.rg),
                                     List("Rf_h", {f.rfHue.begin(), f.rfHue.end()},
                                          Numbered("Rf_h", HUE_BIN_COUNT)),
                                     List("Rcs_h", {f.chromaShift.begin(), f.chromaShift.end()},
                                          Numbered("Rcs_h", HUE_BIN_COUNT)),
                                     List("Rhs_h", {f.hueShift.begin(), f.hueShift.end()},
                                          Numbered("Rhs_h", HUE_BIN_COUNT))},
                                    f.referenceName,
                                    f.warnings};
                   });
}

Score SsiScore(const Spectrum& light, const ScoreContext& context)
{
    return Guarded("ssi",
                   [&]
                   {
                       const SpectralSimilarity s =
                           context.reference ? ComputeSpectralSimilarity(light, *context.reference,
                                                                         context.referenceName)
                                             : ComputeSpectralSimilarity(light);
                       return Score{"ssi",
                                    {Value("value", s.ssi), Value("unrounded", s.unrounded)},
                                    s.referenceName,
                                    s.warnings};
                   });
}

/// A TLCI or TLMF result as a score: Qa (TLCI) or the factor (TLMF), ΔEa,
/// and ΔE00 per chart patch (null where Tech 3355 leaves a patch out).
Score TelevisionScore(const char* key, const char* value, const TelevisionLightingScore& t)
{
    Score s{key, {Value(value, t.qa), Value("delta_Ea", t.deltaEa)}, t.referenceName, t.warnings};
    s.fields.push_back(List("delta_E", t.deltaE, Numbered("delta_E", t.deltaE.size())));
    return s;
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
    {"cie2017", "Rf", "Colour fidelity index", "CIE 224:2017",
     "Rf = 10 ln(exp((100 - 6.73 ΔE')/10) + 1), ΔE' the mean CAM02-UCS difference of the 99 "
     "colour evaluation samples (CIE 1964 10° observer) under the light and under a Planckian "
     "(< 4000 K), daylight (> 5000 K) or blended reference at its CCT; as the CIE calculator "
     "computes it.",
     "Rf", false, false, Cie2017Score},
    {"tm30", "TM-30", "IES method for evaluating light source colour rendition",
     "ANSI/IES TM-30-20 (TM-30-18)",
     "Rf as CIE 224 (as the IES calculator computes it: data brought to 1 nm), the gamut index "
     "Rg (the area of the 16 hue bins' mean a'b' polygon against the reference's, x100), and "
     "per hue bin the fidelity Rf,h, chroma shift Rcs,h (a fraction) and hue shift Rhs,h.",
     "Rg", false, false, Tm30Score},
    {"ssi", "SSI", "Spectral similarity index", "Academy S-2018-001 (SMPTE ST 2122)",
     "How closely the spectrum follows a reference's over 375-675 nm in 10 nm bins, weighted "
     "and smoothed, 100 for proportional spectra; camera-agnostic. The reference: Planckian "
     "up to 4000 K, CIE daylight from 5000 K, blended between as CIE 224 blends, at the "
     "light's CCT, or --reference.",
     "value=SSI:0", false, false, SsiScore},
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
