// SPDX-License-Identifier: BSD-3-Clause
#include "render/SceneColour.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "spectral/SpectralImage.h"
#include "transforms/BandModel.h"

namespace bandlight::detail
{

// ---------------------------------------------------------------------------
// Colour. A light is scaled so its largest band mean is 1 (the band model's I).
// The stimulus φ = light × remittance becomes CIE XYZ divided by N_y, the
// integral of ȳ over the bands: an equal-energy light of band value 1 on a
// white surface has Y = 1. Band mode gets the same XYZ from the band model's
// row-normalised band matrix B: XYZ = diag(N) / N_y · B · (I ⊙ R), N_k the
// band integral of each matching function (B's row normaliser).

Output MakeOutput(const Scene& s)
{
    Output o;
    if (s.settings.output == "bands")
    {
        if (s.settings.mode != RenderSettings::Mode::BAND)
        {
            throw Exception("output 'bands' needs band mode: spectral mode has no bands to write");
        }
        o.bands = true;
        o.channels = int(s.settings.bands.size());
        for (const Band& b : s.settings.bands)
        {
            o.names.push_back(b.name);
        }
        return o;
    }
    if (s.settings.output == SPECTRUM_OUTPUT)
    {
        if (s.settings.mode != RenderSettings::Mode::SPECTRAL)
        {
            throw Exception("spectral radiance needs spectral mode: band mode has no spectrum");
        }
        std::string why;
        const Grid g = MakeGrid(s.settings, GridStep(s, why));
        o.spectrum = true;
        o.channels = g.count;
        for (int i = 0; i < g.count; ++i)
        {
            o.names.push_back(SpectralChannelName(SpectralKind::EMISSIVE, g.wavelength(i)));
        }
        return o;
    }
    o.xyzToRgb = RgbToXyzMatrix(FindRgbSpace(s.settings.output).chromaticities).inverse();
    o.names = {"R", "G", "B"};
    return o;
}

/// Band means of a light or remittance (lines count in their band).
std::vector<double> Means(const SceneSpectrum& s, const BandSet& bands)
{
    std::vector<double> m(bands.size(), 0.0);
    if (!s.continuous.empty())
    {
        m = BandMeans(s.continuous, bands);
    }
    if (s.hasLines())
    {
        const std::vector<double> l = BandMeans(s.lines, bands);
        for (size_t b = 0; b < m.size(); ++b)
        {
            m[b] += l[b];
        }
    }
    return m;
}

double LightScale(const SceneSpectrum& s, const BandSet& bands)
{
    const std::vector<double> m = Means(s, bands);
    const double peak = *std::max_element(m.begin(), m.end());
    if (!(peak > 0.0))
    {
        throw Exception("light '" + s.name + "' has no power in bands " + bands.describe());
    }
    return 1.0 / peak;
}

Grid MakeGrid(const RenderSettings& settings, double step)
{
    // The step bounded so the sample count is a sane int (scene files refuse
    // the same range); the range inside 360–830 nm, the matching functions'.
    if (!(step >= 0.1 && step <= 50.0))
    {
        throw Exception("spectral step " + std::to_string(step) + " nm is outside 0.1-50 nm");
    }
    const double a = settings.rangeMinNm;
    const double b = settings.rangeMaxNm;
    if (!(a >= RenderSettings::kWidestRangeMinNm && b <= RenderSettings::kWidestRangeMaxNm &&
          b - a >= step))
    {
        std::ostringstream o;
        o << "spectral range " << a << "-" << b << " nm must lie within 360-830 nm and span at "
          << "least one step (" << step << " nm)";
        throw Exception(o.str());
    }
    return {a, b, step, int(std::floor((b - a) / step + 1e-9)) + 1};
}

std::string DescribeRange(const RenderSettings& settings, const Grid& grid)
{
    const bool byDefault = settings.rangeMinNm == RenderSettings::kDefaultRangeMinNm &&
                           settings.rangeMaxNm == RenderSettings::kDefaultRangeMaxNm;
    std::ostringstream o;
    o << grid.count << " samples at " << grid.step << " nm over " << grid.start << "-" << grid.end
      << " nm" << (byDefault ? " (the default, as docs/science.md §1.1 sums)" : " (as the scene sets)");
    return o.str();
}

double GridStep(const Scene& s, std::string& why)
{
    if (s.settings.stepNm > 0.0)
    {
        std::ostringstream o;
        o << s.settings.stepNm << " nm as the scene sets";
        why = o.str();
        return s.settings.stepNm;
    }
    return ChooseStep(s, why);
}

namespace
{
Vec3 CmfNorm(const BandSet& bands)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
    Vec3 n;
    const Spectrum* f[3] = {&cmf.x, &cmf.y, &cmf.z};
    for (int k = 0; k < 3; ++k)
    {
        const std::vector<double> m = BandMeans(*f[k], bands);
        double s = 0.0;
        for (size_t b = 0; b < bands.size(); ++b)
        {
            s += m[b] * bands[b].width();
        }
        n(k) = s;
    }
    return n;
}

}  // namespace

Cmf MakeCmf(const Grid& g, const BandSet& bands)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
    Cmf c;
    c.norm = CmfNorm(bands);
    for (int i = 0; i < g.count; ++i)
    {
        const double l = g.wavelength(i);
        c.weight.push_back(Vec3(cmf.x(l), cmf.y(l), cmf.z(l)) * (g.step / c.norm.y()));
    }
    return c;
}

std::vector<double> Sample(const Spectrum& s, const Grid& g)
{
    std::vector<double> v(size_t(g.count));
    for (int i = 0; i < g.count; ++i)
    {
        v[size_t(i)] = s.empty() ? 0.0 : s(g.wavelength(i));
    }
    return v;
}

/// XYZ_EE of (light × remittance), light scaled to its largest band = 1.
Vec3 ProductXyz(const SceneSpectrum& light, double scale, const Spectrum& remittance, const Grid& g,
                const Cmf& cmf)
{
    Vec3 xyz = Vec3::Zero();
    if (!light.continuous.empty())
    {
        for (int i = 0; i < g.count; ++i)
        {
            const double l = g.wavelength(i);
            xyz += light.continuous(l) * remittance(l) * cmf.weight[size_t(i)];
        }
    }
    const MatchingFunctions& f = GetMatchingFunctions(Observer::CIE1931_2DEG);
    for (const SpectralLine& line : light.lines.lines())
    {
        const double l = line.wavelengthNm;
        if (!g.contains(l))
        {
            continue;  // outside the integration range, like the samples
        }
        xyz += line.power * remittance(l) * Vec3(f.x(l), f.y(l), f.z(l)) / cmf.norm.y();
    }
    return xyz * scale;
}

/// diag(N) / N_y · B: band values → XYZ on the scene's scale.
Eigen::MatrixXd BandToXyz(const BandSet& bands)
{
    const Vec3 n = CmfNorm(bands);
    return (n / n.y()).asDiagonal() *
           MatchingBandMatrix(bands, MatchingSet::XYZ, Observer::CIE1931_2DEG);
}

std::vector<double> ToChannels(const Output& out, const Vec3& xyz)
{
    const Vec3 rgb = out.xyzToRgb * xyz;
    return {rgb.x(), rgb.y(), rgb.z()};
}

/// Light × remittance on the grid, scaled as Output::spectrum says; each
/// emission line's power split between its two neighbouring samples, so
/// the sum against the grid's matching functions is the line's exact
/// integral against their linear interpolant.
std::vector<double> ProductSpectrum(const SceneSpectrum& light, double scale,
                                    const Spectrum& remittance, const Grid& g, const Cmf& cmf)
{
    double k = 0.0;  // Σ ȳ·Δλ / N_y over the grid
    for (const Vec3& w : cmf.weight)
    {
        k += w.y();
    }
    std::vector<double> v(size_t(g.count), 0.0);
    if (!light.continuous.empty())
    {
        for (int i = 0; i < g.count; ++i)
        {
            const double l = g.wavelength(i);
            v[size_t(i)] = light.continuous(l) * remittance(l) * scale * k;
        }
    }
    for (const SpectralLine& line : light.lines.lines())
    {
        if (!g.contains(line.wavelengthNm))
        {
            continue;
        }
        const double t = (line.wavelengthNm - g.start) / g.step;
        const int i = std::min(int(t), g.count - 1);
        const double f = i + 1 < g.count ? t - i : 0.0;
        const double power = line.power * remittance(line.wavelengthNm) * scale * k / g.step;
        v[size_t(i)] += power * (1.0 - f);
        if (f > 0.0)
        {
            v[size_t(i) + 1] += power * f;
        }
    }
    return v;
}

/// One unit of `light` on `remittance`, in the output's channels.
std::vector<double> ProductColour(const Scene& s, const Output& out, const SceneSpectrum& light,
                                  const Spectrum& remittance, const Grid& grid, const Cmf& cmf)
{
    const BandSet& bands = s.settings.bands;
    const double scale = LightScale(light, bands);
    if (out.spectrum)
    {
        return ProductSpectrum(light, scale, remittance, grid, cmf);
    }
    if (s.settings.mode == RenderSettings::Mode::SPECTRAL)
    {
        return ToChannels(out, ProductXyz(light, scale, remittance, grid, cmf));
    }
    const std::vector<double> i = Means(light, bands);
    const std::vector<double> r = BandMeans(remittance, bands);
    Eigen::VectorXd product(Eigen::Index(bands.size()));
    for (size_t b = 0; b < bands.size(); ++b)
    {
        product(Eigen::Index(b)) = i[b] * scale * r[b];
    }
    if (out.bands)
    {
        return std::vector<double>(product.data(), product.data() + product.size());
    }
    return ToChannels(out, BandToXyz(bands) * product);
}

/// The coarsest of 20, 10, 5, 2 nm that reproduces every product of the
/// scene (1 nm as the truth) to 1e-4 of the light's white; else 1 nm.
double ChooseStep(const Scene& s, std::string& why)
{
    const BandSet& bands = s.settings.bands;
    const Grid fine = MakeGrid(s.settings, 1.0);
    const Cmf fineCmf = MakeCmf(fine, bands);
    double worst = 0.0;
    std::string worstLight, worstRemittance;
    for (double step : {20.0, 10.0, 5.0, 2.0})
    {
        if (fine.end - fine.start < step)
        {
            continue;
        }
        const Grid g = MakeGrid(s.settings, step);
        const Cmf c = MakeCmf(g, bands);
        worst = 0.0;
        for (const SceneLight& l : s.lights)
        {
            const double scale = LightScale(l.spectrum, bands);
            for (const SceneMaterial& m : s.materials)
            {
                for (const SceneSpectrum* r : {&m.ambient, &m.diffuse, &m.specular, &m.ambientStar})
                {
                    if (r->continuous.empty())
                    {
                        continue;
                    }
                    const Vec3 a = ProductXyz(l.spectrum, scale, r->continuous, g, c);
                    const Vec3 b = ProductXyz(l.spectrum, scale, r->continuous, fine, fineCmf);
                    const double e = (a - b).cwiseAbs().maxCoeff();
                    if (e > worst)
                    {
                        worst = e;
                        worstLight = l.spectrum.name;
                        worstRemittance = r->name;
                    }
                }
            }
        }
        if (worst <= 1e-4)
        {
            std::ostringstream o;
            o << step << " nm reproduces every light x remittance product to " << worst
              << " (1 nm as truth, tolerance 1e-4 of white)";
            why = o.str();
            return step;
        }
    }
    std::ostringstream o;
    o << "1 nm, the reference grid: at 2 nm light '" << worstLight << "' on remittance '"
      << worstRemittance << "' is off by " << worst << " of white (tolerance 1e-4)";
    why = o.str();
    return 1.0;
}

void CheckScene(const Scene& s)
{
    const int n = int(s.materials.size());
    for (const Sphere& sp : s.spheres)
    {
        if (sp.material < 0 || sp.material >= n)
        {
            throw Exception("a sphere uses material " + std::to_string(sp.material) + " of " +
                            std::to_string(n));
        }
    }
    for (const Plane& p : s.planes)
    {
        if (p.material < 0 || p.material >= n)
        {
            throw Exception("a plane uses material " + std::to_string(p.material) + " of " +
                            std::to_string(n));
        }
    }
    if (s.camera.width <= 0 || s.camera.height <= 0)
    {
        throw Exception("the image size must be positive");
    }
    const RenderSettings& set = s.settings;
    if (!(set.rangeMinNm >= RenderSettings::kWidestRangeMinNm &&
          set.rangeMaxNm <= RenderSettings::kWidestRangeMaxNm && set.rangeMinNm < set.rangeMaxNm))
    {
        throw Exception("the spectral range must lie within 360-830 nm, its start below its end");
    }
    // Degenerate geometry is refused here, so that the renderer never
    // normalises a zero vector (the scene reader says the same with a line).
    const Camera& c = s.camera;
    if (!c.position.allFinite() || !c.lookAt.allFinite() || !c.up.allFinite())
    {
        throw Exception("the camera's position, look_at and up must be finite");
    }
    const Vec3 forward = c.lookAt - c.position;
    if (!(forward.norm() > 1e-12))
    {
        throw Exception("the camera's look_at equals its position");
    }
    if (!(forward.normalized().cross(c.up).norm() > 1e-9 * c.up.norm()) || !(c.up.norm() > 0.0))
    {
        throw Exception("the camera's up vector is zero or parallel to its view direction");
    }
    if (c.projection == Camera::Projection::PINHOLE && !(c.fovDeg > 0.0 && c.fovDeg < 180.0))
    {
        throw Exception("the camera's field of view must lie between 0 and 180 degrees");
    }
    if (c.projection == Camera::Projection::ORTHOGRAPHIC && !(c.size > 0.0 && c.size <= 1e9))
    {
        throw Exception("an orthographic camera's size must be positive and at most 1e9");
    }
    for (const Sphere& sp : s.spheres)
    {
        if (!sp.center.allFinite() || !(sp.radius > 0.0) || !std::isfinite(sp.radius))
        {
            throw Exception("a sphere needs a finite centre and a positive, finite radius");
        }
    }
    for (const Plane& p : s.planes)
    {
        if (!p.point.allFinite() || !p.normal.allFinite() ||
            !(std::abs(p.normal.norm() - 1.0) < 1e-6))
        {
            throw Exception(
                "a plane needs a finite point and a unit normal (zero-length normals "
                "have no direction)");
        }
    }
    for (const SceneLight& l : s.lights)
    {
        // The band-mean normalisation every light gets (I_max = 1): a light
        // with no power in any band is refused here, whatever the mode.
        LightScale(l.spectrum, s.settings.bands);
        if (!std::isfinite(l.intensity) || l.intensity < 0.0)
        {
            throw Exception("a light's intensity must be finite and not negative");
        }
        if (l.kind == SceneLight::Kind::DIRECTIONAL && !(l.direction.norm() > 1e-12))
        {
            throw Exception("a directional light needs a non-zero direction");
        }
        if (!l.position.allFinite() || !l.direction.allFinite() || !l.attenuation.allFinite())
        {
            throw Exception("a light's position, direction and attenuation must be finite");
        }
    }
    const auto direct =
        std::count_if(s.lights.begin(), s.lights.end(),
                      [](const SceneLight& l) { return l.kind != SceneLight::Kind::AMBIENT; });
    const bool anyStar =
        std::any_of(s.materials.begin(), s.materials.end(),
                    [](const SceneMaterial& m) { return !m.ambientStar.isZero(); });
    if (anyStar && direct != 1)
    {
        // I = I_0 (R_amb* + ...) is the single-source form: with more or
        // fewer sources R_amb* has no I_0 to scale it.
        throw Exception("R_amb* (ambient_star) needs exactly one direct light, the scene has " +
                        std::to_string(direct));
    }
    for (const SceneMaterial& m : s.materials)
    {
        if (!(m.exponent >= 0.0) || !std::isfinite(m.exponent))
        {
            throw Exception("material '" + m.name +
                            "': the Phong exponent must be finite and not "
                            "negative");
        }
    }
}

}  // namespace bandlight::detail
