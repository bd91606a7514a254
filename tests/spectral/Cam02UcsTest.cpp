// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>

#include <catch2/catch.hpp>

#include "spectral/Cam02Ucs.h"
#include "spectral/Exception.h"

using namespace bandlight;

TEST_CASE("CIECAM02 reproduces Fairchild's worked examples", "[spectral][fidelity][published]")
{
    // M. D. Fairchild, Color Appearance Models, 3rd ed. (Wiley, 2013), the
    // book's worked-example spreadsheet AppModEx.xls, CIECAM02 sheet: four
    // samples, Y_b = 20, average surround, D computed from L_A. The sheet
    // prints J, C, s, Q, M to two decimals and h to one (J 65.96 is 65.955…,
    // so half a unit in the last place plus 1e-4).
    struct Example
    {
        Vec3 xyz, white;
        double la;
        double j, c, h, s, q, m;
    };
    const Example examples[] = {
        {{19.01, 20.00, 21.78},
         {95.05, 100.0, 108.88},
         318.31,
         41.73,
         0.10,
         219.0,
         2.36,
         195.37,
         0.11},
        {{57.06, 43.06, 31.96},
         {95.05, 100.0, 108.88},
         31.83,
         65.96,
         48.57,
         19.6,
         52.25,
         152.67,
         41.67},
        {{3.53, 6.56, 2.14},
         {109.85, 100.0, 35.58},
         318.31,
         21.79,
         46.94,
         177.1,
         58.79,
         141.17,
         48.80},
        {{19.01, 20.00, 21.78},
         {109.85, 100.0, 35.58},
         31.83,
         42.53,
         51.92,
         248.9,
         60.22,
         122.83,
         44.54},
    };
    for (const Example& e : examples)
    {
        CamViewingConditions v;
        v.adaptingLuminance = e.la;
        v.discountIlluminant = false;
        const CamCorrelates r = Cam02(e.white, v).correlates(e.xyz);
        INFO("XYZ " << e.xyz.transpose() << ", L_A " << e.la);
        CHECK(r.j == Approx(e.j).margin(0.0051));
        CHECK(r.c == Approx(e.c).margin(0.0051));
        CHECK(r.h == Approx(e.h).margin(0.051));
        CHECK(r.s == Approx(e.s).margin(0.0051));
        CHECK(r.q == Approx(e.q).margin(0.0051));
        CHECK(r.m == Approx(e.m).margin(0.0051));
    }
}

TEST_CASE("The adopted white has J = 100 and no colourfulness", "[spectral][fidelity]")
{
    // CIE 159:2004: J = 100 (A/A_w)^cz is 100 at the white; with D = 1 its
    // adapted cone responses are equal, so a and b vanish (to the four-figure
    // rounding of the HPE matrix, whose rows sum to 1 ± 1e-5).
    for (const Vec3& white : {Vec3(95.047, 100.0, 108.883), Vec3(109.85, 100.0, 35.58)})
    {
        const Cam02 cam(white);
        const CamCorrelates c = cam.correlates(white);
        CHECK(c.j == Approx(100.0).epsilon(1e-12));
        CHECK(c.m < 0.01);
        const Vec3 ucs = cam.ucs(white);
        CHECK(ucs.x() == Approx(100.0).epsilon(1e-12));
        CHECK(std::hypot(ucs.y(), ucs.z()) < 0.01);
    }
}

TEST_CASE("CAM02-UCS follows Luo, Cui and Li's formulas", "[spectral][fidelity]")
{
    // Luo, Cui & Li, Color Res. Appl. 31(4), 2006: J' = 1.7 J /
    // (1 + 0.007 J), M' = ln(1 + 0.0228 M) / 0.0228; J' = J at 0 and 100.
    CHECK(JmhToCam02Ucs(100.0, 0.0, 0.0).x() == Approx(100.0).epsilon(1e-14));
    CHECK(JmhToCam02Ucs(0.0, 0.0, 0.0).x() == 0.0);
    const Vec3 u = JmhToCam02Ucs(50.0, 40.0, 90.0);
    CHECK(u.x() == Approx(1.7 * 50.0 / 1.35).epsilon(1e-14));
    CHECK(u.y() == Approx(0.0).margin(1e-12));
    CHECK(u.z() == Approx(std::log(1.0 + 0.0228 * 40.0) / 0.0228).epsilon(1e-14));
    CHECK(DeltaECam02Ucs(Vec3(1, 2, 3), Vec3(1, 5, 7)) == Approx(5.0));
}

TEST_CASE("CIECAM02 stays finite outside the spectrum locus", "[spectral][fidelity]")
{
    // Negative cone responses (XYZ no real colour has) must not give NaN.
    const Cam02 cam(Vec3(95.047, 100.0, 108.883));
    for (const Vec3& xyz : {Vec3(0, 0, 0), Vec3(-5, 10, 50), Vec3(80, -2, 0), Vec3(0, 0, 200)})
    {
        const CamCorrelates c = cam.correlates(xyz);
        INFO(xyz.transpose());
        CHECK(std::isfinite(c.j));
        CHECK(std::isfinite(c.c));
        CHECK(std::isfinite(c.h));
        CHECK(std::isfinite(c.m));
        CHECK(std::isfinite(c.s));
    }
    CHECK_THROWS_AS(Cam02(Vec3(0, 0, 0)), Exception);
}
