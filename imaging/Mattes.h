// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A matte (`apply --matte`): its channel read as weights in 0..1 and
// checked against the image, the two sides it mixes (a change of light or a
// look each), and the mix.

#include <string>
#include <vector>

#include "imaging/RelightForms.h"

namespace bandlight::jobs
{

/// A matte's channel as weights in 0..1, one per pixel.
struct Matte
{
    std::string path;
    std::string channel;
    ImageData image;
    std::vector<float> weights;
};

/// One side of a matte as the pixels get it: a change of light or a look
/// of the config, in the space the image is converted to for the matte.
struct MatteSide
{
    RelightForm form;
    /// A change of light beside a look: the processors that take the looks'
    /// pixels to the change's working space, in order, and those back.
    std::vector<OCIO::ConstCPUProcessorRcPtr> into, back;

    BufferWork work(int threads) const
    {
        BufferWork w = form.work(threads);
        if (into.empty() && back.empty())
        {
            return w;
        }
        return [w, into = into, back = back, threads](float* px, long width, long height,
                                                      int channels, const int* rgb)
        {
            for (const OCIO::ConstCPUProcessorRcPtr& p : into)
            {
                ApplyToBuffer(p, px, width, height, channels, rgb, threads);
            }
            w(px, width, height, channels, rgb);
            for (const OCIO::ConstCPUProcessorRcPtr& p : back)
            {
                ApplyToBuffer(p, px, width, height, channels, rgb, threads);
            }
        };
    }
};

Matte ReadMatte(const std::string& given, Reporter& reporter);

/// Throws Exception when the matte does not cover `in`'s data window exactly.
void CheckMatteFits(const Matte& m, const std::string& in, const ImageData& header);

/// A change of light beside a look: it is defined on linear light of known
/// primaries, so it gets the looks' pixels through the config's
/// scene_linear, whose primaries the config shows, and gives them back.
void ConvertForLooks(const ApplyRequest& request, const OCIO::ConstConfigRcPtr& config,
                     const RgbSpace* working, const RelightRequest& relight, MatteSide& s);

/// out = m·inside(pixel) + (1 − m)·outside(pixel), R, G, B only.
BufferWork MixByMatte(const Matte& matte, const BufferWork& in, const BufferWork& out);

}  // namespace bandlight::jobs
