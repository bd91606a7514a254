// SPDX-License-Identifier: BSD-3-Clause
// What every fuzz target asserts: a parser either returns data that is safe
// to compute with, or throws bandlight::Exception with a message that names
// the source. Anything else (another exception type, a crash, a sanitizer
// report, a non-finite value) aborts and libFuzzer saves the input.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/SpectrumIO.h"
#include "transforms/BandModel.h"

namespace bandlight::fuzz
{

[[noreturn]] inline void Abort(const std::string& what)
{
    std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
    std::abort();
}

inline void Check(bool ok, const std::string& what)
{
    if (!ok)
    {
        Abort(what);
    }
}

/// A parse error must start with the source name and be one line.
inline void CheckMessage(const Exception& e, const std::string& source)
{
    const std::string m = e.what();
    Check(m.rfind(source, 0) == 0, "error does not name its source: " + m);
    Check(m.find('\n') == std::string::npos, "error is not one line: " + m);
}

/// A spectrum the readers return is on a positive, finite grid with finite values.
inline void CheckSpectra(const std::vector<NamedSpectrum>& spectra)
{
    Check(!spectra.empty(), "reader returned no spectra without an error");
    for (const NamedSpectrum& s : spectra)
    {
        const Spectrum& sp = s.spectrum;
        Check(sp.size() >= 2, "spectrum with fewer than two samples");
        Check(std::isfinite(sp.start()) && sp.step() > 0.0 && std::isfinite(sp.step()),
              "spectrum grid not finite and increasing");
        for (size_t i = 0; i < sp.size(); ++i)
        {
            Check(std::isfinite(sp.values()[i]), "non-finite spectral value");
        }
    }
}

inline std::string Text(const uint8_t* data, size_t size)
{
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// One input through a spectrum reader, then through what `bandlight xyz`
/// computes from its result: XYZ as an emission, as a remittance under D65,
/// and band means (which may refuse a spectrum that misses a band, by name).
template <typename Reader>
int FuzzSpectrumReader(const uint8_t* data, size_t size, const std::string& source, Reader&& read)
{
    std::vector<NamedSpectrum> spectra;
    try
    {
        spectra = read(Text(data, size), source);
    }
    catch (const Exception& e)
    {
        CheckMessage(e, source);
        return 0;
    }
    CheckSpectra(spectra);
    static const Spectrum d65 = BuiltinIlluminant("D65");
    for (const NamedSpectrum& s : spectra)
    {
        // As a remittance (what `xyz --reflectance` accepts): finite XYZ and L*a*b*.
        bool remittance = true;
        try
        {
            CheckRemittanceMagnitude(s, source);
        }
        catch (const Exception& e)
        {
            CheckMessage(e, source);
            remittance = false;
        }
        if (remittance)
        {
            const Vec3 r = SurfaceXyz(s.spectrum, d65, Observer::CIE1931_2DEG);
            const Vec3 lab = XyzToLab(r, IlluminantWhiteXyz(d65, Observer::CIE1931_2DEG));
            Check(r.allFinite() && lab.allFinite(), "XYZ of an accepted remittance is not finite");
        }
        // As an illuminant (what `xyz --illuminant` and `cri` accept): a
        // finite white, and finite colours of the test samples under it.
        try
        {
            const Spectrum light = UsableIlluminant(s.spectrum, source);
            const Vec3 white = IlluminantWhiteXyz(light, Observer::CIE1931_2DEG);
            Check(white.allFinite() && white.y() > 0.0, "white of an accepted illuminant");
            const XyzIntegrator integrate(light, Observer::CIE1931_2DEG);
            for (const NamedSpectrum& tcs : TestColourSamples())
            {
                const Vec3 x = integrate(tcs.spectrum);
                Check(x.allFinite() && XyzToLab(x, white).allFinite(),
                      "colour under an accepted illuminant is not finite");
            }
        }
        catch (const Exception& e)
        {
            CheckMessage(e, source);
        }
        try
        {
            for (double b : RemittanceBands(s.spectrum, BandSet::Lecture()))
            {
                Check(std::isfinite(b), "band mean of a parsed spectrum is not finite");
            }
        }
        catch (const Exception& e)
        {
            CheckMessage(e, "band");
        }
    }
    return 0;
}

}  // namespace bandlight::fuzz
