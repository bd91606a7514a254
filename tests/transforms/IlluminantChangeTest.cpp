// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include "transforms/LitMethod.h"

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/BandModel.h"
#include "transforms/IlluminantChange.h"
#include "transforms/SurfaceRenderer.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
Light L(const char* name)
{
    return {name, BuiltinIlluminant(name)};
}

/// White of a light in working RGB, Y = 1, as the spectral reference renders it.
Vec3 WhiteRgb(const Light& l, const RgbSpace& space)
{
    return SurfaceRenderer(l.spectrum, space).white();
}
}  // namespace

TEST_CASE("Chromatic adaptations and band3-wp map the source white exactly", "[transforms]")
{
    for (const char* space : {"acescg", "rec709", "rec2020"})
    {
        const RgbSpace& ws = FindRgbSpace(space);
        for (const auto& [from, to] : {std::pair{"A", "D65"}, std::pair{"F11", "D65"},
                                       std::pair{"D65", "F2"}, std::pair{"C", "A"}})
        {
            for (const char* method : {"vonkries", "bradford", "cat02", "band3-wp", "band6-wp"})
            {
                INFO(space << " " << method << " " << from << " → " << to);
                const Mat3 m = IlluminantChangeMatrix(L(from), L(to), test::LitMethod(method), ws);
                CHECK((m * WhiteRgb(L(from), ws) - WhiteRgb(L(to), ws)).norm() < 1e-12);
            }
        }
    }
}

TEST_CASE("band3 is the lecture's diagonal in band space, keeping the white's luminance",
          "[transforms][lecture]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    const Light a = L("A"), d65 = L("D65");
    const Mat3 m = IlluminantChangeMatrix(a, d65, test::LitMethod("band3"), ws);
    // In band space the matrix is diagonal with the ratios I(D65)/I(A), up to one scale.
    const Eigen::MatrixXd toBand = WorkingToBandMatrix(BandSet::Lecture(), ws);
    const Eigen::MatrixXd fromBand = BandToWorkingMatrix(BandSet::Lecture(), ws);
    const Eigen::MatrixXd d = toBand * m * fromBand;
    CHECK(std::abs(d(0, 1)) + std::abs(d(0, 2)) + std::abs(d(1, 0)) + std::abs(d(2, 1)) < 1e-12);
    const std::vector<double> ia = IlluminantBands(a.spectrum, BandSet::Lecture());
    const std::vector<double> id = IlluminantBands(d65.spectrum, BandSet::Lecture());
    const double k = d(1, 1) / (id[1] / ia[1]);
    CHECK(d(0, 0) == Approx(k * id[0] / ia[0]));
    CHECK(d(2, 2) == Approx(k * id[2] / ia[2]));
    // The band model's white under A (its band means) keeps its luminance Y.
    const Mat3 toXyz = RgbToXyzMatrix(ws.chromaticities);
    const Eigen::Vector3d whiteA = fromBand * Eigen::Vector3d(ia[0], ia[1], ia[2]);
    CHECK((toXyz * m * whiteA).y() == Approx((toXyz * whiteA).y()));
    // ... but it is not white-preserving for the spectral white.
    CHECK((m * WhiteRgb(a, ws) - WhiteRgb(d65, ws)).norm() > 1e-3);
}

TEST_CASE("band3 and band3-wp agree when the lights are the same", "[transforms]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    for (const char* method : {"none", "vonkries", "bradford", "band3", "band3-wp", "band10"})
    {
        CHECK(IlluminantChangeMatrix(L("F2"), L("F2"), test::LitMethod(method), ws)
                  .isIdentity(1e-12));
    }
}

TEST_CASE("Method names", "[transforms]")
{
    CHECK(ParseMethod("Bradford").method == ChangeMethod::BRADFORD);
    CHECK(ParseMethod("band3").bands.describe() == "400,500,600,700");
    CHECK(ParseMethod("band6-wp").method == ChangeMethod::BAND_WP);
    CHECK(ParseMethod("band6").bands.size() == 6);
    CHECK(ParseMethod("BAND3-WP").name == "band3-wp");
    CHECK_THROWS_WITH(ParseMethod("band2"), Contains("3 <= N <= 300"));
    // Any band set, named by its edges.
    const MethodSpec custom = ParseMethod("bands380-480-560-780-wp");
    CHECK(custom.method == ChangeMethod::BAND_WP);
    CHECK(custom.bands.describe() == "380,480,560,780");
    CHECK(ParseMethod("bands400-500-600-700").bands.describe() == "400,500,600,700");
    CHECK_THROWS_WITH(ParseMethod("bands400-500-450-700"), Contains("not increasing"));
    CHECK_THROWS_WITH(ParseMethod("bands400-500-600"), Contains("at least three bands"));
    // The same edges as band3 give band3's matrix; other edges another one.
    const Light a{"A", BuiltinIlluminant("A")}, d{"D65", BuiltinIlluminant("D65")};
    const RgbSpace& ws = FindRgbSpace("acescg");
    CHECK((IlluminantChangeMatrix(a, d, test::LitMethod("bands400-500-600-700"), ws) -
           IlluminantChangeMatrix(a, d, test::LitMethod("band3"), ws))
              .norm() < 1e-12);
    CHECK((IlluminantChangeMatrix(a, d, test::LitMethod("bands380-480-560-780"), ws) -
           IlluminantChangeMatrix(a, d, test::LitMethod("band3"), ws))
              .norm() > 1e-3);
    CHECK_THROWS_WITH(ParseMethod("bandx"), Contains("unknown method 'bandx'"));
    CHECK_THROWS_WITH(ParseMethod("magic"), Contains("unknown method 'magic'"));
    CHECK(LinearMethodNames().size() == 6);
    CHECK_THAT(DescribeMethod(ParseMethod("band3")), Contains("not exact on white"));
}

TEST_CASE("An illuminant with an empty band gives a clear error", "[transforms]")
{
    // A narrow-band light with nothing in VB: the band ratio is undefined.
    std::vector<double> v(81, 0.0);
    for (size_t i = 30; i < 60; ++i)
    {
        v[i] = 1.0;  // 530–675 nm
    }
    const Light green{"G", Spectrum(380.0, 5.0, v)};
    CHECK_THROWS_WITH(
        IlluminantChangeMatrix(green, L("D65"), test::LitMethod("band3"), FindRgbSpace("acescg")),
        Contains("illuminant G has no power in band VB"));
}

TEST_CASE("Material tint is the identity for a white remittance", "[transforms]")
{
    const RgbSpace& ws = FindRgbSpace("acescg");
    CHECK(MaterialTintMatrix({1, 1, 1}, BandSet::Lecture(), ws).isIdentity(1e-12));
    // Gold (docs/science.md §1.3, R_diff in R, G, B order = VR, VG, VB: 0.5, 0.5, 0.0).
    const Mat3 gold = MaterialTintMatrix({0.0, 0.5, 0.5}, BandSet::Lecture(), ws);
    const Eigen::MatrixXd toBand = WorkingToBandMatrix(BandSet::Lecture(), ws);
    const Eigen::VectorXd bands = toBand * gold * (toBand.inverse() * Eigen::Vector3d(1, 1, 1));
    CHECK(bands(0) == Approx(0.0).margin(1e-12));
    CHECK(bands(1) == Approx(0.5));
    CHECK_THROWS_AS(MaterialTintMatrix({1, 1}, BandSet::Lecture(), ws), Exception);
}
