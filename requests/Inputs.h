// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// What every job reads from its request: lights and remittances by name or
// file, configs, plates and cameras. Each is resolved here, once, for the
// command, the Python module and C++ hosts alike.

#include <memory>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "farm/Reporter.h"
#include "spectral/CieData.h"
#include "spectral/SpectrumIO.h"
#include "transforms/Defaults.h"
#include "transforms/IlluminantChange.h"

namespace bandlight::jobs
{

/// An illuminant given as a built-in name (A, D65, F11, 3200K, D5600, ...)
/// or a spectrum file (its first spectrum, checked and scaled by
/// UsableIlluminant; a note when it does not cover the visible range).
/// Throws Exception listing the built-in names when it is neither.
Light ResolveIlluminant(const std::string& nameOrFile, Reporter& reporter = SilentReporter());

/// A spectrum file's first spectrum as a light, whatever its name (a path
/// is a file even when it reads like a built-in name).
Light IlluminantFromFile(const std::string& path, Reporter& reporter = SilentReporter());

/// `spectrum` checked as a light (UsableIlluminant), `source` naming it in
/// messages; notes when it does not cover the visible range.
Light CheckedIlluminant(const NamedSpectrum& spectrum, const std::string& source,
                        Reporter& reporter = SilentReporter());

/// Remittances given as a test colour (TCS01–TCS15, case-insensitive; TCS
/// for all) or a file of one or more spectra, each checked as
/// CheckRemittance checks it.
std::vector<NamedSpectrum> ResolveReflectances(const std::string& nameOrFile,
                                               Reporter& reporter = SilentReporter());

/// Every spectrum of a file, checked as remittances.
std::vector<NamedSpectrum> RemittancesFromFile(const std::string& path,
                                               Reporter& reporter = SilentReporter());

/// Throws Exception when a remittance is far outside 0..1 (a percentage
/// file, a light given as a surface); notes when it does not cover the
/// visible range or strays a little outside 0..1.
void CheckRemittance(const NamedSpectrum& s, const std::string& source,
                     Reporter& reporter = SilentReporter());

/// Reads an OCIO config file and (with `checkReferences`) checks that every
/// file it references can be found. OpenColorIO's errors become one line
/// "FILE:LINE: cannot read the config: ..." (LINE when OCIO names one).
OCIO_NAMESPACE::ConstConfigRcPtr ReadConfigFile(const std::string& file,
                                                bool checkReferences = true);

/// A config given as its folder (holding config.ocio) or its .ocio file.
OCIO_NAMESPACE::ConstConfigRcPtr LoadConfig(const std::string& folderOrFile);

/// What the pipeline's images are and, optionally, the camera that shot
/// them: the parameters plates, adaptation, camera and camera_idt.
struct PlatesRequest
{
    std::string plates = defaults::PLATES;          ///< "balanced" or "lit" (accuracy: "both")
    std::string adaptation = defaults::ADAPTATION;  ///< "cat02" or "bradford"
    std::string camera;                             ///< a camera sensitivities file, or "" for none
    std::string idtLight = defaults::IDT_LIGHT;     ///< the light of the camera's one fixed IDT

    /// The parsed convention (plates "both" is refused here).
    Plates parsed() const;
    /// The conventions: both for "both", else the one named.
    std::vector<Plates> all() const;
    /// Plates "both" (ACCURACY_PLATES): every convention of the table.
    bool both() const;
    /// The camera file read (nullptr without camera); read on each call.
    std::shared_ptr<const SpectralCamera> loadCamera() const;
    /// The IDT light resolved.
    Light idt(Reporter& reporter = SilentReporter()) const;
    /// `method` with the plates, the camera and, for rootpoly-camera, its
    /// IDT light set; throws ParameterError when rootpoly-camera has no camera.
    MethodSpec apply(MethodSpec method, const std::shared_ptr<const SpectralCamera>& camera,
                     Reporter& reporter = SilentReporter()) const;
};

/// `method` fitted on `training` remittances (fit3x3, rootpoly, rootpoly3);
/// throws ParameterError for a method that is not fitted.
MethodSpec WithTraining(MethodSpec method, const std::vector<NamedSpectrum>& training);

/// A method by name with its plates, camera and fit3x3's / rootpoly's
/// training remittances (empty: their defaults); throws ParameterError for
/// training given to a method that is not fitted.
MethodSpec MethodFor(const std::string& name, const std::vector<NamedSpectrum>& training,
                     const PlatesRequest& plates, Reporter& reporter = SilentReporter());

/// An illuminant change on pixels without a config: the parameters src,
/// dst, method, training, working_space, observer and the plates.
struct RelightRequest
{
    Light src;
    Light dst;
    std::string method = defaults::METHOD;
    /// fit3x3's and rootpoly's training remittances (empty: their defaults).
    std::vector<NamedSpectrum> training;
    std::string workingSpace = defaults::WORKING_SPACE;
    std::string observer = defaults::OBSERVER;
    PlatesRequest plates;

    /// MethodFor(method, training, plates).
    MethodSpec methodSpec(Reporter& reporter = SilentReporter()) const;
    const RgbSpace& working() const;
    /// The relighter of the request (the per-pixel form of every method).
    Relighter relighter(Reporter& reporter = SilentReporter()) const;
};

/// Splits "a,b,c" into its non-empty items, spaces around each removed.
std::vector<std::string> SplitList(const std::string& text);

/// Throws Exception when a value about to be reported is not finite: a job
/// never reports NaN, Inf or JSON null as a result. `what` says which.
void RequireFinite(double value, const std::string& what);

/// `size` checked against the LUT sizes OpenColorIO takes; `parameter`
/// names it in the message.
int CheckedLutSize(int size, const std::string& parameter);

/// Formats a double with `decimals` places for tables.
std::string Fixed(double v, int decimals);

}  // namespace bandlight::jobs
