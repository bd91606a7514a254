// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes the CGATS spectrum reader (ArgyllCMS .sp, .cmf, .ti3) and what `bandlight xyz` computes from its
// result: XYZ as an emission, as a remittance under D65, and band means.
#include <sstream>

#include "FuzzCheck.h"
#include "spectral/Colorimetry.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"

using namespace bandlight;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const std::string source = "fuzz.sp";
    std::vector<NamedSpectrum> spectra;
    try
    {
        spectra = ReadSpectraText(fuzz::Text(data, size), source);
    }
    catch (const Exception& e)
    {
        fuzz::CheckMessage(e, source);
        return 0;
    }
    fuzz::CheckSpectra(spectra);
    static const Spectrum d65 = BuiltinIlluminant("D65");
    for (const NamedSpectrum& s : spectra)
    {
        const Vec3 e = IntegrateXyz(s.spectrum, Observer::CIE1931_2DEG);
        const Vec3 r = SurfaceXyz(s.spectrum, d65, Observer::CIE1931_2DEG);
        fuzz::Check(e.allFinite() && r.allFinite(), "XYZ of a parsed spectrum is not finite");
        try
        {
            for (double b : RemittanceBands(s.spectrum, BandSet::Lecture()))
            {
                fuzz::Check(std::isfinite(b), "band mean of a parsed spectrum is not finite");
            }
        }
        catch (const Exception&)
        {
            // A spectrum that does not reach a band is refused by name.
        }
    }
    return 0;
}
