// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What an image file says its pixels are — sRGB-encoded, linear with given
// primaries, or nothing — and the OCIO transforms between that and the
// linear space a job works in. bandlight converts or refuses, never guesses
// silently (docs/images.md).

#include <optional>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "imageio/ImageFiles.h"
#include "spectral/RgbSpaces.h"

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// The colour of an image's pixels.
struct ImageEncoding
{
    RgbSpace space;          ///< the primaries and white of the (linear) pixels
    bool srgbCurve = false;  ///< the values are sRGB-encoded (IEC 61966-2-1)
    double gamma = 0.0;      ///< > 0: the values are v^(1/gamma)-encoded (PNG's gAMA)
    bool assumed = false;    ///< the file said nothing; `space` is the caller's
    std::string evidence;    ///< "PNG, sRGB-encoded Rec.709", "EXR chromaticities of Rec.709"
    /// "sRGB-encoded Rec.709", "gamma 1.8-encoded Rec.709", "linear ACEScg",
    /// "linear the file's primaries R (0.64, 0.33) ...".
    std::string describe() const;
};

/// An encoding named by the user: a built-in RGB space's name (linear) or
/// "srgb" (sRGB-encoded Rec.709). Throws ParameterError naming {colorspace}.
ImageEncoding NamedEncoding(const std::string& name);

/// The short name of a built-in space in messages: "ACEScg", "Rec.709", …
std::string SpaceLabel(const RgbSpace& space);

/// Reads what `header` says of its pixels, in this order: colorInteropID,
/// EXR chromaticities, bandlight:colorSpace, oiio:ColorSpace ("sRGB",
/// "GammaX.Y", "Linear", a space's name), then the format (PNG, JPEG, 8- and 16-bit TIFF and any
/// other 8-bit file are sRGB-encoded Rec.709). A float file that says nothing is taken to be in
/// `fallback`, with assumed set. Throws Exception with one line naming
/// `file`, what it says and the parameters that say otherwise
/// ({colorspace}, {working_space}) when the tags contradict each other or
/// name an encoding bandlight does not know (a gamma, a log curve).
ImageEncoding IdentifyImageEncoding(const ImageData& header, const std::string& file,
                                    const RgbSpace& fallback);

/// True for formats that hold display-referred code values (8- and 16-bit
/// integers): what is written to them is encoded and clipped to 0–1.
bool IsDisplayReferred(const ImageData& header);

/// True for file names whose format holds display-referred code values
/// only (.png, .jpg, .gif, .bmp, .webp, …), by extension.
bool IsDisplayReferredFile(const std::string& path);

/// Throws ParameterError when `path`'s format keeps no channel names (every
/// format but OpenEXR, by extension) and `layers` (what the output would
/// hold: "light groups", "spectral channels") need them: "key.R" would come
/// back as "channel3".
void RequireNamedChannels(const std::string& path, const std::string& layers);

/// Encoded pixels of `from` → linear `to`: the sRGB curve (when encoded),
/// then the guarded matrix a bandlight config uses (Bradford between
/// whites). nullptr when nothing changes.
OCIO::ConstCPUProcessorRcPtr EncodingToLinear(const ImageEncoding& from, const RgbSpace& to);

/// The way back: linear `from` → `to`'s encoding.
OCIO::ConstCPUProcessorRcPtr LinearToEncoding(const RgbSpace& from, const ImageEncoding& to);

}  // namespace bandlight
