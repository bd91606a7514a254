// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Illuminants.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"

namespace bandlight
{

double PlanckRadiance(double lambdaNm, double kelvin) noexcept
{
    // c1L = 2hc² (CODATA 2018), W·m²·sr⁻¹.
    constexpr double c1L = 1.191042972e-16;
    const double l = lambdaNm * 1e-9;
    const double x = kPlanckC2 / (l * kelvin);
    // expm1 keeps precision in the Rayleigh–Jeans limit (small x); for large x
    // the result underflows to 0, which is the right limit.
    return c1L / (std::pow(l, 5.0) * std::expm1(x)) * 1e-9;
}

Spectrum Planckian(double kelvin, double startNm, double stepNm, size_t count)
{
    if (!(kelvin > 0.0) || kelvin > 1e6)
    {
        throw Exception("Planckian radiator: temperature must be in (0, 1e6] K, got " +
                        std::to_string(kelvin));
    }
    std::vector<double> v(count);
    const double ref = PlanckRadiance(560.0, kelvin);
    for (size_t i = 0; i < count; ++i)
    {
        v[i] = 100.0 * PlanckRadiance(startNm + stepNm * double(i), kelvin) / ref;
    }
    return Spectrum(startNm, stepNm, std::move(v));
}

Eigen::Vector2d DaylightChromaticity(double cct)
{
    if (!(cct >= 4000.0 && cct <= 25000.0))
    {
        throw Exception("CIE daylight is defined for 4000–25000 K, got " + std::to_string(cct) +
                        " K");
    }
    const double t = 1.0 / cct;
    // CIE 15:2004 eq. 3.3 (two ranges meeting at 7000 K) and eq. 3.4.
    const double x = cct <= 7000.0 ? ((-4.6070e9 * t + 2.9678e6) * t + 0.09911e3) * t + 0.244063
                                   : ((-2.0064e9 * t + 1.9018e6) * t + 0.24748e3) * t + 0.237040;
    const double y = -3.000 * x * x + 2.870 * x - 0.275;
    return {x, y};
}

Spectrum Daylight(double cct)
{
    const Eigen::Vector2d xy = DaylightChromaticity(cct);
    const double x = xy.x(), y = xy.y();
    const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
    // CIE 15:2004 eq. 3.5 and the note that follows it: M1 and M2 are rounded
    // to three decimals before use, as they were for the tabulated D-illuminants.
    const double m1 = std::round((-1.3515 - 1.7703 * x + 5.9114 * y) / m * 1000.0) / 1000.0;
    const double m2 = std::round((0.0300 - 31.4424 * x + 30.0717 * y) / m * 1000.0) / 1000.0;
    const DaylightBasis& b = GetDaylightBasis();
    Spectrum s = b.s0;
    s += b.s1 * m1;
    s += b.s2 * m2;
    return s;
}

double DaylightNominalCct(double hundreds) noexcept
{
    return hundreds * 100.0 * 1.4388 / 1.4380;
}

namespace
{

std::string Upper(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
    return s;
}

/// Parses a whole string as a positive number; false otherwise.
bool ParsePositive(const std::string& s, double& out)
{
    if (s.empty())
    {
        return false;
    }
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return *end == '\0' && std::isfinite(out) && out > 0.0;
}

const NamedSpectrum* FindTabulated(const std::string& upper)
{
    for (const NamedSpectrum& s : TabulatedIlluminants())
    {
        if (s.name == upper)
        {
            return &s;
        }
    }
    return nullptr;
}

}  // namespace

const std::vector<std::string>& StandardIlluminantNames()
{
    static const std::vector<std::string> names = {"A",  "C",  "D50", "D55", "D65", "D75", "E",
                                                   "F1", "F2", "F3",  "F4",  "F5",  "F6",  "F7",
                                                   "F8", "F9", "F10", "F11", "F12"};
    return names;
}

bool IsBuiltinIlluminant(const std::string& name)
{
    try
    {
        BuiltinIlluminant(name);
        return true;
    }
    catch (const Exception&)
    {
        return false;
    }
}

std::string CanonicalIlluminantName(const std::string& name)
{
    return Upper(name);
}

Spectrum BuiltinIlluminant(const std::string& name)
{
    const std::string u = Upper(name);
    if (const NamedSpectrum* s = FindTabulated(u))
    {
        return s->spectrum;
    }
    double v = 0.0;
    if (u.size() > 1 && u[0] == 'D' && ParsePositive(u.substr(1), v) && v >= 40.0 && v <= 250.0)
    {
        return Daylight(DaylightNominalCct(v));
    }
    if (u.size() > 1 && u.back() == 'K' && ParsePositive(u.substr(0, u.size() - 1), v))
    {
        return Planckian(v);
    }
    if (u.rfind("BB", 0) == 0 && ParsePositive(u.substr(2), v))
    {
        return Planckian(v);
    }
    // As lighting data sheets and spectrometers name them: CIE daylight
    // and a Planckian radiator at an exact CCT (no 1.4388/1.438 nominal
    // correction: daylight:6500 is 6500 K, D65 is 6504 K).
    if (u.rfind("DAYLIGHT:", 0) == 0 && ParsePositive(u.substr(9), v))
    {
        return Daylight(v);
    }
    if (u.rfind("PLANCK:", 0) == 0 && ParsePositive(u.substr(7), v))
    {
        return Planckian(v);
    }
    throw Exception("unknown illuminant '" + name +
                    "' (built-in: A, C, D50, D55, D65, D75, Dnn, E, F1-F12, "
                    "a blackbody as 3200K, BB3200 or planck:3200, CIE daylight as "
                    "daylight:5600, or a spectrum file)");
}

Spectrum UsableIlluminant(const Spectrum& illuminant, const std::string& source)
{
    // Colours are integrated on the CIE tables' grid; a spectrum that runs
    // to absurd wavelengths would need that grid extended to match.
    constexpr double kLongestNm = 100000.0;
    if (!(illuminant.end() <= kLongestNm))
    {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%g", illuminant.end());
        throw Exception(source + ": the illuminant's wavelengths run to " + buf +
                        " nm; a light for colour lies below 100000 nm");
    }
    // A handful of samples at least: two rows cannot say what a light is
    // between them, and five at 100 nm (380–780) are the coarsest grid whose
    // linear interpolant still gives a flat light its own white.
    constexpr size_t kFewestSamples = 5;
    if (illuminant.size() < kFewestSamples)
    {
        throw Exception(source + ": an illuminant of " + std::to_string(illuminant.size()) +
                        " sample" + (illuminant.size() == 1 ? "" : "s") +
                        " cannot be integrated honestly: give at least " +
                        std::to_string(kFewestSamples) +
                        " (every 100 nm over 380–780 nm at "
                        "most; the CIE tabulates lights every 5 nm)");
    }
    // And no wider apart than those five: samples thousands of nm apart say
    // nothing of the light where the eye sees, however many rows there are.
    constexpr double kWidestStepNm = 100.0;
    if (!(illuminant.step() <= kWidestStepNm * (1.0 + 1e-9)))
    {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%g", illuminant.step());
        throw Exception(source + ": an illuminant sampled every " + buf +
                        " nm cannot be integrated honestly: give samples 100 nm apart at most "
                        "(the CIE tabulates lights every 5 nm)");
    }
    double peak = 0.0;
    for (const double v : illuminant.values())
    {
        if (!std::isfinite(v))
        {
            throw Exception(source + ": an illuminant must be finite everywhere");
        }
        peak = std::max(peak, std::abs(v));
    }
    if (!(peak > 0.0))
    {
        throw Exception(source +
                        ": the illuminant has no power (all values are 0): it has no white");
    }
    int exponent = 0;
    std::frexp(peak, &exponent);
    Spectrum scaled = illuminant;
    for (double& v : scaled.values())
    {
        v = std::ldexp(v, -exponent);
    }
    // The yardstick: equal energy at the same peak over 380–780 nm.
    const Spectrum flat = Spectrum::Constant(380.0, 5.0, 81, 1.0);
    Vec3 xyz;
    try
    {
        xyz = IntegrateXyz(scaled, Observer::CIE1931_2DEG);
    }
    catch (const Exception& e)
    {
        throw Exception(source + ": " + e.what());  // name the file the spectrum came from
    }
    const double y = xyz.y();
    const double yFlat = IntegrateXyz(flat, Observer::CIE1931_2DEG).y();
    if (!(y >= 1e-6 * yFlat))
    {
        throw Exception(source +
                        ": the illuminant has no power where the eye sees (its luminance is " +
                        (y > 0.0 ? "below 1e-6 of an equal-energy light's" : "not positive") +
                        "): it has no white");
    }
    // L*a*b* and every chromatic adaptation divide by the white's X, Y and
    // Z: a light the eye's z̄ (or x̄) does not see at all (a red laser, power
    // only above 650 nm) has no white to relate colours to.
    if (!(xyz.x() > 1e-6 * y) || !(xyz.z() > 1e-6 * y))
    {
        throw Exception(source + ": the illuminant's white has no " +
                        std::string(xyz.x() > 1e-6 * y ? "Z" : "X") +
                        " (no power where that matching function sees): L*a*b* and chromatic "
                        "adaptation need a white with X, Y and Z all above zero");
    }
    return scaled;
}

}  // namespace bandlight
