// SPDX-License-Identifier: BSD-3-Clause
// The scene reader's lights (render/SceneFile.cpp reads the rest): each
// light's kind, place and spectrum, and the band values a light spectrum or
// a remittance may be written as.
#include "render/detail/SceneParts.h"

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

namespace bandlight::detail
{

namespace
{

using Reader = YamlReader;

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

}  // namespace

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

}  // namespace bandlight::detail
