// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Spectrum.h"
#include "spectral/SpectrumIO.h"
#include "transforms/Methods.h"
#include "transforms/PixelKernels.h"
#include "transforms/RootPolynomial.h"

namespace bandlight
{

/// The 3×3 in the linear RGB space `working` that makes an image lit by
/// `from` look lit by `to`. For the band methods: working RGB → XYZ → band
/// space (pseudo-inverse of the row-normalised band matrix B) → per-band
/// ratio → B → XYZ → working RGB. The exposure of the white is kept: for
/// the von Kries family and band-wp the whites (Y = 1) map onto each other
/// exactly; for the plain band model the diagonal is scaled so that the
/// band model's white keeps its luminance. Throws Exception when an
/// illuminant has no power in a band, or a band coordinate of a white is
/// not positive (band-wp), and for the methods that are not one 3×3
/// (upsample, rootpoly, spectral: see Relighter). For balanced plates
/// (method.plates) the matrix is Bal(to) · M · Bal(from)⁻¹ (BalanceMatrix).
Mat3 IlluminantChangeMatrix(const Light& from, const Light& to, const MethodSpec& method,
                            const RgbSpace& working, Observer observer = Observer::CIE1931_2DEG);

/// The bound every pixel path clamps its input to: ±Inf become ±1e16 and
/// NaN −1e16 before a matrix, so no matrix computes Inf − Inf and every
/// result is finite (at most ‖M‖·1e16). The OCIO transforms do the same
/// with a RangeTransform (OCIO's clamp sends NaN to its lower bound); finite
/// pixels below the bound pass unchanged. Why 1e16: OCIO 2.1 writes a
/// RangeTransform's bounds into GPU shaders as "%.17g" plus "." for whole
/// numbers, which is a valid literal only below 1e17 ("1e+30." is a syntax
/// error in every shading language); 1e16 prints as "10000000000000000."
/// and also lies inside GLSL ES's guaranteed highp range (2^62).
/// docs/robustness.md tabulates the cases.
constexpr double PIXEL_GUARD = 1e16;

/// A pixel as the guard sees it: each channel clamped to ±PIXEL_GUARD, NaN
/// to −PIXEL_GUARD.
Vec3 GuardPixel(const Vec3& rgb) noexcept;

class PixelOp;

/// An illuminant change ready to apply to pixels: a 3×3 for the linear
/// methods, else the op its method makes (transforms/methods/PixelOp.h)
/// behind the pixel guard and the op's input matrix.
class Relighter
{
public:
    /// Throws Exception for `spectral` (it needs spectra, not pixels).
    Relighter(const Light& from, const Light& to, const MethodSpec& method, const RgbSpace& working,
              Observer observer = Observer::CIE1931_2DEG);
    ~Relighter();
    Relighter(Relighter&&) noexcept;

    bool isLinear() const noexcept { return !m_op; }
    /// The 3×3 of a linear method; for a non-linear one the 3×3 its op
    /// stands for (PixelOp::linearPart: upsample's fallback for pixels with
    /// no positive channel, the metamer matrix).
    const Mat3& matrix() const noexcept { return m_matrix; }
    /// rootpoly's fitted map (nullptr for other methods); for balanced
    /// plates it includes the balance for `to`.
    const RootPolynomial* rootPolynomial() const noexcept;

    /// One pixel, working RGB under `from` → as if under `to`; any input,
    /// NaN and Inf included, gives a finite result (see PIXEL_GUARD).
    Vec3 apply(const Vec3& rgb) const;
    /// `count` interleaved RGB float triples in place, on `threads` threads
    /// (0: all cores); upsample's fits are shared with every Relighter from
    /// the same light (UpsampleFits), so a pixel's result depends only on
    /// the pixel. The 3×3 and rootpoly run in float through the SIMD
    /// kernels (transforms/PixelKernels.h), upsample per pixel in double.
    void apply(float* rgb, size_t count, int threads = 0) const;
    /// The same on pixels of `stride` floats (3: RGB, 4: RGBA; R, G, B
    /// first, other channels unchanged).
    void apply(float* pixels, size_t count, size_t stride, int threads) const;

    /// `count` pixels in double precision, in place: apply(Vec3) for each,
    /// except that upsample shares one fit among the pixels of one
    /// chromaticity (all exposures of a colour), as the float path does.
    void apply(Vec3* rgb, size_t count) const;

    /// The 3×3 a non-linear method applies to the guarded pixel before its
    /// own work (balanced plates: the inverse balance for `from`;
    /// rootpoly-camera: the way back to the camera's record), or nullptr.
    const Mat3* inputMatrix() const noexcept;
    /// apply() without the guard and inputMatrix().
    void applyAfterInput(float* rgb, size_t count, int threads = 0) const;

private:
    Mat3 m_matrix = Mat3::Identity();
    /// The kernel's form of the 3×3.
    Matrix3f m_matrixF{};
    /// Non-linear methods: their op (nullptr: the method is m_matrix).
    std::unique_ptr<PixelOp> m_op;
    void build(const Light& from, const Light& to, const MethodSpec& method,
               const RgbSpace& working, Observer observer);
};

/// The description of the look `method` makes from `from` to `to`: the
/// lights, the method's own sentence and the plates it is for, with what
/// it does to 0.18 grey on balanced plates measured, not assumed.
std::string LookDescription(const Light& from, const Light& to, const MethodSpec& method,
                            const RgbSpace& working, Observer observer = Observer::CIE1931_2DEG);

/// Working RGB → band values (N × 3): the band-space conversion, B⁺ · M.
Eigen::MatrixXd WorkingToBandMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer = Observer::CIE1931_2DEG);

/// Band values → working RGB (3 × N): M⁻¹ · B.
Eigen::MatrixXd BandToWorkingMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer = Observer::CIE1931_2DEG);

/// The band model's material tint: working RGB → band space, multiply band b by
/// `remittance[b]` (R_diff), → working RGB. Throws Exception when the
/// remittance has not one value per band.
Mat3 MaterialTintMatrix(const std::vector<double>& remittance, const BandSet& bands,
                        const RgbSpace& working, Observer observer = Observer::CIE1931_2DEG);

}  // namespace bandlight
