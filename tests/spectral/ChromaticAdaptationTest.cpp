// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <Eigen/LU>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Exception.h"

using namespace bandlight;

TEST_CASE("Bradford D65 → D50 matches the published matrix", "[spectral][published]")
{
    // B. Lindbloom, "Chromatic Adaptation" (brucelindbloom.com), Bradford D65 → D50,
    // whites D65 (0.95047, 1, 1.08883) and D50 (0.96422, 1, 0.82521).
    Mat3 expected;
    // clang-format off
    expected <<  1.0478112, 0.0228866, -0.0501270,
                 0.0295424, 0.9904844, -0.0170491,
                -0.0092345, 0.0150436,  0.7521316;
    // clang-format on
    const Mat3 m = AdaptationMatrix(Vec3(0.95047, 1.0, 1.08883), Vec3(0.96422, 1.0, 0.82521),
                                    AdaptationMethod::BRADFORD);
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 3; ++c)
        {
            CHECK(m(r, c) == Approx(expected(r, c)).margin(1e-7));
        }
    }
}

TEST_CASE("Every adaptation maps the source white to the destination white", "[spectral]")
{
    const Vec3 a(109.85, 100.0, 35.585);
    const Vec3 d65(95.047, 100.0, 108.883);
    for (AdaptationMethod m :
         {AdaptationMethod::XYZ_SCALING, AdaptationMethod::BRADFORD, AdaptationMethod::CAT02})
    {
        const Mat3 cat = AdaptationMatrix(a, d65, m);
        CHECK((cat * a - d65).norm() < 1e-10);
        // The inverse adaptation is the matrix inverse.
        CHECK((AdaptationMatrix(d65, a, m) * cat - Mat3::Identity()).norm() < 1e-12);
    }
    CHECK(AdaptationMatrix(a, a, AdaptationMethod::CAT02).isIdentity(1e-12));
    CHECK(ParseAdaptationMethod("VonKries") == AdaptationMethod::XYZ_SCALING);
    CHECK_THROWS_AS(ParseAdaptationMethod("cat16"), Exception);
    CHECK_THROWS_AS(AdaptationMatrix(Vec3::Zero(), d65, AdaptationMethod::XYZ_SCALING), Exception);
}
