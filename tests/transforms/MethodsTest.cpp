// SPDX-License-Identifier: BSD-3-Clause
// The method registry: every entry is complete for its kind, every name a
// user can give parses to it, and every image method relights through it.
#include <set>

#include <catch2/catch.hpp>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/IlluminantChange.h"
#include "transforms/Methods.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("Every registry entry has the builder its exactness needs", "[transforms][methods]")
{
    std::set<ChangeMethod> seen;
    for (const MethodEntry& e : Methods())
    {
        INFO(e.syntax);
        REQUIRE(!e.methods.empty());
        for (ChangeMethod m : e.methods)
        {
            CHECK(seen.insert(m).second);  // one entry per method
            CHECK(&FindMethod(m) == &e);
        }
        CHECK(e.parse != nullptr);
        CHECK(e.describe != nullptr);
        switch (e.exactness)
        {
            case MethodExactness::LINEAR:
                CHECK(e.litMatrix != nullptr);
                CHECK(e.makeOp == nullptr);
                CHECK_FALSE(e.native);
                break;
            case MethodExactness::NONLINEAR:
                CHECK(e.makeOp != nullptr);
                CHECK(e.litMatrix == nullptr);
                CHECK(e.directForm != DirectForm::NONE);  // the cost table times its own form
                break;
            case MethodExactness::REFERENCE:
                CHECK(e.isReference());
                CHECK(e.makeOp == nullptr);
                break;
        }
        // A method that takes a user's training set has a default one.
        CHECK((!e.takesTraining || e.defaultTraining != nullptr));
    }
    // The reference is one entry, named by the registry.
    CHECK(FindMethod(ReferenceMethodName()).isReference());
}

TEST_CASE("The wall's two methods are named by their registry entries", "[transforms][methods]")
{
    // The post-camera look maps a camera's plates to its own plates under
    // another light; the comparison aims at the observer's colours. Both
    // need the camera and are ops per pixel.
    const MethodSpec look = ParseMethod(WallLookMethodName());
    const MethodSpec comparison = ParseMethod(WallComparisonMethodName());
    CHECK(look.name == "rootpoly-plate");
    CHECK(comparison.name == "rootpoly-camera");
    for (const MethodSpec* m : {&look, &comparison})
    {
        CHECK(m->entry().needsCamera);
        CHECK(m->entry().exactness == MethodExactness::NONLINEAR);
        CHECK(m->degree == 2);
    }
}

TEST_CASE("Every default name parses to its own entry and relights A to D65",
          "[transforms][methods]")
{
    const Light a{"A", BuiltinIlluminant("A")};
    const Light d65{"D65", BuiltinIlluminant("D65")};
    const RgbSpace& working = FindRgbSpace("acescg");
    std::vector<std::string> names = AllMethodNames();
    names.insert(names.end(), LinearMethodNames().begin(), LinearMethodNames().end());
    for (const std::string& name : names)
    {
        INFO(name);
        const MethodSpec spec = ParseMethod(name);
        CHECK(spec.name == name);
        CHECK(&spec.entry() == &FindMethod(name));
        CHECK(!DescribeMethod(spec).empty());
        // Lit plates: a white surface under A becomes D65's white, to the
        // method's accuracy (the band model's white is not exact: 5 %).
        MethodSpec lit = spec;
        lit.plates = Plates::Lit();
        const Relighter r(a, d65, lit, working);
        CHECK(r.isLinear() == spec.isLinear());
        const Vec3 out = r.apply(Vec3(1.0, 1.0, 1.0));
        CHECK(out.allFinite());
        CHECK(out.maxCoeff() > 0.3);
    }
}

TEST_CASE("The camera requirement is stated once, for every camera method",
          "[transforms][methods]")
{
    for (const MethodEntry& e : Methods())
    {
        for (const char* name : e.cameraDefaults)
        {
            const MethodSpec spec = ParseMethod(name);
            CHECK(spec.entry().needsCamera);
            CHECK_THROWS_WITH(RequireCamera(spec),
                              Contains("needs the camera that shot the plates"));
            CHECK_THROWS_AS(Relighter(Light{"A", BuiltinIlluminant("A")},
                                      Light{"D65", BuiltinIlluminant("D65")}, spec,
                                      FindRgbSpace("acescg")),
                            ParameterError);
        }
    }
    RequireCamera(ParseMethod("bradford"));  // no camera needed, none given: fine
    CHECK(!CameraMethodNames().empty());
}

TEST_CASE("Training sets come from the registry", "[transforms][methods]")
{
    CHECK(TrainingOf(ParseMethod("bradford")).empty());
    CHECK(TrainingOf(ParseMethod("fit3x3")).size() == 108);   // TCS01-08 and 100 smooth ones
    CHECK(TrainingOf(ParseMethod("rootpoly")).size() == 205);  // rawtoaces' 190 and the 15 TCS
    CHECK(TrainingOf(ParseMethod("rootpoly3-camera")).size() == 205);
    MethodSpec own = ParseMethod("rootpoly");
    own.training = {TrainingOf(ParseMethod("fit3x3")).front()};
    CHECK(TrainingOf(own).size() == 1);
}
