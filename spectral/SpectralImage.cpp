// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/SpectralImage.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "spectral/Exception.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"

namespace bandlight
{

const std::vector<SpectralKindEntry>& SpectralKinds()
{
    static const std::vector<SpectralKindEntry> table = {
        {SpectralKind::EMISSIVE, "emissive"},
        {SpectralKind::REFLECTIVE, "reflective"},
    };
    return table;
}

const std::vector<SpectralSamplingEntry>& SpectralSamplings()
{
    static const std::vector<SpectralSamplingEntry> table = {
        {SpectralSampling::POINTS, "points", "values at the wavelengths"},
        {SpectralSampling::BUCKETS, "buckets", "means over each channel's interval"},
    };
    return table;
}
namespace
{

std::string In(const std::string& file)
{
    return file.empty() ? std::string() : file + ": ";
}

/// SI prefixes as Fichet 2021 allows them, with µ (U+00B5 and U+03BC) for
/// u, as powers of ten.
bool PrefixExponent(const std::string& p, int& exponent)
{
    static const std::pair<const char*, int> kPrefixes[] = {
        {"", 0},   {"Y", 24},        {"Z", 21},        {"E", 18}, {"P", 15},  {"T", 12},  {"G", 9},
        {"M", 6},  {"k", 3},         {"h", 2},         {"da", 1}, {"d", -1},  {"c", -2},  {"m", -3},
        {"u", -6}, {"\xC2\xB5", -6}, {"\xCE\xBC", -6}, {"n", -9}, {"p", -12}, {"f", -15},
    };
    for (const auto& [name, e] : kPrefixes)
    {
        if (p == name)
        {
            exponent = e;
            return true;
        }
    }
    return false;
}

/// "550,000000nm" → 550 nm; false when it does not parse.
bool ParseWavelength(const std::string& text, double& nm, std::string& unit)
{
    // The number: digits with one comma or period as the decimal separator
    // and an optional exponent.
    size_t i = 0;
    std::string number;
    bool digits = false, separator = false;
    for (; i < text.size(); ++i)
    {
        const char c = text[i];
        if (c >= '0' && c <= '9')
        {
            number += c;
            digits = true;
        }
        else if ((c == ',' || c == '.') && !separator)
        {
            number += '.';
            separator = true;
        }
        else
        {
            break;
        }
    }
    if (!digits)
    {
        return false;
    }
    if (i + 1 < text.size() && (text[i] == 'e' || text[i] == 'E') &&
        (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '+' ||
         text[i + 1] == '-'))
    {
        number += 'e';
        ++i;
        if (text[i] == '+' || text[i] == '-')
        {
            number += text[i++];
        }
        bool expDigits = false;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])))
        {
            number += text[i++];
            expDigits = true;
        }
        if (!expDigits)
        {
            return false;
        }
    }
    unit = text.substr(i);
    int exponent = 0;
    const double value = std::strtod(number.c_str(), nullptr);
    if (unit.size() >= 2 && unit.compare(unit.size() - 2, 2, "Hz") == 0)
    {
        if (!PrefixExponent(unit.substr(0, unit.size() - 2), exponent))
        {
            return false;
        }
        const double hz = value * std::pow(10.0, exponent);
        nm = hz > 0.0 ? 299792458.0 / hz * 1e9 : 0.0;
    }
    else if (!unit.empty() && unit.back() == 'm')
    {
        if (!PrefixExponent(unit.substr(0, unit.size() - 1), exponent))
        {
            return false;
        }
        // Scaled by a whole power of ten: nm, um and mm stay exact.
        const int toNm = exponent + 9;
        nm = toNm >= 0 ? value * std::pow(10.0, toNm) : value / std::pow(10.0, -toNm);
    }
    else
    {
        return false;
    }
    return std::isfinite(nm) && nm > 0.0;
}

}  // namespace

std::optional<SpectralChannel> ParseSpectralChannel(const std::string& name,
                                                    const std::string& file)
{
    SpectralChannel c;
    std::string rest;
    if (name.size() > 3 && name[0] == 'S' && name[1] >= '0' && name[1] <= '3' && name[2] == '.')
    {
        c.kind = SpectralKind::EMISSIVE;
        c.stokes = name[1] - '0';
        rest = name.substr(3);
    }
    else if (name.size() > 2 && name[0] == 'T' && name[1] == '.')
    {
        c.kind = SpectralKind::REFLECTIVE;
        rest = name.substr(2);
    }
    else
    {
        return std::nullopt;
    }
    const std::string quoted = "'" + OneLine(name, 80) + "'";
    // A bi-spectral channel T.<λi><unit>.<λo><unit>: the first wavelength's
    // unit is followed by a period.
    if (c.kind == SpectralKind::REFLECTIVE)
    {
        const size_t m = rest.find("m.");
        const size_t hz = rest.find("Hz.");
        if (m != std::string::npos || hz != std::string::npos)
        {
            throw Exception(In(file) + "channel " + quoted +
                            " is bi-spectral (fluorescent re-radiation from one wavelength to "
                            "another), which bandlight does not read; give an image of "
                            "non-fluorescent remittances (T.<wavelength> channels only)");
        }
    }
    if (!ParseWavelength(rest, c.wavelengthNm, c.unit))
    {
        throw Exception(In(file) + "channel " + quoted +
                        " is not a spectral channel name: expected S0.<wavelength><unit> or "
                        "T.<wavelength><unit> with a unit such as nm, um or THz "
                        "(\"S0.550,000000nm\")");
    }
    return c;
}

std::string SpectralChannelName(SpectralKind kind, double wavelengthNm)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", wavelengthNm);
    std::string number(buf);
    std::replace(number.begin(), number.end(), '.', ',');  // '.' separates EXR layers
    return (kind == SpectralKind::EMISSIVE ? "S0." : "T.") + number + "nm";
}

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

/// What a layout is read from: the image's channel names and header, and
/// what the user says about them.
struct LayoutInput
{
    const std::string& file;
    const std::vector<std::string>& channelNames;
    const std::map<std::string, std::string>& attributes;
    const SpectralLayoutOptions& options;
    BandEdges bandEdges;  ///< from bandlight:bands; empty without one

    const std::string* attribute(const std::string& key) const
    {
        const auto it = attributes.find(key);
        return it == attributes.end() ? nullptr : &it->second;
    }
    /// The channel's name on one line, for messages.
    std::string name(int channel) const { return OneLine(channelNames[size_t(channel)], 80); }
};

/// A spectral channel: its wavelength in nm and its image channel.
struct Found
{
    double nm;
    int channel;
};

/// What one family's reader finds, before the checks all families share.
struct FamilyChannels
{
    SpectralKind kind = SpectralKind::EMISSIVE;
    std::vector<Found> found;  ///< in image order
    std::vector<std::string> notes;
};

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

/// Channels named otherwise, at the wavelengths the user gives: point
/// samples of the kind the user says.
FamilyChannels ReadNamedChannels(const LayoutInput& in)
{
    FamilyChannels r;
    r.kind = in.options.namedKind;
    for (const auto& [name, nm] : in.options.namedWavelengths)
    {
        const auto it = std::find(in.channelNames.begin(), in.channelNames.end(), name);
        if (it == in.channelNames.end())
        {
            throw Exception(In(in.file) + "has no channel '" + OneLine(name, 80) +
                            "' (the channel wavelengths name it)");
        }
        if (!std::isfinite(nm) || nm <= 0.0)
        {
            throw Exception(In(in.file) + "channel '" + OneLine(name, 80) +
                            "' is given a wavelength that is " +
                            (std::isfinite(nm) ? "not positive" : "not a finite number"));
        }
        r.found.push_back({nm, int(it - in.channelNames.begin())});
    }
    return r;
}

/// bandlight's own band render: each channel a band's mean radiance, placed
/// at the band's centre; every band listed must be a channel.
FamilyChannels ReadBandRender(const LayoutInput& in)
{
    FamilyChannels r;
    r.kind = SpectralKind::EMISSIVE;
    for (size_t c = 0; c < in.channelNames.size(); ++c)
    {
        const auto it = in.bandEdges.find(in.channelNames[c]);
        if (it != in.bandEdges.end())
        {
            r.found.push_back({0.5 * (it->second.first + it->second.second), int(c)});
        }
    }
    if (r.found.size() != in.bandEdges.size())
    {
        throw Exception(In(in.file) + "bandlight:bands lists " +
                        std::to_string(in.bandEdges.size()) + " bands but the image has " +
                        std::to_string(r.found.size()) + " of them as channels");
    }
    return r;
}

/// Fichet 2021 channel names: S0 (radiance) or T (remittance) channels in
/// one unit; the polarisation components S1–S3 are noted and left out.
FamilyChannels ReadFichet2021(const LayoutInput& in)
{
    FamilyChannels r;
    std::string unit, firstName;
    bool emissive = false, reflective = false;
    std::vector<int> polarised;
    for (size_t c = 0; c < in.channelNames.size(); ++c)
    {
        const std::optional<SpectralChannel> s = ParseSpectralChannel(in.channelNames[c], in.file);
        if (!s)
        {
            continue;
        }
        if (unit.empty())
        {
            unit = s->unit;
            firstName = in.channelNames[c];
        }
        else if (s->unit != unit)
        {
            throw Exception(In(in.file) + "channel '" + in.name(int(c)) + "' is in " +
                            OneLine(s->unit, 16) + " but '" + OneLine(firstName, 80) + "' is in " +
                            unit + ": mixed units in one image");
        }
        if (s->kind == SpectralKind::REFLECTIVE || s->stokes == 0)
        {
            (s->kind == SpectralKind::REFLECTIVE ? reflective : emissive) = true;
            r.found.push_back({s->wavelengthNm, int(c)});
        }
        else
        {
            polarised.push_back(int(c));
        }
    }
    if (!polarised.empty() && !emissive)
    {
        throw Exception(In(in.file) + "channel '" + in.name(polarised[0]) +
                        "' is a Stokes component (S1-S3) but the image has no S0 channels");
    }
    if (emissive && reflective)
    {
        throw Exception(In(in.file) +
                        "has both emissive (S0) and reflective (T) channels; bandlight reads "
                        "one kind per image");
    }
    r.kind = reflective ? SpectralKind::REFLECTIVE : SpectralKind::EMISSIVE;
    if (!polarised.empty())
    {
        r.notes.push_back(std::to_string(polarised.size()) +
                          " polarisation channels (S1-S3) ignored: S0 is the radiance");
    }
    return r;
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

namespace
{

/// ∫ over [a, b] of the product of piecewise-linear f and g (g may be empty:
/// 1), on a 0.1 nm grid by the trapezoid rule: the matching functions are
/// tabulated at 5 nm, so this is exact to 1e-6 of the integral.
double IntegrateProduct(const Spectrum& f, const Spectrum* g, double a, double b)
{
    if (!(b > a))
    {
        return 0.0;
    }
    const int n = std::max(1, int(std::ceil((b - a) / 0.1)));
    const double h = (b - a) / n;
    double s = 0.0;
    for (int i = 0; i <= n; ++i)
    {
        const double l = a + h * i;
        const double v = f(l) * (g ? (*g)(l) : 1.0);
        s += (i == 0 || i == n) ? 0.5 * v : v;
    }
    return s * h;
}

}  // namespace

Eigen::Matrix<double, 3, Eigen::Dynamic> SpectralXyzWeights(const SpectralLayout& layout,
                                                            Observer observer,
                                                            const SpectralLighting& lighting,
                                                            std::vector<std::string>* notes)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    const Spectrum* f[3] = {&cmf.x, &cmf.y, &cmf.z};
    const size_t n = layout.wavelengths.size();
    const bool buckets = layout.sampling == SpectralSampling::BUCKETS;
    const bool reflective = layout.kind == SpectralKind::REFLECTIVE;
    if (reflective && lighting.to.empty())
    {
        throw ParameterError(
            "a reflective spectral image needs the light to render it under: "
            "{dst=}LIGHT");
    }
    if (!reflective && lighting.from.empty() && !lighting.to.empty())
    {
        throw ParameterError(
            "relighting an emissive spectral image needs the light it was lit "
            "by: {src=}LIGHT as well as {dst=}LIGHT");
    }
    // Emissive with S1 alone: integrated as it is (S1 is only the light the
    // caller balances from).
    const bool relight = !reflective && !lighting.from.empty() && !lighting.to.empty();
    // The light each wavelength is seen under: `to` for reflective images;
    // for relit emissive ones `to` over `from`, per cell.
    Eigen::Matrix<double, 3, Eigen::Dynamic> w(3, Eigen::Index(n));
    double norm = 0.0;  // Σ ȳ·Δλ (emissive) or Σ S·ȳ·Δλ (reflective)
    double fromY = 0.0, toY = 0.0;
    int lost = 0;
    for (size_t i = 0; i < n; ++i)
    {
        const double a = layout.edges[i], b = layout.edges[i + 1];
        const double l = layout.wavelengths[i];
        const double width = b - a;
        const Spectrum* light = reflective || relight ? &lighting.to : nullptr;
        for (int k = 0; k < 3; ++k)
        {
            w(k, Eigen::Index(i)) = buckets ? IntegrateProduct(*f[k], light, a, b)
                                            : (*f[k])(l) * (light ? (*light)(l) : 1.0) * width;
        }
        if (reflective)
        {
            norm += w(1, Eigen::Index(i));
            continue;
        }
        norm += buckets ? IntegrateProduct(cmf.y, nullptr, a, b) : cmf.y(l) * width;
        if (relight)
        {
            // The bucket's (or sample's) content over `from`: β ≈ L / S1.
            const double s1 = buckets ? lighting.from.integrateLinear(a, b) / width
                                      : lighting.from(l);  // as LightOnLayout
            const double y1 = buckets ? IntegrateProduct(cmf.y, &lighting.from, a, b)
                                      : cmf.y(l) * lighting.from(l) * width;
            fromY += y1;
            toY += w(1, Eigen::Index(i));
            if (!(s1 > 0.0))
            {
                if (w.col(Eigen::Index(i)).cwiseAbs().maxCoeff() > 0.0)
                {
                    ++lost;
                }
                w.col(Eigen::Index(i)).setZero();
            }
            else
            {
                w.col(Eigen::Index(i)) /= s1;
            }
        }
    }
    if (!(norm > 0.0) || (relight && !(fromY > 0.0 && toY > 0.0)))
    {
        throw Exception("the spectral image's grid (" + layout.describe() + ") sees no luminance" +
                        (relight || reflective ? " under the light" : ""));
    }
    if (relight)
    {
        w *= fromY / toY;  // S2 scaled to S1's luminance over the grid
    }
    if (lost > 0 && notes)
    {
        notes->push_back(std::to_string(lost) +
                         " wavelengths where the source light has no power contribute nothing "
                         "to the relit image");
    }
    return w / norm;
}

std::vector<double> LightOnLayout(const SpectralLayout& layout, const Spectrum& light)
{
    std::vector<double> s(layout.wavelengths.size());
    for (size_t i = 0; i < s.size(); ++i)
    {
        s[i] = layout.sampling == SpectralSampling::BUCKETS
                   ? light.integrateLinear(layout.edges[i], layout.edges[i + 1]) /
                         (layout.edges[i + 1] - layout.edges[i])
                   : light(layout.wavelengths[i]);
    }
    return s;
}

std::map<std::string, double> ReadChannelWavelengths(const std::string& path)
{
    std::string text = ReadTextFile(path, "channel wavelength file");
    CheckUtf8Text(text, path);
    // "channel,wavelength" rows: the first field of the first data row is
    // not a number.
    std::istringstream in(text);
    std::string line;
    size_t lineNo = 0;
    std::map<std::string, double> named;
    bool pairs = false, decided = false;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
        {
            line.pop_back();
        }
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        const size_t comma = line.find_first_of(",;\t");
        const std::string first = line.substr(0, comma);
        const std::string second = comma == std::string::npos ? "" : line.substr(comma + 1);
        char* end = nullptr;
        const double nm = std::strtod(second.c_str(), &end);
        const bool secondNumber = !second.empty() && end && *end == '\0';
        char* end1 = nullptr;
        std::strtod(first.c_str(), &end1);
        const bool firstNumber = !first.empty() && end1 && *end1 == '\0';
        if (!decided)
        {
            decided = true;
            if (firstNumber)
            {
                break;  // sensitivities without a header
            }
            if (!secondNumber)
            {
                // A header row: "wavelength_nm, channel, ..." heads
                // sensitivities, anything else "channel, wavelength".
                std::string lower;
                for (const char ch : first)
                {
                    lower += char(std::tolower(static_cast<unsigned char>(ch)));
                }
                if (lower.rfind("wavelength", 0) == 0 || lower == "nm" || lower == "lambda")
                {
                    break;
                }
                // "channel, wavelength" heads pairs only when its second
                // field reads as a heading; "band_00,abc" is a row whose
                // wavelength is wrong, not a header.
                std::string heading;
                for (const char ch : second)
                {
                    heading += char(std::tolower(static_cast<unsigned char>(ch)));
                }
                pairs = true;
                if (heading.find("wave") != std::string::npos ||
                    heading.find("nm") != std::string::npos ||
                    heading.find("lambda") != std::string::npos)
                {
                    continue;
                }
            }
            pairs = true;
        }
        if (secondNumber && !std::isfinite(nm))
        {
            throw Exception(SourcePosition(path, lineNo) + ": the wavelength of '" +
                            OneLine(first, 80) + "' is not a finite number: '" +
                            OneLine(second, 40) + "'");
        }
        if (!secondNumber || nm <= 0.0)
        {
            throw Exception(SourcePosition(path, lineNo) +
                            ": expected 'channel,wavelength_nm', got '" + OneLine(line, 80) + "'");
        }
        if (!named.emplace(first, nm).second)
        {
            throw Exception(SourcePosition(path, lineNo) + ": channel '" + OneLine(first, 80) +
                            "' is listed twice");
        }
    }
    if (pairs)
    {
        if (named.empty())
        {
            throw Exception(path + ": lists no channels");
        }
        return named;
    }
    for (const NamedSpectrum& s : ReadSpectraFile(path))
    {
        double sum = 0.0, moment = 0.0;
        for (size_t i = 0; i < s.spectrum.size(); ++i)
        {
            sum += s.spectrum[i];
            moment += s.spectrum[i] * s.spectrum.wavelength(i);
        }
        if (!(sum > 0.0))
        {
            throw Exception(path + ": the sensitivity of channel '" + OneLine(s.name, 80) +
                            "' has no positive sum");
        }
        if (!named.emplace(s.name, moment / sum).second)
        {
            throw Exception(path + ": channel '" + OneLine(s.name, 80) + "' is listed twice");
        }
    }
    return named;
}

}  // namespace bandlight
