// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "spectral/CieData.h"
#include "spectral/Spectrum.h"

namespace bandlight
{

/// A camera's spectral sensitivities: the relative response of its red,
/// green and blue channels per wavelength (any common scale: white balance
/// removes it). Outside a channel's grid the response is taken as zero.
struct CameraSensitivities
{
    std::string name;    ///< "manufacturer model" from a JSON header, else the source
    std::string source;  ///< the file it was read from, for messages
    Spectrum red;
    Spectrum green;
    Spectrum blue;

    const Spectrum& channel(int c) const { return c == 0 ? red : c == 1 ? green : blue; }
};

/// Reads camera sensitivities, choosing the reader from the content:
/// - JSON as the Academy's rawtoaces ships them (data/camera/*.json):
///   "header" (manufacturer, model) and "spectral_data" with "index":
///   {"main": ["R", "G", "B"]} and "data": {"main": {"380": [r, g, b], ...}}
///   on a regular grid;
/// - CSV or CGATS (as for spectra) with exactly three spectra: columns
///   named R/G/B or red/green/blue in any order, else taken in file order.
/// Throws Exception "FILE[:LINE]: ..." for anything else: malformed JSON
/// (with its line), missing keys, a value that is not a finite number, an
/// irregular grid, a negative response beyond noise (below −1 % of the
/// channel's peak), or a channel with no response over 380–780 nm.
CameraSensitivities ReadCameraFile(const std::string& path);

/// The same for text in memory; `source` names it in messages.
CameraSensitivities ReadCameraText(const std::string& text, const std::string& source);

/// The CIE observer's x̄, ȳ, z̄ as a camera ("cie1931" / "cie1964"): a
/// camera whose record is colorimetric, for tests and as the reference.
CameraSensitivities ObserverCamera(Observer observer = Observer::CIE1931_2DEG);

}  // namespace bandlight
