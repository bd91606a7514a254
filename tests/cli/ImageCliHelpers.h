// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the command's image tests share: temporary paths, a test plate with
// HDR colour, alpha and depth, reading an image back, comparing two, and a
// config of looks written once.
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <catch2/catch.hpp>

#include "cli/RunCommand.h"

namespace bandlight::test::image
{

using bandlight::test::Bandlight;
using bandlight::test::Result;
using bandlight::test::Sh;

inline std::string Temp(const std::string& name)
{
    return bandlight::test::TempPath("image_" + name);
}

inline bool Exists(const std::string& path)
{
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

/// A float EXR with HDR colour, an alpha ramp and an extra depth channel.
inline void WriteTestImage(const std::string& path, int width = 64, int height = 48,
                           unsigned seed = 1)
{
    OIIO::ImageSpec spec(width, height, 5, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A", "Z"};
    spec.alpha_channel = 3;
    spec.z_channel = 4;
    spec.attribute("Copyright", "bandlight test plate");
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-13.0f, 16.0f);
    std::vector<float> px(size_t(width) * height * 5);
    for (size_t i = 0; i < size_t(width) * height; ++i)
    {
        for (int c = 0; c < 3; ++c)
        {
            px[5 * i + c] = std::exp2(u(rng));
        }
        px[5 * i + 3] = float(i % 97) / 96.0f;
        px[5 * i + 4] = float(i);
    }
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    REQUIRE(out->close());
}

inline OIIO::ImageBuf Read(const std::string& path)
{
    OIIO::ImageBuf buf(path);
    REQUIRE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT));
    return buf;
}

/// Worst |a - b| / max(1, |b|) over channels [c0, c1).
inline double WorstRelative(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, int c0, int c1)
{
    REQUIRE(a.spec().width == b.spec().width);
    REQUIRE(a.spec().height == b.spec().height);
    double worst = 0.0;
    for (OIIO::ImageBuf::ConstIterator<float> pa(a), pb(b); !pa.done(); ++pa, ++pb)
    {
        for (int c = c0; c < c1; ++c)
        {
            worst = std::max(
                worst, double(std::abs(pa[c] - pb[c])) / std::max(1.0, double(std::abs(pb[c]))));
        }
    }
    return worst;
}

inline std::string ConfigDir()
{
    static const std::string dir = []
    {
        const std::string d = Temp("config");
        const Result r =
            Bandlight("config --out '" + d + "' --methods none,bradford,band3,band3-wp,band5");
        REQUIRE(r.code == 0);
        return d;
    }();
    return dir;
}

}  // namespace bandlight::test::image
