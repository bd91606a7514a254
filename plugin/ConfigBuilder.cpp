// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/ConfigBuilder.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/LU>

#include "plugin/ConfigReferences.h"
#include "plugin/SceneLinearEvidence.h"
#include "plugin/detail/ConfigParts.h"
#include "spectral/AtomicFile.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

namespace bandlight
{

namespace
{

using detail::AddInputSpaces;
using detail::AsLutFile;
using detail::IsV1;
using detail::kLutFolder;
using detail::SceneSpace;

constexpr const char* kBandSpaceName = "Bands VB-VG-VR (lecture)";
constexpr const char* kFamilyLooks = "bandlight";

/// Linear RGB → CIE XYZ with a D65 white (Bradford when the space's white differs).
Mat3 SpaceToXyzD65(const RgbSpace& src)
{
    const Vec3 ws = WhiteXyz(src.chromaticities.wx, src.chromaticities.wy);
    const Vec3 d65 = WhiteXyz(0.3127, 0.3290);
    const Mat3 cat = (ws - d65).norm() < 1e-9
                         ? Mat3::Identity()
                         : AdaptationMatrix(ws, d65, AdaptationMethod::BRADFORD);
    return cat * RgbToXyzMatrix(src.chromaticities);
}

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

void AddBandSpace(ConfigPackage& package, const RgbSpace& working, Observer observer,
                  OCIO::TransformRcPtr workingToReference)
{
    OCIO::Config& config = *package.config;
    const BandSet bands = BandSet::Lecture();
    OCIO::ColorSpaceRcPtr cs = SceneSpace(
        kBandSpaceName, "Bands",
        "Radiometric band values of the lecture's 3-band model (VB 400-500, VG 500-600, VR "
        "600-700 nm) as R, G, B channels: band means normalised so that an equal-energy light on "
        "a white surface is (1, 1, 1).",
        "scene-linear");
    const Mat3 bandToWorking = BandToWorkingMatrix(bands, working, observer);
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    if (IsV1(config))
    {
        g->appendTransform(
            AsLutFile(package, "bands_to_scene_linear", GuardedMatrixTransform(bandToWorking)));
    }
    else
    {
        g->appendTransform(GuardedMatrixTransform(bandToWorking));
    }
    if (workingToReference)
    {
        g->appendTransform(workingToReference);
    }
    cs->setTransform(g, OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config.addColorSpace(cs);
}

void AddLooks(ConfigPackage& package, const ConfigOptions& o, const RgbSpace& working,
              const std::string& processSpace)
{
    OCIO::Config& config = *package.config;
    const bool v1 = IsV1(config);
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        methods.push_back(o.method(m));
    }
    std::set<std::string> seen;
    for (const MethodSpec& method : methods)
    {
        for (const Light& from : o.lights)
        {
            for (const Light& to : o.lights)
            {
                if (from.name == to.name)
                {
                    continue;
                }
                const std::string name = LookName(method.name, from.name, to.name);
                if (!seen.insert(name).second)
                {
                    throw Exception("look name '" + name +
                                    "' would be made twice: two illuminants share a name");
                }
                if (config.getLook(name.c_str()) ||
                    config.getNamedTransform(NamedTransformName(name).c_str()) ||
                    config.getColorSpace(name.c_str()) ||
                    config.getColorSpace(NamedTransformName(name).c_str()))
                {
                    throw Exception("look name '" + name +
                                    "' clashes with a look, named transform or colour space the "
                                    "config already has");
                }
                const std::string description =
                    LookDescription(from, to, method, working, o.observer);
                // A matrix inline; a non-linear method as a CLF file the
                // package carries (configs cannot hold a 3D LUT inline).
                OCIO::TransformRcPtr transform;
                if (method.isLinear() && !v1)
                {
                    transform = GuardedMatrixTransform(
                        IlluminantChangeMatrix(from, to, method, working, o.observer));
                }
                else
                {
                    transform = AsLutFile(package, name,
                                          IlluminantChangeTransform(from, to, method, working,
                                                                    o.observer, o.lutSize));
                }
                OCIO::LookRcPtr look = OCIO::Look::Create();
                look->setName(name.c_str());
                look->setProcessSpace(processSpace.c_str());
                look->setTransform(transform);
                look->setDescription(description.c_str());
                config.addLook(look);
                if (v1)
                {
                    continue;  // named transforms are OCIO v2
                }

                // The same as a named transform (OCIO keeps look and named-transform
                // names apart, hence the prefix); it applies to the image as it is,
                // so it states which space it expects.
                OCIO::NamedTransformRcPtr nt = OCIO::NamedTransform::Create();
                nt->setName(NamedTransformName(name).c_str());
                nt->setFamily((std::string(kFamilyLooks) + "/" + method.name).c_str());
                nt->setDescription(
                    (description + " Expects " + working.displayName + " input.").c_str());
                nt->setTransform(transform->createEditableCopy(), OCIO::TRANSFORM_DIR_FORWARD);
                config.addNamedTransform(nt);
            }
        }
    }
}

void RequireLights(const ConfigOptions& o)
{
    if (o.lights.empty() && o.methods.empty() && !o.inputSpaces.empty())
    {
        return;  // input spaces alone: no looks
    }
    if (o.lights.size() < 2)
    {
        throw Exception("a config needs at least two illuminants to change between");
    }
    if (o.methods.empty())
    {
        throw Exception("a config needs at least one method");
    }
    for (const std::string& m : o.methods)
    {
        RequireCamera(o.method(m));
    }
    std::set<std::string> names;
    for (const Light& l : o.lights)
    {
        if (!names.insert(SafeName(l.name)).second)
        {
            throw Exception("two illuminants share a name ('" + l.name +
                            "'): look names would clash");
        }
    }
}

}  // namespace

MethodSpec ConfigOptions::method(const std::string& name) const
{
    MethodSpec m = ParseMethod(name);
    m.plates = plates;
    m.camera = camera;
    if (!idtLightName.empty())
    {
        m.idtLightName = idtLightName;
        m.idtLight = idtLight;
    }
    return m;
}

std::string NamedTransformName(const std::string& lookName)
{
    return "relight_" + lookName;
}

/// Matrix from linear RGB space `src` to `dst`, adapting the white with
/// Bradford when the two whites differ (as the ACES and Blender configs do).
Mat3 SpaceToSpace(const RgbSpace& src, const RgbSpace& dst)
{
    const Mat3 ms = RgbToXyzMatrix(src.chromaticities);
    const Mat3 md = RgbToXyzMatrix(dst.chromaticities);
    const Vec3 ws = WhiteXyz(src.chromaticities.wx, src.chromaticities.wy);
    const Vec3 wd = WhiteXyz(dst.chromaticities.wx, dst.chromaticities.wy);
    const Mat3 cat = (ws - wd).norm() < 1e-9 ? Mat3::Identity()
                                             : AdaptationMatrix(ws, wd, AdaptationMethod::BRADFORD);
    return md.inverse() * cat * ms;
}

/// The sRGB piecewise curve (IEC 61966-2-1) as an OCIO transform, encoded → linear.
OCIO::TransformRcPtr SrgbDecode()
{
    OCIO::ExponentWithLinearTransformRcPtr t = OCIO::ExponentWithLinearTransform::Create();
    const double gamma[4] = {2.4, 2.4, 2.4, 1.0};
    const double offset[4] = {0.055, 0.055, 0.055, 0.0};
    t->setGamma(gamma);
    t->setOffset(offset);
    return t;
}

std::string ColorSpaceName(const RgbSpace& space)
{
    return space.configName.empty() ? space.displayName : space.configName;
}

std::vector<Light> LectureLights()
{
    std::vector<Light> lights;
    for (const char* n : {"A", "C", "D65", "F2", "F11"})
    {
        lights.push_back({n, BuiltinIlluminant(n)});
    }
    return lights;
}

ConfigPackage BuildConfig(const ConfigOptions& o)
{
    RequireLights(o);
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    const std::string workingName = ColorSpaceName(working);

    ConfigPackage package;
    package.config = OCIO::Config::Create();
    OCIO::ConfigRcPtr& config = package.config;
    config->setVersion(2, 0);
    config->setName(("bandlight " + working.name).c_str());
    config->setDescription(
        ("bandlight: illuminant-change looks (the lecture's 3-band model and chromatic "
         "adaptations) for " +
         working.displayName + " scene-linear images. Look names: <method>_<FROM>_to_<TO>. " +
         o.plates.describe(working.displayName) + " Generated by `bandlight config`.")
            .c_str());

    // The working space is the reference: every other space is defined to it.
    OCIO::ColorSpaceRcPtr ref =
        SceneSpace(workingName, "Scene-linear", working.description, "scene-linear");
    config->addColorSpace(ref);
    for (const RgbSpace& s : BuiltinRgbSpaces())
    {
        if (s.name == working.name)
        {
            continue;
        }
        OCIO::ColorSpaceRcPtr cs =
            SceneSpace(ColorSpaceName(s), "Scene-linear", s.description, "scene-linear");
        cs->setTransform(GuardedMatrixTransform(SpaceToSpace(s, working)),
                         OCIO::COLORSPACE_DIR_TO_REFERENCE);
        config->addColorSpace(cs);
    }
    const RgbSpace& rec709 = FindRgbSpace("rec709");
    OCIO::ColorSpaceRcPtr xyz =
        SceneSpace("CIE-XYZ-D65", "Scene-linear", "CIE 1931 XYZ with a D65 white (Y = 1 for white)",
                   "scene-linear");
    xyz->setTransform(GuardedMatrixTransform(SpaceToXyzD65(working).inverse()),
                      OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(xyz);

    OCIO::ColorSpaceRcPtr srgb = SceneSpace(
        "sRGB", "Display", "sRGB (IEC 61966-2-1) encoded Rec.709, for 8-bit images", "sdr-video");
    OCIO::GroupTransformRcPtr srgbToRef = OCIO::GroupTransform::Create();
    srgbToRef->appendTransform(SrgbDecode());
    srgbToRef->appendTransform(GuardedMatrixTransform(SpaceToSpace(rec709, working)));
    srgb->setTransform(srgbToRef, OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(srgb);

    OCIO::ColorSpaceRcPtr data = SceneSpace(
        "Non-Color", "Data", "Data, not colour: normals, masks; never converted", "data");
    data->setIsData(true);
    config->addColorSpace(data);

    AddBandSpace(package, working, o.observer, nullptr);

    // clang-format off
    const std::pair<const char*, std::string> roles[] = {
        {OCIO::ROLE_REFERENCE, workingName},
        {OCIO::ROLE_SCENE_LINEAR, workingName},
        {OCIO::ROLE_RENDERING, workingName},
        {OCIO::ROLE_COLOR_TIMING, workingName},
        {OCIO::ROLE_DEFAULT, workingName},
        {OCIO::ROLE_DATA, "Non-Color"},
        {OCIO::ROLE_COLOR_PICKING, "sRGB"},
        {OCIO::ROLE_TEXTURE_PAINT, "sRGB"},
        {OCIO::ROLE_MATTE_PAINT, "sRGB"},
        {OCIO::ROLE_INTERCHANGE_SCENE, "ACES2065-1"},
        {OCIO::ROLE_INTERCHANGE_DISPLAY, "CIE-XYZ-D65"},
        {"default_byte", "sRGB"},
        {"default_float", workingName},
        {"default_sequencer", "sRGB"},
        {"compositing_linear", workingName},
    };
    // clang-format on
    for (const auto& [role, space] : roles)
    {
        if (space != "ACES2065-1" || config->getColorSpace("ACES2065-1"))
        {
            config->setRole(role, space.c_str());
        }
    }
    config->addDisplayView("sRGB", "Standard", "sRGB", "");
    config->addDisplayView("sRGB", "Raw", "Non-Color", "");
    config->setActiveDisplays("sRGB");
    config->setActiveViews("Standard, Raw");

    AddLooks(package, o, working, workingName);
    AddInputSpaces(package, o.inputSpaces, working, nullptr);
    if (!package.lutFiles.empty())
    {
        config->addSearchPath(kLutFolder);
    }
    config->validate();
    return package;
}

namespace
{

/// `text` as a YAML double-quoted scalar.
std::string YamlQuoted(const std::string& text)
{
    std::string out = "\"";
    for (const char c : text)
    {
        if (c == '"' || c == '\\')
        {
            out += '\\';
            out += c;
        }
        else if (static_cast<unsigned char>(c) < 0x20)
        {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(static_cast<unsigned char>(c)));
            out += buf;
        }
        else
        {
            out += c;
        }
    }
    return out + "\"";
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

std::string SerializeConfig(const OCIO::ConstConfigRcPtr& config)
{
    std::ostringstream out;
    config->serialize(out);
    std::string text = out.str();
    // OCIO 2.1 writes no `environment:` section for a v1 config, though v1
    // has one and its context variables (a show's $SEQ/$SHOT defaults) are
    // what its search paths and looks resolve: put it back after the
    // version line, where OCIO writes it for v2.
    if (config->getMajorVersion() < 2 && config->getNumEnvironmentVars() > 0 &&
        text.find("\nenvironment:") == std::string::npos)
    {
        std::string env = "\nenvironment:\n";
        for (int i = 0; i < config->getNumEnvironmentVars(); ++i)
        {
            const char* name = config->getEnvironmentVarNameByIndex(i);
            env += "  " + YamlQuoted(name) + ": " +
                   YamlQuoted(config->getEnvironmentVarDefault(name)) + "\n";
        }
        const size_t eol = text.find('\n');
        text.insert(eol == std::string::npos ? text.size() : eol + 1, env);
    }
    return text;
}

void WriteConfigPackage(const ConfigPackage& package, const std::string& dir, OutputSet* outputs)
{
    auto makeDir = [](const std::string& d)
    {
        std::error_code ec;
        std::filesystem::create_directories(d, ec);
        if (ec || !std::filesystem::is_directory(d))
        {
            // A file where the folder belongs is ENOTDIR, as for a file on its path.
            throw FileError(d, ec ? ec.value() : ENOTDIR,
                            "cannot create the directory (" +
                                (ec ? ec.message() : std::string("a file is in the way")) + ")");
        }
    };
    makeDir(dir);
    if (!package.lutFiles.empty())
    {
        makeDir(dir + "/" + kLutFolder);
    }
    // The config and its LUTs are one set: a config is never left pointing
    // at LUTs of another run, nor LUTs replaced under an old config.
    OutputSet own;
    OutputSet& set = outputs ? *outputs : own;
    OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateRaw();
    for (const auto& lut : package.lutFiles)
    {
        const auto& transform = lut.second;
        set.write(dir + "/" + lut.first, [&](std::ostream& os)
                  { transform->write(raw, "Academy/ASC Common LUT Format", os); });
    }
    // OCIO 2.1 serialises in time quadratic in the colour spaces: the text
    // ExtendConfig checked is the one written.
    const std::string text = package.text.empty() ? SerializeConfig(package.config) : package.text;
    set.write(dir + "/config.ocio", [&](std::ostream& os) { os << text; });
    own.commit();
}

}  // namespace bandlight
