// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "spectral/Spectrum.h"

namespace bandlight
{

/// The most samples a spectrum read from a file may need on its own grid,
/// extended over 380–780 nm (an irregular grid is resampled onto its
/// smallest step): 0.004 nm steps over the visible range, 1 nm over 100 µm.
constexpr size_t MAX_SPECTRUM_SAMPLES = 100000;

/// A spectrum read from a file, with the identifier the file gives it
/// (a CSV column header, a CGATS SAMPLE_ID / SAMPLE_NAME, or its 1-based
/// position when the file names none).
struct NamedSpectrum
{
    std::string name;
    Spectrum spectrum;
};

/// Builds a regular-grid spectrum from increasing (wavelength, value)
/// pairs; an irregular grid is resampled linearly onto its smallest step.
/// Throws Exception naming `source` (and `line`, when not 0) when the grid
/// would need more than MAX_SPECTRUM_SAMPLES samples or leaves the range
/// bandlight reads.
Spectrum SpectrumFromSamples(const std::vector<double>& wavelengths,
                             const std::vector<double>& values, const std::string& source,
                             size_t line = 0);

/// Reads spectra from CSV text: optional '#' comment lines, an optional
/// header row (first column the wavelength in nm, then one name per
/// spectrum), then rows "wavelength, v1, v2, ..." separated by commas,
/// semicolons, tabs or spaces. Wavelengths must increase; an irregular grid
/// is resampled linearly onto its smallest step. `source` names the input
/// in error messages ("FILE:LINE: ...").
std::vector<NamedSpectrum> ReadCsvSpectra(std::istream& in, const std::string& source);

/// Reads the spectral sets of a CGATS file as written by ArgyllCMS and
/// colord (.sp, .cmf, .ti3, .cie): the grid from SPECTRAL_START_NM /
/// SPECTRAL_END_NM / SPECTRAL_BANDS (or the SPEC_nnn field names), the
/// values divided by SPECTRAL_NORM when present and, for CTI3 files that
/// give no SPECTRAL_NORM, by 100 (ArgyllCMS stores .ti3 remittances in
/// percent). The first table with SPEC_ fields is read.
std::vector<NamedSpectrum> ReadCgatsSpectra(std::istream& in, const std::string& source);

/// Reads a file of spectra, choosing the reader from its content (a CGATS
/// file has BEGIN_DATA_FORMAT) so that either kind may carry any extension.
std::vector<NamedSpectrum> ReadSpectraFile(const std::string& path);

/// The same for text already in memory (used for the embedded tables).
std::vector<NamedSpectrum> ReadSpectraText(const std::string& text, const std::string& source);

/// What the spectral core assumes where a spectrum read from `source` ends
/// short of the visible range 380–780 nm, as one line for the user, or ""
/// when it covers that range: a remittance's end values are held constant
/// (CIE 15:2004 §7.2.1), an illuminant or emission is zero there.
std::string CoverageNote(const NamedSpectrum& spectrum, const std::string& source, bool remittance);

/// A note when a remittance leaves [0, 1] (measured data: noise below 0,
/// fluorescent whitening above 1), or "": such values are used as given.
std::string RemittanceRangeNote(const NamedSpectrum& spectrum, const std::string& source);

/// Remittances beyond this magnitude are not remittances (reflected over
/// incident light exceeds 1 only by fluorescence, never by orders of
/// magnitude).
constexpr double MAX_REMITTANCE = 1000.0;

/// Throws Exception "SOURCE: 'NAME' has a remittance of V; remittances
/// beyond ±1000 are refused" for a value beyond MAX_REMITTANCE.
void CheckRemittanceMagnitude(const NamedSpectrum& spectrum, const std::string& source);

}  // namespace bandlight
