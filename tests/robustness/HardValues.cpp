// SPDX-License-Identifier: BSD-3-Clause
#include "robustness/HardValues.h"

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

namespace bandlight::test
{

void WriteFloatImage(const std::string& path, const std::vector<float>& pixels, int width,
                     int height, int channels)
{
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "none");
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    REQUIRE(out->close());
}

std::vector<float> ReadFloatImage(const std::string& path, int width, int height, int channels)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    REQUIRE(spec.width == width);
    REQUIRE(spec.height == height);
    REQUIRE(spec.nchannels >= channels);
    std::vector<float> pixels(size_t(width) * size_t(height) * size_t(channels));
    REQUIRE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()));
    return pixels;
}

}  // namespace bandlight::test
