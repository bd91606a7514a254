// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "imageio/ImageColour.h"
#include "imageio/ImageFiles.h"
#include "imaging/LightGroups.h"
#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"
#include "transforms/PixelKernels.h"

namespace bandlight::jobs
{
namespace OCIO = OCIO_NAMESPACE;

/// The work on an image's pixels, in the space the job works in: (pixels,
/// width, height, channels per pixel, indices of R, G, B), in place.
using BufferWork = std::function<void(float*, long, long, int, const int*)>;

/// An OCIO processor, on `threads` threads (0: all cores).
BufferWork ProcessorWork(const OCIO::ConstCPUProcessorRcPtr& cpu, int threads);

/// Any per-pixel function on interleaved RGB triples (bandlight's native
/// rootpoly): R, G, B gathered, passed in blocks of rows, scattered back.
BufferWork RgbWork(const std::function<void(float* rgb, size_t count)>& rgbFunction, int threads);

/// A clamp-and-matrix kernel, natively (the SIMD kernel of this CPU on the
/// file's own pixel stride when R, G, B lead each pixel).
BufferWork KernelWork(const ClampMatrixKernel& kernel, int threads);

/// What an image's pixels are to the work.
struct ImageColourRequest
{
    /// The linear space the work runs in: the file's pixels are decoded
    /// and converted into it, and back after the work. nullptr: the pixels
    /// go to the work as they are (a config's colour space the user named).
    const RgbSpace* working = nullptr;
    /// The file's encoding as the user gives it ({colorspace}); nullopt:
    /// as the file says (IdentifyImageEncoding).
    std::optional<ImageEncoding> declared;
};

/// Applies `work` to an image file and writes the result: through
/// OpenImageIO, any format it reads; the output keeps the input's pixel
/// type, channel names, alpha and metadata, and appears only when it is
/// complete (written to a temporary file, then renamed). Only R, G, B
/// change; alpha and other channels pass through. sRGB-encoded images and
/// images of other primaries are converted to `colour.working` for the
/// work and back; what was assumed, and values clipped by a display-referred
/// format, are returned as notes. Throws Exception naming the file on any
/// read or write failure, and for a scene-linear image written to a
/// display-referred format.
std::vector<std::string> ApplyToImage(const BufferWork& work, const std::string& in,
                                      const std::string& out, const std::string& note,
                                      const ImageColourRequest& colour);

/// The light groups of an apply: each named group's work, and the groups
/// the file names otherwise (group → layer prefix, or "r,g,b").
struct LightGroupApply
{
    std::map<std::string, BufferWork> works;  ///< an empty work: named, carried unchanged
    std::map<std::string, std::string> mapped;
    /// One change for the whole image (`apply --from --to` on a file with
    /// light groups): every group the file holds and the residual relit by
    /// it, so the beauty stays their sum. `works` is then empty.
    BufferWork everyGroup;
    /// What the new beauty is made of (a denoised beauty: REBUILD or
    /// DIFFERENCE).
    LightGroupBeauty beauty = LightGroupBeauty::RESIDUAL;
};

/// The light groups of an image (FindLightGroups) checked against `apply`:
/// throws Exception naming the file when a group it relights is not there.
LightGroupLayout CheckedLightGroups(const LightGroupApply& apply, const std::string& file,
                                    const ImageData& header);

/// Applies each group's work to its layer of an image file and writes the
/// result with the beauty as Σ relit groups + residual (RelightLightGroups):
/// every other channel, alpha, the metadata and every other part kept (a
/// part of a multi-part file without light groups is carried). The pixels
/// go to the works in `colour.working`, converted from what the file says
/// and back; a display-referred image is refused. Returns the notes: the
/// groups found and their naming, what was assumed.
std::vector<std::string> ApplyLightGroupsToImage(const LightGroupApply& apply,
                                                 const std::string& in, const std::string& out,
                                                 const std::string& note,
                                                 const ImageColourRequest& colour);

/// Whether an image (one part) holds light groups as FindLightGroups finds
/// them; false for "" and for a file it cannot read (the run names it).
bool HoldsLightGroups(const std::string& file);

/// ApplyToImage and ApplyLightGroupsToImage on an image in memory (read
/// whole, one part; `source` names it in messages): the same pixels those
/// write, without the files. The light-group accuracy measures through these.
std::vector<std::string> ApplyToImageData(const BufferWork& work, ImageData& image,
                                          const std::string& source,
                                          const ImageColourRequest& colour);
std::vector<std::string> ApplyLightGroupsToImageData(const LightGroupApply& apply,
                                                     ImageData& image, const std::string& source,
                                                     const ImageColourRequest& colour);

/// Applies a processor in place to an interleaved float image with RGB in
/// channels rgb[0..2] and `channels` channels per pixel, split by rows over
/// `threads` threads.
void ApplyToBuffer(const OCIO::ConstCPUProcessorRcPtr& cpu, float* pixels, long width, long height,
                   int channels, const int rgb[3], int threads);

}  // namespace bandlight::jobs
