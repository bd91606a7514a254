// SPDX-License-Identifier: BSD-3-Clause
// The planner: what a scene calls for, and its spectral products, computed once.
#include "render/ScenePlan.h"

#include <algorithm>
#include <sstream>

#include "render/SceneColour.h"
#include "spectral/Exception.h"

namespace bandlight
{

using namespace detail;

namespace
{

/// Specular and attenuation: evaluated only where some material or light
/// has them (always with the planner off).
void PlanEffects(const Scene& s, const PlanOptions& options, ScenePlan& p)
{
    const bool anySpecular =
        std::any_of(s.materials.begin(), s.materials.end(),
                    [](const SceneMaterial& m) { return !m.specular.isZero(); });
    p.specular = anySpecular || !options.optimise;
    p.reasons.push_back(anySpecular        ? "specular: evaluated, some material has R_spek > 0"
                        : options.optimise ? "specular: skipped, no material has a specular part"
                                           : "specular: evaluated (planner off)");
    const bool anyAtt = std::any_of(
        s.lights.begin(), s.lights.end(),
        [](const SceneLight& l) { return l.kind == SceneLight::Kind::POINT && l.attenuates(); });
    p.attenuation = anyAtt || !options.optimise;
    p.reasons.push_back(anyAtt ? "attenuation: evaluated, a point light has c2 or c3 or c1 != 1"
                        : options.optimise ? "attenuation: skipped, f_att = 1 for every light"
                                           : "attenuation: evaluated (planner off)");
}

/// Direct lights grouped by what they are — their spectrum's values,
/// exactly — never by what they are called: two `{bands: [...]}` lights
/// share a name but not a colour. One spectral term per group. Returns the
/// number of direct lights.
int GroupLights(const Scene& s, const PlanOptions& options, ScenePlan& p)
{
    int direct = 0;
    for (size_t i = 0; i < s.lights.size(); ++i)
    {
        const SceneLight& l = s.lights[i];
        if (l.kind == SceneLight::Kind::AMBIENT)
        {
            continue;
        }
        ++direct;
        const auto same =
            std::find_if(p.groups.begin(), p.groups.end(),
                         [&](const std::vector<int>& g)
                         { return s.lights[size_t(g[0])].spectrum.sameValues(l.spectrum); });
        if (options.optimise && same != p.groups.end())
        {
            same->push_back(int(i));
        }
        else
        {
            p.groups.push_back({int(i)});
        }
    }
    std::ostringstream g;
    g << "light terms: " << p.groups.size() << " for " << direct << " direct light"
      << (direct == 1 ? "" : "s");
    if (int(p.groups.size()) < direct)
    {
        g << " (lights sharing a spectrum summed into one term)";
    }
    p.reasons.push_back(g.str());
    return direct;
}

/// Ambient light: with one direct source it folds into a per-material
/// constant.
void PlanAmbient(const Scene& s, const PlanOptions& options, int direct, ScenePlan& p)
{
    p.ambient =
        std::any_of(s.lights.begin(), s.lights.end(),
                    [](const SceneLight& l) { return l.kind == SceneLight::Kind::AMBIENT; });
    p.ambientFolded = p.ambient && direct == 1 && options.optimise;
    p.reasons.push_back(!p.ambient ? "ambient: none"
                        : p.ambientFolded
                            ? "ambient: folded into R_amb* (one direct source): a per-material "
                              "constant"
                            : "ambient: a per-material constant term");
}

/// The spectral grid the products are integrated on (spectral mode), with
/// the emission lines it holds; in band mode the bands, and a grid that is
/// not used.
Grid PlanGrid(const Scene& s, ScenePlan& p)
{
    if (s.settings.mode != RenderSettings::Mode::SPECTRAL)
    {
        p.samples = int(s.settings.bands.size());
        p.reasons.push_back("bands: " + std::to_string(p.samples) + " (" +
                            s.settings.bands.describe() + " nm)");
        return MakeGrid(RenderSettings{}, 5.0);
    }
    std::string why;
    const double step = GridStep(s, why);
    const Grid grid = MakeGrid(s.settings, step);
    p.stepNm = step;
    p.samples = grid.count;
    p.reasons.push_back("spectral grid: " + why);
    p.reasons.push_back("spectral range: " + DescribeRange(s.settings, grid));
    int outside = 0;
    for (const SceneLight& l : s.lights)
    {
        for (const SpectralLine& line : l.spectrum.lines.lines())
        {
            (grid.contains(line.wavelengthNm) ? p.lineCount : outside) += 1;
        }
    }
    if (p.lineCount)
    {
        p.reasons.push_back(std::to_string(p.lineCount) +
                            " emission lines integrated exactly, at their wavelengths");
    }
    if (outside)
    {
        p.reasons.push_back(std::to_string(outside) +
                            " emission lines outside the integration range: not counted");
    }
    return grid;
}

/// What the products are integrated with: the scene, its output, the grid
/// and the matching functions on it.
struct ProductSpace
{
    const Scene& s;
    const Output& out;
    const Grid& grid;
    const Cmf& cmf;

    std::vector<double> colour(const SceneSpectrum& light, const Spectrum& remittance) const
    {
        return ProductColour(s, out, light, remittance, grid, cmf);
    }
};

/// Per light group and material, the colour of one unit of the group's
/// light on the diffuse and specular remittances.
void ComputeDirectColours(const ProductSpace& ps, ScenePlan& p)
{
    const size_t nm = ps.s.materials.size();
    p.diffuseColour.assign(p.groups.size(), std::vector<std::vector<double>>(nm));
    p.specularColour.assign(p.groups.size(), std::vector<std::vector<double>>(nm));
    for (size_t gi = 0; gi < p.groups.size(); ++gi)
    {
        const SceneSpectrum& light = ps.s.lights[size_t(p.groups[gi][0])].spectrum;
        for (size_t m = 0; m < nm; ++m)
        {
            const SceneMaterial& mat = ps.s.materials[m];
            p.diffuseColour[gi][m] = ps.colour(light, mat.diffuse.continuous);
            p.specularColour[gi][m] = p.specular
                                          ? ps.colour(light, mat.specular.continuous)
                                          : std::vector<double>(size_t(ps.out.channels), 0.0);
        }
    }
}

/// colour[k] += intensity · c[k].
void AddScaled(std::vector<double>& colour, double intensity, const std::vector<double>& c)
{
    for (size_t k = 0; k < c.size(); ++k)
    {
        colour[k] += intensity * c[k];
    }
}

/// Per material, the summed ambient colour: every ambient light on R_amb,
/// and the single direct source on R_amb* where a material has one.
void ComputeAmbientColours(const ProductSpace& ps, ScenePlan& p)
{
    const Scene& s = ps.s;
    const size_t nm = s.materials.size();
    p.ambientColour.assign(nm, std::vector<double>(size_t(ps.out.channels), 0.0));
    for (const SceneLight& l : s.lights)
    {
        if (l.kind != SceneLight::Kind::AMBIENT)
        {
            continue;
        }
        for (size_t m = 0; m < nm; ++m)
        {
            AddScaled(p.ambientColour[m], l.intensity,
                      ps.colour(l.spectrum, s.materials[m].ambient.continuous));
        }
    }
    const bool anyStar =
        std::any_of(s.materials.begin(), s.materials.end(),
                    [](const SceneMaterial& m) { return !m.ambientStar.isZero(); });
    if (!anyStar)
    {
        return;
    }
    // CheckScene made sure there is exactly one direct light.
    const SceneLight& l = s.lights[size_t(p.groups[0][0])];
    for (size_t m = 0; m < nm; ++m)
    {
        if (!s.materials[m].ambientStar.isZero())
        {
            AddScaled(p.ambientColour[m], l.intensity,
                      ps.colour(l.spectrum, s.materials[m].ambientStar.continuous));
        }
    }
    p.reasons.push_back("R_amb*: the single source's light on R_amb*, a per-material constant");
}

}  // namespace

ScenePlan PlanScene(const Scene& s, const PlanOptions& options)
{
    CheckScene(s);
    ScenePlan p;
    const Output out = MakeOutput(s);
    p.channels = out.channels;
    PlanEffects(s, options, p);
    const int direct = GroupLights(s, options, p);
    PlanAmbient(s, options, direct, p);
    const Grid grid = PlanGrid(s, p);
    const Cmf cmf = MakeCmf(grid, s.settings.bands);
    const ProductSpace products{s, out, grid, cmf};
    ComputeDirectColours(products, p);
    ComputeAmbientColours(products, p);

    const size_t nm = s.materials.size();
    std::ostringstream pre;
    pre << "precomputed: " << p.groups.size() * nm * (p.specular ? 2 : 1) + (p.ambient ? nm : 0)
        << " light x remittance products of " << p.samples
        << (s.settings.mode == RenderSettings::Mode::SPECTRAL ? " samples" : " bands")
        << "; per pixel only scalars x colours";
    p.reasons.push_back(pre.str());
    return p;
}

std::string ExplainPlan(const Scene& s, const ScenePlan& p)
{
    std::ostringstream o;
    o << "plan: " << (s.settings.mode == RenderSettings::Mode::SPECTRAL ? "spectral" : "band")
      << " mode, " << s.camera.width << "x" << s.camera.height << ", output " << s.settings.output
      << " (" << p.channels << " channels)\n";
    for (const std::string& r : p.reasons)
    {
        o << "  " << r << "\n";
    }
    return o.str();
}

}  // namespace bandlight
