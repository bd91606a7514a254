// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The files of a render: RGB or band values (EXR), one layer per light
// group, the spectral radiance beside, and the sRGB preview.

#include <string>
#include <vector>

#include "imageio/ImageFiles.h"
#include "render/Scene.h"
#include "render/SceneRenderer.h"
#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::jobs
{

/// A file the render wrote, and what it holds ("960x360, 3 channels, ACEScg").
struct RenderFile
{
    std::string path;
    std::string what;
};

/// A render by light groups: each group's image (and its spectral
/// radiance), and the beauty, their sum.
struct GroupRender
{
    std::vector<std::string> names;
    std::vector<RenderedImage> images;
    std::vector<RenderedImage> spectra;  ///< empty without spectra
};

/// The sRGB preview of a working-space image through OCIO: the working
/// space to Rec.709 as a config's colour spaces convert it (Bradford
/// between the whites), then the sRGB curve.
std::vector<float> SrgbPreview(const RenderedImage& img, const RgbSpace& working);

std::string Size(const RenderedImage& img);

/// How band values are described: not RGB.
ImageDescription BandDescription(const BandSet& bands);

/// Band values, tagged as what they are: not RGB.
RenderFile WriteBandValues(const RenderedImage& img, const std::string& out, const BandSet& bands,
                           OutputSet& outputs);

/// `parts` summed in double, each value rounded once: the beauty of a
/// light-group render is Σ groups to float precision.
RenderedImage SumImages(const std::vector<RenderedImage>& parts);

/// The render with one layer per light group: the beauty's channels, its
/// spectral radiance (when given), then for each group "<group>.<channel>"
/// for both; the groups listed in bandlight:lightGroups.
RenderFile WriteLightGroups(const RenderedImage& beauty, const RenderedImage* beautySpectra,
                            const GroupRender& groups, const std::string& out, ImageDescription d,
                            OutputSet& outputs);

/// Linear RGB, with the spectral radiance beside it when `spectra`.
RenderFile WriteRgb(const RenderedImage& img, const std::string& out, const RgbSpace& space,
                    const RenderedImage* spectra, OutputSet& outputs);


}  // namespace bandlight::jobs
