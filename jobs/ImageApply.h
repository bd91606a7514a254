// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "jobs/ImageFiles.h"
#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"
#include "transforms/PixelKernels.h"

namespace bandlight::jobs
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

/// The same with a clamp-and-matrix kernel, natively (the SIMD kernel of
/// this CPU on the file's own pixel stride when R, G, B lead each pixel).
void ApplyToImage(const ClampMatrixKernel& kernel, const std::string& in, const std::string& out,
                  int threads, const std::string& note);

/// The clamp and affine 3×3 an optimised OCIO processor consists of, when
/// it is nothing else: a RangeTransform that only clamps (both bounds
/// finite, in = out) followed by a MatrixTransform that leaves alpha alone.
/// Any other op, a matrix without a clamp (NaN would reach OCIO's 4×4 and
/// its alpha), and any look that optimises to more, gives nullopt: it goes
/// through OCIO.
std::optional<ClampMatrixKernel> NativeClampMatrix(const OCIO::ConstProcessorRcPtr& processor);

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

}  // namespace bandlight::jobs
