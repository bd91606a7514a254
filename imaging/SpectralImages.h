// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Spectral images in memory: read and checked, their spectra integrated
// (and relit exactly) to working RGB as one matrix per layout, and written
// back as spectral EXRs (Fichet 2021's layout).

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imageio/ImageFiles.h"
#include "requests/Defaults.h"
#include "requests/Inputs.h"
#include "spectral/AtomicFile.h"
#include "spectral/SpectralImage.h"

namespace bandlight::jobs
{

/// One spectral light group's change of light (`spectral --light-group
/// NAME=FROM:TO`): exact, S2/S1 per wavelength at the group's own light's
/// luminance.
struct SpectralLightGroup
{
    std::string group;
    Light from;
    Light to;
};

/// --sampling's value for "as the layout says" (SpectralSamplings() has the others).
inline constexpr const char* SAMPLING_AUTO = "auto";

/// The spectral kinds' and samplings' keys (auto first), from their tables
/// (spectral/SpectralImage.h), for parsing, choice checks and help.
std::vector<std::string> SpectralKindKeys();
std::vector<std::string> SpectralSamplingKeys();
/// "emissive or reflective"; "auto, points or buckets".
std::string SpectralKindChoices();
std::string SpectralSamplingChoices();
/// --sampling's help: each key with what it means.
std::string SpectralSamplingHelp();

/// How spectral pixels become working-space RGB: the lights, the working
/// space, the plate convention and the observer (docs/spectral.md).
struct SpectralOptions
{
    /// Emissive images: the light the scene was lit by (with `to`: relit;
    /// alone: integrated, and balanced from it). Reflective images: unused.
    Light from;
    /// Emissive images with `from`: the light to relight to. Reflective
    /// images: the light to render the remittances under (required).
    Light to;
    std::string workingSpace = defaults::WORKING_SPACE;
    /// "balanced": the result is white-balanced from the light it shows
    /// (`to`) to the working white (plates.adaptation); "lit": not. An
    /// emissive image only integrated shows no known light and stays lit.
    PlatesRequest plates;
    std::string observer = defaults::OBSERVER;
    /// Channels named otherwise: name → wavelength (nm), or a CSV file of
    /// them (ReadChannelWavelengths); `kind` "emissive" or "reflective".
    std::map<std::string, double> channelWavelengths;
    std::string channelWavelengthsFile;
    std::string kind = defaults::SPECTRAL_KIND;
    /// "auto" (as the layout says), "points" or "buckets".
    std::string sampling = defaults::SPECTRAL_SAMPLING;
    /// Light groups of a render with spectra per group ("<group>.S0.<λ>nm",
    /// as `render --spectra --light-groups` writes them): each named group
    /// relit exactly from its light to its new one (`from`/`to` unused), the
    /// others and the residual (beauty − Σ groups) integrated as they are;
    /// the output holds the beauty, Σ of them, and each group's RGB as
    /// "<group>.R/G/B". Needs plates "lit": a mix of lights has no one white.
    std::vector<SpectralLightGroup> lightGroups;

    /// The layout options these make (the file of wavelengths read).
    SpectralLayoutOptions layoutOptions() const;
};

/// A layout's integration folded into one matrix: RGB = weights · the
/// image's channels (zero for channels that are not spectral).
struct SpectralConversion
{
    SpectralLayout layout;
    /// 3 × (the image's channel count): working RGB per channel value.
    Eigen::Matrix<double, 3, Eigen::Dynamic> weights;
    std::string workingSpace;  ///< the RgbSpace name of the output
    bool balanced = false;     ///< white-balanced to the working white
    std::string applied;       ///< "relit A -> D65, balanced (CAT02), acescg"
    std::vector<std::string> notes;
};

/// The conversion of `layout` (of an image with `channels` channels) under
/// `options`. Throws Exception / ParameterError for lights the layout
/// cannot use (see SpectralXyzWeights).
SpectralConversion MakeSpectralConversion(const SpectralLayout& layout, int channels,
                                          const SpectralOptions& options);

/// What a spectral value that is NaN or infinite means.
enum class NonFiniteSpectra
{
    /// An error: a spectrum is data, and NaN in it is a broken file
    /// (`spectral`, `accuracy --image`).
    REFUSE,
    /// A pixel value, as every pixel path takes one: the pixel's RGB goes
    /// through GuardPixel after integration (NaN to -1e16, ±Inf to ±1e16),
    /// so the light groups of a render follow the policy of plain RGB
    /// light groups (docs/robustness.md).
    GUARD,
};

/// Throws Exception naming `file`, the channel and the pixel ((x, y) for an
/// image `width` pixels wide, else its index) when a spectral value is
/// negative, or NaN or infinite under NonFiniteSpectra::REFUSE. Returns
/// how many pixels hold a NaN or infinite value (0 under REFUSE).
size_t CheckSpectralPixels(const SpectralLayout& layout, const std::string& file,
                           const std::vector<std::string>& channelNames, const float* pixels,
                           size_t count, int channels, int width = 0,
                           NonFiniteSpectra nonFinite = NonFiniteSpectra::REFUSE);

/// RGB (3 floats a pixel) of `count` pixels of `channels` floats each, on
/// `threads` threads: one SIMD dot product per output channel and pixel.
/// Refuses integrated pixels that left float's range (Inf from finite
/// spectra near 3.4e38), naming the file and the pixel ((x, y) when
/// `width` > 0, else its index).
void CheckIntegratedPixels(const std::string& file, const float* rgb, size_t count, int width);

void IntegrateSpectralPixels(const SpectralConversion& conversion, const float* pixels,
                             size_t count, int channels, float* rgb, int threads);

/// A spectral image read into memory.
struct SpectralImage
{
    SpectralLayout layout;
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<std::string> channelNames;
    std::vector<float> pixels;  ///< every channel, interleaved
    /// The spectral channels alone, in wavelength order: height × width × n.
    std::vector<float> spectra() const;
};

/// An image file read through the image module (`pixels`: its pixels too,
/// else its header); throws Exception naming the file.
ImageData ReadImageData(const std::string& path, bool pixels);

/// Reads a spectral EXR through OpenImageIO and checks its layout and
/// values (CheckSpectralPixels, NaN and infinity taken as `nonFinite`
/// says); throws Exception naming the file.
SpectralImage ReadSpectralImage(const std::string& path, const SpectralOptions& options = {},
                                NonFiniteSpectra nonFinite = NonFiniteSpectra::REFUSE);

/// The spectral EXR of an image's spectra (Fichet 2021: S0 or T channels,
/// R, G, B beside, spectralLayoutVersion and emissiveUnits), written with
/// `outputs` when given. `spectra` is height × width × wavelengths.size();
/// `rgb` (3 floats a pixel) is described by `description` (its colour space).
void WriteSpectralImage(const std::string& path, int width, int height, SpectralKind kind,
                        const std::vector<double>& wavelengths, const std::vector<float>& spectra,
                        const std::vector<float>& rgb, ImageDescription description,
                        OutputSet* outputs = nullptr);

}  // namespace bandlight::jobs
