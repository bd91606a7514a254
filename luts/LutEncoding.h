// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// What a LUT file's input and output values are.
///
/// `LINEAR`: the working space's linear values, through bandlight's log2
/// shaper (ShaperSpec) for scene-linear HDR or over [0, 1] without it.
///
/// `ACESCCT`, `ACESCC`: the working space's linear values encoded with the
/// ACEScct curve (Academy S-2016-001) or the ACEScc curve (S-2014-003), in
/// and out, as ACEScct and ACEScc encode ACEScg (AP1): with the working space
/// acescg the LUT takes and returns ACEScct (ACEScc) itself. The 3D LUT's
/// domain is the encoded [0, 1] (OCIO clamps a 3D LUT's input to it): ACEScct
/// 0 … 1 is linear -0.0069 … 222.9, ACEScc 0 … 1 is linear 0.0012 … 222.9.
/// No shaper is needed, so every format holds such a LUT.
enum class LutEncoding
{
    LINEAR,
    ACESCCT,
    ACESCC,
};

/// "linear", "acescct", "acescc" (case-insensitive); throws ParameterError
/// naming `{encoding}` otherwise.
LutEncoding ParseLutEncoding(const std::string& text);

/// "linear", "acescct", "acescc".
const char* LutEncodingName(LutEncoding encoding);

/// "ACEScct", "ACEScc" ("linear" for LINEAR).
const char* LutEncodingTitle(LutEncoding encoding);

/// Linear → encoded, per channel, as OpenColorIO's built-in transforms
/// compute it (nullptr for LINEAR): ACEScct is the inverse of OCIO 2.1's
/// "CURVE - ACEScct-LOG_to_LINEAR" (the S-2016-001 curve, exactly); ACEScc,
/// for which OCIO has no curve alone, is ACEScg → ACES2065-1 followed by the
/// inverse of "ACEScc_to_ACES2065-1" (whose primaries conversions cancel):
/// OCIO's own ACEScc, which clamps non-positive values to ACEScc's floor
/// -0.3584 as S-2014-003 does.
OCIO::TransformRcPtr LutEncodingTransform(LutEncoding encoding);

/// The published curves, evaluated directly (tests and documentation):
/// linear → encoded and back. ACEScct, S-2016-001: 10.5402377416545 · x +
/// 0.0729055341958355 up to x = 0.0078125, (log2 x + 9.72) / 17.52 above.
/// ACEScc, S-2014-003: (log2(2^-16 + x/2) + 9.72) / 17.52 below 2^-15,
/// (log2 x + 9.72) / 17.52 above, -0.3584 for x ≤ 0. LINEAR: the identity.
double EncodeLut(LutEncoding encoding, double linear) noexcept;
double DecodeLut(LutEncoding encoding, double encoded) noexcept;

/// One sentence for a LUT file's description and the command's output:
/// "Input and output: ACEScct (Academy S-2016-001) of ACEScg (AP1) linear
/// values, ...". `working` is the working space's display name.
std::string DescribeLutEncoding(LutEncoding encoding, const std::string& working);

}  // namespace bandlight
