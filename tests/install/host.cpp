// SPDX-License-Identifier: BSD-3-Clause
// A host linking bandlight: builds the A → D65 band3 look as an OCIO group
// and runs a pixel through it.
#include <cmath>
#include <iostream>

#include <bandlight/bandlight.h>

int main()
{
    using namespace bandlight;
    const Light a{"A", BuiltinIlluminant("A")}, d65{"D65", BuiltinIlluminant("D65")};
    // Lit plates: the physical change between the two lights.
    MethodSpec lit = ParseMethod("band3");
    lit.plates = Plates::Lit();
    float rgb[3] = {0.18f, 0.18f, 0.18f};
    OCIO::Config::CreateRaw()
        ->getProcessor(IlluminantChangeTransform(a, d65, lit, FindRgbSpace("acescg")))
        ->getDefaultCPUProcessor()
        ->applyRGB(rgb);
    std::cout << rgb[0] << " " << rgb[1] << " " << rgb[2] << "\n";
    // The default, white-balanced plates (as every face has it): through
    // Bradford, which is exact on white, grey stays grey.
    float grey[3] = {0.18f, 0.18f, 0.18f};
    OCIO::Config::CreateRaw()
        ->getProcessor(
            IlluminantChangeTransform(a, d65, ParseMethod("bradford"), FindRgbSpace("acescg")))
        ->getDefaultCPUProcessor()
        ->applyRGB(grey);
    const bool neutral = std::abs(grey[0] - grey[2]) < 1e-5f && std::abs(grey[1] - 0.18f) < 1e-4f;
    return rgb[2] > rgb[0] && neutral ? 0 : 1;  // daylight is bluer than tungsten
}
