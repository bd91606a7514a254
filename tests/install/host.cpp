// SPDX-License-Identifier: BSD-3-Clause
// A host of the public API: builds the A → D65 band3 change as an OCIO
// transform and runs a pixel through it, lists the methods, and writes a
// LUT that OpenColorIO reads back.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <bandlight/bandlight.h>

namespace OCIO = OCIO_NAMESPACE;

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::cerr << "usage: host FOLDER\n";
        return 2;
    }
    const std::string folder = argv[1];
    // Lit plates: the physical change between the two lights.
    bandlight::ChangeOfLight lit;
    lit.from = "A";
    lit.to = "D65";
    lit.method = "band3";
    lit.plates = "lit";
    float rgb[3] = {0.18f, 0.18f, 0.18f};
    OCIO::Config::CreateRaw()
        ->getProcessor(bandlight::MakeTransform(lit))
        ->getDefaultCPUProcessor()
        ->applyRGB(rgb);
    std::cout << rgb[0] << " " << rgb[1] << " " << rgb[2] << "\n";
    // The default, white-balanced plates through the default method
    // (Bradford, exact on white): grey stays grey.
    bandlight::ChangeOfLight balanced;
    balanced.from = "A";
    balanced.to = "D65";
    float grey[3] = {0.18f, 0.18f, 0.18f};
    OCIO::Config::CreateRaw()
        ->getProcessor(bandlight::MakeTransform(balanced))
        ->getDefaultCPUProcessor()
        ->applyRGB(grey);
    const bool neutral = std::abs(grey[0] - grey[2]) < 1e-5f && std::abs(grey[1] - 0.18f) < 1e-4f;

    // The registry, and a 33³ cube OCIO reads back to the transform's pixel.
    const std::vector<bandlight::MethodInfo> methods = bandlight::ListMethods();
    bandlight::LutSettings settings;
    settings.size = 33;
    const bandlight::WrittenLut lut = bandlight::WriteLut(lit, folder + "/lit.cube", settings);
    std::cout << bandlight::Version() << ": " << methods.size() << " methods; " << lut.lut << " "
              << lut.size << "^3, shaper " << lut.shaper << "\n";
    // A bad light is one line naming it, as the command says it.
    bool refused = false;
    try
    {
        bandlight::ChangeOfLight bad = lit;
        bad.from = "no-such-light";
        bandlight::MakeTransform(bad);
    }
    catch (const std::runtime_error& e)
    {
        refused = std::string(e.what()).find("no-such-light") != std::string::npos;
    }
    const bool ok = rgb[2] > rgb[0] && neutral && methods.size() >= 10 && lut.size == 33 &&
                    !lut.shaper.empty() && refused;
    return ok ? 0 : 1;  // daylight is bluer than tungsten
}
