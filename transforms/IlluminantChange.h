// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Spectrum.h"
#include "transforms/BandSet.h"

namespace bandlight
{

/// A way of changing the illuminant an image appears lit by.
enum class ChangeMethod
{
    NONE,       ///< identity: the reference for "doing nothing"
    VON_KRIES,  ///< von Kries scaling of XYZ by the ratio of the whites
    BRADFORD,   ///< linearised Bradford chromatic adaptation
    CAT02,      ///< CIECAM02 chromatic adaptation
    BAND,       ///< the lecture's band model: band ratios of the two lights
    BAND_WP,    ///< band model whose ratios come from the two whites: exact on white
};

/// A method with its parameters, parsed from its name: "none", "vonkries",
/// "bradford", "cat02", "band3" (the lecture's VB/VG/VR), "band3-wp",
/// "bandN" / "bandN-wp" (N equal bands over 400–700 nm).
struct MethodSpec
{
    ChangeMethod method = ChangeMethod::NONE;
    BandSet bands = BandSet::Lecture();
    std::string name;  ///< canonical name, used in look names: "band3-wp"

    bool usesBands() const noexcept
    {
        return method == ChangeMethod::BAND || method == ChangeMethod::BAND_WP;
    }
};

/// Parses a method name (case-insensitive); throws Exception listing the choices.
MethodSpec ParseMethod(const std::string& name);

/// The linear methods a config gets by default: none, vonkries, bradford,
/// cat02, band3, band3-wp.
const std::vector<std::string>& LinearMethodNames();

/// One sentence on what a method does and how accurate it is, for look
/// descriptions and --help.
std::string DescribeMethod(const MethodSpec& method);

/// An illuminant with the name it is known by.
struct Light
{
    std::string name;
    Spectrum spectrum;
};

/// The 3×3 in the linear RGB space `working` that makes an image lit by
/// `from` look lit by `to`. For the band methods: working RGB → XYZ → band
/// space (pseudo-inverse of the row-normalised band matrix B) → per-band
/// ratio → B → XYZ → working RGB. The exposure of the white is kept: for
/// the von Kries family and band-wp the whites (Y = 1) map onto each other
/// exactly; for the plain band model the diagonal is scaled so that the
/// band model's white keeps its luminance. Throws Exception when an
/// illuminant has no power in a band, or a band coordinate of a white is
/// not positive (band-wp).
Mat3 IlluminantChangeMatrix(const Light& from, const Light& to, const MethodSpec& method,
                            const RgbSpace& working, Observer observer = Observer::CIE1931_2DEG);

/// Working RGB → band values (N × 3): the band-space conversion, B⁺ · M.
Eigen::MatrixXd WorkingToBandMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer = Observer::CIE1931_2DEG);

/// Band values → working RGB (3 × N): M⁻¹ · B.
Eigen::MatrixXd BandToWorkingMatrix(const BandSet& bands, const RgbSpace& working,
                                    Observer observer = Observer::CIE1931_2DEG);

/// The lecture's material tint: working RGB → band space, multiply band b by
/// `remittance[b]` (R_diff), → working RGB. Throws Exception when the
/// remittance has not one value per band.
Mat3 MaterialTintMatrix(const std::vector<double>& remittance, const BandSet& bands,
                        const RgbSpace& working, Observer observer = Observer::CIE1931_2DEG);

}  // namespace bandlight
