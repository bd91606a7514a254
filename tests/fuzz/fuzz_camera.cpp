// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes a camera sensitivities file as `--camera` reads one (rawtoaces
// JSON, CSV, CGATS), then what accuracy and rootpoly-camera compute from it:
// white balance under two lights, the IDT fit, the records of the test
// colours. Every accepted camera gives finite numbers or an error naming
// its file.
#include "FuzzCheck.h"

#include "spectral/CameraFile.h"
#include "transforms/Camera.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace bandlight;
    const std::string source = "fuzz.camera";
    CameraSensitivities cam;
    try
    {
        cam = ReadCameraText(fuzz::Text(data, size), source);
    }
    catch (const Exception& e)
    {
        fuzz::CheckMessage(e, source);
        return 0;
    }
    fuzz::CheckSpectra({{"R", cam.red}, {"G", cam.green}, {"B", cam.blue}});
    static const Spectrum a = BuiltinIlluminant("A");
    static const Spectrum d55 = BuiltinIlluminant("D55");
    static const RgbSpace& ws = FindRgbSpace("acescg");
    try
    {
        const SpectralCamera camera(cam);
        for (const Spectrum* light : {&a, &d55})
        {
            const CameraShot shot(camera, *light);
            fuzz::Check(shot.gains().allFinite(), "white-balance gains not finite");
            for (const NamedSpectrum& t : TestColourSamples())
            {
                fuzz::Check(shot.record(SurfaceRenderer::Sample(t.spectrum)).allFinite(),
                            "camera record not finite");
            }
            const Mat3 idt = FitIdt(camera, *light, ws, AdaptationMethod::CAT02);
            fuzz::Check(idt.allFinite(), "IDT not finite");
        }
    }
    catch (const Exception& e)
    {
        fuzz::CheckMessage(e, source);
    }
    return 0;
}
