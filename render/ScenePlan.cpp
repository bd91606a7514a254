// SPDX-License-Identifier: BSD-3-Clause
// The planner: what a scene calls for, and its spectral products, computed once.
#include "bandlight/render/ScenePlan.h"

#include <algorithm>
#include <sstream>

#include "bandlight/render/SceneColour.h"
#include "bandlight/spectral/Exception.h"

namespace bandlight
{

using namespace detail;

ScenePlan PlanScene(const Scene& s, const PlanOptions& options)
{
    CheckScene(s);
    ScenePlan p;
    const Output out = MakeOutput(s);
    p.channels = out.channels;
    const bool spectral = s.settings.mode == RenderSettings::Mode::SPECTRAL;

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

    // Direct lights grouped by what they are — their spectrum's values,
    // exactly — never by what they are called: two `{bands: [...]}` lights
    // share a name but not a colour. One spectral term per group.
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
    const bool anyAmbient =
        std::any_of(s.lights.begin(), s.lights.end(),
                    [](const SceneLight& l) { return l.kind == SceneLight::Kind::AMBIENT; });
    p.ambient = anyAmbient;
    p.ambientFolded = anyAmbient && direct == 1 && options.optimise;
    p.reasons.push_back(!anyAmbient ? "ambient: none"
                        : p.ambientFolded
                            ? "ambient: folded into R_amb* (one direct source): a per-material "
                              "constant"
                            : "ambient: a per-material constant term");

    // Spectral grid and the products.
    Grid grid = MakeGrid(RenderSettings{}, 5.0);  // band mode: unused
    if (spectral)
    {
        std::string why;
        const double step = GridStep(s, why);
        grid = MakeGrid(s.settings, step);
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
    }
    else
    {
        p.samples = int(s.settings.bands.size());
        p.reasons.push_back("bands: " + std::to_string(p.samples) + " (" +
                            s.settings.bands.describe() + " nm)");
    }
    const Cmf cmf = MakeCmf(grid, s.settings.bands);
    const size_t nm = s.materials.size();
    p.diffuseColour.assign(p.groups.size(), std::vector<std::vector<double>>(nm));
    p.specularColour.assign(p.groups.size(), std::vector<std::vector<double>>(nm));
    for (size_t gi = 0; gi < p.groups.size(); ++gi)
    {
        const SceneSpectrum& light = s.lights[size_t(p.groups[gi][0])].spectrum;
        for (size_t m = 0; m < nm; ++m)
        {
            p.diffuseColour[gi][m] =
                ProductColour(s, out, light, s.materials[m].diffuse.continuous, grid, cmf);
            p.specularColour[gi][m] =
                p.specular
                    ? ProductColour(s, out, light, s.materials[m].specular.continuous, grid, cmf)
                    : std::vector<double>(size_t(out.channels), 0.0);
        }
    }
    p.ambientColour.assign(nm, std::vector<double>(size_t(out.channels), 0.0));
    for (const SceneLight& l : s.lights)
    {
        if (l.kind != SceneLight::Kind::AMBIENT)
        {
            continue;
        }
        for (size_t m = 0; m < nm; ++m)
        {
            const std::vector<double> c =
                ProductColour(s, out, l.spectrum, s.materials[m].ambient.continuous, grid, cmf);
            for (size_t k = 0; k < c.size(); ++k)
            {
                p.ambientColour[m][k] += l.intensity * c[k];
            }
        }
    }
    const bool anyStar =
        std::any_of(s.materials.begin(), s.materials.end(),
                    [](const SceneMaterial& m) { return !m.ambientStar.isZero(); });
    if (anyStar)
    {
        // CheckScene made sure there is exactly one direct light.
        const SceneLight& l = s.lights[size_t(p.groups[0][0])];
        for (size_t m = 0; m < nm; ++m)
        {
            if (s.materials[m].ambientStar.isZero())
            {
                continue;
            }
            const std::vector<double> c =
                ProductColour(s, out, l.spectrum, s.materials[m].ambientStar.continuous, grid, cmf);
            for (size_t k = 0; k < c.size(); ++k)
            {
                p.ambientColour[m][k] += l.intensity * c[k];
            }
        }
        p.reasons.push_back("R_amb*: the single source's light on R_amb*, a per-material constant");
    }
    std::ostringstream pre;
    pre << "precomputed: " << p.groups.size() * nm * (p.specular ? 2 : 1) + (anyAmbient ? nm : 0)
        << " light x remittance products of " << p.samples << (spectral ? " samples" : " bands")
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
