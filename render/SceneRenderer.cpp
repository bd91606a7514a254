// SPDX-License-Identifier: BSD-3-Clause
#include "render/SceneRenderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <sstream>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "render/SceneColour.h"
#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Parallel.h"
#include "transforms/BandModel.h"

namespace bandlight
{

using namespace detail;

namespace
{

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
    bool orthographic;
    double halfHeight;  ///< tan(fov/2) (pinhole), or half the view's height (orthographic)
    double aspect;
    int width, height;

    explicit CameraRays(const Camera& c)
        : origin(c.position),
          forward((c.lookAt - c.position).normalized()),
          right(forward.cross(c.up).normalized()),
          up(right.cross(forward)),
          orthographic(c.projection == Camera::Projection::ORTHOGRAPHIC),
          halfHeight(orthographic ? 0.5 * c.size
                                  : std::tan(0.5 * c.fovDeg * kPi / 180.0)),
          aspect(double(c.width) / double(c.height)),
          width(c.width),
          height(c.height)
    {
    }

    /// The primary ray through the centre of pixel (x, y): its origin and
    /// unit direction.
    void ray(int x, int y, Vec3& o, Vec3& d) const
    {
        const double u = (2.0 * (x + 0.5) / width - 1.0) * halfHeight * aspect;
        const double v = (1.0 - 2.0 * (y + 0.5) / height) * halfHeight;
        if (orthographic)
        {
            o = origin + u * right + v * up;
            d = forward;
            return;
        }
        o = origin;
        d = (forward + u * right + v * up).normalized();
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
    // Back-facing and grazing lights give nothing; rounding cannot push cos α past 1.
    const double cosA = std::min(toLight.dot(hit.normal), 1.0);
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
    std::atomic<int> next{0};
    ParallelRun(threads, size_t(std::max(height, 0)),
                [&]
                {
                    for (int y; (y = next++) < height;)
                    {
                        rowFn(y);
                    }
                });
}

/// A black image of the camera's size in the output's channels.
RenderedImage BlankImage(const Scene& s, const Output& out)
{
    RenderedImage img;
    img.width = s.camera.width;
    img.height = s.camera.height;
    img.channels = out.channels;
    img.channelNames = out.names;
    img.pixels.assign(size_t(img.width) * size_t(img.height) * size_t(img.channels), 0.0f);
    return img;
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

/// Casts one primary ray per pixel, rows on `threads` threads, and lets
/// `shade(hit, direction, scratch, counters, pixel)` write each hit pixel;
/// `scratch` is a per-row buffer of `scratchSize` doubles. Background stays 0.
template <typename Shade>
RenderedImage CastRays(const Scene& s, const Output& out, int threads, RenderCounters* counters,
                       size_t scratchSize, Shade&& shade)
{
    const CameraRays cam(s.camera);
    RenderedImage img = BlankImage(s, out);
    RenderCounters total;
    std::mutex mu;
    ForEachRow(img.height, threads,
               [&](int y)
               {
                   RenderCounters c;
                   std::vector<double> scratch(scratchSize);
                   for (int x = 0; x < img.width; ++x)
                   {
                       ++c.pixels;
                       Vec3 o, d;
                       cam.ray(x, y, o, d);
                       Hit hit;
                       if (!Intersect(s, o, d, hit))
                       {
                           continue;
                       }
                       ++c.hits;
                       shade(hit, d, scratch, c,
                             &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) *
                                         size_t(img.channels)]);
                   }
                   std::lock_guard<std::mutex> lock(mu);
                   Add(total, c);
               });
    if (counters)
    {
        *counters = total;
    }
    // A render never leaves with Inf or NaN in it: values that large come
    // from the scene (intensities, powers or spectra near the double range),
    // and saying so beats writing an image no host can display.
    const size_t bad = size_t(std::count_if(img.pixels.begin(), img.pixels.end(),
                                            [](float v) { return !std::isfinite(v); }));
    if (bad > 0)
    {
        throw Exception("the render overflowed: " + std::to_string(bad) +
                        " pixel values are not finite floats (an intensity, power or spectrum "
                        "value in the scene is too large)");
    }
    return img;
}

}  // namespace

RenderedImage RenderScene(const Scene& s, const ScenePlan& p, int threads, RenderCounters* counters)
{
    const Output out = MakeOutput(s);
    const size_t ch = size_t(out.channels);
    return CastRays(
        s, out, threads, counters, ch,
        [&](const Hit& hit, const Vec3& d, std::vector<double>& acc, RenderCounters& c, float* px)
        {
            const size_t m = size_t(hit.material);
            acc = p.ambientColour[m];
            for (size_t g = 0; g < p.groups.size(); ++g)
            {
                Factors sum;
                for (int li : p.groups[g])
                {
                    const Factors f =
                        LightFactors(s.lights[size_t(li)], hit, -d, s.materials[m].exponent,
                                     p.specular, p.attenuation, c);
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
            for (size_t k = 0; k < ch; ++k)
            {
                px[k] = float(acc[k]);
            }
        });
}

namespace
{

/// A material's remittances on the render's samples.
struct RemittanceSamples
{
    std::vector<double> amb, diff, spec, star;
};

/// What the literal path integrates with: every light (scaled) and every
/// remittance sampled on the grid (spectral mode) or as band means.
struct LiteralSamples
{
    bool spectral;
    Grid grid;  ///< spectral mode; unused in band mode
    Cmf cmf;
    int n;  ///< samples (or bands) per spectrum
    std::vector<std::vector<double>> light;
    std::vector<double> lightScale;  ///< each light's band-model normalisation
    std::vector<RemittanceSamples> rem;
    Eigen::MatrixXd bandToXyz;
};

LiteralSamples SampleScene(const Scene& s)
{
    const bool spectral = s.settings.mode == RenderSettings::Mode::SPECTRAL;
    const BandSet& bands = s.settings.bands;
    // The same grid the planner would choose, so the two paths compare.
    std::string why;
    const Grid grid =
        spectral ? MakeGrid(s.settings, GridStep(s, why)) : MakeGrid(RenderSettings{}, 5.0);
    LiteralSamples ls{spectral, grid, MakeCmf(grid, bands), 0, {}, {}, {}, BandToXyz(bands)};
    ls.n = spectral ? grid.count : int(bands.size());
    for (const SceneLight& l : s.lights)
    {
        const double scale = LightScale(l.spectrum, bands);
        std::vector<double> v =
            spectral ? Sample(l.spectrum.continuous, grid) : Means(l.spectrum, bands);
        for (double& x : v)
        {
            x *= scale;
        }
        ls.lightScale.push_back(scale);
        ls.light.push_back(std::move(v));
    }
    const auto samples = [&](const SceneSpectrum& x)
    {
        if (x.continuous.empty())
        {
            return std::vector<double>(size_t(ls.n), 0.0);
        }
        return spectral ? Sample(x.continuous, grid) : BandMeans(x.continuous, bands);
    };
    for (const SceneMaterial& m : s.materials)
    {
        ls.rem.push_back(
            {samples(m.ambient), samples(m.diffuse), samples(m.specular), samples(m.ambientStar)});
    }
    return ls;
}

/// How much of a light's remittance terms reach the eye from a hit: an
/// ambient light's intensity on R_amb, a direct light's geometry on R_diff
/// and R_spek and its intensity on R_amb*.
struct TermWeights
{
    double kd = 0.0, ks = 0.0, ka = 0.0, kstar = 0.0;
};

/// Every term evaluated, whatever the scene: the literal path.
TermWeights WeighTerms(const SceneLight& l, const Hit& hit, const Vec3& d, double exponent,
                       RenderCounters& c)
{
    TermWeights k;
    if (l.kind == SceneLight::Kind::AMBIENT)
    {
        k.ka = l.intensity;
        return k;
    }
    k.kstar = l.intensity;  // R_amb*: only with one direct light (checked by the plan)
    const Factors fa = LightFactors(l, hit, -d, exponent, true, true, c);
    k.kd = fa.diffuse;
    k.ks = fa.specular;
    return k;
}

/// acc += light × (the weighted remittances), sample by sample.
void AddLightSamples(const std::vector<double>& light, const RemittanceSamples& rem,
                     const TermWeights& k, std::vector<double>& acc)
{
    for (size_t i = 0; i < acc.size(); ++i)
    {
        acc[i] += light[i] * (k.ka * rem.amb[i] + k.kd * rem.diff[i] + k.ks * rem.spec[i] +
                              k.kstar * rem.star[i]);
    }
}

/// xyz += each of the light's emission lines inside the grid on the
/// material's remittances, at the line's own wavelength.
void AddLinesXyz(const LiteralSamples& ls, const SceneLight& l, double lightScale,
                 const SceneMaterial& mat, const TermWeights& k, Vec3& xyz)
{
    const MatchingFunctions& f = GetMatchingFunctions(Observer::CIE1931_2DEG);
    for (const SpectralLine& line : l.spectrum.lines.lines())
    {
        const double w = line.wavelengthNm;
        if (!ls.grid.contains(w))
        {
            continue;
        }
        const double r =
            k.ka * mat.ambient.continuous(w) + k.kd * mat.diffuse.continuous(w) +
            k.ks * mat.specular.continuous(w) +
            (mat.ambientStar.continuous.empty() ? 0.0 : k.kstar * mat.ambientStar.continuous(w));
        xyz += lightScale * line.power * r * Vec3(f.x(w), f.y(w), f.z(w)) / ls.cmf.norm.y();
    }
}

/// A pixel's samples in the output's channels: integrated against the
/// matching functions (spectral mode, with the lines' XYZ), written as they
/// are (band output), or from band values to XYZ to the output.
std::vector<double> LiteralColour(const LiteralSamples& ls, const Output& out,
                                  const std::vector<double>& acc, const Vec3& linesXyz)
{
    if (ls.spectral)
    {
        Vec3 xyz = linesXyz;
        for (int i = 0; i < ls.n; ++i)
        {
            xyz += acc[size_t(i)] * ls.cmf.weight[size_t(i)];
        }
        return ToChannels(out, xyz);
    }
    if (out.bands)
    {
        return acc;
    }
    return ToChannels(out, ls.bandToXyz * Eigen::Map<const Eigen::VectorXd>(acc.data(), ls.n));
}

}  // namespace

RenderedImage RenderSceneUnplanned(const Scene& s, int threads, RenderCounters* counters)
{
    CheckScene(s);
    const Output out = MakeOutput(s);
    const LiteralSamples ls = SampleScene(s);
    return CastRays(
        s, out, threads, counters, size_t(ls.n),
        [&](const Hit& hit, const Vec3& d, std::vector<double>& acc, RenderCounters& c, float* px)
        {
            const size_t m = size_t(hit.material);
            std::fill(acc.begin(), acc.end(), 0.0);
            Vec3 linesXyz = Vec3::Zero();
            for (size_t li = 0; li < s.lights.size(); ++li)
            {
                const SceneLight& l = s.lights[li];
                const TermWeights k = WeighTerms(l, hit, d, s.materials[m].exponent, c);
                AddLightSamples(ls.light[li], ls.rem[m], k, acc);
                c.spectralSamples += uint64_t(ls.n);
                if (ls.spectral)
                {
                    AddLinesXyz(ls, l, ls.lightScale[li], s.materials[m], k, linesXyz);
                }
            }
            const std::vector<double> colour = LiteralColour(ls, out, acc, linesXyz);
            for (size_t k = 0; k < colour.size(); ++k)
            {
                px[k] = float(colour[k]);
            }
        });
}

std::string ExplainUnplanned(const Scene& s)
{
    CheckScene(s);
    const Output out = MakeOutput(s);
    const bool spectral = s.settings.mode == RenderSettings::Mode::SPECTRAL;
    int direct = 0, ambient = 0, lines = 0, outside = 0;
    std::string why;
    const Grid grid =
        spectral ? MakeGrid(s.settings, GridStep(s, why)) : MakeGrid(RenderSettings{}, 5.0);
    for (const SceneLight& l : s.lights)
    {
        (l.kind == SceneLight::Kind::AMBIENT ? ambient : direct) += 1;
        for (const SpectralLine& line : l.spectrum.lines.lines())
        {
            (!spectral || grid.contains(line.wavelengthNm) ? lines : outside) += 1;
        }
    }
    std::ostringstream o;
    o << "unplanned: " << (spectral ? "spectral" : "band") << " mode, " << s.camera.width << "x"
      << s.camera.height << ", output " << s.settings.output << " (" << out.channels
      << " channels), the literal path: no plan\n";
    o << "  per pixel, every light on its own: " << direct << " direct light"
      << (direct == 1 ? "" : "s") << " (cos a, cos^n psi and f_att evaluated for each, whatever "
      << "the materials and lights), " << ambient << " ambient\n";
    if (spectral)
    {
        o << "  per light, per wavelength sample: light x (R_amb, R_diff, R_spek, R_amb*) at "
          << DescribeRange(s.settings, grid) << "; grid " << why << "\n";
        if (lines)
        {
            o << "  " << lines << " emission lines: light x remittance at each line, per pixel\n";
        }
        if (outside)
        {
            o << "  " << outside << " emission lines outside the integration range: not counted\n";
        }
        o << "  then the pixel's spectrum is integrated against the matching functions and "
             "converted to "
          << s.settings.output << "\n";
    }
    else
    {
        o << "  per light, per band: light x (R_amb, R_diff, R_spek, R_amb*) in "
          << s.settings.bands.size() << " bands (" << s.settings.bands.describe() << " nm)\n";
        o << "  then the band values are "
          << (out.bands ? "written as they are" : "converted to " + s.settings.output) << "\n";
    }
    return o.str();
}

}  // namespace bandlight
