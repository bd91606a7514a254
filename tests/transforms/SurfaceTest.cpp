// SPDX-License-Identifier: BSD-3-Clause
// Surfaces as light sees them (spectral/Surface.h), rendered by the
// reference renderer: a remittance as a surface is the remittance, a
// diagonal Donaldson matrix is that remittance, and a fluorescent surface
// sends back light at wavelengths the illuminant does not have.
// Covers, through the entry points it calls: transforms/SurfaceRenderer.cpp.
#include <catch2/catch.hpp>

#include "spectral/CieData.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/Surface.h"
#include "transforms/SurfaceRenderer.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("A remittance surface renders as its remittance, also as a diagonal matrix",
          "[spectral][surface]")
{
    for (const char* light : {"A", "D65", "F11"})
    {
        const SurfaceRenderer r(BuiltinIlluminant(light), FindRgbSpace("acescg"));
        for (const NamedSpectrum& t : TestColourSamples())
        {
            INFO(light << " " << t.name);
            const Vec3 direct = r.render(t.spectrum);
            const Vec3 surface = r.render(RemittanceSurface(t.spectrum));
            CHECK((surface - direct).norm() <= 1e-12 * direct.norm());
            const BispectralSurface diagonal =
                BispectralSurface::FromRemittance(t.spectrum, 380.0, 5.0, 81);
            CHECK((r.render(diagonal) - direct).norm() <= 1e-12 * direct.norm());
        }
        // The perfect white reflector is the renderer's white.
        const Vec3 white =
            r.render(RemittanceSurface(Spectrum::Constant(380.0, 5.0, 81, 1.0)));
        CHECK((white - r.white()).norm() < 1e-12);
    }
}

TEST_CASE("A fluorescent surface sends back light the illuminant lacks", "[spectral][surface]")
{
    // Light only at 450 nm (a 10 nm band); a surface that absorbs half of
    // it and re-radiates that half at 550 nm: the reflected light is green,
    // which no remittance under this light can give.
    std::vector<double> band(81, 0.0);
    band[13] = band[14] = band[15] = 1.0;  // 445, 450, 455 nm
    const Spectrum light(380.0, 5.0, band);
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(81, 81);
    for (int i = 13; i <= 15; ++i)
    {
        d(i, i) = 0.5;       // the reflected half
        d(i + 20, i) = 0.5;  // re-radiated 100 nm longer
    }
    const BispectralSurface fluorescent(380.0, 5.0, d);
    const Spectrum out = fluorescent.reflect(light);
    CHECK(out(550.0) == Approx(0.5));
    CHECK(out(450.0) == Approx(0.5));
    // Energy: what goes out is what came in, no more.
    CHECK(out.values().size() == 81);
    double in = 0.0, back = 0.0;
    for (size_t i = 0; i < 81; ++i)
    {
        in += light[i];
        back += out[i];
    }
    CHECK(back == Approx(in));
    const SurfaceRenderer r(light, FindRgbSpace("lin-rec709"));
    // Beside the same surface without its fluorescence (the diagonal alone),
    // what it adds is the colour of 550 nm light: green.
    const Vec3 plain = r.render(BispectralSurface(380.0, 5.0, Eigen::MatrixXd(d.diagonal().asDiagonal())));
    const Vec3 added = r.render(fluorescent) - plain;
    CHECK(added.y() > 2.0 * std::max(added.x(), added.z()));
    CHECK(added.y() > 0.5 * plain.norm());
    CHECK_THROWS_WITH(BispectralSurface(380.0, 5.0, Eigen::MatrixXd::Constant(3, 2, 0.1)),
                      Contains("square Donaldson matrix"));
    CHECK_THROWS_WITH(BispectralSurface(380.0, 5.0, -Eigen::MatrixXd::Identity(3, 3)),
                      Contains("non-negative"));
}
