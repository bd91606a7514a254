// SPDX-License-Identifier: BSD-3-Clause
// ExtendConfig: bandlight's looks and band space added to a copy of an
// existing config, which is checked to keep every pixel of the base (its
// colour spaces, displays and views, looks and named transforms).
#include "plugin/ConfigBuilder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>
#include <sstream>

#include "plugin/ConfigReferences.h"
#include "plugin/SceneLinearEvidence.h"
#include "plugin/detail/ConfigParts.h"
#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

using detail::AddBandSpace;
using detail::AddInputSpaces;
using detail::AddLooks;
using detail::IsV1;
using detail::kBandSpaceName;
using detail::kLutFolder;
using detail::RequireLights;

/// A transform taking the base config's scene_linear space to its reference,
/// so that spaces added relative to scene_linear need no knowledge of the
/// base's reference.
OCIO::TransformRcPtr SceneLinearToReference(const OCIO::ConstColorSpaceRcPtr& sceneLinear)
{
    if (OCIO::ConstTransformRcPtr t = sceneLinear->getTransform(OCIO::COLORSPACE_DIR_TO_REFERENCE))
    {
        return t->createEditableCopy();
    }
    if (OCIO::ConstTransformRcPtr t =
            sceneLinear->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE))
    {
        OCIO::TransformRcPtr inv = t->createEditableCopy();
        inv->setDirection(inv->getDirection() == OCIO::TRANSFORM_DIR_FORWARD
                              ? OCIO::TRANSFORM_DIR_INVERSE
                              : OCIO::TRANSFORM_DIR_FORWARD);
        return inv;
    }
    return nullptr;  // scene_linear is the reference itself
}

std::string Serialized(const OCIO::ConstConfigRcPtr& config)
{
    return SerializeConfig(config);
}

/// A copy of `base` that OCIO 2.1 would serialise to the same text.
/// Config::createEditableCopy drops default_view_transform (every display
/// conversion of an ACES studio config changes with it), so it is restored;
/// any other difference is refused rather than written.
OCIO::ConfigRcPtr EditableCopy(const OCIO::ConstConfigRcPtr& base)
{
    OCIO::ConfigRcPtr copy = base->createEditableCopy();
    copy->setDefaultViewTransformName(base->getDefaultViewTransformName());
    return copy;
}

OCIO::ConfigRcPtr FaithfulCopy(const OCIO::ConstConfigRcPtr& base)
{
    OCIO::ConfigRcPtr copy = EditableCopy(base);
    const std::string a = Serialized(base);
    const std::string b = Serialized(copy);
    if (a != b)
    {
        size_t line = 1, i = 0;
        for (; i < std::min(a.size(), b.size()) && a[i] == b[i]; ++i)
        {
            line += a[i] == '\n' ? 1 : 0;
        }
        const size_t start = a.rfind('\n', i == 0 ? 0 : i - 1);
        const size_t end = a.find('\n', i);
        const std::string text = a.substr(start == std::string::npos ? 0 : start + 1,
                                          (end == std::string::npos ? a.size() : end) -
                                              (start == std::string::npos ? 0 : start + 1));
        throw Exception("OpenColorIO loses part of the base config when copying it (line " +
                        std::to_string(line) + " of its serialised form: '" + OneLine(text, 120) +
                        "'): refusing to write a config that differs from the base");
    }
    return copy;
}

/// Every base transform a host can ask for, as (description, processor maker).
std::vector<
    std::pair<std::string, std::function<OCIO::ConstProcessorRcPtr(const OCIO::ConstConfigRcPtr&)>>>
BaseTransforms(const OCIO::ConstConfigRcPtr& base)
{
    std::vector<std::pair<std::string,
                          std::function<OCIO::ConstProcessorRcPtr(const OCIO::ConstConfigRcPtr&)>>>
        out;
    const char* sl = OCIO::ROLE_SCENE_LINEAR;
    // Each colour space's own transforms, to and from its reference, each
    // distinct transform once: a colour space to scene_linear is its
    // transform to the reference then scene_linear's from it, so checking
    // every piece checks every pair, in time linear in the config (asking
    // OCIO 2.1 for a processor by name scans every colour space).
    std::set<std::string> seen;
    for (const OCIO::ConstColorSpaceRcPtr& cs : AllColorSpaces(base))
    {
        const std::string name = cs->getName();
        for (const auto dir :
             {OCIO::COLORSPACE_DIR_TO_REFERENCE, OCIO::COLORSPACE_DIR_FROM_REFERENCE})
        {
            const OCIO::ConstTransformRcPtr t = cs->getTransform(dir);
            if (!t)
            {
                continue;
            }
            std::ostringstream key;
            key << int(dir) << " " << *t;
            if (!seen.insert(key.str()).second)
            {
                continue;  // the same transform as a colour space checked already
            }
            const bool toRef = dir == OCIO::COLORSPACE_DIR_TO_REFERENCE;
            out.push_back({"colour space '" + name + "' " +
                               (toRef ? "to its reference" : "from its reference"),
                           [t](const OCIO::ConstConfigRcPtr& c) { return c->getProcessor(t); }});
        }
    }
    for (int d = 0; d < base->getNumDisplaysAll(); ++d)
    {
        const std::string display = base->getDisplayAll(d);
        for (int v = 0; v < base->getNumViews(OCIO::VIEW_DISPLAY_DEFINED, display.c_str()) +
                                base->getNumViews(OCIO::VIEW_SHARED, display.c_str());
             ++v)
        {
            const int defined = base->getNumViews(OCIO::VIEW_DISPLAY_DEFINED, display.c_str());
            const std::string view =
                v < defined ? base->getView(OCIO::VIEW_DISPLAY_DEFINED, display.c_str(), v)
                            : base->getView(OCIO::VIEW_SHARED, display.c_str(), v - defined);
            out.push_back({"display '" + display + "', view '" + view + "'",
                           [display, view, sl](const OCIO::ConstConfigRcPtr& c)
                           {
                               OCIO::DisplayViewTransformRcPtr t =
                                   OCIO::DisplayViewTransform::Create();
                               t->setSrc(sl);
                               t->setDisplay(display.c_str());
                               t->setView(view.c_str());
                               return c->getProcessor(t);
                           }});
        }
    }
    for (int i = 0; i < base->getNumLooks(); ++i)
    {
        const std::string look = base->getLookNameByIndex(i);
        out.push_back({"look '" + look + "'", [look, sl](const OCIO::ConstConfigRcPtr& c)
                       {
                           OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
                           t->setSrc(sl);
                           t->setDst(sl);
                           t->setLooks(look.c_str());
                           return c->getProcessor(t);
                       }});
    }
    for (int i = 0; i < base->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i)
    {
        const std::string nt = base->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i);
        out.push_back({"named transform '" + nt + "'", [nt](const OCIO::ConstConfigRcPtr& c)
                       {
                           OCIO::ConstNamedTransformRcPtr t = c->getNamedTransform(nt.c_str());
                           OCIO::ConstTransformRcPtr fwd =
                               t->getTransform(OCIO::TRANSFORM_DIR_FORWARD);
                           return c->getProcessor(
                               fwd ? fwd : t->getTransform(OCIO::TRANSFORM_DIR_INVERSE),
                               fwd ? OCIO::TRANSFORM_DIR_FORWARD : OCIO::TRANSFORM_DIR_INVERSE);
                       }});
    }
    return out;
}

/// Checks that every transform of the base gives the same pixels in the
/// extended config (its search paths rewritten, its LUT folder added) (16 colours from -0.1 to 16,
/// 1e-5 relative): the extension only adds. Transforms the base itself cannot build (a missing
/// file, a context variable, a singular inverse) are skipped; the extended
/// config must then fail the same way.
void VerifyBaseUnchanged(const OCIO::ConstConfigRcPtr& base, const OCIO::ConstConfigRcPtr& ext)
{
    static const float probe[16][3] = {{0, 0, 0},
                                       {0.18f, 0.18f, 0.18f},
                                       {1, 1, 1},
                                       {16, 16, 16},
                                       {1, 0, 0},
                                       {0, 1, 0},
                                       {0, 0, 1},
                                       {0.5f, 0.2f, 0.05f},
                                       {0.05f, 0.3f, 0.7f},
                                       {-0.1f, 0.2f, 0.4f},
                                       {0.01f, 0.01f, 0.02f},
                                       {4, 2, 1},
                                       {0.9f, 0.9f, 0.1f},
                                       {0.3f, 0.6f, 0.9f},
                                       {2e-3f, 5e-3f, 1e-3f},
                                       {0.7f, 0.1f, 0.8f}};
    for (const auto& [what, make] : BaseTransforms(base))
    {
        OCIO::ConstCPUProcessorRcPtr a;
        try
        {
            a = make(base)->getDefaultCPUProcessor();
        }
        catch (const OCIO::Exception&)
        {
            continue;
        }
        OCIO::ConstCPUProcessorRcPtr b;
        try
        {
            b = make(ext)->getDefaultCPUProcessor();
        }
        catch (const OCIO::Exception& e)
        {
            throw Exception("extending the base config would break its " + what + " (" +
                            OneLine(e.what(), 200) + ")");
        }
        for (const auto& p : probe)
        {
            float x[3] = {p[0], p[1], p[2]}, y[3] = {p[0], p[1], p[2]};
            a->applyRGB(x);
            b->applyRGB(y);
            for (int c = 0; c < 3; ++c)
            {
                // 1e-5: OCIO writes a config's numbers with fewer digits than
                // some files give them (Blender's False Color view changes by
                // 4e-6 when OCIO merely re-serialises Blender's own config).
                const bool same = (std::isnan(x[c]) && std::isnan(y[c])) || x[c] == y[c] ||
                                  std::abs(x[c] - y[c]) <= 1e-5f * std::max(1.0f, std::abs(x[c]));
                if (!same)
                {
                    char values[160];
                    std::snprintf(values, sizeof values,
                                  "(%g, %g, %g) gives %.9g in channel %d instead of %.9g", p[0],
                                  p[1], p[2], double(y[c]), c, double(x[c]));
                    throw Exception("extending the base config would change its " + what + ": " +
                                    values + "; refusing to write it");
                }
            }
        }
    }
}

/// A base search path as seen from the extended config's folder.
std::string Relocated(const std::string& path, const std::string& baseDir, const ConfigOptions& o)
{
    if (path.empty() || path[0] == '/' || path[0] == '$' || baseDir.empty())
    {
        return path;  // absolute, or resolved by a context variable
    }
    namespace fs = std::filesystem;
    const fs::path target = fs::weakly_canonical(fs::path(baseDir) / path);
    if (o.absoluteBasePaths || o.outputDir.empty())
    {
        return target.string();
    }
    const fs::path from = fs::weakly_canonical(fs::absolute(o.outputDir));
    const fs::path rel = target.lexically_relative(from);
    return rel.empty() ? target.string() : rel.string();
}

}  // namespace

ConfigPackage ExtendConfig(const OCIO::ConstConfigRcPtr& base, ConfigOptions o, bool detect,
                           std::string* identifiedSpace)
{
    RequireLights(o);
    CheckConfigReferences(base, o.baseName);
    OCIO::ConstColorSpaceRcPtr sceneLinear = base->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    if (!sceneLinear)
    {
        throw Exception("the base config has no scene_linear role: looks need a process space");
    }
    const std::string processSpace = sceneLinear->getName();
    std::string evidence;
    if (detect)
    {
        const SceneLinearIdentity id = IdentifySceneLinear(base);
        o.workingSpace = id.space->name;
        evidence = id.evidence;
    }
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    if (identifiedSpace)
    {
        *identifiedSpace = working.name;
    }

    ConfigPackage package;
    package.evidence = evidence;
    package.config = FaithfulCopy(base);
    OCIO::ConfigRcPtr& config = package.config;
    // An OCIO v1 base stays v1: OCIO 2.1 evaluates some v1 transforms
    // differently in a v2 config (a CDL look on negative values changes by
    // 0.03), so upgrading would change the base's pixels. The additions are
    // CLF files instead (see AddLooks).
    package.v1 = IsV1(*config);
    // The extended config is written elsewhere: the base's relative search
    // paths (its LUT folders) are rewritten to reach the base's folder from
    // there — relative to the output folder by default, so the two trees
    // move together.
    const std::string baseDir = base->getWorkingDir();
    if (!baseDir.empty() && base->getNumSearchPaths() > 0)
    {
        std::vector<std::string> paths;
        for (int i = 0; i < base->getNumSearchPaths(); ++i)
        {
            paths.push_back(Relocated(base->getSearchPath(i), baseDir, o));
        }
        config->clearSearchPaths();
        for (const std::string& p : paths)
        {
            config->addSearchPath(p.c_str());
        }
    }
    if (!o.outputDir.empty())
    {
        config->setWorkingDir(o.outputDir.c_str());
    }
    if (!config->getColorSpace(kBandSpaceName))  // a bandlight config has it already
    {
        AddBandSpace(package, working, o.observer, SceneLinearToReference(sceneLinear));
    }
    AddLooks(package, o, working, processSpace);
    AddInputSpaces(package, o.inputSpaces, working, SceneLinearToReference(sceneLinear));
    if (!package.lutFiles.empty())
    {
        config->addSearchPath(kLutFolder);
    }
    config->validate();
    // The check runs on the config as it will be read back from its file
    // (serialisation may lose what the in-memory copy still has); base
    // transforms never touch bandlight's LUT files, so it can run before
    // they are written.
    package.text = SerializeConfig(config);
    std::istringstream text(package.text);
    OCIO::ConfigRcPtr reread = EditableCopy(OCIO::Config::CreateFromStream(text));
    reread->setWorkingDir(config->getWorkingDir());
    VerifyBaseUnchanged(base, reread);
    return package;
}

}  // namespace bandlight
