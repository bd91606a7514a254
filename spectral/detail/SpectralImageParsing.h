// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What the parts of spectral/SpectralImage.h share: the "FILE: " prefix of
// their messages, and what FindSpectralLayout (spectral/SpectralLayout.cpp)
// hands the reader of each layout family (spectral/SpectralLayoutFamilies.cpp)
// and gets back from it. Not installed.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "spectral/Exception.h"
#include "spectral/SpectralImage.h"

namespace bandlight::detail
{

/// "FILE: " before a message about `file`; "" when no file is named.
std::string In(const std::string& file);

/// Band edges per channel name, as bandlight:bands lists them (nm).
using BandEdges = std::map<std::string, std::pair<double, double>>;

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

/// Channels named otherwise, at the wavelengths the user gives: point
/// samples of the kind the user says.
FamilyChannels ReadNamedChannels(const LayoutInput& in);

/// bandlight's own band render: each channel a band's mean radiance, placed
/// at the band's centre; every band listed must be a channel.
FamilyChannels ReadBandRender(const LayoutInput& in);

/// Fichet 2021 channel names: S0 (radiance) or T (remittance) channels in
/// one unit; the polarisation components S1–S3 are noted and left out.
FamilyChannels ReadFichet2021(const LayoutInput& in);

}  // namespace bandlight::detail
