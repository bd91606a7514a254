// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "spectral/CieData.h"
#include "spectral/SpectrumIO.h"

namespace bandlight::cli
{

/// An illuminant given on the command line as a built-in name or a file
/// (the file's first spectrum); the name is the canonical built-in name or
/// the file's name for the spectrum.
NamedSpectrum ResolveIlluminant(const std::string& nameOrFile);

/// Remittances given as a test-colour name (TCS01..TCS15, case-insensitive)
/// or a file of one or more spectra.
std::vector<NamedSpectrum> ResolveReflectances(const std::string& nameOrFile);

/// Adds --observer with its check and default (1931).
CLI::Option* AddObserverOption(CLI::App& app, std::string& value);

/// Formats a double with `decimals` places for tables.
std::string Fixed(double v, int decimals);

}  // namespace bandlight::cli
