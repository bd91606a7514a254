// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include <OpenColorIO/OpenColorIO.h>

#include "spectral/RgbSpaces.h"

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// The primaries of a config's scene_linear space, and what showed them.
struct SceneLinearIdentity
{
    const RgbSpace* space = nullptr;
    std::string evidence;  ///< one line: "colour space 'sRGB' is the sRGB encoding of ..."
};

/// Identifies the primaries (one of BuiltinRgbSpaces()) of `config`'s
/// scene_linear space by measuring it against colour spaces whose
/// definition is standard, in this order of trust:
///  1. the interchange roles (cie_xyz_d65_interchange, aces_interchange),
///     whose meaning OCIO defines;
///  2. any other colour space C of the config: scene_linear → C is measured
///     on 64 colours and, after undoing a standard encoding (none, the sRGB
///     curve, gamma 2.2/2.4/2.6, the BT.709 OETF), must be a 3×3 M to 1e-3;
///     M must equal, within 2e-3, the matrix from some built-in primaries P
///     to a standard target T (a built-in RGB space, or CIE XYZ with a D65,
///     E or the space's own white; whites adapted with Bradford or CAT02).
///     A space that merely repeats scene_linear (M = identity) counts only
///     when its name, aliases or family name its primaries ("sRGB",
///     "Rec.709", "ACEScg", "AP0", "XYZ", ...).
/// Every piece of evidence found must agree. Throws Exception naming what
/// was tried when nothing identifies the primaries, or what disagrees.
SceneLinearIdentity IdentifySceneLinear(const OCIO::ConstConfigRcPtr& config);

}  // namespace bandlight
