// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What the spectrum readers share: the CSV reader and the notes
// (spectral/SpectrumIO.cpp) and the CGATS reader (spectral/SpectrumCgats.cpp)
// quote, parse and refuse values, and check grids, the same way. Not
// installed.

#include <cstddef>
#include <string>

namespace bandlight::detail
{

/// A wavelength or value as messages print it ("380", "0.5").
std::string Nm(double v);

/// Throws Exception "SOURCE:LINE: what" (what on one line).
[[noreturn]] void Fail(const std::string& source, size_t line, const std::string& what);

/// A value from a file, as messages quote it: one line, at most 80 bytes.
std::string Quoted(const std::string& token);

/// Parses a whole token as a finite double; NaN, Inf and trailing garbage
/// are errors (a spectrum with them would poison every integral).
double ParseNumber(const std::string& token, const std::string& source, size_t line,
                   const char* what);

/// Whether the whole of `s` reads as a number.
bool LooksNumeric(const std::string& s);

/// Refuses a grid that would need more than MAX_SPECTRUM_SAMPLES samples
/// once it spans the visible range too (spectra are extended over 380–780 nm
/// on their own step): a step of 1e-6 nm, or wavelengths of 1e16 nm.
void CheckGrid(double first, double last, double step, const std::string& source, size_t line);

}  // namespace bandlight::detail
