// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "plugin/OcioTransforms.h"
#include "spectral/AtomicFile.h"

namespace bandlight
{

/// What goes into a config: the working space, the lights and the methods.
/// Every ordered pair of distinct lights gets one look per method, named
/// <method>_<FROM>_to_<TO>, and the same as a named transform relight_<look>.
struct ConfigOptions
{
    std::string workingSpace = "acescg";
    std::vector<Light> lights;
    std::vector<std::string> methods;
    Observer observer = Observer::CIE1931_2DEG;
};

/// A config with the LUT files its non-linear looks reference (paths
/// relative to the config's directory, "luts/<look>.clf").
struct ConfigPackage
{
    OCIO::ConfigRcPtr config;
    std::vector<std::pair<std::string, OCIO::GroupTransformRcPtr>> lutFiles;
};

/// The lecture's five illuminants: A, C, D65, F2, F11.
std::vector<Light> LectureLights();

/// A complete OCIO v2 config whose reference and scene_linear space is the
/// working space: linear spaces for every built-in primaries set, ACES2065-1
/// and CIE-XYZ-D65 interchange spaces, an sRGB-encoded space, a Non-Color
/// data space, the lecture's band space, an sRGB display with Standard and
/// Raw views, every role ociocheck and Blender ask for, and the looks and
/// named transforms. Built with the OCIO Config API and validated. Linear
/// methods are inline matrices; upsample looks are FileTransforms of CLF
/// files (shaper + 33³ LUT + inverse shaper) in the package's luts/ folder.
ConfigPackage BuildConfig(const ConfigOptions& options);

/// Adds the same looks, named transforms and band space to a copy of an
/// existing config, leaving everything it had intact. The looks' process
/// space is the base's scene_linear role; its primaries are identified by
/// measuring it against the base's cie_xyz_d65_interchange or
/// aces_interchange space unless `options.workingSpace` is given explicitly
/// (`detect` false). Throws Exception when the space cannot be identified
/// or a new name clashes with one the base already has.
ConfigPackage ExtendConfig(const OCIO::ConstConfigRcPtr& base, ConfigOptions options, bool detect,
                           std::string* identifiedSpace = nullptr);

/// Writes the package as DIR/config.ocio plus its LUT files (creating the
/// folders), as one set of outputs: all files are replaced together once
/// all are written, or none is. With `outputs`, the files join that set
/// and the caller commits it.
void WriteConfigPackage(const ConfigPackage& package, const std::string& dir,
                        OutputSet* outputs = nullptr);

/// The named transform that carries the same transform as a look:
/// "relight_<look>" (OCIO does not let the two share a name).
std::string NamedTransformName(const std::string& lookName);

/// The name of the colour space that holds a built-in RGB space in configs
/// bandlight builds ("ACEScg", "Linear Rec.709 (sRGB)", ...).
std::string ColorSpaceName(const RgbSpace& space);

}  // namespace bandlight
