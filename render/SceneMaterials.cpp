// SPDX-License-Identifier: BSD-3-Clause
// The scene reader's materials (render/SceneFile.cpp reads the rest): the
// Phong materials in their lecture, compact and full forms, and the
// remittances they are made of.
#include "render/detail/SceneParts.h"

#include <algorithm>
#include <cctype>

#include "spectral/CieData.h"
#include "spectral/Exception.h"

namespace bandlight::detail
{

namespace
{

using Reader = YamlReader;

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

}  // namespace

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

}  // namespace bandlight::detail
