// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A spectral image as an accuracy test set: what every look does to this
// shot against the exact relight (`accuracy --image`), and where, as ΔE00
// heat maps.

#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "imaging/SpectralImages.h"
#include "spectral/AtomicFile.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight::jobs
{

/// At most this many distinct pixels of an image go into its accuracy set
/// (on a regular stride over the image); the heat maps cover every pixel.
constexpr size_t kMaxImageSamples = 4096;

/// The remittances of a spectral image's pixels, as a set named after the
/// file. Reflective images give their remittances as they are; emissive
/// ones are divided by `options.from` (the light the scene was lit by,
/// required) and scaled so that the brightest pixel (99.9th percentile of
/// Y) has Y = 1 under it. Black pixels and repeated spectra are left out;
/// spectra on an irregular grid are resampled linearly onto the smallest
/// step. Throws Exception naming the file.
ReflectanceSet ReflectanceSetFromSpectralImage(const std::string& path,
                                               const SpectralOptions& options,
                                               size_t maxSamples = kMaxImageSamples,
                                               Reporter& reporter = SilentReporter());

/// One method's ΔE00 map over an image.
struct HeatmapSummary
{
    std::string image;  ///< the spectral image mapped
    std::string method;
    double mean = 0.0;
    double p95 = 0.0;
    double max = 0.0;
    std::string exr;  ///< the map, one float channel "dE00"
    std::string png;  ///< the map in colour, with its scale
};

/// For each method (ideal forms, plates `options.plates`): every pixel
/// under `options.from` through the method, against the exact relight to
/// `options.to`, in CIEDE2000 (L*a*b* relative to the white the plates
/// say: `to`'s for lit plates, the working white for balanced ones; emissive
/// images scaled as ReflectanceSetFromSpectralImage scales them). Writes
/// DIR/<stem>_<method>_dE00.exr and .png (0 to 10 ΔE00, its scale beside)
/// into `outputs`, the run's one set of outputs, which the caller commits
/// after all of its work (HeatmapStems gives each image a distinct stem).
std::vector<HeatmapSummary> WriteAccuracyHeatmaps(const std::string& path,
                                                  const SpectralOptions& options,
                                                  const std::vector<std::string>& methods,
                                                  const std::string& dir, const std::string& stem,
                                                  OutputSet& outputs,
                                                  Reporter& reporter = SilentReporter());

/// The stems of the heat maps of `images`, distinct: each image's file stem,
/// with its folder's name before it (and then its place in the list) where
/// two images share a stem, so that shotA/beauty.exr and shotB/beauty.exr
/// give shotA_beauty_… and shotB_beauty_… and neither map replaces the other.
std::vector<std::string> HeatmapStems(const std::vector<std::string>& images);

}  // namespace bandlight::jobs
