// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A CIEDE2000 map over an image: what `render --compare` writes beside a
// render and `accuracy --heatmaps` beside a spectral shot. One value a
// pixel, their summary, and the two files: the values as an EXR and a PNG
// in colour with its scale.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "spectral/AtomicFile.h"

namespace bandlight
{

/// The top of a map's colour scale, in ΔE00: values at or above it are
/// drawn white. 10 is far beyond a visible difference (about 1 to 2), so
/// the scale spends its colours where methods differ.
inline constexpr double kDeltaEMapTop = 10.0;

/// ΔE00 over the pixels of a map that were measured.
struct DeltaESummary
{
    size_t pixels = 0;  ///< how many were measured
    double mean = 0.0;
    double p95 = 0.0;  ///< 95th percentile, nearest rank (spectral/Statistics.h)
    double max = 0.0;
};

/// ΔE00 per pixel of a width × height image, row by row, top row first.
/// Pixels not measured (a render's background, a shot's black pixels) are
/// 0 in the map and left out of the summary.
class DeltaEMap
{
public:
    DeltaEMap(int width, int height);

    /// Pixel `index` (y · width + x) was measured: ΔE00 `deltaE`.
    void set(size_t index, double deltaE);

    int width() const noexcept { return m_width; }
    int height() const noexcept { return m_height; }
    /// Every pixel's value, 0 where nothing was measured.
    const std::vector<float>& values() const noexcept { return m_values; }
    /// 1 where the pixel was measured, 0 where not.
    const std::vector<char>& measured() const noexcept { return m_mask; }
    /// Mean, 95th percentile and maximum of the measured pixels (all 0
    /// when none was).
    DeltaESummary summary() const;

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<float> m_values;
    std::vector<char> m_mask;
    std::vector<double> m_measured;  ///< in the order set() was called
};

/// Writes `map` into `outputs` (the caller commits the set): `exr`, one
/// float channel "dE00" in colour space "data" with `attributes`; and
/// `png`, the map in colour from 0 (black) to kDeltaEMapTop (white) with
/// its colour bar and `title` above it (block means when the image is
/// wider than 400 pixels; drawn by gnuplot, RunGnuplot). Throws Exception
/// naming the file.
void WriteDeltaEMap(const DeltaEMap& map, const std::string& exr, const std::string& png,
                    const std::string& title,
                    const std::vector<std::pair<std::string, std::string>>& attributes,
                    OutputSet& outputs);

}  // namespace bandlight
