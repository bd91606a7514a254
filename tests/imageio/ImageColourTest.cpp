// SPDX-License-Identifier: BSD-3-Clause
// What an image's header says its pixels are (imageio/ImageColour.h), and
// the OCIO conversions between that and a linear working space: headers
// built in memory, so no image file or OpenImageIO is involved.
#include <catch2/catch.hpp>

#include <string>

#include "imageio/ImageColour.h"
#include "spectral/Exception.h"

using namespace bandlight;

namespace
{
ImageData Header(const std::string& format, const std::string& type)
{
    ImageData h;
    h.width = h.height = 1;
    h.channels = 3;
    h.channelNames = {"R", "G", "B"};
    h.channelTypes = {type, type, type};
    h.format = format;
    return h;
}

float Through(const OCIO::ConstCPUProcessorRcPtr& cpu, float v)
{
    float rgb[3] = {v, v, v};
    cpu->applyRGB(rgb);
    return rgb[0];
}
}  // namespace

TEST_CASE("A user's colour space name is an encoding, or refused naming the parameter",
          "[imageio]")
{
    const ImageEncoding srgb = NamedEncoding("srgb");
    CHECK(srgb.srgbCurve);
    CHECK(srgb.space.name == FindRgbSpace("rec709").name);
    const ImageEncoding acescg = NamedEncoding("acescg");
    CHECK_FALSE(acescg.srgbCurve);
    CHECK(acescg.describe() == "linear ACEScg");
    CHECK_THROWS_AS(NamedEncoding("log-c"), ParameterError);
}

TEST_CASE("An 8-bit file is sRGB-encoded Rec.709; a float file that says nothing is assumed",
          "[imageio]")
{
    const RgbSpace& acescg = FindRgbSpace("acescg");
    const ImageEncoding png = IdentifyImageEncoding(Header("png", "uint8"), "a.png", acescg);
    CHECK(png.srgbCurve);
    CHECK(png.space.name == FindRgbSpace("rec709").name);
    CHECK_FALSE(png.assumed);
    CHECK(IsDisplayReferred(Header("png", "uint8")));

    const ImageEncoding exr = IdentifyImageEncoding(Header("openexr", "half"), "a.exr", acescg);
    CHECK(exr.assumed);
    CHECK_FALSE(exr.srgbCurve);
    CHECK(exr.space.name == acescg.name);
    CHECK_FALSE(IsDisplayReferred(Header("openexr", "float")));

    ImageData tagged = Header("openexr", "float");
    tagged.attributes["colorInteropID"] = "lin_rec709_scene";
    tagged.attributes["bandlight:colorSpace"] = "acescg";
    CHECK_THROWS_AS(IdentifyImageEncoding(tagged, "t.exr", acescg), Exception);
}

TEST_CASE("Formats are display-referred by their extension", "[imageio]")
{
    for (const char* f : {"a.png", "b.JPG", "c.jpeg", "d.gif", "e.bmp"})
    {
        CHECK(IsDisplayReferredFile(f));
    }
    for (const char* f : {"a.exr", "b.EXR", "c.hdr", "no-extension"})
    {
        CHECK_FALSE(IsDisplayReferredFile(f));
    }
}

TEST_CASE("sRGB code values go to linear through IEC 61966-2-1's curve and back", "[imageio]")
{
    const RgbSpace& rec709 = FindRgbSpace("rec709");
    const ImageEncoding srgb = NamedEncoding("srgb");
    const OCIO::ConstCPUProcessorRcPtr in = EncodingToLinear(srgb, rec709);
    const OCIO::ConstCPUProcessorRcPtr out = LinearToEncoding(rec709, srgb);
    REQUIRE(in);
    REQUIRE(out);
    // IEC 61966-2-1: 0.5 → ((0.5 + 0.055) / 1.055)^2.4 = 0.214041; the
    // linear toe below 0.04045 is v / 12.92.
    CHECK(Through(in, 0.5f) == Approx(0.214041).margin(2e-5));
    CHECK(Through(in, 0.02f) == Approx(0.02 / 12.92).margin(1e-6));
    for (const float v : {0.0f, 0.01f, 0.2f, 0.5f, 0.9f, 1.0f})
    {
        CHECK(Through(out, Through(in, v)) == Approx(v).margin(2e-5));
    }
    // A linear image already in the working space needs no conversion.
    CHECK_FALSE(EncodingToLinear(NamedEncoding("rec709"), rec709));
}
