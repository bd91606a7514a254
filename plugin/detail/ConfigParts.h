// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The pieces configs are put together with, shared by the config builders
// (BuildConfig in plugin/ConfigBuilder.cpp, ExtendConfig in
// plugin/ConfigExtension.cpp), the input colour spaces
// (plugin/ConfigInputSpaces.cpp) and the writer (plugin/ConfigWriter.cpp).
// Not installed.

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "plugin/ConfigBuilder.h"
#include "plugin/ConfigInputSpaces.h"

namespace bandlight::detail
{

/// The folder, beside config.ocio, of the CLF files a package carries.
inline constexpr const char* kLutFolder = "luts";

/// An empty scene-referred colour space with its name, family, description
/// and encoding set.
OCIO::ColorSpaceRcPtr SceneSpace(const std::string& name, const std::string& family,
                                 const std::string& description, const std::string& encoding);

/// An OCIO v1 config cannot hold bandlight's guard (a v2 RangeTransform)
/// inline, nor named transforms: its additions are CLF files the package
/// carries, referenced by FileTransforms (which OCIO reads whatever the
/// config's version), so the base keeps its v1 meaning exactly.
bool IsV1(const OCIO::Config& config);

/// `t` as a FileTransform of a CLF file the package carries (luts/<name>.clf).
OCIO::TransformRcPtr AsLutFile(ConfigPackage& package, const std::string& name,
                               const OCIO::GroupTransformRcPtr& t);

/// The band model's band space: a base that has it already (a bandlight
/// config) does not get it again.
inline constexpr const char* kBandSpaceName = "Bands VB-VG-VR (lecture)";

/// Throws Exception unless the options make a config: at least two lights of
/// distinct names and one method (with the camera it needs), or input
/// spaces alone.
void RequireLights(const ConfigOptions& o);

/// The band space (kBandSpaceName): the lecture's band values to the working
/// space, then to the reference (`workingToReference`, none when the working
/// space is the reference). In a v1 config the matrix is a CLF file.
void AddBandSpace(ConfigPackage& package, const RgbSpace& working, Observer observer,
                  OCIO::TransformRcPtr workingToReference);

/// The looks, one per method and ordered pair of distinct lights, processed
/// in `processSpace`, and (OCIO v2) each the same as a named transform. A
/// linear method is an inline matrix, the rest (and all in a v1 config) CLF
/// files. Throws Exception for a name made twice or one the config has.
void AddLooks(ConfigPackage& package, const ConfigOptions& o, const RgbSpace& working,
              const std::string& processSpace);

/// The input colour spaces (camera IDTs), each to the config's reference:
/// its matrix into its space, that space into the working space, then the
/// working space to the reference (`workingToReference`, none when the
/// working space is the reference). Each matrix is also a CLF file. Throws
/// Exception for a name the config already has.
void AddInputSpaces(ConfigPackage& package, const std::vector<InputSpace>& spaces,
                    const RgbSpace& working, const OCIO::ConstTransformRcPtr& workingToReference);

}  // namespace bandlight::detail
