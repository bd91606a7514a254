// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/SpectralSimilarity.h"

#include <array>
#include <cmath>
#include <cstdio>

#include "spectral/ColourFidelity.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

namespace bandlight
{

namespace
{

// Academy S-2018-001 §4.1–4.2: 1 nm samples over 375–675 nm, integrated in
// 30 bands of 10 nm centred on 380, 390, …, 670 nm.
constexpr double kFirstNm = 375.0;
constexpr size_t kSamples = 301;
constexpr size_t kBands = 30;
static_assert(kSamples == 10 * kBands + 1, "each band spans 11 samples, its ends shared");

/// §4.6: the weights that fade the spectrum's ends.
// clang-format off
constexpr std::array<double, kBands> kWeights = {
    12.0 / 45.0, 22.0 / 45.0, 32.0 / 45.0, 40.0 / 45.0, 44.0 / 45.0,
    1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    1.0, 1.0, 1.0, 1.0, 1.0,
    11.0 / 15.0, 3.0 / 15.0};
// clang-format on
static_assert(kWeights[kBands - 1] == 3.0 / 15.0 && kWeights[kBands - 2] == 11.0 / 15.0,
              "one weight per band");

constexpr double kMinCct = 1000.0;
constexpr double kMaxCct = 25000.0;

std::string Format(const char* format, double a)
{
    char text[96];
    std::snprintf(text, sizeof(text), format, a);
    return text;
}

/// Data that stop short of 375 or 675 nm by at most kHeldNm (the CIE's
/// tables start at 380 nm) are held at their end value there, as CIE
/// 15:2004 §7.2.1 recommends for missing data; a longer gap counts as zero
/// (and the result says so).
constexpr double kHeldNm = 10.0;
constexpr double kLastNm = 675.0;

bool Held(const Spectrum& s)
{
    return s.start() - kFirstNm <= kHeldNm + 1e-9 && kLastNm - s.end() <= kHeldNm + 1e-9;
}

Spectrum Covered(const Spectrum& s)
{
    if ((s.start() <= kFirstNm + 1e-9 && s.end() >= kLastNm - 1e-9) || !Held(s))
    {
        return s;
    }
    return s.extended(std::min(s.start(), kFirstNm), std::max(s.end(), kLastNm));
}

/// §4.1–4.3: the 30 band integrals of a spectrum's 1 nm linear
/// interpolant (trapezoids of 1 nm), normalised to sum 1.
std::array<double, kBands> Bands(const Spectrum& s, const char* what)
{
    const Spectrum fine = Covered(s).resampled(kFirstNm, 1.0, kSamples);
    std::array<double, kBands> band{};
    double total = 0.0;
    for (size_t b = 0; b < kBands; ++b)
    {
        double sum = 0.5 * (fine[10 * b] + fine[10 * b + 10]);
        for (size_t k = 1; k < 10; ++k)
        {
            sum += fine[10 * b + k];
        }
        band[b] = sum;
        total += sum;
    }
    if (!(total > 0.0) || !std::isfinite(total))
    {
        throw Exception(std::string("SSI: the ") + what +
                        " has no positive finite power in 375–675 nm");
    }
    for (double& v : band)
    {
        v /= total;
    }
    return band;
}

}  // namespace

Spectrum SsiReference(double cctK)
{
    if (!(cctK >= kMinCct && cctK <= kMaxCct))
    {
        throw Exception("SSI: CCT " + Format("%.0f", cctK) +
                        " K is outside 1000–25000 K, where S-2018-001 defines a reference");
    }
    // CIE 224's reference on a grid from 375 nm to the end of the visible,
    // so the two lights of a blend are matched in luminance over all of it,
    // then cut to the SSI's range.
    constexpr size_t kVisible = size_t(780.0 - kFirstNm) + 1;
    return ColourFidelityReference(cctK, kFirstNm, 1.0, kVisible)
        .resampled(kFirstNm, 1.0, kSamples);
}

std::string SsiReferenceName(double cctK)
{
    return ColourFidelityReferenceName(cctK);
}

SpectralSimilarity ComputeSpectralSimilarity(const Spectrum& test, const Spectrum& reference,
                                             const std::string& referenceName)
{
    const std::array<double, kBands> t = Bands(test, "test light");
    const std::array<double, kBands> r = Bands(reference, "reference");
    // §4.4–4.6: the difference relative to the reference (offset by the
    // mean band value 1/30, so empty reference bands do not divide by
    // zero), weighted.
    std::array<double, kBands> w{};
    for (size_t b = 0; b < kBands; ++b)
    {
        w[b] = kWeights[b] * (t[b] - r[b]) / (r[b] + 1.0 / double(kBands));
    }
    // §4.7: smoothed by {0.22, 0.56, 0.22} with a zero beyond either end.
    double sum2 = 0.0;
    for (size_t b = 0; b < kBands; ++b)
    {
        const double before = b > 0 ? w[b - 1] : 0.0;
        const double after = b + 1 < kBands ? w[b + 1] : 0.0;
        const double s = 0.22 * before + 0.56 * w[b] + 0.22 * after;
        sum2 += s * s;
    }
    SpectralSimilarity out;
    // §4.8.
    out.unrounded = 100.0 - 32.0 * std::sqrt(sum2);
    out.ssi = std::round(out.unrounded);
    out.referenceName = referenceName;
    if (!Held(test))
    {
        out.warnings.push_back(
            Format("the test data cover %.0f", test.start()) +
            Format("–%.0f nm; the rest of 375–675 nm counts as zero", test.end()));
    }
    return out;
}

SpectralSimilarity ComputeSpectralSimilarity(const Spectrum& test)
{
    const CctDuv cct = ColourFidelityCct(test);
    SpectralSimilarity out =
        ComputeSpectralSimilarity(test, SsiReference(cct.cctK), SsiReferenceName(cct.cctK));
    out.cctK = cct.cctK;
    return out;
}

double ComputeSsi(const Spectrum& test, const Spectrum& reference)
{
    return ComputeSpectralSimilarity(test, reference).ssi;
}

}  // namespace bandlight
