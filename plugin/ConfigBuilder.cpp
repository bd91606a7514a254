// SPDX-License-Identifier: BSD-3-Clause
// BuildConfig: a complete config of bandlight's own, and the pieces it shares
// with ExtendConfig (plugin/ConfigExtension.cpp): the band space, the looks
// and the check of the options. Writing a package is plugin/ConfigWriter.cpp.
#include "plugin/ConfigBuilder.h"

#include <set>

#include <Eigen/LU>

#include "plugin/detail/ConfigParts.h"
#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

namespace bandlight
{

namespace
{

using detail::AddBandSpace;
using detail::AddInputSpaces;
using detail::AddLooks;
using detail::kLutFolder;
using detail::RequireLights;
using detail::SceneSpace;

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

}  // namespace

namespace detail
{

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

}  // namespace detail

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
    const RgbSpace& rec709 = Rec709Space();
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

}  // namespace bandlight
