// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "spectral/Spectrum.h"
#include "spectral/SpectrumIO.h"

namespace bandlight
{

/// The CIE standard colorimetric observers.
enum class Observer
{
    CIE1931_2DEG,   ///< CIE 1931 2° (CIE 15:2004 Table T.4)
    CIE1964_10DEG,  ///< CIE 1964 10° (CIE 15:2004 Table T.5)
};

/// One row of the observer table: the observer, its key in options and
/// files, its other spellings and its name in reports.
struct ObserverEntry
{
    Observer observer;
    const char* key;                   ///< "1931"
    std::vector<const char*> aliases;  ///< "2", "cie1931", "2deg"
    const char* name;                  ///< "CIE 1931 2°"
};

/// Every observer, in the order they are listed to users.
const std::vector<ObserverEntry>& Observers();

/// "1931" / "1964" (also "2", "10", "cie1931"..., any case); throws
/// Exception listing the keys otherwise.
Observer ParseObserver(const std::string& text);
/// "CIE 1931 2°", "CIE 1964 10°".
const char* ObserverName(Observer observer);

/// Colour-matching functions x̄, ȳ, z̄ of an observer, 360–830 nm at 5 nm,
/// as tabulated (ȳ peaks at 1.0 at 555 nm).
struct MatchingFunctions
{
    Spectrum x;
    Spectrum y;
    Spectrum z;
};

const MatchingFunctions& GetMatchingFunctions(Observer observer);

/// The same observer at 1 nm, 360–830 nm (CIE 15:2004 Tables T.4, T.5 at
/// 1 nm; their 5 nm rows are GetMatchingFunctions'), for the computations a
/// standard defines at 1 nm (CIE 224:2017): interpolating the 5 nm tables
/// linearly moves CIE 224's Rf,i of a 1 nm light by up to 0.2.
const MatchingFunctions& GetMatchingFunctions1nm(Observer observer);

/// The CIE daylight basis S0, S1, S2 (CIE 15:2004 Table T.2), 300–830 nm at 5 nm.
struct DaylightBasis
{
    Spectrum s0;
    Spectrum s1;
    Spectrum s2;
};

const DaylightBasis& GetDaylightBasis();

/// The CIE 13.3 test colour samples TCS01–TCS14 and TCS15, spectral
/// radiance factors 360–830 nm at 5 nm, in order.
const std::vector<NamedSpectrum>& TestColourSamples();

/// The 99 colour evaluation samples CES01–CES99 of CIE 224:2017 and
/// ANSI/IES TM-30-18, spectral reflectance factors 380–780 nm at 1 nm, in
/// order (source in data/ref/cie224_ces.csv).
const std::vector<NamedSpectrum>& ColourEvaluationSamples();

/// The 190 measured training reflectances published with the Academy's
/// rawtoaces (patch1 … patch190, 380–780 nm at 5 nm; source in
/// data/ref/rawtoaces_190.csv). Fitting data for rootpoly, never a test set.
const std::vector<NamedSpectrum>& Rawtoaces190();

/// The tabulated illuminants carried in data/: A, C, D50, D55, D65, E,
/// F1–F12, in that order, each on its own table's range at 5 nm.
const std::vector<NamedSpectrum>& TabulatedIlluminants();

}  // namespace bandlight
