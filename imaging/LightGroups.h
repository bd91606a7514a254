// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Light groups: the layers of a render that each hold the light of one lamp
// or group of lamps, and the beauty they sum to (docs/lightgroups.md).
// Renderers name them their own way:
// - Blender/Cycles view-layer light groups: "<ViewLayer>.Combined_<group>.R"
//   (or "Combined_<group>.R" without the view layer), beauty "Combined";
// - Arnold light-group AOVs: "RGBA_<group>.R", beauty "RGBA";
// - bandlight's own `render --light-groups`: "<group>.R", beauty "R, G, B",
//   the groups listed in the header attribute bandlight:lightGroups;
// - any other naming, mapped by the user: group → layer prefix, or three
//   channels "r,g,b".
// What the groups do not hold (emission, lights in no group) is the
// residual, beauty − Σ groups, carried unchanged.

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace bandlight::jobs
{

/// The header attribute in which bandlight's renders list their groups.
inline constexpr const char* LIGHT_GROUPS_ATTRIBUTE = "bandlight:lightGroups";

/// How a file names its light groups.
enum class LightGroupNaming
{
    BLENDER,    ///< <ViewLayer>.Combined_<group>
    ARNOLD,     ///< RGBA_<group>
    BANDLIGHT,  ///< <group>, listed in bandlight:lightGroups
    MAPPED,     ///< named by the user
};

/// "Blender/Cycles", "Arnold", "bandlight", "mapped".
const char* LightGroupNamingName(LightGroupNaming naming);

/// One light group of an image: its R, G, B channels.
struct LightGroupLayer
{
    std::string name;   ///< the group: "key"
    std::string layer;  ///< as the file names it: "ViewLayer.Combined_key", "RGBA_key", "key"
    int rgb[3] = {-1, -1, -1};  ///< channel indices of R, G, B
    LightGroupNaming naming = LightGroupNaming::BANDLIGHT;
};

/// The light groups of an image and the beauty they sum to.
struct LightGroupLayout
{
    std::string beautyLayer;  ///< "ViewLayer.Combined", "Combined", "RGBA", "" (plain R, G, B)
    int beauty[3] = {-1, -1, -1};
    std::vector<LightGroupLayer> groups;  ///< in the order the file lists them
    /// Some group or beauty channel is stored as half: the partition check
    /// allows half's rounding.
    bool half = false;

    /// The group named `name` (case-sensitive, as the file spells it), or nullptr.
    const LightGroupLayer* find(const std::string& name) const;
    /// "2 light groups (key, fill), Blender/Cycles naming, beauty ViewLayer.Combined".
    std::string describe() const;
};

/// Finds the light groups and the beauty of an image from its channel names
/// and header attributes. `mapped`: group → its layer prefix ("LAYER": the
/// channels LAYER.R, LAYER.G, LAYER.B) or its three channels ("r,g,b");
/// mapped groups are added to (or replace) those the naming shows. Throws
/// Exception with one line naming `file` when no group is found, when a
/// mapped layer is not in the image, when two groups resolve to the same
/// channels, when groups of different view layers mix, and when no beauty
/// is found. Groups of different namings (a Blender pass beside an Arnold
/// AOV) may stand together: each is found by its own naming, and the
/// report names the namings.
LightGroupLayout FindLightGroups(const std::string& file,
                                 const std::vector<std::string>& channelNames,
                                 const std::map<std::string, std::string>& attributes,
                                 const std::map<std::string, std::string>& mapped = {});

/// A group's change of light on pixels: (pixels, width, height, channels per
/// pixel, indices of R, G, B), in place (a BufferWork).
using LightGroupWork = std::function<void(float*, long, long, int, const int*)>;

/// Relights the groups of an interleaved float image in place: checks that
/// the groups do not sum to more than the beauty beyond float noise (a file
/// whose groups are no partition of the beauty), then applies each group's
/// work to its channels (groups without one are carried unchanged) and
/// writes the beauty as Σ relit groups + residual (beauty − Σ groups as
/// read), summed in double. NaN and infinite values of the beauty or a group
/// go through the guard of every pixel path first (GuardPixel: NaN to
/// −1e16, ±Inf to ±1e16; docs/robustness.md), so every value written is
/// finite; returns how many pixels held such values. The works are called
/// on blocks of whole rows, top to bottom. Channels other than the groups'
/// and the beauty's R, G, B are not touched. Throws Exception naming `file`
/// and the first pixel at fault, before any pixel changes.
/// What the relit beauty is made of.
enum class LightGroupBeauty
{
    /// Σ relit groups + the residual (beauty − Σ groups as read), the
    /// groups checked to be a partition of the beauty: a render's own.
    RESIDUAL,
    /// Σ relit groups alone: the beauty rebuilt from them (a denoised
    /// beauty's groups, noisy, are the image; emission in no group is lost).
    REBUILD,
    /// Σ relit groups + (beauty − Σ groups as read), that difference carried
    /// whatever its sign: a denoised beauty keeps what the denoiser did.
    DIFFERENCE,
};

/// "residual", "rebuild", "difference".
const char* LightGroupBeautyName(LightGroupBeauty beauty);
/// What an output's bandlight:transform adds for the rule ("" for RESIDUAL).
std::string LightGroupBeautyNote(LightGroupBeauty beauty);
/// The rule of a name; throws ParameterError naming {light_group_beauty}.
LightGroupBeauty ParseLightGroupBeauty(const std::string& name);

/// With `residual`, the residual is relit by it too (one change for the
/// whole image), as a 3-channel float buffer. `beauty` says what the new
/// beauty is made of; only RESIDUAL checks the groups are a partition.
size_t RelightLightGroups(const LightGroupLayout& layout,
                          const std::map<std::string, LightGroupWork>& works, float* pixels,
                          long width, long height, int channels, const std::string& file,
                          const LightGroupWork& residual = nullptr,
                          LightGroupBeauty beauty = LightGroupBeauty::RESIDUAL);

/// The largest excess of Σ groups over the beauty a partition may show, for
/// a pixel value `level` (max of |beauty| and Σ |group|) in an image whose
/// brightest beauty value is `peak`: float rounding of the sums (and half
/// storage when `half`), nothing more.
double PartitionTolerance(double level, double peak, bool half);

}  // namespace bandlight::jobs
