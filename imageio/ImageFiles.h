// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The image-file half of bandlight, built as a module that the command loads
// only when it reads or writes an image: OpenImageIO's shared library and its
// dependencies cost about 0.4 s to start, which the spectral and OCIO
// commands should not pay.

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"

namespace bandlight
{

enum class PixelType
{
    FLOAT,
    HALF,
    UINT8,
};

/// What an image written by bandlight says about its pixels.
struct ImageDescription
{
    std::string colorSpace;             ///< oiio:ColorSpace (an OCIO space name, or "sRGB")
    std::vector<float> chromaticities;  ///< 8 values: R, G, B, white xy; empty: none
    std::vector<std::pair<std::string, std::string>> attributes;  ///< more string attributes
    /// When not empty, write the file under this name instead (a temporary
    /// of an OutputSet in the caller, which renames it); errors still name
    /// the destination.
    std::string writeAs;
};

/// An image as read: every channel as float, and its header.
struct ImageData
{
    int width = 0;
    int height = 0;
    int x = 0;  ///< the data window's origin (OpenEXR's dataWindow min)
    int y = 0;
    int channels = 0;
    std::vector<std::string> channelNames;
    std::vector<std::string> channelTypes;  ///< per channel: "half", "float", "uint8", …
    /// Every header attribute, its value as text (OIIO's formatting).
    std::map<std::string, std::string> attributes;
    std::string format;         ///< OpenImageIO's format name: "openexr", "png", …
    std::vector<float> pixels;  ///< interleaved, top row first; empty for a header read
    /// Of a multi-part file (stereo views, AOVs in parts): which part this
    /// is, of how many, and its name as messages give it ("part 1 ('right')";
    /// empty for a file of one part).
    int part = 0;
    int parts = 1;
    std::string partName;
};

/// Processes interleaved float pixels in place: (pixels, width, height,
/// channels, indices of R, G, B, the file's header without pixels). An
/// exception it throws becomes the call's error.
using PixelProcess =
    std::function<void(float*, long, long, int, const int*, const ImageData& header)>;

/// What a call into the module reports. The module has its own copy of the
/// library (its own exception types), so an error crosses as plain data and
/// ThrowIfFailed() throws it again on this side: a file that could not be
/// opened, read, created or written as FileError, anything else (a
/// malformed or unsupported image) as Exception.
struct ImageFilesStatus
{
    std::string message;     ///< empty on success; else the whole message, naming the file
    bool fileError = false;  ///< the file could not be used (path, error below)
    std::string path;        ///< the file, for a file error
    int error = 0;           ///< its errno (0 when the system gave none)
};

/// Throws what `status` reports (nothing on success).
void ThrowIfFailed(const ImageFilesStatus& status);

/// Whether a channel, by its name, is left out of an output.
using ChannelFilter = std::function<bool(const std::string& channel)>;

/// The module's entry points.
struct ImageFilesApi
{
    int version;
    /// Reads every part of `in`, processes the parts holding channels named
    /// R, G and B (every part with `everyPart`; a file of one part always),
    /// and writes all the parts to `out`, each with its own pixel types,
    /// channels and metadata: a part not processed is carried unchanged. A
    /// deep or MIP-mapped part, a multi-part file with no R, G, B part, and
    /// a multi-part file written to a format of one image are refused naming
    /// the part, nothing written.
    /// `drop`, when given, names the channels of a processed part left out
    /// of the output (a spectral render's S0.<λ> channels, which a change
    /// of its RGB would leave stale). With `joinParts`, the parts of a
    /// multi-part file (all one size) go to `process` as one image, their
    /// channels side by side (a name that repeats across parts prefixed by
    /// its part's name), and go back each to its part: light groups split
    /// across parts.
    ImageFilesStatus (*transform)(const std::string& in, const std::string& out,
                                  const PixelProcess& process, const std::string& note,
                                  bool everyPart, const ChannelFilter& drop, bool joinParts);
    ImageFilesStatus (*write)(const std::string& path, const float* pixels, int width, int height,
                              int channels, const std::vector<std::string>& channelNames,
                              const ImageDescription& description, PixelType type);
    /// Reads an image's first part, and counts its parts (with `pixels`
    /// false, only its header; the size is
    /// checked against memory before anything is allocated).
    ImageFilesStatus (*read)(const std::string& path, ImageData& image, bool pixels);
    /// Removes the module's temporary files in flight (async-signal-safe):
    /// the module carries its own copy of AtomicFile's registry.
    void (*removeTemporaryFiles)() noexcept;
};

constexpr int kImageFilesApiVersion = 9;

/// The loaded module's API; throws Exception when it cannot be found, naming
/// the places looked in (beside the executable, ../lib/bandlight, or
/// $BANDLIGHT_IMAGE_MODULE).
const ImageFilesApi& ImageFiles();

/// Writes interleaved float pixels through OIIO, atomically, stored as
/// `type`, with channel names, the colour space (and chromaticities, when
/// given) in `description`. With `outputs`, the image joins that set of
/// outputs (the caller commits it). Throws Exception naming the file.
void WriteImage(const std::string& path, const float* pixels, int width, int height, int channels,
                const std::vector<std::string>& channelNames, ImageDescription description,
                PixelType type, OutputSet* outputs = nullptr);

/// The description of linear pixels in `space`: the colour space's name
/// as the config calls it (`name`) and the space's chromaticities.
ImageDescription LinearImageDescription(const RgbSpace& space, const std::string& name);

}  // namespace bandlight

extern "C" const bandlight::ImageFilesApi* bandlight_image_files_api();
