// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes the channel names and header of a spectral EXR: one name per line,
// lines "@key=value" as header attributes. The layout either comes back on a
// finite, increasing grid whose weights integrate to finite XYZ, or is
// refused with one line that names the file.
#include <cmath>
#include <map>
#include <sstream>

#include "FuzzCheck.h"
#include "spectral/SpectralImage.h"

using namespace bandlight;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size > 4096)
    {
        return 0;
    }
    std::istringstream in(fuzz::Text(data, size));
    std::vector<std::string> names;
    std::map<std::string, std::string> attributes;
    std::string line;
    while (std::getline(in, line))
    {
        if (!line.empty() && line[0] == '@')
        {
            const size_t eq = line.find('=');
            attributes[line.substr(1, eq == std::string::npos ? std::string::npos : eq - 1)] =
                eq == std::string::npos ? "" : line.substr(eq + 1);
        }
        else
        {
            names.push_back(line);
        }
    }
    SpectralLayout layout;
    try
    {
        layout = FindSpectralLayout("fuzz.exr", names, attributes);
    }
    catch (const Exception& e)
    {
        fuzz::CheckMessage(e, "fuzz.exr");
        return 0;
    }
    const size_t n = layout.wavelengths.size();
    fuzz::Check(n >= 2 && layout.channels.size() == n && layout.edges.size() == n + 1,
                "layout sizes disagree");
    for (size_t i = 0; i < n; ++i)
    {
        fuzz::Check(std::isfinite(layout.wavelengths[i]) && layout.wavelengths[i] >= 100.0 &&
                        layout.wavelengths[i] <= 100000.0,
                    "wavelength out of range");
        fuzz::Check(i == 0 || layout.wavelengths[i] > layout.wavelengths[i - 1],
                    "wavelengths not increasing");
        fuzz::Check(layout.channels[i] >= 0 && size_t(layout.channels[i]) < names.size(),
                    "channel index out of range");
        fuzz::Check(layout.edges[i + 1] > layout.edges[i], "cell edges not increasing");
    }
    try
    {
        SpectralLighting lighting;
        if (layout.kind == SpectralKind::REFLECTIVE)
        {
            lighting.to = BuiltinIlluminant("D65");
        }
        const Eigen::Matrix<double, 3, Eigen::Dynamic> w =
            SpectralXyzWeights(layout, Observer::CIE1931_2DEG, lighting);
        fuzz::Check(w.allFinite(), "weights not finite");
    }
    catch (const Exception&)
    {
        // A grid outside the eye's range: refused, not computed.
    }
    return 0;
}
