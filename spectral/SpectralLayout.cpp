// SPDX-License-Identifier: BSD-3-Clause
// Finding an image's spectral layout (FindSpectralLayout): the header
// checked, the family chosen (named channels, a bandlight band render or
// Fichet 2021 names, pbrt-v4's film among the last), its channels read
// (spectral/SpectralLayoutFamilies.cpp) and checked as one spectrum, the
// header's value attributes noted, and the cell or bucket edges the
// samples stand for; with SpectralLayout::describe().
#include "spectral/SpectralImage.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "spectral/Exception.h"
#include "spectral/detail/SpectralImageParsing.h"

namespace bandlight
{

std::string SpectralLayout::describe() const
{
    std::ostringstream o;
    o << wavelengths.size() << (kind == SpectralKind::EMISSIVE ? " emissive " : " reflective ")
      << (sampling == SpectralSampling::BUCKETS ? "buckets" : "samples");
    if (!wavelengths.empty())
    {
        const double lo =
            sampling == SpectralSampling::BUCKETS ? edges.front() : wavelengths.front();
        const double hi = sampling == SpectralSampling::BUCKETS ? edges.back() : wavelengths.back();
        o << " " << lo << "-" << hi << " nm";
    }
    o << " (" << SpectralLayoutFamilyName(family) << ")";
    return o.str();
}

namespace
{

using detail::BandEdges;
using detail::FamilyChannels;
using detail::Found;
using detail::In;
using detail::LayoutInput;
using detail::ReadBandRender;
using detail::ReadFichet2021;
using detail::ReadNamedChannels;

/// Cell edges of point samples: halfway between neighbours, the ends as far
/// outward as inward. A regular grid (names rounded to a few decimals, as
/// pbrt-v4's are) gets the edges of its fitted step.
std::vector<double> CellEdges(const std::vector<double>& w)
{
    std::vector<double> e(w.size() + 1);
    const double step = (w.back() - w.front()) / double(w.size() - 1);
    bool regular = true;
    for (size_t i = 0; i < w.size(); ++i)
    {
        regular = regular && std::abs(w[i] - (w.front() + step * double(i))) <= 1e-3 * step;
    }
    if (regular)
    {
        for (size_t i = 0; i <= w.size(); ++i)
        {
            e[i] = w.front() + step * (double(i) - 0.5);
        }
        return e;
    }
    for (size_t i = 1; i < w.size(); ++i)
    {
        e[i] = 0.5 * (w[i - 1] + w[i]);
    }
    e.front() = w.front() - (e[1] - w.front());
    e.back() = w.back() + (w.back() - e[w.size() - 1]);
    return e;
}

/// pbrt-v4's default spectral film: 16 buckets over 360–830 nm, named by
/// their centres to 3 decimals.
bool IsPbrtDefaultGrid(const std::vector<double>& w)
{
    if (w.size() != 16)
    {
        return false;
    }
    for (size_t i = 0; i < w.size(); ++i)
    {
        const double centre = 360.0 + (double(i) + 0.5) / 16.0 * 470.0;
        if (std::abs(w[i] - centre) > 6e-4)
        {
            return false;
        }
    }
    return true;
}

bool IsRegular(const std::vector<double>& w)
{
    const double step = (w.back() - w.front()) / double(w.size() - 1);
    for (size_t i = 0; i < w.size(); ++i)
    {
        if (std::abs(w[i] - (w.front() + step * double(i))) > 1e-3 * step)
        {
            return false;
        }
    }
    return true;
}

/// Band edges per channel name, as bandlight:bands lists them (nm).
using BandEdges = std::map<std::string, std::pair<double, double>>;

/// bandlight's band renders list their bands in bandlight:bands as
/// "B 400-500,G 500-600,R 600-700" (channel name, edges in nm); returns the
/// edges per channel name.
BandEdges BandRenderEdges(const std::string& text)
{
    BandEdges bands;
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
    {
        std::istringstream words(item);
        std::string name, range;
        words >> name >> range;
        double a = 0.0, b = 0.0;
        if (std::sscanf(range.c_str(), "%lf-%lf", &a, &b) == 2)
        {
            bands[name] = {a, b};
        }
    }
    return bands;
}

/// The header before any channel: the layout version and a channel count a
/// spectrum could have.
void CheckHeader(const LayoutInput& in)
{
    // "1.0" as the layout writes it (a float 1, as some tools write it, too).
    if (const std::string* v = in.attribute("spectralLayoutVersion");
        v && *v != "1.0" && std::strtod(v->c_str(), nullptr) != 1.0)
    {
        throw Exception(In(in.file) + "spectralLayoutVersion is '" + OneLine(*v, 40) +
                        "'; bandlight reads version 1.0 of the layout (Fichet et al. 2021)");
    }
    // Room for the non-spectral channels (RGBA, depth, …) beside the spectrum.
    if (in.channelNames.size() > size_t(kMaxSpectralChannels) + 16)
    {
        throw Exception(In(in.file) + "has " + std::to_string(in.channelNames.size()) +
                        " channels; bandlight reads at most " +
                        std::to_string(kMaxSpectralChannels) + " spectral channels");
    }
}

/// One entry per layout family: its name as describe() prints it, the
/// reader of its channels, and what a channel's value is unless the user
/// says otherwise.
struct LayoutFamilyEntry
{
    SpectralLayoutFamily family;
    const char* name;
    FamilyChannels (*read)(const LayoutInput&);
    SpectralSampling sampling;
};

// clang-format off
const LayoutFamilyEntry kLayoutFamilies[] = {
    {SpectralLayoutFamily::FICHET_2021,    "Fichet 2021",           ReadFichet2021,    SpectralSampling::POINTS},
    // pbrt-v4 names its buckets as Fichet 2021 does; found among Fichet 2021 images.
    {SpectralLayoutFamily::PBRT_V4_FILM,   "pbrt-v4 spectral film", ReadFichet2021,    SpectralSampling::BUCKETS},
    {SpectralLayoutFamily::NAMED_CHANNELS, "named channels",        ReadNamedChannels, SpectralSampling::POINTS},
    {SpectralLayoutFamily::BAND_RENDER,    "bandlight band render", ReadBandRender,    SpectralSampling::BUCKETS},
};
// clang-format on

const LayoutFamilyEntry& FamilyEntry(SpectralLayoutFamily family)
{
    for (const LayoutFamilyEntry& e : kLayoutFamilies)
    {
        if (e.family == family)
        {
            return e;
        }
    }
    assert(false && "a layout family without a table entry");
    return kLayoutFamilies[0];
}

/// Which family the channels are read as: wavelengths the user gives come
/// first, then a band list in the header, then the channels' own names.
SpectralLayoutFamily ChooseFamily(const LayoutInput& in)
{
    if (!in.options.namedWavelengths.empty())
    {
        return SpectralLayoutFamily::NAMED_CHANNELS;
    }
    if (!in.bandEdges.empty())
    {
        return SpectralLayoutFamily::BAND_RENDER;
    }
    return SpectralLayoutFamily::FICHET_2021;
}

/// The checks every family shares: between two and kMaxSpectralChannels
/// channels, no two at one wavelength, all within 100–100000 nm. Sorts
/// `found` by wavelength.
void SortAndCheck(const LayoutInput& in, std::vector<Found>& found)
{
    if (found.empty())
    {
        throw Exception(In(in.file) +
                        "has no spectral channels (S0.<wavelength>nm or T.<wavelength>nm, "
                        "or channels given wavelengths)");
    }
    if (found.size() == 1)
    {
        throw Exception(In(in.file) + "channel '" + in.name(found[0].channel) +
                        "' is its only spectral channel; a spectrum needs at least two");
    }
    if (found.size() > size_t(kMaxSpectralChannels))
    {
        throw Exception(In(in.file) + "has " + std::to_string(found.size()) +
                        " spectral channels; bandlight reads at most " +
                        std::to_string(kMaxSpectralChannels));
    }
    std::sort(found.begin(), found.end(),
              [](const Found& a, const Found& b) { return a.nm < b.nm; });
    for (size_t i = 1; i < found.size(); ++i)
    {
        if (!(found[i].nm - found[i - 1].nm > 1e-6 * found[i].nm))
        {
            throw Exception(In(in.file) + "channels '" + in.name(found[i - 1].channel) + "' and '" +
                            in.name(found[i].channel) + "' have the same wavelength");
        }
    }
    if (found.front().nm < 100.0 || found.back().nm > 100000.0)
    {
        const Found& f = found.front().nm < 100.0 ? found.front() : found.back();
        throw Exception(In(in.file) + "channel '" + in.name(f.channel) + "' lies at " +
                        std::to_string(f.nm) +
                        " nm; spectral channels must lie within 100-100000 nm");
    }
}

/// What the header says of the values: emissiveUnits on a reflective image
/// is refused; units other than radiance, and an exposure, are noted.
void ReadValueAttributes(const LayoutInput& in, SpectralLayout& layout)
{
    if (layout.kind == SpectralKind::REFLECTIVE && in.attribute("emissiveUnits"))
    {
        throw Exception(In(in.file) +
                        "says emissiveUnits but its spectral channels are reflective (T)");
    }
    if (layout.kind == SpectralKind::EMISSIVE && layout.family == SpectralLayoutFamily::FICHET_2021)
    {
        if (const std::string* u = in.attribute("emissiveUnits");
            u && *u != "W.m^-2.sr^-1" && *u != "W.m^-2.sr^-1.nm^-1")
        {
            layout.notes.push_back("emissiveUnits '" + OneLine(*u, 40) +
                                   "' read as relative radiance");
        }
    }
    if (const std::string* ev = in.attribute("EV"); ev && std::strtod(ev->c_str(), nullptr) != 0.0)
    {
        layout.notes.push_back("EV " + OneLine(*ev, 20) +
                               " (the exposure the image was made at) is noted, not applied: "
                               "values are integrated as stored");
    }
}

/// pbrt-v4's spectral film among Fichet 2021 images: radiance on its
/// default 16-bucket grid, or on a regular grid under the header attributes
/// pbrt writes (samplesPerPixel, worldToNDC).
bool IsPbrtFilm(const LayoutInput& in, const SpectralLayout& layout)
{
    return layout.family == SpectralLayoutFamily::FICHET_2021 &&
           layout.kind == SpectralKind::EMISSIVE &&
           (IsPbrtDefaultGrid(layout.wavelengths) ||
            (in.attribute("samplesPerPixel") && in.attribute("worldToNDC") &&
             IsRegular(layout.wavelengths)));
}

/// A band render's bucket edges, as its band list gives them: increasing
/// within each band, contiguous from one band to the next.
std::vector<double> BandRenderBucketEdges(const LayoutInput& in, const std::vector<int>& channels)
{
    std::vector<std::pair<double, double>> buckets;
    for (const int c : channels)
    {
        const auto& e = in.bandEdges.at(in.channelNames[size_t(c)]);
        if (!(e.first < e.second) || !std::isfinite(e.first) || !std::isfinite(e.second))
        {
            throw Exception(In(in.file) + "bandlight:bands lists band '" + in.name(c) + "' as " +
                            OneLine(std::to_string(e.first), 20) + "-" +
                            OneLine(std::to_string(e.second), 20) +
                            " nm: not an interval of increasing wavelengths");
        }
        buckets.push_back(e);
    }
    std::vector<double> edges{buckets.front().first};
    for (size_t i = 0; i < buckets.size(); ++i)
    {
        if (i > 0 && std::abs(buckets[i].first - buckets[i - 1].second) > 1e-9)
        {
            throw Exception(In(in.file) + "bandlight:bands lists bands that are not contiguous");
        }
        edges.push_back(buckets[i].second);
    }
    return edges;
}

/// The edges of the layout's cells: a band render's own, pbrt-v4's default
/// buckets, or halfway between neighbouring samples.
std::vector<double> LayoutEdges(const LayoutInput& in, const SpectralLayout& layout)
{
    if (layout.family == SpectralLayoutFamily::BAND_RENDER)
    {
        return BandRenderBucketEdges(in, layout.channels);
    }
    if (IsPbrtDefaultGrid(layout.wavelengths))
    {
        // pbrt-v4's buckets exactly: 360 + i · 470 / 16 nm.
        std::vector<double> edges;
        for (int i = 0; i <= 16; ++i)
        {
            edges.push_back(360.0 + 470.0 * i / 16.0);
        }
        return edges;
    }
    return CellEdges(layout.wavelengths);
}

}  // namespace

const char* SpectralLayoutFamilyName(SpectralLayoutFamily family)
{
    return FamilyEntry(family).name;
}

SpectralLayout FindSpectralLayout(const std::string& file,
                                  const std::vector<std::string>& channelNames,
                                  const std::map<std::string, std::string>& attributes,
                                  const SpectralLayoutOptions& options)
{
    LayoutInput in{file, channelNames, attributes, options, {}};
    CheckHeader(in);
    if (const std::string* bands = in.attribute("bandlight:bands"))
    {
        in.bandEdges = BandRenderEdges(*bands);
    }
    SpectralLayout layout;
    layout.family = ChooseFamily(in);
    FamilyChannels read = FamilyEntry(layout.family).read(in);
    SortAndCheck(in, read.found);
    layout.kind = read.kind;
    layout.notes = std::move(read.notes);
    for (const Found& f : read.found)
    {
        layout.wavelengths.push_back(f.nm);
        layout.channels.push_back(f.channel);
    }
    ReadValueAttributes(in, layout);
    if (IsPbrtFilm(in, layout))
    {
        layout.family = SpectralLayoutFamily::PBRT_V4_FILM;
    }
    layout.sampling = options.sampling ? *options.sampling : FamilyEntry(layout.family).sampling;
    layout.edges = LayoutEdges(in, layout);
    return layout;
}

}  // namespace bandlight
