// SPDX-License-Identifier: BSD-3-Clause
#include "bandlight/plugin/SceneLinearEvidence.h"

#include "bandlight/plugin/ConfigReferences.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "bandlight/spectral/ChromaticAdaptation.h"
#include "bandlight/spectral/Exception.h"

namespace bandlight
{

namespace
{

/// A standard encoding, as the function that undoes it (encoded → linear).
struct Decoding
{
    const char* name;
    std::function<double(double)> decode;
};

double SignedPow(double v, double p)
{
    return v < 0.0 ? -std::pow(-v, p) : std::pow(v, p);
}

const std::vector<Decoding>& Decodings()
{
    static const std::vector<Decoding> d = {
        {"linear", [](double v) { return v; }},
        {"the sRGB curve (IEC 61966-2-1)",
         [](double v)
         {
             const double a = std::abs(v);
             const double l = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
             return v < 0.0 ? -l : l;
         }},
        {"gamma 2.2", [](double v) { return SignedPow(v, 2.2); }},
        {"gamma 2.4 (BT.1886)", [](double v) { return SignedPow(v, 2.4); }},
        {"gamma 2.6", [](double v) { return SignedPow(v, 2.6); }},
        {"the BT.709 OETF",
         [](double v)
         {
             const double a = std::abs(v);
             const double l = a < 0.081 ? a / 4.5 : std::pow((a + 0.099) / 1.099, 1.0 / 0.45);
             return v < 0.0 ? -l : l;
         }},
    };
    return d;
}

/// A standard target a colour space may hold: its matrix from primaries P.
struct Target
{
    std::string name;
    std::vector<std::string> keywords;  ///< lower-case words that name it
    std::function<std::vector<Mat3>(const RgbSpace&)> fromPrimaries;  ///< accepted matrices
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
                     }});
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
    t.push_back({"CIE XYZ (D65 white)", {"xyz"}, xyz(WhiteXyz(0.3127, 0.3290))});
    t.push_back({"CIE XYZ (equal-energy white)", {"xyz"}, xyz(Vec3(1.0, 1.0, 1.0))});
    t.push_back({"CIE XYZ (the space's own white)", {"xyz"}, [](const RgbSpace& p) {
                     return std::vector<Mat3>{RgbToXyzMatrix(p.chromaticities)};
                 }});
    return t;
}

std::string Lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

/// The words a colour space is known by: name, aliases, family, lower-case.
std::string NamesOf(const OCIO::ConstColorSpaceRcPtr& cs)
{
    std::string all = Lower(cs->getName()) + " " + Lower(cs->getFamily());
    for (size_t i = 0; i < cs->getNumAliases(); ++i)
    {
        all += " " + Lower(cs->getAlias(i));
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

    // Candidate spaces: the interchange roles first, then every colour space.
    struct Candidate
    {
        OCIO::ConstColorSpaceRcPtr cs;
        std::string role;
    };
    std::vector<Candidate> candidates;
    for (const char* role : {OCIO::ROLE_INTERCHANGE_DISPLAY, OCIO::ROLE_INTERCHANGE_SCENE})
    {
        if (OCIO::ConstColorSpaceRcPtr cs = config->getColorSpace(role))
        {
            candidates.push_back({cs, role});
        }
    }
    for (const OCIO::ConstColorSpaceRcPtr& cs : AllColorSpaces(config))
    {
        if (cs->getName() != slName && !cs->isData())
        {
            candidates.push_back({cs, ""});
        }
    }

    for (const Candidate& cand : candidates)
    {
        OCIO::ConstCPUProcessorRcPtr cpu;
        try
        {
            cpu = config->getProcessor(slName.c_str(), cand.cs->getName())
                      ->getOptimizedCPUProcessor(OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32,
                                                 OCIO::OPTIMIZATION_NONE);
        }
        catch (const OCIO::Exception&)
        {
            continue;  // a space OCIO cannot reach (missing file, context variable)
        }
        const std::string names = NamesOf(cand.cs);
        for (const Decoding& d : Decodings())
        {
            // The interchange roles are linear by definition.
            if (!cand.role.empty() && std::string(d.name) != "linear")
            {
                continue;
            }
            Mat3 m;
            if (!FitMatrix(cpu, d, m))
            {
                continue;
            }
            const bool identity = (m - Mat3::Identity()).cwiseAbs().maxCoeff() < 2e-3;
            for (const Target& t : targets)
            {
                if (!cand.role.empty())
                {
                    // cie_xyz_d65_interchange is XYZ D65; aces_interchange is AP0.
                    const std::string meant = cand.role == OCIO::ROLE_INTERCHANGE_DISPLAY
                                                  ? "CIE XYZ (D65 white)"
                                                  : FindRgbSpace("aces2065-1").displayName;
                    if (t.name != meant)
                    {
                        continue;
                    }
                }
                const bool named = std::any_of(t.keywords.begin(), t.keywords.end(),
                                               [&](const std::string& k)
                                               { return names.find(k) != std::string::npos; });
                if (identity && !named && cand.role.empty())
                {
                    continue;  // a copy of scene_linear says nothing by itself
                }
                for (const RgbSpace& p : BuiltinRgbSpaces())
                {
                    for (const Mat3& expected : t.fromPrimaries(p))
                    {
                        if ((m - expected).cwiseAbs().maxCoeff() < 2e-3)
                        {
                            const std::string what =
                                cand.role.empty()
                                    ? "colour space '" + std::string(cand.cs->getName()) + "'"
                                    : "the " + cand.role + " role ('" + cand.cs->getName() + "')";
                            findings.push_back({&p,
                                                what + " holds " + t.name +
                                                    (std::string(d.name) == "linear"
                                                         ? ""
                                                         : std::string(" encoded with ") + d.name) +
                                                    ", which scene_linear '" + slName +
                                                    "' reaches from " + p.displayName +
                                                    " primaries",
                                                !cand.role.empty() ? 2
                                                : named            ? 1
                                                                   : 0});
                            break;
                        }
                    }
                }
            }
        }
    }
    if (findings.empty())
    {
        throw ParameterError(
            "cannot tell the primaries of the base config's scene_linear space '" + slName +
            "': no interchange role, and no colour space of the config is a standard "
            "encoding (linear, sRGB, gamma, BT.709) of standard primaries or CIE XYZ "
            "measured from it: give {working_space}");
    }
    // The most trusted evidence decides; anything as trusted must agree.
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
    return {chosen->primaries, chosen->evidence};
}

}  // namespace bandlight
