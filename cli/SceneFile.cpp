// SPDX-License-Identifier: BSD-3-Clause
#include "cli/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include <yaml-cpp/yaml.h>
#include <Eigen/Geometry>

#include "cli/Common.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"
#include "transforms/IlluminantChange.h"

namespace bandlight::cli
{

namespace
{

/// Scene coordinates beyond this are refused: squared distances stay finite.
constexpr double kMaxCoordinate = 1e9;
/// Any number in a scene beyond this magnitude is refused: products of
/// intensities, powers and remittances over a spectrum stay far from
/// overflow (1e12 squared, times 10^4 samples, is 1e28).
constexpr double kMaxMagnitude = 1e12;
/// The spectral grid's step, nm: finer than 0.1 nm resolves nothing the CIE
/// tables hold (and would take 4701+ samples a product); coarser than 50 nm
/// cannot resolve a band.
constexpr double kMinStepNm = 0.1;
constexpr double kMaxStepNm = 50.0;

/// Reading context: the file for messages and relative paths.
struct Reader
{
    std::string path;
    std::string dir;

    [[noreturn]] void fail(const YAML::Node& n, const std::string& what) const
    {
        throw Exception(SourcePosition(path, n.Mark().is_null() ? 0 : size_t(n.Mark().line) + 1) +
                        ": " + OneLine(what));
    }

    void keys(const YAML::Node& map, const std::string& where,
              std::initializer_list<const char*> allowed) const
    {
        if (!map.IsMap())
        {
            fail(map, where + " must be a mapping");
        }
        for (const auto& kv : map)
        {
            const std::string k = kv.first.as<std::string>();
            if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return k == a; }))
            {
                std::string list;
                for (const char* a : allowed)
                {
                    list += (list.empty() ? "" : ", ") + std::string(a);
                }
                fail(kv.first, "unknown key '" + k + "' in " + where + " (allowed: " + list + ")");
            }
        }
    }

    /// A number with the scene-wide magnitude limit.
    double number(const YAML::Node& n, const std::string& what) const
    {
        const double v = finiteNumber(n, what);
        if (std::abs(v) > kMaxMagnitude)
        {
            fail(n, what + " must be at most 1e12 in magnitude, got " + n.Scalar());
        }
        return v;
    }

    /// Any finite number, for values that check a narrower range themselves.
    double finiteNumber(const YAML::Node& n, const std::string& what) const
    {
        if (!n.IsScalar())
        {
            fail(n, what + " must be a number");
        }
        try
        {
            const double v = n.as<double>();
            if (!std::isfinite(v))
            {
                fail(n, what + " must be finite, got '" + n.Scalar() + "'");
            }
            return v;
        }
        catch (const YAML::Exception&)
        {
            fail(n, what + " must be a number, got '" + n.Scalar() + "'");
        }
    }

    double positive(const YAML::Node& n, const std::string& what) const
    {
        const double v = number(n, what);
        if (!(v > 0.0))
        {
            fail(n, what + " must be positive, got " + n.Scalar());
        }
        return v;
    }

    /// An image size: a whole number of pixels, 1 to 16384.
    int pixels(const YAML::Node& n, const std::string& what) const
    {
        const double v = finiteNumber(n, what);
        if (!(v >= 1.0 && v <= 16384.0) || v != std::floor(v))
        {
            fail(n, what + " must be a whole number of pixels from 1 to 16384, got " + n.Scalar());
        }
        return int(v);
    }

    Vec3 vec3(const YAML::Node& n, const std::string& what) const
    {
        if (!n.IsSequence() || n.size() != 3)
        {
            fail(n, what + " must be a list of three numbers [x, y, z]");
        }
        const Vec3 v(finiteNumber(n[0], what), finiteNumber(n[1], what), finiteNumber(n[2], what));
        if (v.cwiseAbs().maxCoeff() > kMaxCoordinate)
        {
            fail(n, what + " must lie within ±1e9 (got a coordinate of " +
                        std::to_string(v.cwiseAbs().maxCoeff()) + ")");
        }
        return v;
    }

    std::vector<double> numbers(const YAML::Node& n, const std::string& what) const
    {
        if (!n.IsSequence() || n.size() == 0)
        {
            fail(n, what + " must be a list of numbers");
        }
        std::vector<double> v;
        for (const auto& x : n)
        {
            v.push_back(number(x, what));
        }
        return v;
    }

    std::string file(const YAML::Node& n) const
    {
        const std::string f = n.as<std::string>();
        return !f.empty() && f[0] == '/' ? f : dir + f;
    }

    std::vector<NamedSpectrum> readFile(const YAML::Node& n) const
    {
        try
        {
            return ReadSpectraFile(file(n));
        }
        catch (const Exception& e)
        {
            fail(n, e.what());
        }
    }
};

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
    r.keys(n, "a light spectrum", {"cct", "blackbody", "lines", "bands", "file"});
    if (n.size() != 1)
    {
        r.fail(n, "a light spectrum has exactly one of cct, blackbody, lines, bands, file");
    }
    const auto kv = *n.begin();
    const std::string kind = kv.first.as<std::string>();
    const YAML::Node& v = kv.second;
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
        const std::vector<double> b = r.numbers(v, "bands");
        if (b.size() != bands.size())
        {
            r.fail(v, "bands has " + std::to_string(b.size()) + " values for " +
                          std::to_string(bands.size()) + " bands");
        }
        return {"bands " + bands.describe(), StepSpectrum(bands, b), {}};
    }
    const std::vector<NamedSpectrum> s = r.readFile(v);
    return {v.as<std::string>(), s.front().spectrum, {}};
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
    r.keys(n, "a remittance", {"bands", "file", "sample"});
    if (n["bands"])
    {
        const std::vector<double> b = r.numbers(n["bands"], "bands");
        if (b.size() != bands.size())
        {
            r.fail(n["bands"], "bands has " + std::to_string(b.size()) + " values for " +
                                   std::to_string(bands.size()) + " bands");
        }
        return {"bands", StepSpectrum(bands, b), {}};
    }
    if (!n["file"])
    {
        r.fail(n, "a remittance mapping needs bands or file");
    }
    const std::vector<NamedSpectrum> all = r.readFile(n["file"]);
    if (n["sample"])
    {
        const std::string id = n["sample"].as<std::string>();
        for (const NamedSpectrum& s : all)
        {
            if (s.name == id)
            {
                return {id, s.spectrum, {}};
            }
        }
        r.fail(n["sample"], "no sample '" + id + "' in " + n["file"].as<std::string>());
    }
    return {all.front().name, all.front().spectrum, {}};
}

SceneSpectrum Scaled(SceneSpectrum s, double k)
{
    s.continuous *= k;
    return s;
}

SceneMaterial Material(const Reader& r, const std::string& name, const YAML::Node& n,
                       const BandSet& bands)
{
    if (n.IsScalar() && n.Scalar() == "lecture")
    {
        try
        {
            return LectureMaterial(name);
        }
        catch (const Exception& e)
        {
            r.fail(n, e.what());
        }
    }
    r.keys(n, "material '" + name + "'",
           {"lecture", "ambient", "diffuse", "specular", "exponent", "ambient_star", "k_a", "k_d",
            "k_s", "O_a", "O_d", "O_s", "n"});
    if (n["lecture"])
    {
        try
        {
            SceneMaterial m = LectureMaterial(n["lecture"].as<std::string>());
            m.name = name;
            return m;
        }
        catch (const Exception& e)
        {
            r.fail(n["lecture"], e.what());
        }
    }
    SceneMaterial m;
    m.name = name;
    const bool full = n["k_a"] || n["k_d"] || n["k_s"] || n["O_a"] || n["O_d"] || n["O_s"];
    const bool compact = n["ambient"] || n["diffuse"] || n["specular"] || n["exponent"];
    if (full && compact)
    {
        r.fail(n, "material '" + name +
                      "' mixes the full Phong form (k_a, O_a, ...) with the compact one "
                      "(ambient, diffuse, specular)");
    }
    const SceneSpectrum zero{"0", ConstantRemittance(0.0), {}};
    if (full)
    {
        // R_amb = k_a·O_a, R_diff = k_d·O_d, R_spek = k_s·O_s (SPEC §1.3).
        auto part = [&](const char* k, const char* o)
        {
            if (!n[k])
            {
                return zero;
            }
            const double kv = r.number(n[k], k);
            if (kv < 0.0)
            {
                r.fail(n[k], std::string(k) + " must not be negative");
            }
            return Scaled(
                n[o] ? Remittance(r, n[o], bands) : SceneSpectrum{"1", ConstantRemittance(1.0), {}},
                kv);
        };
        m.ambient = part("k_a", "O_a");
        m.diffuse = part("k_d", "O_d");
        m.specular = part("k_s", "O_s");
        m.exponent = n["n"] ? r.number(n["n"], "n") : 1.0;
    }
    else
    {
        m.ambient = n["ambient"] ? Remittance(r, n["ambient"], bands) : zero;
        m.diffuse = n["diffuse"] ? Remittance(r, n["diffuse"], bands) : zero;
        m.specular = n["specular"] ? Remittance(r, n["specular"], bands) : zero;
        m.exponent = n["exponent"] ? r.number(n["exponent"], "exponent") : 1.0;
    }
    if (n["ambient_star"])
    {
        m.ambientStar = Remittance(r, n["ambient_star"], bands);
    }
    if (m.exponent < 0.0)
    {
        r.fail(n, "material '" + name + "': the Phong exponent must not be negative");
    }
    return m;
}

}  // namespace

namespace
{

Scene ParseScene(const YAML::Node& root, const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const Reader r{path, slash == std::string::npos ? "" : path.substr(0, slash + 1)};
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
        r.keys(rn, "render", {"mode", "step", "output", "bands"});
        if (rn["bands"])
        {
            try
            {
                std::string edges;
                for (double e : r.numbers(rn["bands"], "bands"))
                {
                    edges += (edges.empty() ? "" : ",") + std::to_string(e);
                }
                s.settings.bands = BandSet::Parse(edges);
            }
            catch (const Exception& e)
            {
                r.fail(rn["bands"], e.what());
            }
        }
        if (rn["mode"])
        {
            const std::string mode = rn["mode"].as<std::string>();
            if (mode == "spectral")
            {
                s.settings.mode = RenderSettings::Mode::SPECTRAL;
            }
            else if (mode.rfind("band", 0) == 0)
            {
                s.settings.mode = RenderSettings::Mode::BAND;
                if (!rn["bands"])
                {
                    try
                    {
                        s.settings.bands = ParseMethod(mode).bands;
                    }
                    catch (const Exception&)
                    {
                        r.fail(rn["mode"],
                               "mode must be band3, bandN or spectral, got '" + mode + "'");
                    }
                }
            }
            else
            {
                r.fail(rn["mode"], "mode must be band3, bandN or spectral, got '" + mode + "'");
            }
        }
        if (rn["step"])
        {
            s.settings.stepNm = r.positive(rn["step"], "step");
            if (!(s.settings.stepNm >= kMinStepNm && s.settings.stepNm <= kMaxStepNm))
            {
                r.fail(rn["step"], "step must be from 0.1 to 50 nm, got " + rn["step"].Scalar());
            }
        }
        if (rn["output"])
        {
            s.settings.output = rn["output"].as<std::string>();
            if (s.settings.output != "bands")
            {
                try
                {
                    s.settings.output = FindRgbSpace(s.settings.output).name;
                }
                catch (const Exception& e)
                {
                    r.fail(rn["output"], e.what());
                }
            }
        }
    }
    const BandSet& bands = s.settings.bands;

    if (const YAML::Node c = root["camera"])
    {
        r.keys(c, "camera", {"position", "look_at", "up", "fov", "width", "height"});
        if (c["position"])
            s.camera.position = r.vec3(c["position"], "camera position");
        if (c["look_at"])
            s.camera.lookAt = r.vec3(c["look_at"], "camera look_at");
        if (c["up"])
            s.camera.up = r.vec3(c["up"], "camera up");
        if (c["fov"])
            s.camera.fovDeg = r.positive(c["fov"], "fov");
        if (c["width"])
            s.camera.width = r.pixels(c["width"], "width");
        if (c["height"])
            s.camera.height = r.pixels(c["height"], "height");
        if (s.camera.fovDeg >= 180.0)
        {
            r.fail(c["fov"], "fov must be below 180 degrees");
        }
        if (s.camera.width > 16384 || s.camera.height > 16384)
        {
            r.fail(c, "image size above 16384 pixels");
        }
        if ((s.camera.lookAt - s.camera.position).norm() < 1e-12)
        {
            r.fail(c, "camera look_at equals its position");
        }
        if (!((s.camera.lookAt - s.camera.position).normalized().cross(s.camera.up).norm() >
              1e-9 * s.camera.up.norm()))
        {
            r.fail(c["up"] ? c["up"] : c, "camera up is zero or parallel to the view direction");
        }
    }

    if (const YAML::Node ls = root["lights"])
    {
        if (!ls.IsSequence())
        {
            r.fail(ls, "lights must be a list");
        }
        for (const auto& l : ls)
        {
            r.keys(l, "a light",
                   {"type", "spectrum", "intensity", "position", "direction", "attenuation"});
            SceneLight light;
            const std::string type = l["type"] ? l["type"].as<std::string>() : "point";
            if (type == "ambient")
            {
                light.kind = SceneLight::Kind::AMBIENT;
            }
            else if (type == "point")
            {
                light.kind = SceneLight::Kind::POINT;
            }
            else if (type == "directional")
            {
                light.kind = SceneLight::Kind::DIRECTIONAL;
            }
            else
            {
                r.fail(l["type"],
                       "light type must be ambient, point or directional, got '" + type + "'");
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
            s.lights.push_back(light);
        }
    }

    std::map<std::string, int> materialIndex;
    if (const YAML::Node ms = root["materials"])
    {
        if (!ms.IsMap())
        {
            r.fail(ms, "materials must be a mapping of name: definition");
        }
        for (const auto& kv : ms)
        {
            const std::string name = kv.first.as<std::string>();
            materialIndex[name] = int(s.materials.size());
            s.materials.push_back(Material(r, name, kv.second, bands));
        }
    }

    if (const YAML::Node os = root["objects"])
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
            const std::string mat = o["material"].as<std::string>();
            const auto it = materialIndex.find(mat);
            if (it == materialIndex.end())
            {
                r.fail(o["material"], "unknown material '" + mat + "'");
            }
            if (o["sphere"])
            {
                const YAML::Node sp = o["sphere"];
                r.keys(sp, "a sphere", {"center", "radius"});
                Sphere sphere;
                sphere.center = sp["center"] ? r.vec3(sp["center"], "sphere center") : Vec3::Zero();
                sphere.radius = sp["radius"] ? r.positive(sp["radius"], "sphere radius") : 1.0;
                if (sphere.radius > kMaxCoordinate)
                {
                    r.fail(sp["radius"], "sphere radius must not exceed 1e9");
                }
                sphere.material = it->second;
                s.spheres.push_back(sphere);
            }
            else if (o["plane"])
            {
                const YAML::Node pl = o["plane"];
                r.keys(pl, "a plane", {"point", "normal"});
                Plane plane;
                plane.point = pl["point"] ? r.vec3(pl["point"], "plane point") : Vec3::Zero();
                plane.normal = pl["normal"] ? r.vec3(pl["normal"], "plane normal") : Vec3(0, 1, 0);
                if (plane.normal.norm() < 1e-12)
                {
                    r.fail(pl["normal"], "plane normal must not be zero");
                }
                plane.normal.normalize();
                plane.material = it->second;
                s.planes.push_back(plane);
            }
            else
            {
                r.fail(o, "an object is a sphere or a plane");
            }
        }
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

}  // namespace bandlight::cli
