// SPDX-License-Identifier: BSD-3-Clause
#include <sstream>

#include <catch2/catch.hpp>

#include "plugin/ConfigBuilder.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
ConfigOptions Options(const std::string& space)
{
    ConfigOptions o;
    o.workingSpace = space;
    o.lights = LectureLights();
    o.methods = LinearMethodNames();
    o.methods.push_back("band6");
    return o;
}

Light L(const std::string& name)
{
    return {name, BuiltinIlluminant(name)};
}

/// The 3×3 the config applies for a look, measured through its processor.
Mat3 LookMatrix(const OCIO::ConstConfigRcPtr& config, const std::string& look,
                const std::string& space)
{
    OCIO::LookTransformRcPtr t = OCIO::LookTransform::Create();
    t->setSrc(space.c_str());
    t->setDst(space.c_str());
    t->setLooks(look.c_str());
    return MeasureMatrix(config->getProcessor(t));
}
}  // namespace

TEST_CASE("Every look of a built config is the library's matrix", "[plugin]")
{
    for (const char* space : {"acescg", "rec709"})
    {
        const ConfigOptions o = Options(space);
        const OCIO::ConstConfigRcPtr config = BuildConfig(o);
        // 5 lights → 20 ordered pairs, 7 methods.
        CHECK(config->getNumLooks() == 140);
        CHECK(config->getNumNamedTransforms() == 140);
        const RgbSpace& ws = FindRgbSpace(space);
        for (const std::string& method : o.methods)
        {
            for (const auto& [from, to] : {std::pair{"A", "D65"}, std::pair{"F11", "D65"},
                                           std::pair{"D65", "F2"}, std::pair{"C", "A"}})
            {
                const std::string name = LookName(method, from, to);
                INFO(space << " " << name);
                const Mat3 expected =
                    IlluminantChangeMatrix(L(from), L(to), ParseMethod(method), ws);
                const Mat3 viaLook = LookMatrix(config, name, OCIO::ROLE_SCENE_LINEAR);
                CHECK((viaLook - expected).cwiseAbs().maxCoeff() <
                      1e-6 * expected.cwiseAbs().maxCoeff());
                const Mat3 viaNamed = MeasureMatrix(
                    config->getProcessor(config->getNamedTransform(NamedTransformName(name).c_str())
                                             ->getTransform(OCIO::TRANSFORM_DIR_FORWARD)));
                CHECK((viaNamed - expected).cwiseAbs().maxCoeff() <
                      1e-6 * expected.cwiseAbs().maxCoeff());
                CHECK_THAT(config->getLook(name.c_str())->getDescription(), Contains(from));
            }
        }
    }
}

TEST_CASE("A built config has the roles, spaces and views hosts ask for", "[plugin]")
{
    const OCIO::ConstConfigRcPtr config = BuildConfig(Options("acescg"));
    for (const char* role :
         {"scene_linear", "data", "color_picking", "texture_paint", "default_byte", "default_float",
          "default_sequencer", "reference", "aces_interchange", "cie_xyz_d65_interchange",
          "default", "rendering", "color_timing", "matte_paint"})
    {
        INFO(role);
        CHECK(config->hasRole(role));
    }
    CHECK(std::string(config->getColorSpace("scene_linear")->getName()) == "ACEScg");
    CHECK(config->getColorSpace("Non-Color")->isData());
    CHECK(config->getColorSpace("sRGB"));
    CHECK(config->getColorSpace("Linear Rec.709 (sRGB)"));
    CHECK(config->getColorSpace("Bands VB-VG-VR (lecture)"));
    CHECK(std::string(config->getDefaultDisplay()) == "sRGB");
    CHECK(config->getNumViews("sRGB") == 2);
    // No ':' or '=' in any look name: hosts' option syntax breaks on them.
    for (int i = 0; i < config->getNumLooks(); ++i)
    {
        const std::string n = config->getLookNameByIndex(i);
        CHECK(n.find_first_of(":=") == std::string::npos);
    }
}

TEST_CASE("The sRGB space decodes the IEC 61966-2-1 curve", "[plugin]")
{
    const OCIO::ConstConfigRcPtr config = BuildConfig(Options("rec709"));
    auto cpu = config->getProcessor("sRGB", "Linear Rec.709 (sRGB)")->getDefaultCPUProcessor();
    float rgb[3] = {0.5f, 0.04045f, 1.0f};
    cpu->applyRGB(rgb);
    CHECK(rgb[0] == Approx(0.214041).epsilon(1e-5));  // ((0.5 + 0.055) / 1.055)^2.4
    CHECK(rgb[1] == Approx(0.04045 / 12.92).epsilon(1e-4));
    CHECK(rgb[2] == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("A config survives serialisation", "[plugin]")
{
    const OCIO::ConstConfigRcPtr config = BuildConfig(Options("acescg"));
    std::ostringstream os;
    config->serialize(os);
    std::istringstream is(os.str());
    const OCIO::ConstConfigRcPtr back = OCIO::Config::CreateFromStream(is);
    back->validate();
    CHECK(back->getNumLooks() == config->getNumLooks());
    const Mat3 a = LookMatrix(config, "band3_F11_to_D65", "ACEScg");
    const Mat3 b = LookMatrix(back, "band3_F11_to_D65", "ACEScg");
    CHECK((a - b).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("The band space converts working RGB to the lecture's bands", "[plugin]")
{
    const OCIO::ConstConfigRcPtr config = BuildConfig(Options("acescg"));
    const Mat3 m = MeasureMatrix(config->getProcessor("ACEScg", "Bands VB-VG-VR (lecture)"));
    const Eigen::MatrixXd expected =
        WorkingToBandMatrix(BandSet::Lecture(), FindRgbSpace("acescg"));
    CHECK((m - expected).cwiseAbs().maxCoeff() < 1e-5);
}

TEST_CASE("Extending a base config keeps it and identifies its scene_linear", "[plugin]")
{
    // A studio-like base: a Rec.709 scene_linear with an XYZ interchange role,
    // built from a bandlight config in another working space.
    const OCIO::ConstConfigRcPtr base = BuildConfig(Options("rec709"));
    ConfigOptions o = Options("acescg");
    o.lights = {L("A"), L("D65")};
    o.methods = {"bradford", "band3"};
    OCIO::ConfigRcPtr ext;
    // The base already holds these looks: the clash is refused.
    CHECK_THROWS_WITH(ExtendConfig(base, o, true), Contains("clashes"));

    o.lights = {L("D50"), L("D75")};
    std::string identified;
    ext = ExtendConfig(base, o, true, &identified);
    CHECK(identified == "rec709");
    CHECK(ext->getNumLooks() == base->getNumLooks() + 4);
    for (int i = 0; i < base->getNumColorSpaces(); ++i)
    {
        CHECK(ext->getColorSpace(base->getColorSpaceNameByIndex(i)));
    }
    const Mat3 expected =
        IlluminantChangeMatrix(L("D50"), L("D75"), ParseMethod("band3"), FindRgbSpace("rec709"));
    const Mat3 got = LookMatrix(ext, "band3_D50_to_D75", "Linear Rec.709 (sRGB)");
    CHECK((got - expected).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("Config errors are clear", "[plugin]")
{
    ConfigOptions o = Options("acescg");
    o.lights = {L("A")};
    CHECK_THROWS_WITH(BuildConfig(o), Contains("at least two illuminants"));
    o = Options("acescg");
    o.methods = {"bradford", "wizardry"};
    CHECK_THROWS_WITH(BuildConfig(o), Contains("unknown method 'wizardry'"));
    o = Options("prophoto");
    CHECK_THROWS_WITH(BuildConfig(o), Contains("unknown working space 'prophoto'"));
    o = Options("acescg");
    o.lights = {L("A"), L("A")};
    CHECK_THROWS_WITH(BuildConfig(o), Contains("two illuminants share a name"));
}
