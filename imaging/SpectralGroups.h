// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The light groups of a spectral render ("<group>.S0.<λ>nm"), each relit
// exactly from its own light to its new one, and the beauty rebuilt.

#include <map>
#include <string>
#include <vector>

#include "imaging/SpectralImages.h"

namespace bandlight::jobs
{

/// One spectral light-group image relit: RGB of the beauty (Σ relit groups
/// + the residual, integrated as it is) and of each group, `count` pixels
/// of 3 floats each, on `threads` threads. Throws Exception naming the file
/// and the group for a group that is not there or not spectral, groups that
/// sum to more than the beauty, and negative values. NaN and infinite
/// values (the image read with NonFiniteSpectra::GUARD) are guarded after
/// integration, as RGB light groups guard them, and counted in a note.
struct GroupConversion
{
    std::vector<std::string> groups;
    std::vector<std::vector<float>> rgb;  ///< per group
    std::vector<float> beauty;
    std::string applied;
    std::vector<std::string> notes;
};

GroupConversion ConvertLightGroups(const std::string& in, const SpectralImage& image,
                                   const std::map<std::string, std::string>& attributes,
                                   const SpectralOptions& options, int threads);

}  // namespace bandlight::jobs
