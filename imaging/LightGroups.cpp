// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/LightGroups.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "spectral/Exception.h"

namespace bandlight::jobs
{

namespace
{

/// The R, G, B channel indices of each layer that has all three, by layer
/// name ("" for plain R, G, B).
using RgbLayerMap = std::map<std::string, std::array<int, 3>>;

/// The layers of an image that hold R, G and B ("" for plain R, G, B), with
/// their channel indices.
RgbLayerMap RgbLayers(const std::vector<std::string>& names)
{
    RgbLayerMap layers;
    std::map<std::string, int> index;
    for (size_t i = 0; i < names.size(); ++i)
    {
        index[names[i]] = int(i);
    }
    for (const std::string& n : names)
    {
        std::string layer;
        if (n == "R")
        {
            layer = "";
        }
        else if (n.size() > 2 && n.compare(n.size() - 2, 2, ".R") == 0)
        {
            layer = n.substr(0, n.size() - 2);
        }
        else
        {
            continue;
        }
        const std::string prefix = layer.empty() ? "" : layer + ".";
        const auto g = index.find(prefix + "G");
        const auto b = index.find(prefix + "B");
        if (g != index.end() && b != index.end())
        {
            layers[layer] = {index[prefix + "R"], g->second, b->second};
        }
    }
    return layers;
}

/// A layer name split at its last dot: "ViewLayer.Combined_key" → view
/// "ViewLayer.", pass "Combined_key"; a name without a dot is all pass.
struct LayerName
{
    std::string view;
    std::string pass;
};

LayerName SplitViewLayer(const std::string& layer)
{
    const size_t dot = layer.rfind('.');
    if (dot == std::string::npos)
    {
        return {"", layer};
    }
    return {layer.substr(0, dot + 1), layer.substr(dot + 1)};
}

/// What follows `prefix` in `s`, or "" when `s` does not start with it.
std::string AfterPrefix(const std::string& s, const std::string& prefix)
{
    const bool starts = s.size() > prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
    return starts ? s.substr(prefix.size()) : "";
}

std::string Quoted(const std::string& s)
{
    return "'" + OneLine(s, 80) + "'";
}

/// The group a layer holds in one naming, or "" when it holds none in that
/// naming. `listed`: the groups bandlight's header lists.
using GroupRecogniser = std::string (*)(const std::string& layer,
                                        const std::set<std::string>& listed);

/// Blender/Cycles: "<ViewLayer>.Combined_<group>" or "Combined_<group>".
std::string BlenderGroup(const std::string& layer, const std::set<std::string>&)
{
    return AfterPrefix(SplitViewLayer(layer).pass, "Combined_");
}

/// Arnold: "RGBA_<group>", in no view layer.
std::string ArnoldGroup(const std::string& layer, const std::set<std::string>&)
{
    const LayerName n = SplitViewLayer(layer);
    return n.view.empty() ? AfterPrefix(n.pass, "RGBA_") : "";
}

/// bandlight's `render --light-groups`: "<group>", listed in the header.
std::string BandlightGroup(const std::string& layer, const std::set<std::string>& listed)
{
    return listed.count(layer) ? layer : "";
}

/// One way of naming light groups. A layer holds the group of the first
/// naming (in table order) that recognises it.
struct NamingConvention
{
    LightGroupNaming naming;
    const char* name;  ///< as reported: "Blender/Cycles"
    /// How a file without groups is told what was looked for; nullptr for
    /// a naming no layer shows.
    const char* lookedFor;
    GroupRecogniser group;  ///< nullptr: its groups are not found in layer names
    /// Its groups belong to a view layer (the layer name up to its last
    /// dot), and one file holds one view layer's.
    bool viewLayers;
    /// The layers its beauty is looked for in, in order, after the view
    /// layer ("" for plain R, G, B); nullptr past the last. None: the
    /// groups sit beside whatever beauty the file has (kAnyBeauty).
    std::array<const char*, 2> beauty;
};

// clang-format off
constexpr NamingConvention kNamings[] = {
    {LightGroupNaming::BLENDER,   "Blender/Cycles", "Blender/Cycles '<ViewLayer>.Combined_<group>'",
     BlenderGroup,   true,  {"Combined", nullptr}},
    // Arnold's beauty is R, G, B, A; an "RGBA" layer when written as one.
    {LightGroupNaming::ARNOLD,    "Arnold",         "Arnold 'RGBA_<group>'",
     ArnoldGroup,    false, {"", "RGBA"}},
    {LightGroupNaming::BANDLIGHT, "bandlight",      "bandlight's own layers",
     BandlightGroup, false, {nullptr, nullptr}},
    {LightGroupNaming::MAPPED,    "mapped",         nullptr,
     nullptr,        false, {nullptr, nullptr}},
};
// clang-format on

/// The beauty of groups whose naming has none of its own: bandlight's
/// plain R, G, B, then Blender's and Arnold's layers.
constexpr std::array<const char*, 3> kAnyBeauty = {"", "Combined", "RGBA"};

/// The items of a comma-separated list as written, spaces and empty items
/// included: "a, b" → "a", " b".
std::vector<std::string> SplitAtCommas(const std::string& list)
{
    std::vector<std::string> items;
    for (size_t at = 0; at <= list.size();)
    {
        const size_t comma = std::min(list.find(',', at), list.size());
        items.push_back(list.substr(at, comma - at));
        at = comma + 1;
    }
    return items;
}

/// The header's list of bandlight's groups as written ("" when it has none).
std::string ListedAttribute(const std::map<std::string, std::string>& attributes)
{
    const auto a = attributes.find(LIGHT_GROUPS_ATTRIBUTE);
    return a == attributes.end() ? "" : a->second;
}

/// The names a group list holds: its items without spaces, empty ones left out.
std::set<std::string> ListedGroups(const std::string& list)
{
    std::set<std::string> listed;
    for (std::string item : SplitAtCommas(list))
    {
        item.erase(std::remove(item.begin(), item.end(), ' '), item.end());
        if (!item.empty())
        {
            listed.insert(item);
        }
    }
    return listed;
}

/// The groups the layer names show, in the order of `layers`, and the view
/// layers of those named after one (all of them, mapped over or not).
struct NamedGroups
{
    std::vector<LightGroupLayer> groups;
    std::set<std::string> views;  ///< "ViewLayer.", or "" for none
};

NamedGroups RecogniseGroups(const RgbLayerMap& layers, const std::set<std::string>& listed)
{
    NamedGroups out;
    for (const auto& [layer, rgb] : layers)
    {
        for (const NamingConvention& c : kNamings)
        {
            LightGroupLayer g;
            g.name = c.group ? c.group(layer, listed) : "";
            if (g.name.empty())
            {
                continue;
            }
            g.layer = layer;
            g.naming = c.naming;
            std::copy(rgb.begin(), rgb.end(), g.rgb);
            if (c.viewLayers)
            {
                out.views.insert(SplitViewLayer(layer).view);
            }
            out.groups.push_back(g);
            break;
        }
    }
    return out;
}

/// A group the user maps to three channels "r,g,b".
LightGroupLayer MappedChannels(const std::string& file, const std::string& name,
                               const std::string& where,
                               const std::vector<std::string>& channelNames)
{
    const std::vector<std::string> three = SplitAtCommas(where);
    if (three.size() != 3)
    {
        throw Exception(file + ": light group " + Quoted(name) + " is mapped to " + Quoted(where) +
                        ": give a layer prefix or three channels r,g,b");
    }
    LightGroupLayer g;
    for (int c = 0; c < 3; ++c)
    {
        const auto at = std::find(channelNames.begin(), channelNames.end(), three[size_t(c)]);
        if (at == channelNames.end())
        {
            throw Exception(file + ": light group " + Quoted(name) + ": channel " +
                            Quoted(three[size_t(c)]) + " is not in the image");
        }
        g.rgb[c] = int(at - channelNames.begin());
    }
    return g;
}

/// A group the user maps to a layer prefix: LAYER.R, LAYER.G, LAYER.B.
LightGroupLayer MappedLayer(const std::string& file, const std::string& name,
                            const std::string& where, const RgbLayerMap& layers)
{
    const auto l = layers.find(where);
    if (l == layers.end())
    {
        throw Exception(file + ": light group " + Quoted(name) + ": the image has no layer " +
                        Quoted(where) + " (no channels " + where + ".R, " + where + ".G, " + where +
                        ".B)");
    }
    LightGroupLayer g;
    std::copy(l->second.begin(), l->second.end(), g.rgb);
    return g;
}

/// A group the user maps: `where` is three channels when it has a comma,
/// else a layer prefix.
LightGroupLayer MappedGroup(const std::string& file, const std::string& name,
                            const std::string& where, const std::vector<std::string>& channelNames,
                            const RgbLayerMap& layers)
{
    LightGroupLayer g = where.find(',') != std::string::npos
                            ? MappedChannels(file, name, where, channelNames)
                            : MappedLayer(file, name, where, layers);
    g.name = name;
    g.layer = where;
    g.naming = LightGroupNaming::MAPPED;
    return g;
}

/// Puts bandlight's groups in the order its header lists them (the
/// scene's), ahead of the others, which keep theirs. `list` is the header's
/// list as written: a name written with spaces in it ranks with the others
/// (bandlight writes none).
void SortAsListed(std::vector<LightGroupLayer>& groups, const std::string& list)
{
    const std::vector<std::string> order = SplitAtCommas(list);
    const auto rank = [&](const LightGroupLayer& g)
    {
        const auto i = std::find(order.begin(), order.end(), g.name);
        return g.naming == LightGroupNaming::BANDLIGHT ? size_t(i - order.begin()) : order.size();
    };
    std::stable_sort(groups.begin(), groups.end(),
                     [&](const LightGroupLayer& a, const LightGroupLayer& b)
                     { return rank(a) < rank(b); });
}

/// Throws when no group was found, naming what was looked for.
void RequireSomeGroup(const std::string& file, const std::vector<LightGroupLayer>& groups)
{
    if (!groups.empty())
    {
        return;
    }
    std::vector<std::string> namings;
    for (const NamingConvention& c : kNamings)
    {
        if (c.lookedFor)
        {
            namings.push_back(c.lookedFor);
        }
    }
    std::string list;
    for (size_t i = 0; i < namings.size(); ++i)
    {
        list += (i == 0 ? "" : i + 1 == namings.size() ? " and " : ", ") + namings[i];
    }
    throw Exception(file + ": holds no light groups (looked for " + list +
                    "; other namings are mapped to a group by their layer)");
}

/// Throws when the groups belong to more than one view layer.
void RequireOneViewLayer(const std::string& file, const std::set<std::string>& views)
{
    if (views.size() <= 1)
    {
        return;
    }
    std::string list;
    for (const std::string& v : views)
    {
        list += (list.empty() ? "" : ", ") +
                (v.empty() ? std::string("(none)") : v.substr(0, v.size() - 1));
    }
    throw Exception(file + ": holds light groups of several view layers (" + list +
                    "); relight one view layer's file at a time");
}

/// Throws when two groups have one name, or share a channel.
void RequireDistinctGroups(const std::string& file, const std::vector<LightGroupLayer>& groups,
                           const std::vector<std::string>& channelNames)
{
    for (size_t i = 0; i < groups.size(); ++i)
    {
        for (size_t j = 0; j < i; ++j)
        {
            const LightGroupLayer& a = groups[j];
            const LightGroupLayer& b = groups[i];
            if (a.name == b.name)
            {
                throw Exception(file + ": light group " + Quoted(a.name) + " is named twice (" +
                                Quoted(a.layer) + " and " + Quoted(b.layer) + ")");
            }
            for (int c = 0; c < 3; ++c)
            {
                if (std::find(b.rgb, b.rgb + 3, a.rgb[c]) != b.rgb + 3)
                {
                    throw Exception(file + ": light groups " + Quoted(a.name) + " and " +
                                    Quoted(b.name) + " resolve to the same channel " +
                                    Quoted(channelNames[size_t(a.rgb[c])]));
                }
            }
        }
    }
}

/// The layers the groups' beauty may be, in the order looked for: those of
/// each naming present that has a beauty of its own (in table order, after
/// the view layer), else kAnyBeauty.
std::vector<std::string> BeautyCandidates(const std::vector<LightGroupLayer>& groups,
                                          const std::set<std::string>& views)
{
    const std::string view = views.empty() ? "" : *views.begin();
    std::vector<std::string> candidates;
    for (const NamingConvention& c : kNamings)
    {
        const bool present = std::any_of(groups.begin(), groups.end(),
                                         [&](const auto& g) { return g.naming == c.naming; });
        for (const char* layer : c.beauty)
        {
            if (present && layer)
            {
                candidates.push_back((c.viewLayers ? view : "") + layer);
            }
        }
    }
    if (candidates.empty())
    {
        candidates.assign(kAnyBeauty.begin(), kAnyBeauty.end());
    }
    return candidates;
}

/// Sets the layout's beauty to the first of `candidates` the image has;
/// throws naming them all when it has none.
void FindBeauty(const std::string& file, const RgbLayerMap& layers,
                const std::vector<std::string>& candidates, LightGroupLayout& out)
{
    for (const std::string& c : candidates)
    {
        if (const auto l = layers.find(c); l != layers.end())
        {
            out.beautyLayer = c;
            std::copy(l->second.begin(), l->second.end(), out.beauty);
            return;
        }
    }
    std::string list;
    for (const std::string& c : candidates)
    {
        list += (list.empty() ? "" : ", ") + (c.empty() ? std::string("R, G, B") : c + ".R/G/B");
    }
    throw Exception(file + ": has light groups but no beauty they sum to (looked for " + list +
                    ")");
}

/// Throws when a group resolves to one of the beauty's channels.
void RequireGroupsApartFromBeauty(const std::string& file, const LightGroupLayout& layout,
                                  const std::vector<std::string>& channelNames)
{
    for (const LightGroupLayer& g : layout.groups)
    {
        for (int c = 0; c < 3; ++c)
        {
            if (std::find(layout.beauty, layout.beauty + 3, g.rgb[c]) != layout.beauty + 3)
            {
                throw Exception(file + ": light group " + Quoted(g.name) +
                                " resolves to the beauty's own channel " +
                                Quoted(channelNames[size_t(g.rgb[c])]));
            }
        }
    }
}

}  // namespace

const char* LightGroupNamingName(LightGroupNaming naming)
{
    for (const NamingConvention& c : kNamings)
    {
        if (c.naming == naming)
        {
            return c.name;
        }
    }
    return "";
}

const LightGroupLayer* LightGroupLayout::find(const std::string& name) const
{
    for (const LightGroupLayer& g : groups)
    {
        if (g.name == name)
        {
            return &g;
        }
    }
    return nullptr;
}

std::string LightGroupLayout::describe() const
{
    std::string names;
    std::set<std::string> namings;
    for (const LightGroupLayer& g : groups)
    {
        names += (names.empty() ? "" : ", ") + g.name;
        namings.insert(LightGroupNamingName(g.naming));
    }
    std::string naming;
    for (const std::string& n : namings)
    {
        naming += (naming.empty() ? "" : " and ") + n;
    }
    return std::to_string(groups.size()) + " light group" + (groups.size() == 1 ? "" : "s") + " (" +
           names + "), " + naming + " naming, beauty " +
           (beautyLayer.empty() ? std::string("R, G, B") : beautyLayer);
}

LightGroupLayout FindLightGroups(const std::string& file,
                                 const std::vector<std::string>& channelNames,
                                 const std::map<std::string, std::string>& attributes,
                                 const std::map<std::string, std::string>& mapped)
{
    const RgbLayerMap layers = RgbLayers(channelNames);
    const std::string listed = ListedAttribute(attributes);
    const NamedGroups named = RecogniseGroups(layers, ListedGroups(listed));
    LightGroupLayout out;
    // A group the user maps replaces the one of that name the layers show.
    for (const LightGroupLayer& g : named.groups)
    {
        if (!mapped.count(g.name))
        {
            out.groups.push_back(g);
        }
    }
    for (const auto& [name, where] : mapped)
    {
        out.groups.push_back(MappedGroup(file, name, where, channelNames, layers));
    }
    SortAsListed(out.groups, listed);
    RequireSomeGroup(file, out.groups);
    RequireOneViewLayer(file, named.views);
    RequireDistinctGroups(file, out.groups, channelNames);
    FindBeauty(file, layers, BeautyCandidates(out.groups, named.views), out);
    RequireGroupsApartFromBeauty(file, out, channelNames);
    return out;
}

}  // namespace bandlight::jobs
