// SPDX-License-Identifier: BSD-3-Clause
// The YAML scene reader. It says no to what it would ignore: a key is
// either used or an error naming its file, line and name. This file reads
// the render settings, the camera and the objects and puts the scene
// together; the lights are read in render/SceneLights.cpp, the materials in
// render/SceneMaterials.cpp.
#include "render/SceneFile.h"

#include <cmath>

#include <Eigen/Geometry>

#include "render/detail/SceneParts.h"
#include "render/detail/YamlReader.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/TextFile.h"

namespace bandlight
{

namespace
{

using detail::kMaxCoordinate;
using detail::MaterialIndex;
using detail::ReadLights;
using detail::ReadMaterials;
using Reader = detail::YamlReader;

/// The spectral grid's step, nm: finer than 0.1 nm resolves nothing the CIE
/// tables hold (and would take 4701+ samples a product); coarser than 50 nm
/// cannot resolve a band.
constexpr double kMinStepNm = 0.1;
constexpr double kMaxStepNm = 50.0;

void ReadRender(const Reader& r, const YAML::Node& rn, RenderSettings& settings)
{
    r.keys(rn, "render", {"mode", "step", "range", "output", "bands"});
    if (rn["bands"])
    {
        try
        {
            settings.bands = BandSet::FromEdges(r.numbers(rn["bands"], "bands"));
        }
        catch (const Exception& e)
        {
            r.fail(rn["bands"], e.what());
        }
    }
    if (rn["mode"])
    {
        const std::string mode = r.text(rn["mode"]);
        const BandSet explicitBands = settings.bands;
        try
        {
            SetRenderMode(settings, mode);
        }
        catch (const Exception& e)
        {
            r.fail(rn["mode"], e.what());
        }
        if (rn["bands"])
        {
            // The mode's N must agree with the edges given, else it is ignored.
            const size_t n = ModeBandCount(mode);
            if (n != 0 && n != explicitBands.size())
            {
                r.fail(rn["mode"], "mode " + mode + " names " + std::to_string(n) +
                                       " bands, but render bands gives " +
                                       std::to_string(explicitBands.size()));
            }
            settings.bands = explicitBands;
        }
    }
    if (rn["step"])
    {
        settings.stepNm = r.positive(rn["step"], "step");
        if (!(settings.stepNm >= kMinStepNm && settings.stepNm <= kMaxStepNm))
        {
            r.fail(rn["step"], "step must be from 0.1 to 50 nm, got " + rn["step"].Scalar());
        }
    }
    if (rn["range"])
    {
        const YAML::Node range = rn["range"];
        if (!range.IsSequence() || range.size() != 2)
        {
            r.fail(range, "range must be [start_nm, end_nm]");
        }
        const double a = r.number(range[0], "range start");
        const double b = r.number(range[1], "range end");
        // At least the coarsest step, so every grid has two samples.
        if (!(a >= RenderSettings::kWidestRangeMinNm && b <= RenderSettings::kWidestRangeMaxNm &&
              a + kMaxStepNm <= b))
        {
            r.fail(range, "range must lie within 360-830 nm and span at least 50 nm, got [" +
                              range[0].Scalar() + ", " + range[1].Scalar() + "]");
        }
        settings.rangeMinNm = a;
        settings.rangeMaxNm = b;
    }
    if (rn["output"])
    {
        settings.output = r.text(rn["output"]);
        if (settings.output != "bands")
        {
            try
            {
                settings.output = FindRgbSpace(settings.output).name;
            }
            catch (const Exception& e)
            {
                r.fail(rn["output"], e.what());
            }
        }
        else if (settings.mode == RenderSettings::Mode::SPECTRAL)
        {
            r.fail(rn["output"],
                   "output 'bands' needs band mode: spectral mode has no bands to write");
        }
    }
}

void ReadCamera(const Reader& r, const YAML::Node& c, Camera& camera)
{
    r.keys(c, "camera", {"type", "position", "look_at", "up", "fov", "size", "width", "height"});
    const std::string type = c["type"] ? r.text(c["type"]) : "pinhole";
    if (type == "orthographic")
    {
        camera.projection = Camera::Projection::ORTHOGRAPHIC;
        if (c["fov"])
        {
            r.failKey(c, "fov",
                      "key 'fov' is unused by an orthographic camera: its view is 'size' scene "
                      "units high");
        }
    }
    else if (type == "pinhole")
    {
        if (c["size"])
        {
            r.failKey(c, "size",
                      "key 'size' is unused by a pinhole camera: its view is 'fov' degrees high "
                      "(type: orthographic has a size)");
        }
    }
    else
    {
        r.fail(c["type"], "camera type must be pinhole or orthographic, got '" + type + "'");
    }
    if (c["position"])
        camera.position = r.vec3(c["position"], "camera position");
    if (c["look_at"])
        camera.lookAt = r.vec3(c["look_at"], "camera look_at");
    if (c["up"])
        camera.up = r.vec3(c["up"], "camera up");
    if (c["fov"])
        camera.fovDeg = r.positive(c["fov"], "fov");
    if (c["size"])
    {
        camera.size = r.positive(c["size"], "camera size");
        if (camera.size > kMaxCoordinate)
        {
            r.fail(c["size"], "camera size must not exceed 1e9");
        }
    }
    if (c["width"])
        camera.width = r.pixels(c["width"], "width");
    if (c["height"])
        camera.height = r.pixels(c["height"], "height");
    if (camera.fovDeg >= 180.0)
    {
        r.fail(c["fov"], "fov must be below 180 degrees");
    }
    if ((camera.lookAt - camera.position).norm() < 1e-12)
    {
        r.fail(c["look_at"]    ? c["look_at"]
               : c["position"] ? c["position"]
                               : c,
               "camera look_at equals its position");
    }
    if (!((camera.lookAt - camera.position).normalized().cross(camera.up).norm() >
          1e-9 * camera.up.norm()))
    {
        r.fail(c["up"] ? c["up"] : c, "camera up is zero or parallel to the view direction");
    }
}

/// {center: [x, y, z], radius: r}; the origin and 1 when not given.
Sphere ReadSphere(const Reader& r, const YAML::Node& sp, int material)
{
    r.keys(sp, "a sphere", {"center", "radius"});
    Sphere sphere;
    sphere.center = sp["center"] ? r.vec3(sp["center"], "sphere center") : Vec3::Zero();
    sphere.radius = sp["radius"] ? r.positive(sp["radius"], "sphere radius") : 1.0;
    if (sphere.radius > kMaxCoordinate)
    {
        r.fail(sp["radius"], "sphere radius must not exceed 1e9");
    }
    sphere.material = material;
    return sphere;
}

/// {point: [x, y, z], normal: [x, y, z]}; the origin and +y when not given.
Plane ReadPlane(const Reader& r, const YAML::Node& pl, int material)
{
    r.keys(pl, "a plane", {"point", "normal"});
    Plane plane;
    plane.point = pl["point"] ? r.vec3(pl["point"], "plane point") : Vec3::Zero();
    plane.normal = pl["normal"] ? r.vec3(pl["normal"], "plane normal") : Vec3(0, 1, 0);
    if (plane.normal.norm() < 1e-12)
    {
        r.fail(pl["normal"], "plane normal must not be zero");
    }
    plane.normal.normalize();
    plane.material = material;
    return plane;
}

/// The objects: each one sphere or one plane, of a material the scene
/// defines.
void ReadObjects(const Reader& r, const YAML::Node& os, const MaterialIndex& materials, Scene& s)
{
    if (!os.IsSequence())
    {
        r.fail(os, "objects must be a list");
    }
    for (const auto& o : os)
    {
        r.keys(o, "an object", {"sphere", "plane", "material"});
        if (!o["material"])
        {
            r.fail(o, "an object needs a material");
        }
        const std::string mat = r.text(o["material"]);
        const auto it = materials.find(mat);
        if (it == materials.end())
        {
            r.fail(o["material"], "unknown material '" + mat + "'");
        }
        if (o["sphere"] && o["plane"])
        {
            r.failKey(o, "plane", "an object is one sphere or one plane, not both");
        }
        if (o["sphere"])
        {
            s.spheres.push_back(ReadSphere(r, o["sphere"], it->second));
        }
        else if (o["plane"])
        {
            s.planes.push_back(ReadPlane(r, o["plane"], it->second));
        }
        else
        {
            r.fail(o, "an object is a sphere or a plane");
        }
    }
}

Scene ParseScene(const YAML::Node& root, const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const Reader r(path, slash == std::string::npos ? "" : path.substr(0, slash + 1));
    if (!root.IsMap())
    {
        throw Exception(path +
                        ": a scene is a YAML mapping (camera, render, lights, materials, "
                        "objects)");
    }
    r.keys(root, "the scene", {"camera", "render", "lights", "materials", "objects"});
    Scene s;
    if (const YAML::Node rn = root["render"])
    {
        ReadRender(r, rn, s.settings);
    }
    if (const YAML::Node c = root["camera"])
    {
        ReadCamera(r, c, s.camera);
    }
    const int direct = root["lights"] ? ReadLights(r, root["lights"], s.settings.bands, s) : 0;
    const MaterialIndex materials =
        root["materials"] ? ReadMaterials(r, root["materials"], s.settings.bands, direct, s)
                          : MaterialIndex{};
    if (const YAML::Node os = root["objects"])
    {
        ReadObjects(r, os, materials, s);
    }
    if (s.lights.empty())
    {
        throw Exception(path + ": the scene has no lights");
    }
    return s;
}

}  // namespace

Scene ReadSceneText(const std::string& text, const std::string& path)
{
    try
    {
        std::string checked = text;
        CheckUtf8Text(checked, path);
        return ParseScene(YAML::Load(checked), path);
    }
    catch (const YAML::Exception& e)
    {
        // Syntax errors, and a value of the wrong kind where the reader asks
        // yaml-cpp for a string (a list where a name belongs).
        const size_t line = e.mark.is_null() ? 0 : size_t(e.mark.line) + 1;
        // yaml-cpp says only "bad conversion" when a list or mapping stands
        // where the reader asked for a single value.
        const std::string what =
            e.msg == YAML::ErrorMsg::BAD_CONVERSION
                ? "expected a single value (a name or a number) here, not a list or mapping"
                : e.msg;
        throw Exception(SourcePosition(path, line) + ": " + OneLine(what));
    }
}

Scene ReadSceneFile(const std::string& path)
{
    return ReadSceneText(ReadTextFile(path, "scene file"), path);
}

}  // namespace bandlight
