// SPDX-License-Identifier: BSD-3-Clause
// The apply job (jobs/ApplyJob) run in process, as a C++ host runs it:
// the command's pixels for a change of light, OCIO's for a look of any
// config.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "bandlight/jobs/ApplyJob.h"
#include "bandlight/jobs/ImageApply.h"
#include "bandlight/jobs/Inputs.h"
#include "bandlight/spectral/Exception.h"
#include "jobs/JobsTestSupport.h"

using namespace bandlight;
namespace fs = std::filesystem;

namespace
{
/// The image module is found beside the bandlight executable; this test
/// program lives elsewhere, so it says where.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

std::vector<float> ReadPixels(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> px(size_t(spec.image_pixels()) * size_t(spec.nchannels));
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}
}  // namespace

TEST_CASE("the apply job writes the command's image, and names its parameters", "[jobs]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = test::Fresh("apply");
    fs::create_directories(dir);
    std::vector<float> px(16 * 8 * 4);
    for (size_t i = 0; i < px.size(); ++i)
    {
        px[i] = (i % 4 == 3) ? 1.0f : 0.01f * float(i % 97);
    }
    WriteImage(dir + "/plate.exr", px.data(), 16, 8, 4, {"R", "G", "B", "A"},
               LinearImageDescription(FindRgbSpace("acescg"), "ACEScg"), PixelType::FLOAT);
    jobs::ApplyRequest request;
    request.input = dir + "/plate.exr";
    request.output = dir + "/lib.exr";
    jobs::RelightRequest relight;
    relight.src = jobs::ResolveIlluminant("A");
    relight.dst = jobs::ResolveIlluminant("D65");
    request.relight = relight;
    const jobs::ApplyResult result = jobs::ApplyImages(request);
    CHECK(result.frames == 1);
    CHECK(result.applied == "bradford_A_to_D65");
    REQUIRE(test::Bandlight("apply '" + dir + "/plate.exr' '" + dir + "/cli.exr' --from A --to D65")
                .code == 0);
    const std::vector<float> lib = ReadPixels(dir + "/lib.exr");
    REQUIRE(lib.size() == px.size());
    CHECK(lib == ReadPixels(dir + "/cli.exr"));
    CHECK(lib[3] == 1.0f);     // alpha passes through
    CHECK(lib[40] != px[40]);  // and the colour changed

    jobs::ApplyRequest none;
    none.input = request.input;
    none.output = dir + "/none.exr";
    try
    {
        jobs::ApplyImages(none);
        FAIL("accepted");
    }
    catch (const ParameterError& e)
    {
        CHECK(e.spelled(Face::COMMAND) ==
              "give --look NAME --config DIR, or --from S1 --to S2 [--method M]");
        CHECK(e.spelled(Face::PYTHON) == "give look=NAME config=DIR, or src=S1 dst=S2 [method=M]");
    }
    CHECK_FALSE(fs::exists(none.output));
}

TEST_CASE("apply --look runs a matrix look of any config natively, with OCIO's pixels", "[jobs]")
{
    REQUIRE(g_moduleFound);
    const std::string dir = test::Fresh("apply_look");
    fs::create_directories(dir);
    // A config that is not bandlight's: a look that clamps and grades by a
    // matrix with an offset, the same matrix without the clamp, and an
    // exponent (not a matrix). Only the first is a clamp and a matrix.
    OCIO::ConfigRcPtr config = OCIO::Config::CreateRaw()->createEditableCopy();
    OCIO::RangeTransformRcPtr clamp = OCIO::RangeTransform::Create();
    clamp->setMinInValue(-100.0);
    clamp->setMinOutValue(-100.0);
    clamp->setMaxInValue(1000.0);
    clamp->setMaxOutValue(1000.0);
    OCIO::MatrixTransformRcPtr grade = OCIO::MatrixTransform::Create();
    const double m44[16] = {1.1, 0.05, 0, 0, 0.02, 0.9, 0.01, 0, 0, 0.1, 1.2, 0, 0, 0, 0, 1};
    const double offset[4] = {0.01, -0.02, 0.0, 0.0};
    grade->setMatrix(m44);
    grade->setOffset(offset);
    OCIO::GroupTransformRcPtr clamped = OCIO::GroupTransform::Create();
    clamped->appendTransform(clamp);
    clamped->appendTransform(grade);
    OCIO::LookRcPtr look = OCIO::Look::Create();
    look->setName("grade");
    look->setProcessSpace("raw");
    look->setTransform(clamped);
    config->addLook(look);
    OCIO::LookRcPtr plain = OCIO::Look::Create();
    plain->setName("plain");
    plain->setProcessSpace("raw");
    plain->setTransform(grade);
    config->addLook(plain);
    OCIO::ExponentTransformRcPtr gamma = OCIO::ExponentTransform::Create();
    const double g[4] = {1.2, 1.2, 1.2, 1.0};
    gamma->setValue(g);
    OCIO::LookRcPtr curve = OCIO::Look::Create();
    curve->setName("curve");
    curve->setProcessSpace("raw");
    curve->setTransform(gamma);
    config->addLook(curve);
    config->setRole(OCIO::ROLE_SCENE_LINEAR, "raw");
    {
        std::ofstream f(dir + "/config.ocio");
        config->serialize(f);
    }
    std::vector<float> px(64 * 8 * 4);
    for (size_t i = 0; i < px.size(); ++i)
    {
        px[i] = i % 4 == 3 ? 0.5f : std::exp2(float(int(i % 29) - 14));
    }
    px[0] = std::numeric_limits<float>::quiet_NaN();
    px[5] = std::numeric_limits<float>::infinity();
    WriteImage(dir + "/plate.exr", px.data(), 64, 8, 4, {"R", "G", "B", "A"}, ImageDescription{},
               PixelType::FLOAT);
    for (const std::string name : {"grade", "plain", "curve"})
    {
        jobs::ApplyRequest request;
        request.input = dir + "/plate.exr";
        request.output = dir + "/" + name + ".exr";
        request.look = name;
        request.config = dir;
        const jobs::ApplyResult result = jobs::ApplyImages(request);
        CHECK(result.native == (name == "grade"));
        OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
        t->setSrc("raw");
        t->setDst("raw");
        t->setLooks(name.c_str());
        std::vector<float> want = px;
        OCIO::PackedImageDesc desc(want.data(), 64, 8, 4);
        config->getProcessor(t)->getDefaultCPUProcessor()->apply(desc);
        const std::vector<float> got = ReadPixels(request.output);
        REQUIRE(got.size() == want.size());
        for (size_t i = 0; i < got.size(); ++i)
        {
            INFO(name << " value " << i << ": " << got[i] << " against OCIO's " << want[i]);
            if (std::isnan(want[i]))
            {
                CHECK(std::isnan(got[i]));
            }
            else
            {
                CHECK(got[i] == Approx(want[i]).epsilon(1e-6).margin(1e-30));
            }
        }
    }
}
