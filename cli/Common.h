// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>
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

/// --from/--to/--method/--working-space: an illuminant change without a config.
struct RelightOptions
{
    std::string from;
    std::string to;
    std::string method = "bradford";
    std::string workingSpace = "acescg";
};

/// Adds the four options above to a command.
void AddRelightOptions(CLI::App& app, RelightOptions& o, bool required);

/// The illuminant-change transform the options name (one MatrixTransform for
/// the linear methods), and whether it is a plain matrix.
OCIO_NAMESPACE::GroupTransformRcPtr RelightTransform(const RelightOptions& o, bool* isMatrix);

/// Splits "a,b,c" into its non-empty items.
/// Reads an OCIO config file. OpenColorIO's errors become one line
/// "FILE:LINE: cannot read the config: ..." (LINE when OCIO names one).
OCIO_NAMESPACE::ConstConfigRcPtr ReadConfigFile(const std::string& file);

std::vector<std::string> SplitList(const std::string& text);

/// Throws Exception when a value about to be printed is not finite: a
/// command never reports NaN, Inf or JSON null with exit code 0. `what`
/// says which result it is.
void RequireFinite(double value, const std::string& what);

/// Formats a double with `decimals` places for tables.
std::string Fixed(double v, int decimals);

}  // namespace bandlight::cli
