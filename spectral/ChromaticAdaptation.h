// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// Linear chromatic adaptation transforms: a cone-like space in which the
/// white is scaled channel by channel (a von Kries transform).
enum class AdaptationMethod
{
    XYZ_SCALING,  ///< von Kries scaling on XYZ itself
    BRADFORD,     ///< Lam (1985) / Hunt, the linearised Bradford matrix
    CAT02,        ///< CIECAM02 (CIE 159:2004)
    SHARP,        ///< spectrally sharpened sensors (Süsstrunk, Holm & Finlayson 2001)
};

/// One row of the adaptation table: the method, its name in options, files
/// and look names, and the other spellings it is given by.
struct AdaptationEntry
{
    AdaptationMethod method;
    const char* key;                   ///< "bradford"
    std::vector<const char*> aliases;  ///< "von-kries", "xyz" ...
};

/// Every adaptation method, in the order they are listed to users.
const std::vector<AdaptationEntry>& AdaptationMethods();

/// "vonkries"/"xyz", "bradford", "cat02", "sharp" (any case); throws
/// Exception listing the names otherwise.
AdaptationMethod ParseAdaptationMethod(const std::string& text);

/// The method's key: "vonkries", "bradford", "cat02", "sharp".
std::string AdaptationName(AdaptationMethod method);

/// The cone-response matrix of a method (XYZ → LMS).
Mat3 ConeResponseMatrix(AdaptationMethod method);

/// The 3×3 that maps XYZ seen under the source white to the corresponding
/// XYZ under the destination white: M⁻¹ · diag(M·dst / M·src) · M.
/// Whites may be on any common scale. Throws Exception for a white whose
/// cone response has a zero channel.
Mat3 AdaptationMatrix(const Vec3& srcWhiteXyz, const Vec3& dstWhiteXyz, AdaptationMethod method);

}  // namespace bandlight
