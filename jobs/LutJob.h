// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <optional>
#include <string>

#include "requests/Inputs.h"
#include "luts/LutWriter.h"
#include "requests/Defaults.h"

namespace bandlight::jobs
{

/// `lut`: an illuminant change as a LUT file, written by OpenColorIO.
struct LutRequest
{
    RelightRequest relight;
    std::string out;  ///< the LUT file
    /// clf, ctf, cube, spi3d, 3dl, resolve_cube, csp, houdini (LutFormats());
    /// empty: the format that owns `out`'s extension (LutFormatForPath).
    std::string format;
    /// 3D LUT points per axis (default defaults::LUT_SIZE); for CLF/CTF,
    /// giving it bakes a 3D LUT instead of the exact matrix.
    std::optional<int> size;
    std::string shaper = defaults::LUT_SHAPER;  ///< "log2" or "none" (linear encoding only)
    /// "linear", "acescct" or "acescc": with a log encoding the 3D LUT takes
    /// and returns that encoding of the working space's linear values (ACEScct
    /// itself with the working space acescg) and `shaper` is not used.
    std::string encoding = defaults::LUT_ENCODING;
};

struct LutResult
{
    LutFiles files;
    int size = defaults::LUT_SIZE;
    ShaperSpec shaper;  ///< the shaper the lattice was baked through (linear encoding)
    std::string encodingDescription;  ///< what the LUT takes and returns, one sentence
};

/// Writes the LUT (and its companion shaper) of `request`, as one set.
LutResult MakeLut(const LutRequest& request, Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
