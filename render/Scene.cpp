// SPDX-License-Identifier: BSD-3-Clause
#include "render/Scene.h"

#include <algorithm>
#include <cctype>

#include "spectral/Exception.h"

namespace bandlight
{

bool SceneSpectrum::isZero() const noexcept
{
    const auto& v = continuous.values();
    const bool flatZero = std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
    const bool noLines = std::all_of(lines.lines().begin(), lines.lines().end(),
                                     [](const SpectralLine& l) { return l.power == 0.0; });
    return flatZero && noLines;
}

bool SceneSpectrum::sameValues(const SceneSpectrum& other) const noexcept
{
    const Spectrum& a = continuous;
    const Spectrum& b = other.continuous;
    const bool sameContinuous =
        a.empty() == b.empty() &&
        (a.empty() || (a.start() == b.start() && a.step() == b.step() && a.values() == b.values()));
    const auto& la = lines.lines();
    const auto& lb = other.lines.lines();
    return sameContinuous && la.size() == lb.size() &&
           std::equal(la.begin(), la.end(), lb.begin(),
                      [](const SpectralLine& x, const SpectralLine& y)
                      { return x.wavelengthNm == y.wavelengthNm && x.power == y.power; });
}

size_t ModeBandCount(const std::string& mode)
{
    std::string m = mode;
    std::transform(m.begin(), m.end(), m.begin(), [](unsigned char c) { return std::tolower(c); });
    if (m == "spectral")
    {
        return 0;
    }
    const std::string digits = m.rfind("band", 0) == 0 ? m.substr(4) : std::string();
    const bool ok = !digits.empty() && digits.size() <= 3 &&
                    std::all_of(digits.begin(), digits.end(),
                                [](unsigned char c) { return std::isdigit(c) != 0; });
    const int n = ok ? std::stoi(digits) : 0;
    if (n < 3 || n > 300)
    {
        throw Exception("mode must be band3, bandN (3 <= N <= 300) or spectral, got '" + mode +
                        "'");
    }
    return size_t(n);
}

void SetRenderMode(RenderSettings& settings, const std::string& mode)
{
    const size_t n = ModeBandCount(mode);
    if (n == 0)
    {
        settings.mode = RenderSettings::Mode::SPECTRAL;
        return;
    }
    settings.mode = RenderSettings::Mode::BAND;
    settings.bands = n == 3 ? BandSet::Lecture() : BandSet::Equal(n, 400.0, 700.0);
}

Spectrum StepSpectrum(const BandSet& bands, const std::vector<double>& values)
{
    // 1 nm samples so band edges fall on samples; a sample at λ belongs to
    // the band with a ≤ λ < b, as the band model's band means count them.
    std::vector<double> v(471, 0.0);
    for (size_t i = 0; i < v.size(); ++i)
    {
        const double l = 360.0 + double(i);
        for (size_t b = 0; b < bands.size(); ++b)
        {
            if (l >= bands[b].minNm && l < bands[b].maxNm)
            {
                v[i] = values[b];
            }
        }
    }
    return Spectrum(360.0, 1.0, std::move(v));
}

Spectrum ConstantRemittance(double value)
{
    return Spectrum::Constant(360.0, 5.0, 95, value);
}

const std::vector<std::string>& LectureMaterialNames()
{
    static const std::vector<std::string> names = {
        "copper", "gold", "silver", "aluminium", "tin", "matte lacquer", "gloss lacquer"};
    return names;
}

SceneMaterial LectureMaterial(const std::string& name)
{
    // docs/science.md §1.3 (components R, G, B; here in band order VB, VG, VR).
    struct Row
    {
        const char* name;
        double n;
        double diff[3];  // R, G, B
        double spek[3];
    };
    // clang-format off
    static const Row table[] = {
        {"copper",        2,  {1.0, 0.5, 0.4}, {0.9, 0.7, 0.3}},
        {"gold",          32, {0.5, 0.5, 0.0}, {1.0, 1.0, 0.0}},
        {"silver",        32, {0.5, 0.5, 0.5}, {1.0, 1.0, 1.0}},
        {"aluminium",     4,  {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}},
        {"tin",           8,  {0.8, 0.8, 0.8}, {1.0, 1.0, 1.0}},
        {"matte lacquer", 8,  {0.0, 1.0, 1.0}, {1.0, 1.0, 1.0}},
        {"gloss lacquer", 64, {1.0, 1.0, 0.0}, {1.0, 1.0, 1.0}},
    };
    // clang-format on
    for (const Row& r : table)
    {
        if (name == r.name)
        {
            const BandSet bands = BandSet::Lecture();
            const std::vector<double> diff = {r.diff[2], r.diff[1], r.diff[0]};
            const std::vector<double> spek = {r.spek[2], r.spek[1], r.spek[0]};
            SceneMaterial m;
            m.name = r.name;
            m.exponent = r.n;
            m.diffuse = {std::string(r.name) + " R_diff", StepSpectrum(bands, diff), {}};
            m.ambient = {std::string(r.name) + " R_amb", StepSpectrum(bands, diff), {}};
            m.specular = {std::string(r.name) + " R_spek", StepSpectrum(bands, spek), {}};
            return m;
        }
    }
    throw Exception("unknown lecture material '" + name +
                    "' (copper, gold, silver, aluminium, tin, matte lacquer, gloss lacquer)");
}

namespace
{
/// A light's group; a scene built in code may leave names empty: its
/// reader's rule then, light<N> in order.
std::string GroupOf(const Scene& scene, size_t i)
{
    const SceneLight& l = scene.lights[i];
    return !l.group.empty() ? l.group : !l.name.empty() ? l.name : "light" + std::to_string(i + 1);
}
}  // namespace

std::vector<std::string> LightGroupNames(const Scene& scene)
{
    std::vector<std::string> names;
    for (size_t i = 0; i < scene.lights.size(); ++i)
    {
        const std::string g = GroupOf(scene, i);
        if (std::find(names.begin(), names.end(), g) == names.end())
        {
            names.push_back(g);
        }
    }
    return names;
}

Scene SceneOfLightGroup(const Scene& scene, const std::string& group)
{
    Scene s = scene;
    s.lights.clear();
    bool direct = false;
    for (size_t i = 0; i < scene.lights.size(); ++i)
    {
        const SceneLight& l = scene.lights[i];
        if (GroupOf(scene, i) == group)
        {
            s.lights.push_back(l);
            direct = direct || l.kind != SceneLight::Kind::AMBIENT;
        }
    }
    if (s.lights.empty())
    {
        throw Exception("the scene has no light group '" + group + "'");
    }
    if (!direct)
    {
        for (SceneMaterial& m : s.materials)
        {
            m.ambientStar = SceneSpectrum();
        }
    }
    return s;
}

void CheckLightGroupName(const std::string& name)
{
    const bool chars =
        !name.empty() && std::all_of(name.begin(), name.end(),
                                     [](char c) {
                                         return std::isalnum(static_cast<unsigned char>(c)) ||
                                                c == '_' || c == '-';
                                     });
    if (!chars)
    {
        throw Exception(
            "a light's name or group must be letters, digits, '_' and '-' (it names "
            "the layer <group>.R, <group>.G, <group>.B), got '" +
            OneLine(name, 80) + "'");
    }
    for (const char* reserved : {"R", "G", "B", "A", "S0", "S1", "S2", "S3", "T"})
    {
        if (name == reserved)
        {
            throw Exception("a light group cannot be called '" + name +
                            "': it is a channel name of the render itself");
        }
    }
}

}  // namespace bandlight
