// SPDX-License-Identifier: BSD-3-Clause
// What the tests of light groups across the jobs (apply, spectral, render)
// share: multi-part EXRs written and read back channel by channel through
// OpenImageIO, a change of light by name, and a scratch folder.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "requests/Inputs.h"
#include "cli/RunCommand.h"

namespace bandlight::test
{

/// A scratch folder for a light-group test, created empty.
inline std::string FreshLightGroupDir(const std::string& name)
{
    const std::string dir = TempPath("lightgroups_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// An EXR read back through OpenImageIO: every part, channels by name.
struct Exr
{
    struct Part
    {
        OIIO::ImageSpec spec;
        std::vector<float> pixels;
        float at(size_t p, const std::string& channel) const
        {
            const auto c = std::find(spec.channelnames.begin(), spec.channelnames.end(), channel);
            REQUIRE(c != spec.channelnames.end());
            return pixels[p * size_t(spec.nchannels) + size_t(c - spec.channelnames.begin())];
        }
        size_t count() const { return size_t(spec.width) * size_t(spec.height); }
    };
    std::vector<Part> parts;
    const Part& operator[](size_t i) const { return parts.at(i); }
};

inline Exr ReadExr(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    Exr exr;
    for (int p = 0; in->seek_subimage(p, 0); ++p)
    {
        Exr::Part part;
        part.spec = in->spec();
        part.pixels.resize(part.spec.image_pixels() * size_t(part.spec.nchannels));
        REQUIRE(in->read_image(p, 0, 0, part.spec.nchannels, OIIO::TypeDesc::FLOAT,
                               part.pixels.data()));
        exr.parts.push_back(std::move(part));
    }
    return exr;
}

/// Writes parts (each: channel names and a function of (pixel, channel)).
struct PartSpec
{
    std::vector<std::string> channels;
    std::function<float(size_t, size_t)> value;
    std::string name = "";
    std::map<std::string, std::string> attributes = {};
};

inline void WriteExr(const std::string& path, int width, int height,
                     const std::vector<PartSpec>& parts)
{
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    std::vector<OIIO::ImageSpec> specs;
    std::vector<std::vector<float>> pixels;
    for (const PartSpec& p : parts)
    {
        OIIO::ImageSpec spec(width, height, int(p.channels.size()), OIIO::TypeDesc::FLOAT);
        spec.channelnames = p.channels;
        spec.alpha_channel = -1;
        if (!p.name.empty())
        {
            spec.attribute("name", p.name);
        }
        for (const auto& [k, v] : p.attributes)
        {
            spec.attribute(k, v);
        }
        specs.push_back(spec);
        std::vector<float> px(size_t(width) * size_t(height) * p.channels.size());
        for (size_t i = 0; i < size_t(width) * size_t(height); ++i)
        {
            for (size_t c = 0; c < p.channels.size(); ++c)
            {
                px[i * p.channels.size() + c] = p.value(i, c);
            }
        }
        pixels.push_back(std::move(px));
    }
    if (specs.size() == 1)
    {
        REQUIRE(out->open(path, specs[0]));
    }
    else
    {
        REQUIRE(out->open(path, int(specs.size()), specs.data()));
    }
    for (size_t p = 0; p < specs.size(); ++p)
    {
        if (p > 0)
        {
            REQUIRE(out->open(path, specs[p], OIIO::ImageOutput::AppendSubimage));
        }
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixels[p].data()));
    }
    REQUIRE(out->close());
}

/// The change of light from `from` to `to` by `method`, on `plates`.
inline jobs::RelightRequest Change(const std::string& from, const std::string& to,
                                   const std::string& method, const std::string& plates = "lit")
{
    jobs::RelightRequest r;
    r.src = jobs::ResolveIlluminant(from);
    r.dst = jobs::ResolveIlluminant(to);
    r.method = method;
    r.plates.plates = plates;
    return r;
}

/// The largest |value| of an image.
inline double MaxAbs(const std::vector<float>& v)
{
    double m = 0.0;
    for (const float x : v)
    {
        m = std::max(m, double(std::abs(x)));
    }
    return m;
}

}  // namespace bandlight::test
