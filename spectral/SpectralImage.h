// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Spectral images: what the channels of an image say about the spectrum
// of each pixel, and the weights that integrate them to XYZ. Knows nothing
// of files: the caller hands over the channel names and header attributes
// (jobs/SpectralJob reads them through OpenImageIO).
//
// Layouts read (docs/spectral.md):
// - Fichet, Pacanowski & Wilkie 2021, "An OpenEXR Layout for Spectral
//   Images", JCGT 10(3): emissive "S0.<λ><unit>" (Stokes S0–S3) and
//   reflective "T.<λ><unit>" channels, a comma as the decimal separator,
//   units m with an SI prefix, or Hz;
// - pbrt-v4's spectral film: "S0.<centre>nm" buckets over 360–830 nm, each
//   the mean over its bucket;
// - channels named otherwise, with wavelengths the user gives.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/CieData.h"
#include "spectral/Spectrum.h"

namespace bandlight
{

enum class SpectralKind
{
    EMISSIVE,    ///< radiance (S0): light leaving the scene
    REFLECTIVE,  ///< a remittance factor (T) in [0, 1] per wavelength
};

/// How a channel's value relates to the spectrum.
enum class SpectralSampling
{
    /// The spectrum's value at the channel's wavelength (Fichet 2021): each
    /// sample stands for the interval halfway to its neighbours, the first
    /// and last as far outward as inward, so a regular grid weights every
    /// sample by its step (the CIE sum, CIE 15:2004 §7.1).
    POINTS,
    /// The spectrum's mean over the channel's bucket (pbrt-v4's spectral
    /// film, bandlight's band renders): weights are the matching functions
    /// integrated over the bucket, exact for a spectrum constant within it.
    BUCKETS,
};

/// One row of the spectral-kind table: the kind and its name in options.
struct SpectralKindEntry
{
    SpectralKind kind;
    const char* key;  ///< "emissive"
};

/// Every spectral kind, in the order they are listed to users.
const std::vector<SpectralKindEntry>& SpectralKinds();

/// One row of the sampling table: the sampling, its name in options and
/// what it means to a user (help texts).
struct SpectralSamplingEntry
{
    SpectralSampling sampling;
    const char* key;   ///< "buckets"
    const char* help;  ///< "means over each channel's interval"
};

/// Every sampling, in the order they are listed to users.
const std::vector<SpectralSamplingEntry>& SpectralSamplings();

/// A spectral channel name, parsed.
struct SpectralChannel
{
    SpectralKind kind = SpectralKind::EMISSIVE;
    int stokes = 0;  ///< 0–3 for emissive channels
    double wavelengthNm = 0.0;
    std::string unit;  ///< as written: "nm", "um", "Hz", ...
};

/// At most this many spectral channels in one image (an EXR holds any
/// number; a spectrum finer than 0.05 nm over the visible range is not one
/// a renderer writes).
constexpr int kMaxSpectralChannels = 8192;

/// Parses a Fichet 2021 channel name: "S0.550,000000nm", "T.0,55um",
/// "S0.545,077THz" (a period as the separator is read too: pbrt-v4 writes
/// "S0.374.688nm"). Returns nullopt for a name that is not spectral (R, G,
/// B, A, Y, …). Throws Exception naming `file` and the channel for a name
/// that begins as a spectral channel ("S0." … "S3.", "T.") and does not
/// parse, and for a bi-spectral (fluorescent) "T.<λi>.<λo>" channel.
std::optional<SpectralChannel> ParseSpectralChannel(const std::string& name,
                                                    const std::string& file = "");

/// The Fichet 2021 name of a channel: "S0.550,000000nm" or "T.550,000000nm".
std::string SpectralChannelName(SpectralKind kind, double wavelengthNm);

/// The layouts bandlight reads (docs/spectral.md).
enum class SpectralLayoutFamily
{
    FICHET_2021,     ///< Fichet et al. 2021: S0.<λ><unit> and T.<λ><unit> channels
    PBRT_V4_FILM,    ///< pbrt-v4's spectral film: Fichet 2021 names, bucket means
    NAMED_CHANNELS,  ///< channels named otherwise, at wavelengths the user gives
    BAND_RENDER,     ///< bandlight's band renders: band means listed in bandlight:bands
};

/// "Fichet 2021", "pbrt-v4 spectral film", "named channels" or "bandlight
/// band render": the family as messages and describe() name it.
const char* SpectralLayoutFamilyName(SpectralLayoutFamily family);

/// The spectral channels of an image and how to integrate them.
struct SpectralLayout
{
    SpectralKind kind = SpectralKind::EMISSIVE;
    SpectralSampling sampling = SpectralSampling::POINTS;
    std::vector<double> wavelengths;  ///< nm, increasing
    std::vector<int> channels;        ///< the image channel of each wavelength
    /// BUCKETS: the bucket edges, wavelengths.size() + 1 of them, nm.
    std::vector<double> edges;
    SpectralLayoutFamily family = SpectralLayoutFamily::FICHET_2021;
    std::vector<std::string> notes;  ///< what was ignored or assumed, one line each

    /// "16 emissive buckets 360-830 nm (pbrt-v4 spectral film)".
    std::string describe() const;
};

/// What to read a layout with.
struct SpectralLayoutOptions
{
    /// Channels named otherwise (Mitsuba 3's specfilm, a camera's bands):
    /// channel name → wavelength in nm; these are point samples of `kind`.
    std::map<std::string, double> namedWavelengths;
    SpectralKind namedKind = SpectralKind::EMISSIVE;
    /// nullopt: as the layout says (buckets for pbrt-v4 and bandlight band
    /// renders, points otherwise).
    std::optional<SpectralSampling> sampling;
};

/// Finds the spectral layout of an image from its channel names and header
/// attributes (name → value as text). Throws Exception with one line naming
/// `file` and the channel for: names that do not parse, mixed units, duplicate
/// wavelengths, a single spectral channel or more than kMaxSpectralChannels,
/// S1–S3 without S0, emissive and reflective channels in one image,
/// bi-spectral channels, an unknown spectralLayoutVersion, and headers that
/// contradict the channels (emissiveUnits on a reflective image, a band list
/// that does not match the channels).
SpectralLayout FindSpectralLayout(const std::string& file,
                                  const std::vector<std::string>& channelNames,
                                  const std::map<std::string, std::string>& attributes,
                                  const SpectralLayoutOptions& options = {});

/// The lights of an integration.
struct SpectralLighting
{
    /// Emissive: the light the image was lit by (empty: integrate only).
    /// Reflective: unused.
    Spectrum from;
    /// Emissive with `from`: the light to relight to, scaled to `from`'s
    /// luminance. Reflective: the light the remittances are rendered under
    /// (required).
    Spectrum to;
};

/// Weights W (3 × wavelengths) such that XYZ = W · values for one pixel:
/// - emissive: XYZ = Σ L·cmf·Δλ / Σ ȳ·Δλ (pbrt-v4's convention: a spectrum
///   of constant value 1 has Y = 1); relit, each wavelength is multiplied
///   by S2/S1 with S2 scaled to S1's luminance, so that a white reflector
///   keeps its Y;
/// - reflective: XYZ = Σ T·S·cmf·Δλ / Σ S·ȳ·Δλ (a white reflector has
///   Y = 1).
/// Sums run over the layout's grid with its own weights. Where S1 is zero
/// at a sample the relit weight is zero (nothing of it survives), and a note
/// says how many. Throws Exception for a reflective layout without `to`, a
/// light with no luminance over the grid, or `to` without `from`.
Eigen::Matrix<double, 3, Eigen::Dynamic> SpectralXyzWeights(
    const SpectralLayout& layout, Observer observer, const SpectralLighting& lighting,
    std::vector<std::string>* notes = nullptr);

/// A light's value on each of the layout's samples: at the wavelength for
/// point samples, its mean over the bucket for buckets (what a white
/// reflector lit by it records there).
std::vector<double> LightOnLayout(const SpectralLayout& layout, const Spectrum& light);

/// Parses a CSV of channel wavelengths: rows "channel,wavelength_nm", or
/// sensitivities (a wavelength_nm column, then one column per channel named
/// in the header), each channel placed at its sensitivity's centroid
/// Σ λ·s / Σ s. Throws Exception naming the file and line.
std::map<std::string, double> ReadChannelWavelengths(const std::string& path);

}  // namespace bandlight
