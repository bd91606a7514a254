// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "spectral/ColourRendering.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

using namespace bandlight;

TEST_CASE("CCT and Ra of F1–F12 match CIE 15:2004", "[spectral][published]")
{
    // CIE 15:2004 Table T.8.2 (fluorescent illuminants FL1–FL12, CIE 1931
    // observer): CCT in kelvin (printed to 10 K) and Ra (printed as integers).
    struct Published
    {
        double cct;
        int ra;
    };
    const Published table[12] = {{6430, 76}, {4230, 64}, {3450, 57}, {2940, 51},
                                 {6350, 72}, {4150, 59}, {6500, 90}, {5000, 95},
                                 {4150, 90}, {5000, 81}, {4000, 83}, {3000, 83}};
    for (int i = 0; i < 12; ++i)
    {
        const std::string name = "F" + std::to_string(i + 1);
        const ColourRendering cr = ComputeColourRendering(BuiltinIlluminant(name));
        INFO(name << ": CCT " << cr.cctK << " K, Ra " << cr.ra);
        CHECK(std::lround(cr.ra) == table[i].ra);
        // 10 K printing, and F10's printed chromaticity is itself 0.0003 off its SPD.
        CHECK(cr.cctK == Approx(table[i].cct).margin(15.0));
    }
}

TEST_CASE("A Planckian radiator renders perfectly: Ra = 100", "[spectral]")
{
    for (double t : {2000.0, 2856.0, 4500.0})
    {
        // On the matching functions' full grid, so the CCT search sees the same locus.
        const ColourRendering cr = ComputeColourRendering(Planckian(t, 360.0, 5.0, 95));
        INFO("T = " << t);
        CHECK(cr.cctK == Approx(t).epsilon(1e-6));
        CHECK(cr.duv == Approx(0.0).margin(1e-9));
        CHECK(cr.ra == Approx(100.0).margin(1e-6));
        for (double r : cr.r)
        {
            CHECK(r == Approx(100.0).margin(1e-6));
        }
    }
}

TEST_CASE("D65 has CCT 6504 K and renders like daylight", "[spectral][published]")
{
    // CIE 15:2004 §3.1: D65's correlated colour temperature is about 6504 K.
    const ColourRendering cr = ComputeColourRendering(BuiltinIlluminant("D65"));
    CHECK(cr.cctK == Approx(6504.0).margin(2.0));
    CHECK(std::abs(cr.duv) < 5e-3);
    CHECK(cr.ra > 99.5);
}

TEST_CASE("CCT is the nearest point of the Planckian locus", "[spectral]")
{
    // A point displaced along the locus normal keeps the CCT and gets that Duv.
    const double t = 3500.0;
    const Eigen::Vector2d p = PlanckianUv(t);
    const Eigen::Vector2d tangent = (PlanckianUv(t + 0.5) - PlanckianUv(t - 0.5)).normalized();
    Eigen::Vector2d normal(-tangent.y(), tangent.x());
    if (normal.y() < 0)
    {
        normal = -normal;
    }
    const Eigen::Vector2d uv = p + 0.01 * normal;
    // Back from (u, v) to XYZ with Y = 1.
    const double v = uv.y(), u = uv.x();
    const Vec3 xyz(1.5 * u / v, 1.0, (4.0 - u - 10.0 * v) / (2.0 * v));
    const CctDuv r = ComputeCct(xyz);
    CHECK(r.cctK == Approx(t).margin(0.5));
    CHECK(r.duv == Approx(0.01).margin(1e-6));
    CHECK_THROWS_AS(ComputeCct(Vec3::Zero()), Exception);
}
