// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// bandlight's public header, as a host includes it: <bandlight/bandlight.h>
// (find_package(bandlight), target bandlight::bandlight). It needs nothing
// of bandlight's own beyond <bandlight/Types.h>, and of its dependencies
// only OpenColorIO's public header, for the transforms it returns.
//
// Errors are thrown as std::runtime_error (bandlight's own exceptions
// derive from it), the message naming the file, line and value at fault:
// the one line the command prints.

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include <bandlight/Types.h>

namespace bandlight
{

/// bandlight's version, "MAJOR.MINOR.PATCH".
std::string Version();

/// Every method of the registry, in its order (`bandlight methods`).
std::vector<MethodInfo> ListMethods();

/// The change of light as an OCIO transform on working-space RGB: the
/// pixel guard and one MatrixTransform for a linear method; for a method
/// that is not, its op baked into a 3D LUT between a log2 shaper and its
/// inverse. The spectral reference has no such form (refused).
OCIO_NAMESPACE::ConstTransformRcPtr MakeTransform(const ChangeOfLight& change);

/// The change of light written as a LUT file by OpenColorIO's writers (with
/// its companion shaper for 3D-only formats): complete or absent.
WrittenLut WriteLut(const ChangeOfLight& change, const std::string& path,
                    const LutSettings& settings = {});

/// A config of looks (a new one, or a studio's extended) written into
/// `settings.out`: config.ocio and its LUT files, all or none.
WrittenConfig WriteConfig(const ConfigSettings& settings);

/// The change of light applied to an image, or to a frame sequence
/// (`input` and `output` patterns such as plate.####.exr, over `frames`
/// such as "1001-1100"), through OpenImageIO: alpha, other channels and
/// metadata kept; `output` may be `input`.
WrittenImages RelightImages(const std::string& input, const std::string& output,
                            const ChangeOfLight& change, const std::string& frames = "");

/// A look of a config (folder or .ocio file) applied to an image or a
/// frame sequence, in `colorspace` (empty: the config's scene_linear, the
/// image converted to it from what the file says).
WrittenImages ApplyLook(const std::string& input, const std::string& output,
                        const std::string& config, const std::string& look,
                        const std::string& colorspace = "", const std::string& frames = "");

}  // namespace bandlight
