// SPDX-License-Identifier: BSD-3-Clause
// The YAML scene reader. It says no to what it would ignore: a key is
// either used or an error naming its file, line and name.
#include "render/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include <Eigen/Geometry>

#include "render/detail/YamlReader.h"
#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/RgbSpaces.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"

namespace bandlight
{

namespace
{

using detail::Among;
using detail::kMaxCoordinate;
using detail::List;
using Reader = detail::YamlReader;

/// The spectral grid's step, nm: finer than 0.1 nm resolves nothing the CIE
/// tables hold (and would take 4701+ samples a product); coarser than 50 nm
/// cannot resolve a band.
constexpr double kMinStepNm = 0.1;
constexpr double kMaxStepNm = 50.0;

/// Band values `{bands: [...]}`, one per render band; `name` gets them as written.
std::vector<double> BandValues(const Reader& r, const YAML::Node& v, const BandSet& bands,
                               std::string& name)
{
    const std::vector<double> b = r.numbers(v, "bands");
    if (b.size() != bands.size())
    {
        r.fail(v, "bands has " + std::to_string(b.size()) + " values for " +
                      std::to_string(bands.size()) + " bands");
    }
    name = "bands";
    for (size_t i = 0; i < v.size(); ++i)
    {
        name += (i ? "," : " ") + v[i].Scalar();
    }
    return b;
}

const std::initializer_list<const char*> kLightSpectrumKeys = {"cct", "blackbody", "lines", "bands",
                                                               "file"};

/// A light's spectrum: a built-in name, {cct: K}, {blackbody: K},
/// {lines: [[nm, power], ...]}, {bands: [...]}, {file: path}.
SceneSpectrum LightSpectrum(const Reader& r, const YAML::Node& n, const BandSet& bands)
{
    if (n.IsScalar())
    {
        const std::string name = n.as<std::string>();
        try
        {
            return {CanonicalIlluminantName(name), BuiltinIlluminant(name), {}};
        }
        catch (const Exception& e)
        {
            r.fail(n, e.what());
        }
    }
    const std::vector<std::string> keys = r.keys(n, "a light spectrum", kLightSpectrumKeys);
    if (keys.empty())
    {
        r.fail(n, "a light spectrum needs one of " + List(kLightSpectrumKeys));
    }
    if (keys.size() > 1)
    {
        r.failKey(n, keys[1],
                  "a light spectrum has exactly one of " + List(kLightSpectrumKeys) + "; '" +
                      keys[1] + "' follows '" + keys[0] + "'");
    }
    const std::string kind = keys[0];
    const YAML::Node v = n[kind];
    try
    {
        if (kind == "cct")
        {
            const double k = r.positive(v, "cct");
            return {"daylight " + v.Scalar() + " K", Daylight(k), {}};
        }
        if (kind == "blackbody")
        {
            const double k = r.positive(v, "blackbody");
            return {"blackbody " + v.Scalar() + " K", Planckian(k, 360.0, 5.0, 95), {}};
        }
    }
    catch (const Exception& e)
    {
        r.fail(v, e.what());
    }
    if (kind == "lines")
    {
        if (!v.IsSequence() || v.size() == 0)
        {
            r.fail(v, "lines must be a list of [wavelength_nm, power]");
        }
        std::vector<SpectralLine> lines;
        std::string name = "lines";
        for (const auto& l : v)
        {
            if (!l.IsSequence() || l.size() != 2)
            {
                r.fail(l, "a line is [wavelength_nm, power]");
            }
            const double w = r.positive(l[0], "a line's wavelength");
            const double p = r.number(l[1], "a line's power");
            if (p < 0.0)
            {
                r.fail(l[1], "a line's power must not be negative");
            }
            lines.push_back({w, p});
            name += " " + l[0].Scalar() + ":" + l[1].Scalar();
        }
        return {name, {}, LineSpectrum(lines)};
    }
    if (kind == "bands")
    {
        std::string name;
        const std::vector<double> b = BandValues(r, v, bands, name);
        return {name, StepSpectrum(bands, b), {}};
    }
    const std::vector<NamedSpectrum> s = r.readFile(v);
    return {v.Scalar(), s.front().spectrum, {}};
}

/// A remittance: a number (constant), TCS01..TCS15, {bands: [...]},
/// {file: path[, sample: id]}.
SceneSpectrum Remittance(const Reader& r, const YAML::Node& n, const BandSet& bands)
{
    if (n.IsScalar())
    {
        const std::string text = n.Scalar();
        std::string upper = text;
        std::transform(upper.begin(), upper.end(), upper.begin(),
                       [](unsigned char c) { return std::toupper(c); });
        for (const NamedSpectrum& t : TestColourSamples())
        {
            if (t.name == upper)
            {
                return {t.name, t.spectrum, {}};
            }
        }
        const double v = r.number(n, "a remittance (a number, TCS01-TCS15, {bands}, {file})");
        if (v < 0.0)
        {
            r.fail(n, "a remittance must not be negative, got " + text);
        }
        return {text, ConstantRemittance(v), {}};
    }
    const std::vector<std::string> keys = r.keys(n, "a remittance", {"bands", "file", "sample"});
    if (n["bands"])
    {
        for (const std::string& k : keys)
        {
            if (k != "bands")
            {
                r.failKey(n, k,
                          "key '" + k +
                              "' is unused beside 'bands': a remittance is either "
                              "{bands: [...]} or {file: path, sample: id}");
            }
        }
        std::string name;
        const std::vector<double> b = BandValues(r, n["bands"], bands, name);
        return {name, StepSpectrum(bands, b), {}};
    }
    if (!n["file"])
    {
        if (n["sample"])
        {
            r.failKey(n, "sample", "key 'sample' needs 'file': the sample is an id in that file");
        }
        r.fail(n, "a remittance mapping needs bands or file");
    }
    const std::vector<NamedSpectrum> all = r.readFile(n["file"]);
    if (n["sample"])
    {
        const std::string id = r.text(n["sample"]);
        for (const NamedSpectrum& s : all)
        {
            if (s.name == id)
            {
                return {id, s.spectrum, {}};
            }
        }
        r.fail(n["sample"], "no sample '" + id + "' in " + n["file"].Scalar());
    }
    return {all.front().name, all.front().spectrum, {}};
}

SceneSpectrum Scaled(SceneSpectrum s, double k)
{
    s.continuous *= k;
    s.name = std::to_string(k) + " x " + s.name;
    return s;
}

const std::initializer_list<const char*> kCompactKeys = {"ambient", "diffuse", "specular",
                                                         "exponent"};
const std::initializer_list<const char*> kFullKeys = {"k_a", "k_d", "k_s", "O_a",
                                                      "O_d", "O_s", "n"};

/// The Phong exponent (`exponent` or `n`): used only with a specular part.
double Exponent(const Reader& r, const YAML::Node& n, const std::string& name, const char* key,
                const char* specularKey)
{
    if (!n[key])
    {
        return 1.0;
    }
    const double e = r.number(n[key], key);
    if (e < 0.0)
    {
        r.fail(n[key], "material '" + name + "': the Phong exponent must not be negative");
    }
    if (!n[specularKey])
    {
        r.failKey(n, key,
                  "key '" + std::string(key) + "' in material '" + name +
                      "' is unused: the material has no specular part (give '" + specularKey +
                      "')");
    }
    return e;
}

SceneMaterial Material(const Reader& r, const std::string& name, const YAML::Node& n,
                       const BandSet& bands)
{
    if (n.IsScalar())
    {
        if (n.Scalar() != "lecture")
        {
            r.fail(n, "material '" + name +
                          "' must be 'lecture' or a mapping (the compact or the full Phong form, "
                          "or {lecture: NAME}), got '" +
                          n.Scalar() + "'");
        }
        try
        {
            return LectureMaterial(name);
        }
        catch (const Exception& e)
        {
            r.fail(n, e.what());
        }
    }
    const std::vector<std::string> keys =
        r.keys(n, "material '" + name + "'",
               {"lecture", "ambient", "diffuse", "specular", "exponent", "ambient_star", "k_a",
                "k_d", "k_s", "O_a", "O_d", "O_s", "n"});
    if (n["lecture"])
    {
        for (const std::string& k : keys)
        {
            if (k != "lecture")
            {
                r.failKey(n, k,
                          "key '" + k + "' in material '" + name +
                              "' is unused beside 'lecture': a lecture material takes every "
                              "value from the table; write the compact or the full form to "
                              "change one");
            }
        }
        try
        {
            SceneMaterial m = LectureMaterial(r.text(n["lecture"]));
            m.name = name;
            return m;
        }
        catch (const Exception& e)
        {
            r.fail(n["lecture"], e.what());
        }
    }
    // The first key of either form decides the form; a key of the other
    // form would be ignored by it, so it is an error.
    const auto first = std::find_if(keys.begin(), keys.end(),
                                    [](const std::string& k)
                                    { return Among(k, kCompactKeys) || Among(k, kFullKeys); });
    const bool full = first != keys.end() && Among(*first, kFullKeys);
    for (const std::string& k : keys)
    {
        if (full ? Among(k, kCompactKeys) : Among(k, kFullKeys))
        {
            const std::string hint = k == "n"          ? ": write 'exponent'"
                                     : k == "exponent" ? ": write 'n'"
                                                       : "";
            r.failKey(n, k,
                      "key '" + k + "' in material '" + name + "' belongs to the " +
                          (full ? "compact form (" + List(kCompactKeys) + ")"
                                : "full form (" + List(kFullKeys) + ")") +
                          ", but '" + *first + "' makes it the " +
                          (full ? "full form" : "compact form") + hint);
        }
    }
    SceneMaterial m;
    m.name = name;
    const SceneSpectrum zero{"0", ConstantRemittance(0.0), {}};
    if (full)
    {
        // R_amb = k_a·O_a, R_diff = k_d·O_d, R_spek = k_s·O_s (docs/science.md §1.3);
        // O_* defaults to 1, and an O_* without its k_* would be ignored.
        auto part = [&](const char* k, const char* o, const char* r_)
        {
            if (!n[k])
            {
                if (n[o])
                {
                    r.failKey(n, o,
                              "key '" + std::string(o) + "' in material '" + name +
                                  "' is unused without '" + k + "' (" + r_ + " = " + k + "·" + o +
                                  ")");
                }
                return zero;
            }
            const double kv = r.notNegative(n[k], k);
            return Scaled(
                n[o] ? Remittance(r, n[o], bands) : SceneSpectrum{"1", ConstantRemittance(1.0), {}},
                kv);
        };
        m.ambient = part("k_a", "O_a", "R_amb");
        m.diffuse = part("k_d", "O_d", "R_diff");
        m.specular = part("k_s", "O_s", "R_spek");
        m.exponent = Exponent(r, n, name, "n", "k_s");
    }
    else
    {
        m.ambient = n["ambient"] ? Remittance(r, n["ambient"], bands) : zero;
        m.diffuse = n["diffuse"] ? Remittance(r, n["diffuse"], bands) : zero;
        m.specular = n["specular"] ? Remittance(r, n["specular"], bands) : zero;
        m.exponent = Exponent(r, n, name, "exponent", "specular");
    }
    if (n["ambient_star"])
    {
        m.ambientStar = Remittance(r, n["ambient_star"], bands);
    }
    return m;
}

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

SceneLight Light(const Reader& r, const YAML::Node& l, const BandSet& bands, size_t index)
{
    r.keys(
        l, "a light",
        {"type", "name", "group", "spectrum", "intensity", "position", "direction", "attenuation"});
    SceneLight light;
    light.name = l["name"] ? r.text(l["name"]) : "light" + std::to_string(index + 1);
    light.group = l["group"] ? r.text(l["group"]) : light.name;
    for (const char* key : {"name", "group"})
    {
        if (l[key])
        {
            try
            {
                CheckLightGroupName(r.text(l[key]));
            }
            catch (const Exception& e)
            {
                r.fail(l[key], e.what());
            }
        }
    }
    const std::string type = l["type"] ? r.text(l["type"]) : "point";
    // What each kind uses besides spectrum and intensity; anything else
    // given would be ignored, so it is an error.
    const char* unused[2] = {nullptr, nullptr};
    std::string why;
    if (type == "ambient")
    {
        light.kind = SceneLight::Kind::AMBIENT;
        for (const char* k : {"position", "direction", "attenuation"})
        {
            if (l[k])
            {
                r.failKey(l, k,
                          "key '" + std::string(k) +
                              "' is unused by an ambient light: it lights every surface alike "
                              "(spectrum and intensity only)");
            }
        }
    }
    else if (type == "point")
    {
        light.kind = SceneLight::Kind::POINT;
        unused[0] = "direction";
        why = "a point light shines from its position in every direction";
    }
    else if (type == "directional")
    {
        light.kind = SceneLight::Kind::DIRECTIONAL;
        unused[0] = "position";
        unused[1] = "attenuation";
        why =
            "a directional light is infinitely far: it has a direction, and no position or "
            "attenuation";
    }
    else
    {
        r.fail(l["type"], "light type must be ambient, point or directional, got '" + type + "'");
    }
    for (const char* k : unused)
    {
        if (k && l[k])
        {
            r.failKey(l, k,
                      "key '" + std::string(k) + "' is unused by a " + type + " light: " + why);
        }
    }
    if (!l["spectrum"])
    {
        r.fail(l, "a light needs a spectrum");
    }
    light.spectrum = LightSpectrum(r, l["spectrum"], bands);
    if (l["intensity"])
    {
        light.intensity = r.number(l["intensity"], "intensity");
        if (light.intensity < 0.0)
        {
            r.fail(l["intensity"], "intensity must not be negative");
        }
    }
    if (l["position"])
        light.position = r.vec3(l["position"], "light position");
    if (l["direction"])
    {
        light.direction = r.vec3(l["direction"], "light direction");
        if (light.direction.norm() < 1e-12)
        {
            r.fail(l["direction"], "light direction must not be zero");
        }
    }
    if (l["attenuation"])
    {
        light.attenuation = r.vec3(l["attenuation"], "attenuation [c1, c2, c3]");
        if ((light.attenuation.array() < 0.0).any() || light.attenuation.sum() <= 0.0)
        {
            r.fail(l["attenuation"], "attenuation coefficients must be >= 0, not all 0");
        }
    }
    return light;
}

/// The lights, each named once. Returns the number of direct (not ambient)
/// lights.
int ReadLights(const Reader& r, const YAML::Node& ls, const BandSet& bands, Scene& s)
{
    if (!ls.IsSequence())
    {
        r.fail(ls, "lights must be a list");
    }
    int direct = 0;
    for (const auto& l : ls)
    {
        s.lights.push_back(Light(r, l, bands, s.lights.size()));
        for (size_t i = 0; i + 1 < s.lights.size(); ++i)
        {
            if (s.lights[i].name == s.lights.back().name)
            {
                r.fail(l, "two lights are named '" + s.lights.back().name +
                              "': a light's name is its own (lights share a layer through "
                              "group:)");
            }
        }
        direct += s.lights.back().kind != SceneLight::Kind::AMBIENT;
    }
    return direct;
}

/// Material name → index into Scene::materials.
using MaterialIndex = std::map<std::string, int>;

/// The materials, each defined once; R_amb* only beside exactly one direct
/// light.
MaterialIndex ReadMaterials(const Reader& r, const YAML::Node& ms, const BandSet& bands, int direct,
                            Scene& s)
{
    if (!ms.IsMap())
    {
        r.fail(ms, "materials must be a mapping of name: definition");
    }
    MaterialIndex index;
    for (const auto& kv : ms)
    {
        const std::string name = r.text(kv.first);
        if (index.count(name))
        {
            r.fail(kv.first, "material '" + name + "' is defined twice");
        }
        index[name] = int(s.materials.size());
        s.materials.push_back(Material(r, name, kv.second, bands));
        if (kv.second.IsMap() && kv.second["ambient_star"] && direct != 1)
        {
            // The single-source form: I_0 is the one direct light.
            r.failKey(kv.second, "ambient_star",
                      "ambient_star (R_amb*) needs exactly one direct light, the scene has " +
                          std::to_string(direct));
        }
    }
    return index;
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
