// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/ConfigBuilder.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <set>

#include <Eigen/LU>

#include "plugin/ConfigReferences.h"
#include "spectral/AtomicFile.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

namespace bandlight
{

namespace
{

constexpr const char* kBandSpaceName = "Bands VB-VG-VR (lecture)";
constexpr const char* kFamilyLooks = "bandlight";

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

OCIO::ColorSpaceRcPtr SceneSpace(const std::string& name, const std::string& family,
                                 const std::string& description, const std::string& encoding)
{
    OCIO::ColorSpaceRcPtr cs = OCIO::ColorSpace::Create(OCIO::REFERENCE_SPACE_SCENE);
    cs->setName(name.c_str());
    cs->setFamily(family.c_str());
    cs->setDescription(description.c_str());
    cs->setEncoding(encoding.c_str());
    return cs;
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

void AddBandSpace(OCIO::Config& config, const RgbSpace& working, Observer observer,
                  OCIO::TransformRcPtr workingToReference)
{
    const BandSet bands = BandSet::Lecture();
    OCIO::ColorSpaceRcPtr cs = SceneSpace(
        kBandSpaceName, "Bands",
        "Radiometric band values of the lecture's 3-band model (VB 400-500, VG 500-600, VR "
        "600-700 nm) as R, G, B channels: band means normalised so that an equal-energy light on "
        "a white surface is (1, 1, 1).",
        "scene-linear");
    const Mat3 bandToWorking = BandToWorkingMatrix(bands, working, observer);
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(GuardedMatrixTransform(bandToWorking));
    if (workingToReference)
    {
        g->appendTransform(workingToReference);
    }
    cs->setTransform(g, OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config.addColorSpace(cs);
}

constexpr const char* kLutFolder = "luts";

void AddLooks(ConfigPackage& package, const ConfigOptions& o, const RgbSpace& working,
              const std::string& processSpace)
{
    OCIO::Config& config = *package.config;
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        methods.push_back(ParseMethod(m));
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
                const std::string description = "Relight from " + from.name + " to " + to.name +
                                                " in " + working.displayName + ". " +
                                                DescribeMethod(method);
                // A matrix inline; a non-linear method as a CLF file the
                // package carries (configs cannot hold a 3D LUT inline).
                OCIO::TransformRcPtr transform;
                if (method.isLinear())
                {
                    transform = GuardedMatrixTransform(
                        IlluminantChangeMatrix(from, to, method, working, o.observer));
                }
                else
                {
                    const std::string file = name + ".clf";
                    package.lutFiles.emplace_back(
                        std::string(kLutFolder) + "/" + file,
                        IlluminantChangeTransform(from, to, method, working, o.observer));
                    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
                    f->setSrc(file.c_str());
                    f->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
                    transform = f;
                }
                OCIO::LookRcPtr look = OCIO::Look::Create();
                look->setName(name.c_str());
                look->setProcessSpace(processSpace.c_str());
                look->setTransform(transform);
                look->setDescription(description.c_str());
                config.addLook(look);

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
        ParseMethod(m);
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

std::string NamedTransformName(const std::string& lookName)
{
    return "relight_" + lookName;
}

std::string ColorSpaceName(const RgbSpace& space)
{
    if (space.name == "acescg")
    {
        return "ACEScg";
    }
    if (space.name == "aces2065-1")
    {
        return "ACES2065-1";
    }
    return space.displayName;
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
         working.displayName +
         " scene-linear images. Look names: <method>_<FROM>_to_<TO>. Generated by "
         "`bandlight config`.")
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

    AddBandSpace(*config, working, o.observer, nullptr);

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
    if (!package.lutFiles.empty())
    {
        config->addSearchPath(kLutFolder);
    }
    config->validate();
    return package;
}

ConfigPackage ExtendConfig(const OCIO::ConstConfigRcPtr& base, ConfigOptions o, bool detect,
                           std::string* identifiedSpace)
{
    RequireLights(o);
    CheckConfigReferences(base, "the base config");
    OCIO::ConstColorSpaceRcPtr sceneLinear = base->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    if (!sceneLinear)
    {
        throw Exception("the base config has no scene_linear role: looks need a process space");
    }
    const std::string processSpace = sceneLinear->getName();
    if (detect)
    {
        // Measure scene_linear against an interchange space and find which
        // built-in primaries (with the usual white adaptations) it matches.
        const char* interchange =
            base->getColorSpace(OCIO::ROLE_INTERCHANGE_DISPLAY) ? OCIO::ROLE_INTERCHANGE_DISPLAY
            : base->getColorSpace(OCIO::ROLE_INTERCHANGE_SCENE) ? OCIO::ROLE_INTERCHANGE_SCENE
                                                                : nullptr;
        if (!interchange)
        {
            throw Exception("cannot tell the primaries of the base config's scene_linear space '" +
                            processSpace +
                            "' (no cie_xyz_d65_interchange or aces_interchange role): give "
                            "--working-space");
        }
        const Mat3 measured =
            MeasureMatrix(base->getProcessor(OCIO::ROLE_SCENE_LINEAR, interchange));
        const bool toXyz = std::string(interchange) == OCIO::ROLE_INTERCHANGE_DISPLAY;
        const RgbSpace* found = nullptr;
        for (const RgbSpace& s : BuiltinRgbSpaces())
        {
            const Mat3 expected =
                toXyz ? SpaceToXyzD65(s) : SpaceToSpace(s, FindRgbSpace("aces2065-1"));
            // Configs adapt whites with Bradford or CAT02 and round their
            // matrices: 2e-3 tells the primaries sets apart with a wide margin.
            if ((measured - expected).cwiseAbs().maxCoeff() < 2e-3)
            {
                found = &s;
                break;
            }
        }
        if (!found)
        {
            throw Exception("the base config's scene_linear space '" + processSpace +
                            "' matches none of the built-in primaries: give --working-space");
        }
        o.workingSpace = found->name;
    }
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    if (identifiedSpace)
    {
        *identifiedSpace = working.name;
    }

    ConfigPackage package;
    package.config = base->createEditableCopy();
    OCIO::ConfigRcPtr& config = package.config;
    // The extended config is written elsewhere: anchor the base's relative
    // search paths (its LUT folders) at the base's own directory.
    const std::string baseDir = base->getWorkingDir();
    if (!baseDir.empty())
    {
        std::vector<std::string> paths;
        for (int i = 0; i < base->getNumSearchPaths(); ++i)
        {
            std::string p = base->getSearchPath(i);
            if (!p.empty() && p[0] != '/' && p[0] != '$')
            {
                p = baseDir + "/" + p;
            }
            paths.push_back(p);
        }
        config->clearSearchPaths();
        for (const std::string& p : paths)
        {
            config->addSearchPath(p.c_str());
        }
    }
    if (!config->getColorSpace(kBandSpaceName))  // a bandlight config has it already
    {
        AddBandSpace(*config, working, o.observer, SceneLinearToReference(sceneLinear));
    }
    AddLooks(package, o, working, processSpace);
    if (!package.lutFiles.empty())
    {
        config->addSearchPath(kLutFolder);
    }
    config->validate();
    return package;
}

void WriteConfigPackage(const ConfigPackage& package, const std::string& dir, OutputSet* outputs)
{
    auto makeDir = [](const std::string& d)
    {
        if (::mkdir(d.c_str(), 0777) != 0 && errno != EEXIST)
        {
            throw Exception(d + ": cannot create the directory (" + std::strerror(errno) + ")");
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
    set.write(dir + "/config.ocio", [&](std::ostream& os) { package.config->serialize(os); });
    own.commit();
}

}  // namespace bandlight
