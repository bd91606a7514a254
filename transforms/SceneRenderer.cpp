// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/SceneRenderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"
#include "transforms/BandModel.h"

namespace bandlight
{

namespace
{

constexpr double kStartNm = 360.0;
constexpr double kEndNm = 830.0;

// ---------------------------------------------------------------------------
// Colour. A light is scaled so its largest band mean is 1 (the lecture's I).
// The stimulus φ = light × remittance becomes CIE XYZ divided by N_y, the
// integral of ȳ over the bands: an equal-energy light of band value 1 on a
// white surface has Y = 1. Band mode gets the same XYZ from the lecture's
// row-normalised band matrix B: XYZ = diag(N) / N_y · B · (I ⊙ R), N_k the
// band integral of each matching function (B's row normaliser).

struct Output
{
    bool bands = false;
    int channels = 3;
    std::vector<std::string> names;
    Mat3 xyzToRgb = Mat3::Identity();
};

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

/// Sampling grid for spectral mode.
struct Grid
{
    double step;
    int count;
    double wavelength(int i) const { return kStartNm + step * i; }
};

Grid MakeGrid(double step)
{
    return {step, int(std::floor((kEndNm - kStartNm) / step + 1e-9)) + 1};
}

/// Matching functions on the grid, each divided by its integral over the
/// bands (the lecture's rule, so B's rows and these agree).
struct Cmf
{
    std::vector<Vec3> weight;  // cmf(λ_i) · Δλ / N_y
    Vec3 norm;                 // N_k
};

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

/// One unit of `light` on `remittance`, in the output's channels.
std::vector<double> ProductColour(const Scene& s, const Output& out, const SceneSpectrum& light,
                                  const Spectrum& remittance, const Grid& grid, const Cmf& cmf)
{
    const BandSet& bands = s.settings.bands;
    const double scale = LightScale(light, bands);
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

bool IsZero(const Spectrum& s)
{
    return std::all_of(s.values().begin(), s.values().end(), [](double v) { return v == 0.0; });
}

/// The coarsest of 20, 10, 5, 2, 1 nm that reproduces every product of the
/// scene (1 nm as the truth) to 1e-4 of the light's white.
double ChooseStep(const Scene& s, std::string& why)
{
    const BandSet& bands = s.settings.bands;
    const Grid fine = MakeGrid(1.0);
    const Cmf fineCmf = MakeCmf(fine, bands);
    for (double step : {20.0, 10.0, 5.0, 2.0})
    {
        const Grid g = MakeGrid(step);
        const Cmf c = MakeCmf(g, bands);
        double worst = 0.0;
        for (const SceneLight& l : s.lights)
        {
            const double scale = LightScale(l.spectrum, bands);
            for (const SceneMaterial& m : s.materials)
            {
                for (const SceneSpectrum* r : {&m.ambient, &m.diffuse, &m.specular})
                {
                    if (r->continuous.empty())
                    {
                        continue;
                    }
                    const Vec3 a = ProductXyz(l.spectrum, scale, r->continuous, g, c);
                    const Vec3 b = ProductXyz(l.spectrum, scale, r->continuous, fine, fineCmf);
                    worst = std::max(worst, (a - b).cwiseAbs().maxCoeff());
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
    why = "the spectra have detail finer than 2 nm: 1 nm";
    return 1.0;
}

// ---------------------------------------------------------------------------
// Geometry.

struct Hit
{
    Vec3 point;
    Vec3 normal;
    int material = -1;
};

bool Intersect(const Scene& s, const Vec3& o, const Vec3& d, Hit& hit)
{
    double best = 1e300;
    for (const Sphere& sp : s.spheres)
    {
        const Vec3 oc = o - sp.center;
        const double b = oc.dot(d);
        const double c = oc.squaredNorm() - sp.radius * sp.radius;
        const double disc = b * b - c;
        if (disc < 0.0)
        {
            continue;
        }
        const double sq = std::sqrt(disc);
        double t = -b - sq;
        if (t <= 1e-9)
        {
            t = -b + sq;
        }
        if (t > 1e-9 && t < best)
        {
            best = t;
            hit.point = o + t * d;
            hit.normal = (hit.point - sp.center) / sp.radius;
            hit.material = sp.material;
        }
    }
    for (const Plane& pl : s.planes)
    {
        const double den = pl.normal.dot(d);
        if (std::abs(den) < 1e-12)
        {
            continue;
        }
        const double t = pl.normal.dot(pl.point - o) / den;
        if (t > 1e-9 && t < best)
        {
            best = t;
            hit.point = o + t * d;
            hit.normal = den < 0.0 ? Vec3(pl.normal) : Vec3(-pl.normal);  // face the eye
            hit.material = pl.material;
        }
    }
    return hit.material >= 0;
}

struct CameraRays
{
    Vec3 origin, forward, right, up;
    double tanHalf, aspect;
    int width, height;

    explicit CameraRays(const Camera& c)
        : origin(c.position),
          forward((c.lookAt - c.position).normalized()),
          right(forward.cross(c.up).normalized()),
          up(right.cross(forward)),
          tanHalf(std::tan(0.5 * c.fovDeg * 3.14159265358979323846 / 180.0)),
          aspect(double(c.width) / double(c.height)),
          width(c.width),
          height(c.height)
    {
    }

    Vec3 direction(int x, int y) const
    {
        const double u = (2.0 * (x + 0.5) / width - 1.0) * tanHalf * aspect;
        const double v = (1.0 - 2.0 * (y + 0.5) / height) * tanHalf;
        return (forward + u * right + v * up).normalized();
    }
};

/// The direct light's scalar factors at a hit: f_att·I·cos α and
/// f_att·I·cosⁿψ (zero for a light behind the surface).
struct Factors
{
    double diffuse = 0.0;
    double specular = 0.0;
};

Factors LightFactors(const SceneLight& l, const Hit& hit, const Vec3& toEye, double exponent,
                     bool specular, bool attenuation, RenderCounters& c)
{
    Vec3 toLight;
    double dist = 0.0;
    if (l.kind == SceneLight::Kind::DIRECTIONAL)
    {
        toLight = -l.direction.normalized();
    }
    else
    {
        toLight = l.position - hit.point;
        dist = toLight.norm();
        if (!(dist > 1e-12))
        {
            return {};
        }
        toLight /= dist;
    }
    ++c.lightTerms;
    const double cosA = toLight.dot(hit.normal);
    if (!(cosA > 0.0))
    {
        return {};
    }
    double f = l.intensity;
    if (attenuation && l.kind == SceneLight::Kind::POINT)
    {
        ++c.attenuationTerms;
        const Vec3& a = l.attenuation;
        f *= std::min(1.0, 1.0 / (a.x() + a.y() * dist + a.z() * dist * dist));
    }
    Factors out;
    out.diffuse = f * cosA;
    if (specular)
    {
        ++c.specularTerms;
        const Vec3 reflected = 2.0 * cosA * hit.normal - toLight;
        const double cosPsi = std::clamp(reflected.dot(toEye), 0.0, 1.0);
        out.specular = f * std::pow(cosPsi, exponent);
    }
    return out;
}

template <typename PixelFn>
void ForEachRow(int height, int threads, PixelFn&& rowFn)
{
    if (threads <= 0)
    {
        threads = int(std::max(1u, std::thread::hardware_concurrency()));
    }
    std::atomic<int> next{0};
    auto work = [&]
    {
        for (int y; (y = next++) < height;)
        {
            rowFn(y);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
    {
        pool.emplace_back(work);
    }
    work();
    for (std::thread& t : pool)
    {
        t.join();
    }
}

void Add(RenderCounters& into, const RenderCounters& c)
{
    into.pixels += c.pixels;
    into.hits += c.hits;
    into.lightTerms += c.lightTerms;
    into.specularTerms += c.specularTerms;
    into.attenuationTerms += c.attenuationTerms;
    into.spectralSamples += c.spectralSamples;
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
}

}  // namespace

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

    // Direct lights grouped by spectrum: one spectral term per group.
    std::map<std::string, size_t> byName;
    int direct = 0;
    for (size_t i = 0; i < s.lights.size(); ++i)
    {
        const SceneLight& l = s.lights[i];
        if (l.kind == SceneLight::Kind::AMBIENT)
        {
            continue;
        }
        ++direct;
        const auto it = byName.find(l.spectrum.name);
        if (options.optimise && it != byName.end())
        {
            p.groups[it->second].push_back(int(i));
        }
        else
        {
            byName[l.spectrum.name] = p.groups.size();
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
    Grid grid = MakeGrid(5.0);
    if (spectral)
    {
        std::string why;
        const double step = s.settings.stepNm > 0.0 ? s.settings.stepNm : ChooseStep(s, why);
        grid = MakeGrid(step);
        p.stepNm = step;
        p.samples = grid.count;
        p.reasons.push_back(
            "spectral grid: " +
            (s.settings.stepNm > 0.0 ? std::to_string(step) + " nm as the scene sets" : why));
        for (const SceneLight& l : s.lights)
        {
            p.lineCount += int(l.spectrum.lines.lines().size());
        }
        if (p.lineCount)
        {
            p.reasons.push_back(std::to_string(p.lineCount) +
                                " emission lines integrated exactly, at their wavelengths");
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
        if (direct != 1)
        {
            throw Exception("R_amb* (ambient_star) needs exactly one direct light, the scene has " +
                            std::to_string(direct));
        }
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

RenderedImage RenderScene(const Scene& s, const ScenePlan& p, int threads, RenderCounters* counters)
{
    const Output out = MakeOutput(s);
    const CameraRays cam(s.camera);
    RenderedImage img;
    img.width = s.camera.width;
    img.height = s.camera.height;
    img.channels = out.channels;
    img.channelNames = out.names;
    img.pixels.assign(size_t(img.width) * size_t(img.height) * size_t(img.channels), 0.0f);
    RenderCounters total;
    std::mutex mu;
    const size_t ch = size_t(out.channels);
    ForEachRow(img.height, threads,
               [&](int y)
               {
                   RenderCounters c;
                   std::vector<double> acc(ch);
                   for (int x = 0; x < img.width; ++x)
                   {
                       ++c.pixels;
                       const Vec3 d = cam.direction(x, y);
                       Hit hit;
                       if (!Intersect(s, cam.origin, d, hit))
                       {
                           continue;
                       }
                       ++c.hits;
                       const size_t m = size_t(hit.material);
                       acc = p.ambientColour[m];
                       for (size_t g = 0; g < p.groups.size(); ++g)
                       {
                           Factors sum;
                           for (int li : p.groups[g])
                           {
                               const Factors f = LightFactors(s.lights[size_t(li)], hit, -d,
                                                              s.materials[m].exponent, p.specular,
                                                              p.attenuation, c);
                               sum.diffuse += f.diffuse;
                               sum.specular += f.specular;
                           }
                           for (size_t k = 0; k < ch; ++k)
                           {
                               acc[k] += sum.diffuse * p.diffuseColour[g][m][k];
                               if (p.specular)
                               {
                                   acc[k] += sum.specular * p.specularColour[g][m][k];
                               }
                           }
                       }
                       float* px = &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * ch];
                       for (size_t k = 0; k < ch; ++k)
                       {
                           px[k] = float(acc[k]);
                       }
                   }
                   std::lock_guard<std::mutex> lock(mu);
                   Add(total, c);
               });
    if (counters)
    {
        *counters = total;
    }
    return img;
}

RenderedImage RenderSceneUnplanned(const Scene& s, int threads, RenderCounters* counters)
{
    CheckScene(s);
    const Output out = MakeOutput(s);
    const bool spectral = s.settings.mode == RenderSettings::Mode::SPECTRAL;
    const BandSet& bands = s.settings.bands;
    // The same grid the planner would choose, so the two paths compare.
    std::string why;
    const Grid grid = MakeGrid(!spectral                 ? 5.0
                               : s.settings.stepNm > 0.0 ? s.settings.stepNm
                                                         : ChooseStep(s, why));
    const Cmf cmf = MakeCmf(grid, bands);
    const int n = spectral ? grid.count : int(bands.size());

    // Samples of every light (scaled) and remittance: band means or the grid.
    auto samplesOf = [&](const SceneSpectrum& sp, double scale)
    {
        std::vector<double> v = spectral ? Sample(sp.continuous, grid) : Means(sp, bands);
        for (double& x : v)
        {
            x *= scale;
        }
        return v;
    };
    std::vector<std::vector<double>> light(s.lights.size());
    std::vector<double> lightScale(s.lights.size());
    for (size_t i = 0; i < s.lights.size(); ++i)
    {
        lightScale[i] = LightScale(s.lights[i].spectrum, bands);
        light[i] = samplesOf(s.lights[i].spectrum, lightScale[i]);
    }
    struct Rem
    {
        std::vector<double> amb, diff, spec, star;
    };
    std::vector<Rem> rem;
    for (const SceneMaterial& m : s.materials)
    {
        auto r = [&](const SceneSpectrum& x)
        {
            if (x.continuous.empty())
            {
                return std::vector<double>(size_t(n), 0.0);
            }
            return spectral ? Sample(x.continuous, grid) : BandMeans(x.continuous, bands);
        };
        rem.push_back({r(m.ambient), r(m.diffuse), r(m.specular), r(m.ambientStar)});
    }
    const Eigen::MatrixXd bm = BandToXyz(bands);
    const MatchingFunctions& f = GetMatchingFunctions(Observer::CIE1931_2DEG);

    const CameraRays cam(s.camera);
    RenderedImage img;
    img.width = s.camera.width;
    img.height = s.camera.height;
    img.channels = out.channels;
    img.channelNames = out.names;
    img.pixels.assign(size_t(img.width) * size_t(img.height) * size_t(img.channels), 0.0f);
    RenderCounters total;
    std::mutex mu;
    ForEachRow(
        img.height, threads,
        [&](int y)
        {
            RenderCounters c;
            std::vector<double> acc(static_cast<size_t>(n));
            for (int x = 0; x < img.width; ++x)
            {
                ++c.pixels;
                const Vec3 d = cam.direction(x, y);
                Hit hit;
                if (!Intersect(s, cam.origin, d, hit))
                {
                    continue;
                }
                ++c.hits;
                const size_t m = size_t(hit.material);
                std::fill(acc.begin(), acc.end(), 0.0);
                Vec3 lineXyz = Vec3::Zero();
                for (size_t li = 0; li < s.lights.size(); ++li)
                {
                    const SceneLight& l = s.lights[li];
                    double kd = 0.0, ks = 0.0, ka = 0.0, kstar = 0.0;
                    if (l.kind == SceneLight::Kind::AMBIENT)
                    {
                        ka = l.intensity;
                    }
                    else
                    {
                        kstar = l.intensity;  // R_amb*: only with one direct light (checked by the
                                              // plan)
                        const Factors fa =
                            LightFactors(l, hit, -d, s.materials[m].exponent, true, true, c);
                        kd = fa.diffuse;
                        ks = fa.specular;
                    }
                    for (int i = 0; i < n; ++i)
                    {
                        acc[size_t(i)] +=
                            light[li][size_t(i)] *
                            (ka * rem[m].amb[size_t(i)] + kd * rem[m].diff[size_t(i)] +
                             ks * rem[m].spec[size_t(i)] + kstar * rem[m].star[size_t(i)]);
                    }
                    c.spectralSamples += uint64_t(n);
                    if (spectral)
                    {
                        const SceneMaterial& mat = s.materials[m];
                        for (const SpectralLine& line : l.spectrum.lines.lines())
                        {
                            const double w = line.wavelengthNm;
                            const double r = ka * mat.ambient.continuous(w) +
                                             kd * mat.diffuse.continuous(w) +
                                             ks * mat.specular.continuous(w) +
                                             (mat.ambientStar.continuous.empty()
                                                  ? 0.0
                                                  : kstar * mat.ambientStar.continuous(w));
                            lineXyz += lightScale[li] * line.power * r *
                                       Vec3(f.x(w), f.y(w), f.z(w)) / cmf.norm.y();
                        }
                    }
                }
                std::vector<double> colour;
                if (spectral)
                {
                    Vec3 xyz = lineXyz;
                    for (int i = 0; i < n; ++i)
                    {
                        xyz += acc[size_t(i)] * cmf.weight[size_t(i)];
                    }
                    colour = ToChannels(out, xyz);
                }
                else if (out.bands)
                {
                    colour = acc;
                }
                else
                {
                    colour = ToChannels(out, bm * Eigen::Map<const Eigen::VectorXd>(acc.data(), n));
                }
                float* px =
                    &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels)];
                for (size_t k = 0; k < colour.size(); ++k)
                {
                    px[k] = float(colour[k]);
                }
            }
            std::lock_guard<std::mutex> lock(mu);
            Add(total, c);
        });
    if (counters)
    {
        *counters = total;
    }
    return img;
}

}  // namespace bandlight
