// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "cli/ImageFiles.h"
#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::cli
{
namespace OCIO = OCIO_NAMESPACE;

/// Applies an OCIO processor to an image file and writes the result:
/// through OpenImageIO, any format it reads; the output keeps the input's
/// pixel type, channel names, alpha and metadata, and appears only when it
/// is complete (written to a temporary file, then renamed). Only the R, G,
/// B channels change; alpha and any other channel pass through. The pixels
/// are processed on `threads` threads (0: all cores). Throws Exception
/// naming the file on any read or write failure.
void ApplyToImage(const OCIO::ConstCPUProcessorRcPtr& cpu, const std::string& in,
                  const std::string& out, int threads, const std::string& note);

/// The same with any per-pixel function on interleaved RGB triples
/// (bandlight's native rootpoly): the R, G, B channels are gathered, passed
/// to `rgbFunction` in blocks of rows on `threads` threads, and scattered
/// back; alpha and other channels pass through.
void ApplyToImage(const std::function<void(float* rgb, size_t count)>& rgbFunction,
                  const std::string& in, const std::string& out, int threads,
                  const std::string& note);

/// Applies a processor in place to an interleaved float image with RGB in
/// channels rgb[0..2] and `channels` channels per pixel, split by rows over
/// `threads` threads.
void ApplyToBuffer(const OCIO::ConstCPUProcessorRcPtr& cpu, float* pixels, long width, long height,
                   int channels, const int rgb[3], int threads);

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

/// Expands a frame pattern: "plate.####.exr" (or "%04d") with frame 1001
/// gives "plate.1001.exr"; a name without a pattern is returned unchanged.
std::string ExpandFramePattern(const std::string& pattern, int frame);
bool HasFramePattern(const std::string& pattern);

/// Frame numbers are at most this wide in a pattern ("%09d", "#########").
constexpr int kMaxFrameWidth = 9;
/// At most this many frames in one call: a farm splits longer ranges.
constexpr long kMaxFramesPerCall = 1000000;

/// Parses "1001-1100" or "1001" into the frames it names (at most
/// kMaxFramesPerCall, numbers of at most 9 digits); throws Exception.
std::vector<int> ParseFrameRange(const std::string& text);

}  // namespace bandlight::cli
