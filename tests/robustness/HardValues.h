// SPDX-License-Identifier: BSD-3-Clause
// The hard values every pixel path is fed, and small helpers shared by the
// robustness tests.
#pragma once

#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "spectral/Colorimetry.h"

namespace bandlight::test
{

using Vec3f = Eigen::Vector3f;

struct HardPixel
{
    const char* label;
    Vec3f rgb;
    bool finite = true;
    bool denormal = false;
};

/// NaN, ±Inf, negative, denormal, zero and HDR (half's 65504, float 1e6),
/// alone and mixed with ordinary channels.
inline const std::vector<HardPixel>& HardPixels()
{
    constexpr float inf = std::numeric_limits<float>::infinity();
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    constexpr float den = std::numeric_limits<float>::denorm_min() * 64.0f;
    static const std::vector<HardPixel> pixels = {
        {"NaN in red", Vec3f(nan, 0.18f, 0.18f), false},
        {"NaN everywhere", Vec3f(nan, nan, nan), false},
        {"+Inf in red", Vec3f(inf, 0.18f, 0.18f), false},
        {"-Inf in red", Vec3f(-inf, 0.18f, 0.18f), false},
        {"+Inf everywhere", Vec3f(inf, inf, inf), false},
        {"+Inf, -Inf, 0", Vec3f(inf, -inf, 0.0f), false},
        {"negative red", Vec3f(-0.05f, 0.18f, 0.18f)},
        {"all negative", Vec3f(-1.0f, -2.0f, -0.5f)},
        {"denormal", Vec3f(den, den, den), true, true},
        {"zero", Vec3f(0.0f, 0.0f, 0.0f)},
        {"mid grey", Vec3f(0.18f, 0.18f, 0.18f)},
        {"half max", Vec3f(65504.0f, 65504.0f, 65504.0f)},
        {"float 1e6", Vec3f(1e6f, 1e6f, 1e6f)},
        {"saturated 1e6", Vec3f(1e6f, 0.01f, 0.5f)},
        {"float 1e30", Vec3f(1e30f, 1e30f, 1e30f)},
    };
    return pixels;
}

/// A path in the temporary folder, prefixed so tests do not collide.
inline std::string TempFile(const std::string& name)
{
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir ? dir : "/tmp") + "/bandlight_robustness_" + name;
}

/// Writes interleaved float pixels as an uncompressed float EXR (OIIO).
void WriteFloatImage(const std::string& path, const std::vector<float>& pixels, int width,
                     int height, int channels);
/// Reads an image's first `channels` channels as float; REQUIREs its size.
std::vector<float> ReadFloatImage(const std::string& path, int width, int height, int channels);

}  // namespace bandlight::test
