// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/SceneLinearEvidence.h"

#include "plugin/ConfigReferences.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/TextFile.h"

namespace bandlight
{

namespace
{

/// A standard encoding, as the function that undoes it (encoded → linear).
struct Decoding
{
    const char* name;
    bool linear;  ///< no encoding at all
    std::function<double(double)> decode;
};

double SignedPow(double v, double p)
{
    return v < 0.0 ? -std::pow(-v, p) : std::pow(v, p);
}

const std::vector<Decoding>& Decodings()
{
    static const std::vector<Decoding> d = {
        {"linear", true, [](double v) { return v; }},
        {"the sRGB curve (IEC 61966-2-1)", false,
         [](double v)
         {
             const double a = std::abs(v);
             const double l = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
             return v < 0.0 ? -l : l;
         }},
        {"gamma 2.2", false, [](double v) { return SignedPow(v, 2.2); }},
        {"gamma 2.4 (BT.1886)", false, [](double v) { return SignedPow(v, 2.4); }},
        {"gamma 2.6", false, [](double v) { return SignedPow(v, 2.6); }},
        {"the BT.709 OETF", false,
         [](double v)
         {
             const double a = std::abs(v);
             const double l = a < 0.081 ? a / 4.5 : std::pow((a + 0.099) / 1.099, 1.0 / 0.45);
             return v < 0.0 ? -l : l;
         }},
    };
    return d;
}

/// The interchange roles, whose meaning OCIO defines.
enum class InterchangeRole
{
    NONE,
    DISPLAY,  ///< cie_xyz_d65_interchange: CIE XYZ with a D65 white
    SCENE,    ///< aces_interchange: ACES2065-1 (AP0 primaries)
};

const char* RoleName(InterchangeRole role)
{
    return role == InterchangeRole::DISPLAY ? OCIO::ROLE_INTERCHANGE_DISPLAY
                                            : OCIO::ROLE_INTERCHANGE_SCENE;
}

/// A standard target a colour space may hold: its matrix from primaries P.
struct Target
{
    std::string name;
    std::vector<std::string> keywords;  ///< lower-case words that name it
    std::function<std::vector<Mat3>(const RgbSpace&)> fromPrimaries;  ///< accepted matrices
    InterchangeRole role;  ///< the interchange role whose space this target is, if any
};

Mat3 Adapt(const Vec3& from, const Vec3& to, AdaptationMethod m)
{
    return (from - to).norm() < 1e-9 ? Mat3::Identity() : AdaptationMatrix(from, to, m);
}

Vec3 White(const RgbSpace& s)
{
    return WhiteXyz(s.chromaticities.wx, s.chromaticities.wy);
}

std::vector<Target> Targets()
{
    std::vector<Target> t;
    const RgbSpace* ap0 = &Aces2065Space();
    for (const RgbSpace& target : BuiltinRgbSpaces())
    {
        const RgbSpace* tp = &target;
        t.push_back({target.displayName, target.keywords,
                     [tp](const RgbSpace& p)
                     {
                         const Mat3 to = RgbToXyzMatrix(tp->chromaticities).inverse();
                         const Mat3 from = RgbToXyzMatrix(p.chromaticities);
                         return std::vector<Mat3>{
                             to * Adapt(White(p), White(*tp), AdaptationMethod::BRADFORD) * from,
                             to * Adapt(White(p), White(*tp), AdaptationMethod::CAT02) * from};
                     },
                     tp == ap0 ? InterchangeRole::SCENE : InterchangeRole::NONE});
    }
    const auto xyz = [](const Vec3& white)
    {
        return [white](const RgbSpace& p)
        {
            const Mat3 from = RgbToXyzMatrix(p.chromaticities);
            return std::vector<Mat3>{Adapt(White(p), white, AdaptationMethod::BRADFORD) * from,
                                     Adapt(White(p), white, AdaptationMethod::CAT02) * from};
        };
    };
    t.push_back(
        {"CIE XYZ (D65 white)", {"xyz"}, xyz(WhiteXyz(0.3127, 0.3290)), InterchangeRole::DISPLAY});
    t.push_back(
        {"CIE XYZ (equal-energy white)", {"xyz"}, xyz(Vec3(1.0, 1.0, 1.0)), InterchangeRole::NONE});
    t.push_back({"CIE XYZ (the space's own white)",
                 {"xyz"},
                 [](const RgbSpace& p)
                 { return std::vector<Mat3>{RgbToXyzMatrix(p.chromaticities)}; },
                 InterchangeRole::NONE});
    return t;
}

/// The words a colour space is known by: name, aliases, family, lower-case.
std::string NamesOf(const OCIO::ConstColorSpaceRcPtr& cs)
{
    std::string all = ToLower(cs->getName()) + " " + ToLower(cs->getFamily());
    for (size_t i = 0; i < cs->getNumAliases(); ++i)
    {
        all += " " + ToLower(cs->getAlias(i));
    }
    return all;
}

/// What one measurement showed.
struct Finding
{
    const RgbSpace* primaries;
    std::string evidence;
    int trust;  ///< 2: interchange role, 1: a named standard space, 0: a matrix alone
};

/// 64 colours in (0.02, 0.9)³, the same each run.
std::vector<Vec3> Probes()
{
    std::vector<Vec3> v;
    for (int i = 0; i < 64; ++i)
    {
        const double a = 0.02 + 0.88 * ((i * 37 % 64) / 63.0);
        const double b = 0.02 + 0.88 * ((i * 11 % 64) / 63.0);
        const double c = 0.02 + 0.88 * ((i * 53 % 64) / 63.0);
        v.emplace_back(a, b, c);
    }
    return v;
}

/// Fits scene_linear → decode(C) as a 3×3; false when it is not one.
bool FitMatrix(const OCIO::ConstCPUProcessorRcPtr& cpu, const Decoding& d, Mat3& m)
{
    static const std::vector<Vec3> probes = Probes();
    Eigen::MatrixXd x(3, probes.size()), y(3, probes.size());
    for (size_t i = 0; i < probes.size(); ++i)
    {
        float rgb[3] = {float(probes[i].x()), float(probes[i].y()), float(probes[i].z())};
        cpu->applyRGB(rgb);
        for (int c = 0; c < 3; ++c)
        {
            if (!std::isfinite(rgb[c]))
            {
                return false;
            }
            x(c, Eigen::Index(i)) = probes[i][c];
            y(c, Eigen::Index(i)) = d.decode(rgb[c]);
        }
    }
    m = y * x.transpose() * (x * x.transpose()).inverse();
    const Eigen::MatrixXd fitted = m * x;
    const double scale = std::max(1e-6, y.cwiseAbs().maxCoeff());
    return (fitted - y).cwiseAbs().maxCoeff() <= 1e-3 * scale && m.allFinite() &&
           std::abs(m.determinant()) > 1e-6;
}

/// A colour space scene_linear is measured against.
struct Candidate
{
    OCIO::ConstColorSpaceRcPtr cs;
    InterchangeRole role;  ///< the interchange role it was found through, if any
};

/// The interchange roles first, then every other colour space that is not
/// data.
std::vector<Candidate> Candidates(const OCIO::ConstConfigRcPtr& config, const std::string& slName)
{
    std::vector<Candidate> candidates;
    for (const InterchangeRole role : {InterchangeRole::DISPLAY, InterchangeRole::SCENE})
    {
        if (OCIO::ConstColorSpaceRcPtr cs = config->getColorSpace(RoleName(role)))
        {
            candidates.push_back({cs, role});
        }
    }
    for (const OCIO::ConstColorSpaceRcPtr& cs : AllColorSpaces(config))
    {
        if (cs->getName() != slName && !cs->isData())
        {
            candidates.push_back({cs, InterchangeRole::NONE});
        }
    }
    return candidates;
}

/// scene_linear → the candidate, on the CPU in float; null for a space OCIO
/// cannot reach (a missing file, a context variable).
OCIO::ConstCPUProcessorRcPtr ProcessorTo(const OCIO::ConstConfigRcPtr& config,
                                         const std::string& slName, const Candidate& cand)
{
    try
    {
        return config->getProcessor(slName.c_str(), cand.cs->getName())
            ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                       OCIO::OPTIMIZATION_NONE);
    }
    catch (const OCIO::Exception&)
    {
        return nullptr;
    }
}

/// One measurement: scene_linear → decode(candidate) is the 3×3 `m`.
struct Measurement
{
    const Candidate& cand;
    const Decoding& decoding;
    const Mat3& m;
    const std::string& names;  ///< the candidate's names, lower-case (NamesOf)
    const std::string& slName;
};

/// True when `m` is the matrix from primaries `p` to the target (within
/// 2e-3, with either adaptation the target accepts).
bool Reaches(const Target& t, const RgbSpace& p, const Mat3& m)
{
    const std::vector<Mat3> accepted = t.fromPrimaries(p);
    return std::any_of(accepted.begin(), accepted.end(),
                       [&](const Mat3& expected)
                       { return (m - expected).cwiseAbs().maxCoeff() < 2e-3; });
}

/// "colour space 'X' holds T encoded with E, which scene_linear 'S' reaches
/// from P primaries".
std::string Evidence(const Measurement& ms, const Target& t, const RgbSpace& p)
{
    const Candidate& cand = ms.cand;
    const std::string what =
        cand.role == InterchangeRole::NONE
            ? "colour space '" + std::string(cand.cs->getName()) + "'"
            : "the " + std::string(RoleName(cand.role)) + " role ('" + cand.cs->getName() + "')";
    return what + " holds " + t.name +
           (ms.decoding.linear ? "" : std::string(" encoded with ") + ms.decoding.name) +
           ", which scene_linear '" + ms.slName + "' reaches from " + p.displayName + " primaries";
}

/// Every target the measured space may hold (an interchange role holds only
/// its own), and every set of built-in primaries that gives the measured
/// matrix there.
void MatchTargets(const Measurement& ms, const std::vector<Target>& targets,
                  std::vector<Finding>& findings)
{
    const InterchangeRole role = ms.cand.role;
    const bool identity = (ms.m - Mat3::Identity()).cwiseAbs().maxCoeff() < 2e-3;
    for (const Target& t : targets)
    {
        if (role != InterchangeRole::NONE && t.role != role)
        {
            continue;
        }
        const bool named = std::any_of(t.keywords.begin(), t.keywords.end(),
                                       [&](const std::string& k)
                                       { return ms.names.find(k) != std::string::npos; });
        if (identity && !named && role == InterchangeRole::NONE)
        {
            continue;  // a copy of scene_linear says nothing by itself
        }
        for (const RgbSpace& p : BuiltinRgbSpaces())
        {
            if (Reaches(t, p, ms.m))
            {
                findings.push_back({&p, Evidence(ms, t, p),
                                    role != InterchangeRole::NONE ? 2
                                    : named                       ? 1
                                                                  : 0});
            }
        }
    }
}

/// The most trusted evidence decides; anything as trusted must agree.
const Finding& Decide(const std::vector<Finding>& findings, const std::string& slName)
{
    if (findings.empty())
    {
        throw ParameterError(
            "cannot tell the primaries of the base config's scene_linear space '" + slName +
            "': no interchange role, and no colour space of the config is a standard "
            "encoding (linear, sRGB, gamma, BT.709) of standard primaries or CIE XYZ "
            "measured from it: give {working_space}");
    }
    const int best =
        std::max_element(findings.begin(), findings.end(),
                         [](const Finding& a, const Finding& b) { return a.trust < b.trust; })
            ->trust;
    const Finding* chosen = nullptr;
    for (const Finding& f : findings)
    {
        if (f.trust != best)
        {
            continue;
        }
        if (!chosen)
        {
            chosen = &f;
        }
        else if (f.primaries != chosen->primaries)
        {
            throw ParameterError("the base config's scene_linear space '" + slName +
                                 "' has conflicting evidence: " + chosen->evidence + "; but " +
                                 f.evidence + ": give {working_space}");
        }
    }
    return *chosen;
}

}  // namespace

SceneLinearIdentity IdentifySceneLinear(const OCIO::ConstConfigRcPtr& config)
{
    const OCIO::ConstColorSpaceRcPtr sceneLinear = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    if (!sceneLinear)
    {
        throw Exception("the base config has no scene_linear role: looks need a process space");
    }
    const std::string slName = sceneLinear->getName();
    const std::vector<Target> targets = Targets();
    std::vector<Finding> findings;
    for (const Candidate& cand : Candidates(config, slName))
    {
        const OCIO::ConstCPUProcessorRcPtr cpu = ProcessorTo(config, slName, cand);
        if (!cpu)
        {
            continue;
        }
        const std::string names = NamesOf(cand.cs);
        for (const Decoding& d : Decodings())
        {
            // The interchange roles are linear by definition.
            if (cand.role != InterchangeRole::NONE && !d.linear)
            {
                continue;
            }
            Mat3 m;
            if (FitMatrix(cpu, d, m))
            {
                MatchTargets({cand, d, m, names, slName}, targets, findings);
            }
        }
    }
    const Finding& chosen = Decide(findings, slName);
    return {chosen.primaries, chosen.evidence};
}

}  // namespace bandlight
