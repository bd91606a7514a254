// SPDX-License-Identifier: BSD-3-Clause
// The readers of the spectral layout families: each finds an image's
// spectral channels and their wavelengths its own way (channels named
// otherwise, at wavelengths the user gives; a bandlight band render's band
// list; Fichet 2021 channel names) and hands them to FindSpectralLayout
// (spectral/SpectralLayout.cpp), which checks what all families share.
#include <algorithm>
#include <cmath>
#include <optional>

#include "spectral/Exception.h"
#include "spectral/SpectralImage.h"
#include "spectral/detail/SpectralImageParsing.h"

namespace bandlight::detail
{

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

}  // namespace bandlight::detail
