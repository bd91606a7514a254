// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What transforms/Idt.cpp and transforms/IdtAsShot.cpp share: the range of
// temperatures the lights are searched over, a camera's raw response to a
// light and the log chromaticity of a neutral.

#include "spectral/Colorimetry.h"
#include "spectral/Spectrum.h"
#include "transforms/Camera.h"

namespace bandlight::detail
{

/// rawtoaces and DNG take CIE daylight from this temperature up.
inline constexpr double kDaylightFromK = 4000.0;
inline constexpr double kLowestCctK = 1000.0;
inline constexpr double kHighestCctK = 25000.0;

/// The raw response of the camera (on SurfaceRenderer's grid, the units
/// CameraShot balances) to a light's white.
Vec3 Response(const SpectralCamera& camera, const Spectrum& light);

/// (log R/G, log B/G): what a neutral says about the light, any scale.
Eigen::Vector2d LogChromaticity(const Vec3& rgb);

}  // namespace bandlight::detail
