// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// Chromaticities (CIE 1931 x, y) of three primaries and a white point.
struct Chromaticities
{
    double rx, ry, gx, gy, bx, by, wx, wy;
};

/// A Color Interop Forum ID of a space (colorInteropID, as OpenColorIO 2.4+
/// and OpenImageIO 2.5+ write them): linear, or sRGB-encoded.
struct InteropId
{
    std::string id;           ///< "lin_rec709_scene"
    bool srgbEncoded = false;  ///< the sRGB curve over the space's primaries
};

/// A linear RGB colour space defined by its chromaticities, with every name
/// it is known by: the one registry entry each part of bandlight reads
/// (parsing, help, configs, image tags, the identification of a studio
/// config's scene-linear space), as colour-science keeps RGB_COLOURSPACES.
struct RgbSpace
{
    std::string name;         ///< canonical key: "acescg", "rec709", ...
    std::string displayName;  ///< "Linear Rec.709 (sRGB)", ...
    std::string description;  ///< standard and white point
    Chromaticities chromaticities;
    /// Other names a user may give (case-insensitive; "lin-", "linear-" and
    /// "lin_" before the key or an alias name the same space).
    std::vector<std::string> aliases;
    /// The name of its colour space in the configs bandlight writes.
    std::string configName;
    /// The short label messages use: "Rec.709".
    std::string label;
    /// Its Color Interop Forum IDs; the first linear one is written into
    /// images in this space.
    std::vector<InteropId> interopIds;
    /// Lower-case words that, in a config's colour-space name, family or
    /// description, point to this space (identifying a studio config's
    /// scene-linear space).
    std::vector<std::string> keywords;
};

/// The built-in spaces: acescg (AP1), aces2065-1 (AP0), rec709 (linear
/// Rec.709, sRGB's primaries), rec2020, p3-d65, ebu3213.
const std::vector<RgbSpace>& BuiltinRgbSpaces();

/// Looks a space up by case-insensitive key or alias ("lin-rec709", "ap1",
/// "ap0", "ebu"); throws ParameterError listing the choices otherwise. A
/// space is linear: "srgb" alone names the sRGB-encoded image encoding, not
/// a working space, and is refused with a message pointing to rec709 and to
/// {colorspace} srgb.
const RgbSpace& FindRgbSpace(const std::string& name);

/// The built-in spaces code names for what they are rather than by a key
/// string: the sRGB and PNG previews' primaries (Rec.709), ACES's two, the
/// band model's EBU Tech 3213 and BT.2100's (Rec.2020).
const RgbSpace& Rec709Space();
const RgbSpace& Rec2020Space();
const RgbSpace& AcesCgSpace();
const RgbSpace& Aces2065Space();
const RgbSpace& Ebu3213Space();

/// The keys of the built-in spaces as help and errors list them:
/// "acescg, aces2065-1, rec709, rec2020, p3-d65, ebu3213".
std::string RgbSpaceChoices();

/// The RGB → XYZ matrix of a space, derived from its chromaticities
/// (SMPTE RP 177): columns are the primaries scaled so that RGB (1, 1, 1)
/// is the white point with Y = 1. Throws Exception for degenerate primaries.
Mat3 RgbToXyzMatrix(const Chromaticities& c);

/// XYZ (Y = 1) of a chromaticity.
Vec3 WhiteXyz(double x, double y);

/// Matrix from linear RGB space `src` to `dst`, the whites adapted with
/// Bradford when they differ (as the ACES and Blender configs do): what a
/// bandlight config's colour spaces hold.
Mat3 SpaceToSpace(const RgbSpace& src, const RgbSpace& dst);

}  // namespace bandlight
