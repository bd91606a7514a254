// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>
#include <CLI/CLI.hpp>

#include "spectral/CieData.h"
#include "spectral/SpectrumIO.h"
#include "transforms/IlluminantChange.h"

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

/// --plates/--adaptation/--camera/--camera-idt: what the pipeline's images
/// are and, optionally, the camera that shot them.
struct PlatesOptions
{
    std::string plates = "balanced";
    std::string adaptation = "cat02";
    std::string camera;  ///< a camera sensitivities file, or ""
    std::string idtLight = "D55";

    /// The parsed convention.
    Plates parsed() const;
    /// The camera file read (nullptr without --camera); read once per call.
    std::shared_ptr<const SpectralCamera> loadCamera() const;
    /// `method` with the plates, the camera and its IDT light set.
    MethodSpec apply(MethodSpec method, const std::shared_ptr<const SpectralCamera>& camera) const;
};

/// Adds the four options above. `allowBoth`: --plates also takes "both"
/// (accuracy measures the two conventions).
void AddPlatesOptions(CLI::App& app, PlatesOptions& o, bool allowBoth = false);

/// --from/--to/--method/--working-space: an illuminant change without a config.
struct RelightOptions
{
    std::string from;
    std::string to;
    std::string method = "bradford";
    std::string workingSpace = "acescg";
    PlatesOptions plates;

    /// The method with its plates and camera.
    MethodSpec methodSpec() const;
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
