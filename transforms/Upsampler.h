// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <memory>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "transforms/SurfaceRenderer.h"

namespace bandlight
{

/// Spectral upsampling after W. Jakob and J. Hanika, "A Low-Dimensional
/// Function Space for Efficient Spectral Upsampling", Computer Graphics
/// Forum 38(2), 2019: a remittance r(λ) = S(c0 t² + c1 t + c2), t = (λ −
/// 380 nm) / 400 nm, with the sigmoid S(x) = ½ + x / (2 √(1 + x²)), so r is
/// smooth and strictly inside (0, 1). The three coefficients are fitted by
/// Levenberg–Marquardt so that r reproduces a pixel under illuminant S1.
class Upsampler
{
public:
    using Coeffs = Eigen::Vector3d;

    explicit Upsampler(const SurfaceRenderer& from);

    struct Fit
    {
        Coeffs coeffs = Coeffs::Zero();
        double residual = 0.0;  ///< |A1·r − c| / |w1| at the end
        int iterations = 0;
    };

    /// Fits c (working RGB under S1, at most the white in each channel)
    /// starting from `start` (the flat grey 0.5 by default).
    Fit fit(const Vec3& rgb, const Coeffs& start = Coeffs::Zero()) const;

    /// The remittance of a fit on the renderer's grid.
    static SurfaceRenderer::Samples Remittance(const Coeffs& c);

    /// The scale every pixel is fitted at: it is divided by
    /// k = max_i(c_i / w1_i) / kCanonicalLevel before fitting and its
    /// result multiplied by k after. A pixel's level is irradiance ×
    /// remittance and says nothing about the surface, so fitting its
    /// chromaticity at one level makes upsample exactly exposure invariant
    /// (f(k·c) = k·f(c)); HDR values and greys keep their ratios.
    double gamutScale(const Vec3& rgb) const noexcept;
    /// The level (largest channel relative to the white) pixels are fitted
    /// at. Chosen on training data, never on a test set: over rawtoaces'
    /// 190 reflectances, A/F2/F11/D50/D65 pairs, mean ΔE00 1.92 at 0.2,
    /// 1.68 at 0.35, 1.60 at 0.5, 1.73 at 0.7, 2.69 at 0.9 (too bright:
    /// saturated colours leave the smooth remittances' gamut).
    static constexpr double kCanonicalLevel = 0.5;

    const SurfaceRenderer& renderer() const noexcept { return m_from; }

private:
    const SurfaceRenderer& m_from;
    /// The renderer's matrix transposed: each channel's weights contiguous.
    Eigen::Matrix<double, SurfaceRenderer::kSamples, 3> m_rows;
};

/// upsample's fits for one source light, shared by every Relighter whose
/// source renderer (S1, working space, observer) is the same. A fit depends
/// only on the source light and the pixel's chromaticity: every pixel is
/// fitted at the canonical level (see gamutScale), so all the nodes of a
/// log lattice's ray through black, every target light and both plate
/// conventions (whose input matrices lead back to the colour under S1)
/// share it. Keyed by the scaled colour quantised to 2^-19 of the white,
/// each entry is the fit of its key's own colour from the flat grey, a pure
/// function of the key: results never depend on which pixel, thread or
/// target asked first. Thread safe; at most kMaxEntries are kept (further
/// fits are made and not stored), so a store serving images stays bounded.
class UpsampleFits
{
public:
    static constexpr size_t kMaxEntries = size_t(1) << 18;

    /// The store of `from`'s source light: the one every live user of that
    /// light holds, or a new one. It lives while anyone holds it.
    static std::shared_ptr<UpsampleFits> ForSource(const SurfaceRenderer& from);

    explicit UpsampleFits(const SurfaceRenderer& from);
    UpsampleFits(const UpsampleFits&) = delete;
    UpsampleFits& operator=(const UpsampleFits&) = delete;

    /// The key of a colour already scaled to the canonical level; false
    /// when a channel lies beyond ±1 of the white (the key cannot hold it).
    bool key(const Vec3& scaled, uint64_t& key) const noexcept;
    /// The fit of a key's colour, made now or earlier.
    Upsampler::Coeffs coeffs(uint64_t key);

    const Upsampler& upsampler() const noexcept { return m_up; }
    bool sameSource(const SurfaceRenderer& from) const noexcept;
    size_t size() const;

private:
    SurfaceRenderer m_from;
    Upsampler m_up;
    mutable std::shared_mutex m_mutex;
    std::unordered_map<uint64_t, Upsampler::Coeffs> m_fits;
};

/// One target's relit colours at the canonical level by UpsampleFits key:
/// the remittance is rendered once per chromaticity. One per thread. An
/// open-addressing table (a lattice bake looks up every node), keys never 0
/// (a key's largest channel is at the canonical level, above zero).
class UpsampleRendered
{
public:
    const Vec3* find(uint64_t key) const noexcept;
    void insert(uint64_t key, const Vec3& value);

private:
    size_t slot(uint64_t key) const noexcept;
    std::vector<uint64_t> m_keys;
    std::vector<Vec3> m_values;
    size_t m_size = 0;
    int m_bits = 0;
};

/// `upsample` for one pixel: scale into the gamut, fit under S1 (from the
/// flat grey), render the remittance under S2, scale back. Pixels with no
/// positive channel go through `fallback` (a linear 3×3: black and negative
/// noise have no remittance).
Vec3 UpsampleRelight(const Upsampler& up, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb);

/// The same through shared fits: the pixel's chromaticity is fitted once
/// in `fits` (its key's colour) and rendered once per target in `rendered`.
Vec3 UpsampleRelight(UpsampleFits& fits, const SurfaceRenderer& to, const Mat3& fallback,
                     const Vec3& rgb, UpsampleRendered& rendered);

}  // namespace bandlight
