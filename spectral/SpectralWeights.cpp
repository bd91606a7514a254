// SPDX-License-Identifier: BSD-3-Clause
// Integrating a spectral layout: the weights that take a pixel's spectral
// channels to XYZ (SpectralXyzWeights), emissive or reflective, relit or
// not, over points or buckets, and a light's value on the layout's samples
// (LightOnLayout).
#include "spectral/SpectralImage.h"

#include <algorithm>
#include <cmath>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{

/// ∫ over [a, b] of the product of piecewise-linear f and g (g may be empty:
/// 1), on a 0.1 nm grid by the trapezoid rule: the matching functions are
/// tabulated at 5 nm, so this is exact to 1e-6 of the integral.
double IntegrateProduct(const Spectrum& f, const Spectrum* g, double a, double b)
{
    if (!(b > a))
    {
        return 0.0;
    }
    const int n = std::max(1, int(std::ceil((b - a) / 0.1)));
    const double h = (b - a) / n;
    double s = 0.0;
    for (int i = 0; i <= n; ++i)
    {
        const double l = a + h * i;
        const double v = f(l) * (g ? (*g)(l) : 1.0);
        s += (i == 0 || i == n) ? 0.5 * v : v;
    }
    return s * h;
}

}  // namespace

Eigen::Matrix<double, 3, Eigen::Dynamic> SpectralXyzWeights(const SpectralLayout& layout,
                                                            Observer observer,
                                                            const SpectralLighting& lighting,
                                                            std::vector<std::string>* notes)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    const Spectrum* f[3] = {&cmf.x, &cmf.y, &cmf.z};
    const size_t n = layout.wavelengths.size();
    const bool buckets = layout.sampling == SpectralSampling::BUCKETS;
    const bool reflective = layout.kind == SpectralKind::REFLECTIVE;
    if (reflective && lighting.to.empty())
    {
        throw ParameterError(
            "a reflective spectral image needs the light to render it under: "
            "{dst=}LIGHT");
    }
    if (!reflective && lighting.from.empty() && !lighting.to.empty())
    {
        throw ParameterError(
            "relighting an emissive spectral image needs the light it was lit "
            "by: {src=}LIGHT as well as {dst=}LIGHT");
    }
    // Emissive with S1 alone: integrated as it is (S1 is only the light the
    // caller balances from).
    const bool relight = !reflective && !lighting.from.empty() && !lighting.to.empty();
    // The light each wavelength is seen under: `to` for reflective images;
    // for relit emissive ones `to` over `from`, per cell.
    Eigen::Matrix<double, 3, Eigen::Dynamic> w(3, Eigen::Index(n));
    double norm = 0.0;  // Σ ȳ·Δλ (emissive) or Σ S·ȳ·Δλ (reflective)
    double fromY = 0.0, toY = 0.0;
    int lost = 0;
    for (size_t i = 0; i < n; ++i)
    {
        const double a = layout.edges[i], b = layout.edges[i + 1];
        const double l = layout.wavelengths[i];
        const double width = b - a;
        const Spectrum* light = reflective || relight ? &lighting.to : nullptr;
        for (int k = 0; k < 3; ++k)
        {
            w(k, Eigen::Index(i)) = buckets ? IntegrateProduct(*f[k], light, a, b)
                                            : (*f[k])(l) * (light ? (*light)(l) : 1.0) * width;
        }
        if (reflective)
        {
            norm += w(1, Eigen::Index(i));
            continue;
        }
        norm += buckets ? IntegrateProduct(cmf.y, nullptr, a, b) : cmf.y(l) * width;
        if (relight)
        {
            // The bucket's (or sample's) content over `from`: β ≈ L / S1.
            const double s1 = buckets ? lighting.from.integrateLinear(a, b) / width
                                      : lighting.from(l);  // as LightOnLayout
            const double y1 = buckets ? IntegrateProduct(cmf.y, &lighting.from, a, b)
                                      : cmf.y(l) * lighting.from(l) * width;
            fromY += y1;
            toY += w(1, Eigen::Index(i));
            if (!(s1 > 0.0))
            {
                if (w.col(Eigen::Index(i)).cwiseAbs().maxCoeff() > 0.0)
                {
                    ++lost;
                }
                w.col(Eigen::Index(i)).setZero();
            }
            else
            {
                w.col(Eigen::Index(i)) /= s1;
            }
        }
    }
    if (!(norm > 0.0) || (relight && !(fromY > 0.0 && toY > 0.0)))
    {
        throw Exception("the spectral image's grid (" + layout.describe() + ") sees no luminance" +
                        (relight || reflective ? " under the light" : ""));
    }
    if (relight)
    {
        w *= fromY / toY;  // S2 scaled to S1's luminance over the grid
    }
    if (lost > 0 && notes)
    {
        notes->push_back(std::to_string(lost) +
                         " wavelengths where the source light has no power contribute nothing "
                         "to the relit image");
    }
    return w / norm;
}

std::vector<double> LightOnLayout(const SpectralLayout& layout, const Spectrum& light)
{
    std::vector<double> s(layout.wavelengths.size());
    for (size_t i = 0; i < s.size(); ++i)
    {
        s[i] = layout.sampling == SpectralSampling::BUCKETS
                   ? light.integrateLinear(layout.edges[i], layout.edges[i + 1]) /
                         (layout.edges[i + 1] - layout.edges[i])
                   : light(layout.wavelengths[i]);
    }
    return s;
}

}  // namespace bandlight
