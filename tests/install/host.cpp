// SPDX-License-Identifier: BSD-3-Clause
// A host linking bandlight: builds the A → D65 band3 look as an OCIO group
// and runs a pixel through it.
#include <iostream>

#include <plugin/OcioTransforms.h>
#include <spectral/Illuminants.h>

int main()
{
    using namespace bandlight;
    const OCIO::GroupTransformRcPtr t =
        IlluminantChangeTransform({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")},
                                  ParseMethod("band3"), FindRgbSpace("acescg"));
    float rgb[3] = {0.18f, 0.18f, 0.18f};
    OCIO::Config::CreateRaw()->getProcessor(t)->getDefaultCPUProcessor()->applyRGB(rgb);
    std::cout << rgb[0] << " " << rgb[1] << " " << rgb[2] << "\n";
    return rgb[2] > rgb[0] ? 0 : 1;  // daylight is bluer than tungsten
}
