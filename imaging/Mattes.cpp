// SPDX-License-Identifier: BSD-3-Clause
#include "imaging/Mattes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "plugin/SceneLinearEvidence.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{


Matte ReadMatte(const std::string& given, Reporter& reporter)
{
    Matte m;
    m.path = given;
    // MATTE.exr:channel, unless the whole text names a file.
    const size_t colon = given.rfind(':');
    std::error_code ec;
    if (colon != std::string::npos && !std::filesystem::exists(given, ec) &&
        given.find('/', colon) == std::string::npos)
    {
        m.path = given.substr(0, colon);
        m.channel = given.substr(colon + 1);
    }
    CheckImageInput(m.path);
    ThrowIfFailed(ImageFiles().read(m.path, m.image, true));
    const std::vector<std::string>& names = m.image.channelNames;
    int index = -1;
    if (!m.channel.empty())
    {
        const auto at = std::find(names.begin(), names.end(), m.channel);
        if (at == names.end())
        {
            throw Exception(m.path + ": the matte has no channel '" + OneLine(m.channel, 80) + "'");
        }
        index = int(at - names.begin());
    }
    else
    {
        for (const char* name : {"A", "Y"})
        {
            const auto at = std::find(names.begin(), names.end(), name);
            if (at != names.end())
            {
                index = int(at - names.begin());
                break;
            }
        }
        if (index < 0 && names.size() == 1)
        {
            index = 0;
        }
        if (index < 0)
        {
            throw Exception(m.path + ": the matte has no channel A or Y and " +
                            std::to_string(names.size()) +
                            " channels: name the one to use, {matte=}MATTE.exr:CHANNEL");
        }
        m.channel = names[size_t(index)];
    }
    const size_t count = size_t(m.image.width) * size_t(m.image.height);
    m.weights.resize(count);
    size_t clamped = 0;
    for (size_t p = 0; p < count; ++p)
    {
        const float v = m.image.pixels[p * size_t(m.image.channels) + size_t(index)];
        if (!std::isfinite(v))
        {
            throw Exception(m.path + ": matte channel '" + m.channel + "' is " +
                            (std::isnan(v) ? "NaN" : "infinite") + " at pixel (" +
                            std::to_string(p % size_t(m.image.width)) + ", " +
                            std::to_string(p / size_t(m.image.width)) + ")");
        }
        m.weights[p] = std::clamp(v, 0.0f, 1.0f);
        clamped += m.weights[p] != v ? 1 : 0;
    }
    if (clamped > 0)
    {
        reporter.note(m.path + ": " + std::to_string(clamped) + " matte values outside 0-1 " +
                      "taken as 0 or 1");
    }
    m.image.pixels.clear();
    return m;
}

void CheckMatteFits(const Matte& m, const std::string& in, const ImageData& header)
{
    const auto window = [](const ImageData& d)
    {
        return std::to_string(d.width) + "x" + std::to_string(d.height) + " at (" +
               std::to_string(d.x) + ", " + std::to_string(d.y) + ")";
    };
    if (m.image.width != header.width || m.image.height != header.height || m.image.x != header.x ||
        m.image.y != header.y)
    {
        throw Exception(m.path + ": the matte's data window is " + window(m.image) + ", " +
                        PathInMessage(in) + "'s " + window(header) +
                        ": a matte must cover the image pixel for pixel");
    }
}


void ConvertForLooks(const ApplyRequest& r, const OCIO::ConstConfigRcPtr& config,
                     const RgbSpace* working, const RelightRequest& relight, MatteSide& s)
{
    const RgbSpace* sceneLinear = working;
    std::string why;
    if (!sceneLinear)
    {
        try
        {
            sceneLinear = IdentifySceneLinear(config).space;
        }
        catch (const Exception& e)
        {
            why = e.what();
        }
    }
    if (!sceneLinear)
    {
        throw ParameterError("{matte}: the change of light " + relight.src.name + " to " +
                             relight.dst.name + " works in linear " +
                             SpaceLabel(relight.working()) +
                             ", and it would get the looks' pixels through " + r.config +
                             "'s scene_linear, whose primaries are unknown (" + why +
                             "): give both sides as looks of the config");
    }
    const std::string space = LookSpace(r, config);
    ImageEncoding linear;
    linear.space = *sceneLinear;
    if (!r.colorspace.empty())
    {
        s.into.push_back(
            config->getProcessor(space.c_str(), OCIO::ROLE_SCENE_LINEAR)->getDefaultCPUProcessor());
    }
    if (const OCIO::ConstCPUProcessorRcPtr p = EncodingToLinear(linear, relight.working()))
    {
        s.into.push_back(p);
    }
    if (const OCIO::ConstCPUProcessorRcPtr p = LinearToEncoding(relight.working(), linear))
    {
        s.back.push_back(p);
    }
    if (!r.colorspace.empty())
    {
        s.back.push_back(
            config->getProcessor(OCIO::ROLE_SCENE_LINEAR, space.c_str())->getDefaultCPUProcessor());
    }
}

BufferWork MixByMatte(const Matte& matte, const BufferWork& in, const BufferWork& out)
{
    return [&matte, in, out](float* px, long w, long h, int n, const int* rgb)
    {
        const std::vector<float>& m = matte.weights;
        if (size_t(w) * size_t(h) != m.size())
        {
            throw Exception(matte.path + ": the matte is " + std::to_string(matte.image.width) +
                            "x" + std::to_string(matte.image.height) + ", the image " +
                            std::to_string(w) + "x" + std::to_string(h));
        }
        std::vector<float> lit(px, px + size_t(w) * size_t(h) * size_t(n));
        in(lit.data(), w, h, n, rgb);
        out(px, w, h, n, rgb);
        for (size_t p = 0; p < m.size(); ++p)
        {
            for (int c = 0; c < 3; ++c)
            {
                float& v = px[p * size_t(n) + size_t(rgb[c])];
                v = m[p] * lit[p * size_t(n) + size_t(rgb[c])] + (1.0f - m[p]) * v;
            }
        }
    };
}

}  // namespace bandlight::jobs
