// SPDX-License-Identifier: BSD-3-Clause
// Covers, through the entry points it calls: spectral/SpectralLayout.cpp,
// spectral/SpectralLayoutFamilies.cpp, spectral/SpectralWeights.cpp.
#include "spectral/SpectralImage.h"

#include <catch2/catch.hpp>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

using namespace bandlight;
using Catch::Matchers::Contains;

namespace
{
std::vector<std::string> Names(SpectralKind kind, double start, double step, int count)
{
    std::vector<std::string> n;
    for (int i = 0; i < count; ++i)
    {
        n.push_back(SpectralChannelName(kind, start + step * i));
    }
    return n;
}

Eigen::VectorXd Values(const SpectralLayout& layout, const std::function<double(double)>& f)
{
    Eigen::VectorXd v(Eigen::Index(layout.wavelengths.size()));
    for (size_t i = 0; i < layout.wavelengths.size(); ++i)
    {
        v(Eigen::Index(i)) = f(layout.wavelengths[i]);
    }
    return v;
}
}  // namespace

TEST_CASE("Fichet 2021 channel names parse in every unit", "[spectral]")
{
    // Names as the layout's reference code writes them (comma as the
    // decimal separator: '.' separates EXR layers).
    CHECK(ParseSpectralChannel("S0.550,000000nm")->wavelengthNm == Approx(550.0).epsilon(1e-12));
    CHECK(ParseSpectralChannel("T.0,55um")->wavelengthNm == Approx(550.0).epsilon(1e-12));
    CHECK(ParseSpectralChannel("T.0,55\xC2\xB5m")->wavelengthNm == Approx(550.0).epsilon(1e-12));
    CHECK(ParseSpectralChannel("S0.5,5e-7m")->wavelengthNm == Approx(550.0).epsilon(1e-12));
    // 545.077 THz is 550 nm (c = 299 792 458 m/s).
    CHECK(ParseSpectralChannel("S0.545,0771THz")->wavelengthNm == Approx(550.0).epsilon(1e-6));
    // pbrt-v4's bucket centres, 3 decimals.
    CHECK(ParseSpectralChannel("S0.374,688nm")->wavelengthNm == Approx(374.688));
    CHECK(ParseSpectralChannel("S0.550.5nm")->wavelengthNm == Approx(550.5));
    const auto s2 = ParseSpectralChannel("S2.600nm");
    CHECK(s2->stokes == 2);
    CHECK(s2->kind == SpectralKind::EMISSIVE);
    CHECK(ParseSpectralChannel("T.600nm")->kind == SpectralKind::REFLECTIVE);
    for (const char* other : {"R", "G", "B", "A", "Y", "S4.500nm", "diffuse.R", "S0", "T"})
    {
        CHECK_FALSE(ParseSpectralChannel(other).has_value());
    }
    CHECK(SpectralChannelName(SpectralKind::EMISSIVE, 550.0) == "S0.550,000000nm");
    CHECK(
        ParseSpectralChannel(SpectralChannelName(SpectralKind::REFLECTIVE, 412.25))->wavelengthNm ==
        412.25);
}

TEST_CASE("Spectral channel names that do not parse name the file and the channel", "[spectral]")
{
    CHECK_THROWS_WITH(ParseSpectralChannel("S0.abcnm", "shot.exr"),
                      Contains("shot.exr: channel 'S0.abcnm' is not a spectral channel name"));
    CHECK_THROWS_WITH(ParseSpectralChannel("S0.550", "f.exr"), Contains("'S0.550'"));
    CHECK_THROWS_WITH(ParseSpectralChannel("S0.550parsec", "f.exr"), Contains("'S0.550parsec'"));
    CHECK_THROWS_WITH(ParseSpectralChannel("S0.550,1,2nm", "f.exr"), Contains("'S0.550,1,2nm'"));
    CHECK_THROWS_WITH(ParseSpectralChannel("T.400nm.500nm", "f.exr"),
                      Contains("channel 'T.400nm.500nm' is bi-spectral"));
    // A newline in a name stays on one line.
    CHECK_THROWS_WITH(ParseSpectralChannel("S0.5\n00nm", "f.exr"), Contains("S0.5\\n00nm"));
}

TEST_CASE("Spectral layouts refuse bad channel sets with one line", "[spectral]")
{
    const auto layout =
        [](std::vector<std::string> names, std::map<std::string, std::string> attributes = {})
    { return FindSpectralLayout("x.exr", names, attributes); };
    CHECK_THROWS_WITH(layout({"R", "G", "B"}), Contains("x.exr: has no spectral channels"));
    CHECK_THROWS_WITH(layout({"R", "S0.500nm"}),
                      Contains("channel 'S0.500nm' is its only spectral channel"));
    CHECK_THROWS_WITH(layout({"S0.500nm", "S0.0,5um"}),
                      Contains("is in um but 'S0.500nm' is in nm: mixed units"));
    CHECK_THROWS_WITH(layout({"S0.500nm", "S0.500,000nm"}), Contains("have the same wavelength"));
    CHECK_THROWS_WITH(layout({"S1.500nm", "S1.600nm"}),
                      Contains("channel 'S1.500nm' is a Stokes component (S1-S3) but the image "
                               "has no S0 channels"));
    CHECK_THROWS_WITH(layout({"S0.500nm", "T.600nm", "S0.600nm"}),
                      Contains("both emissive (S0) and reflective (T) channels"));
    CHECK_THROWS_WITH(layout({"S0.500nm", "S0.600nm"}, {{"spectralLayoutVersion", "2.0"}}),
                      Contains("spectralLayoutVersion is '2.0'"));
    CHECK_THROWS_WITH(layout({"T.500nm", "T.600nm"}, {{"emissiveUnits", "W.m^-2.sr^-1"}}),
                      Contains("says emissiveUnits but its spectral channels are reflective"));
    CHECK_THROWS_WITH(layout({"S0.5nm", "S0.600nm"}), Contains("must lie within 100-100000 nm"));
    CHECK_THROWS_WITH(layout(Names(SpectralKind::EMISSIVE, 380.0, 0.01, 10000)),
                      Contains("10000 channels; bandlight reads at most 8192"));
    // Polarisation beside S0 is noted and ignored.
    const SpectralLayout p = layout({"S0.500nm", "S0.600nm", "S1.500nm", "S1.600nm", "R"});
    CHECK(p.wavelengths == std::vector<double>{500.0, 600.0});
    REQUIRE(p.notes.size() == 1);
    CHECK_THAT(p.notes[0], Contains("2 polarisation channels (S1-S3) ignored"));
}

TEST_CASE("Spectral layouts find their channels in any order and their sampling", "[spectral]")
{
    // EXR sorts channels by name: 1000 nm before 380 nm.
    const SpectralLayout l =
        FindSpectralLayout("x.exr", {"A", "S0.1000nm", "S0.380nm", "S0.700nm", "B"}, {});
    CHECK(l.wavelengths == std::vector<double>{380.0, 700.0, 1000.0});
    CHECK(l.channels == std::vector<int>{2, 3, 1});
    CHECK(l.sampling == SpectralSampling::POINTS);
    // Cells halfway to the neighbours, the ends mirrored.
    CHECK(l.edges == std::vector<double>{220.0, 540.0, 850.0, 1150.0});

    // pbrt-v4's default film: 16 buckets over 360–830 nm.
    std::vector<std::string> pbrt = {"R", "G", "B"};
    for (int i = 0; i < 16; ++i)
    {
        char name[64];
        std::snprintf(name, sizeof name, "S0.%.3fnm", 360.0 + (i + 0.5) / 16.0 * 470.0);
        std::string n(name);
        std::replace(n.begin(), n.end(), '.', ',');
        pbrt.push_back("S0." + n.substr(3));
    }
    const SpectralLayout b = FindSpectralLayout("p.exr", pbrt, {});
    CHECK(b.sampling == SpectralSampling::BUCKETS);
    CHECK(b.family == SpectralLayoutFamily::PBRT_V4_FILM);
    CHECK_THAT(b.describe(), Contains("(pbrt-v4 spectral film)"));
    CHECK(b.edges.front() == Approx(360.0).margin(1e-3));
    CHECK(b.edges.back() == Approx(830.0).margin(1e-3));

    // Named channels.
    SpectralLayoutOptions named;
    named.namedWavelengths = {{"band1", 450.0}, {"band2", 550.0}, {"band3", 650.0}};
    const SpectralLayout m = FindSpectralLayout("m.exr", {"band3", "band1", "band2"}, {}, named);
    CHECK(m.wavelengths == std::vector<double>{450.0, 550.0, 650.0});
    CHECK(m.channels == std::vector<int>{1, 2, 0});
    named.namedWavelengths["band9"] = 700.0;
    CHECK_THROWS_WITH(FindSpectralLayout("m.exr", {"band3", "band1", "band2"}, {}, named),
                      Contains("m.exr: has no channel 'band9'"));

    // bandlight's band renders: buckets with the bands' edges.
    const SpectralLayout bands = FindSpectralLayout(
        "b.exr", {"B", "G", "R"}, {{"bandlight:bands", "B 400-500,G 500-600,R 600-700"}});
    CHECK(bands.sampling == SpectralSampling::BUCKETS);
    CHECK(bands.edges == std::vector<double>{400.0, 500.0, 600.0, 700.0});
    CHECK_THROWS_WITH(FindSpectralLayout("b.exr", {"B", "G", "R"},
                                         {{"bandlight:bands", "B 728-500,G 500-600,R 600-700"}}),
                      Contains("lists band 'B' as 728.000000-500.000000 nm: not an interval"));
    CHECK_THROWS_WITH(FindSpectralLayout("b.exr", {"B", "G"},
                                         {{"bandlight:bands", "B 400-500,G 500-600,R 600-700"}}),
                      Contains("lists 3 bands but the image has 2"));
}

TEST_CASE("A spectrum of constant value 1 integrates to Y = 1 on any grid", "[spectral]")
{
    // pbrt-v4's convention: XYZ = Σ L·cmf·Δλ / Σ ȳ·Δλ.
    for (const auto& [start, step, count] :
         {std::tuple{380.0, 5.0, 81}, std::tuple{360.0, 1.0, 471}, std::tuple{400.0, 10.0, 31}})
    {
        const SpectralLayout l =
            FindSpectralLayout("", Names(SpectralKind::EMISSIVE, start, step, count), {});
        for (const SpectralSampling s : {SpectralSampling::POINTS, SpectralSampling::BUCKETS})
        {
            SpectralLayout ls = l;
            ls.sampling = s;
            const Vec3 xyz =
                SpectralXyzWeights(ls, Observer::CIE1931_2DEG, {}) * Eigen::VectorXd::Ones(count);
            CHECK(xyz.y() == Approx(1.0).epsilon(1e-12));
        }
    }
}

TEST_CASE("A reflective image under a light equals the CIE's surface colour", "[spectral]")
{
    // CIE 15:2004 §7.1: X = k Σ S β x̄ Δλ, k = 100 / Σ S ȳ Δλ; on the
    // illuminant's own 5 nm grid the point weights are exactly that sum.
    const Spectrum d65 = BuiltinIlluminant("D65");
    const std::vector<NamedSpectrum>& tcs = TestColourSamples();
    const SpectralLayout l = FindSpectralLayout(
        "", Names(SpectralKind::REFLECTIVE, d65.start(), d65.step(), int(d65.size())), {});
    SpectralLighting lighting;
    lighting.to = d65;
    const auto w = SpectralXyzWeights(l, Observer::CIE1931_2DEG, lighting);
    for (const NamedSpectrum& s : tcs)
    {
        const Vec3 xyz =
            w * Values(l, [&](double nm) { return s.spectrum.extended(300, 830)(nm); });
        const Vec3 ref = SurfaceXyz(s.spectrum, d65, Observer::CIE1931_2DEG) / 100.0;
        CHECK((xyz - ref).cwiseAbs().maxCoeff() < 1e-12);
    }
    // A white reflector has Y = 1.
    CHECK((w * Eigen::VectorXd::Ones(Eigen::Index(l.wavelengths.size()))).y() ==
          Approx(1.0).epsilon(1e-12));
    CHECK_THROWS_WITH(SpectralXyzWeights(l, Observer::CIE1931_2DEG, {}),
                      Contains("needs the light to render it under"));
}

TEST_CASE("Relighting multiplies by S2/S1 and keeps a white reflector's Y", "[spectral]")
{
    const Spectrum a = BuiltinIlluminant("A");
    const Spectrum d65 = BuiltinIlluminant("D65");
    const SpectralLayout l =
        FindSpectralLayout("", Names(SpectralKind::EMISSIVE, 380.0, 5.0, 81), {});
    SpectralLighting lighting{a, d65};
    const auto w = SpectralXyzWeights(l, Observer::CIE1931_2DEG, lighting);
    const auto plain = SpectralXyzWeights(l, Observer::CIE1931_2DEG, {});
    // A surface under A, relit: the surface under D65 at A's luminance.
    for (const NamedSpectrum& s : TestColourSamples())
    {
        const Eigen::VectorXd underA = Values(l, [&](double nm) { return a(nm) * s.spectrum(nm); });
        const Eigen::VectorXd underD65 =
            Values(l, [&](double nm) { return d65(nm) * s.spectrum(nm); });
        const double white = (plain * Values(l, [&](double nm) { return a(nm); })).y() /
                             (plain * Values(l, [&](double nm) { return d65(nm); })).y();
        const Vec3 relit = w * underA;
        const Vec3 exact = plain * underD65 * white;
        CHECK((relit - exact).cwiseAbs().maxCoeff() < 1e-12 * std::max(1.0, exact.maxCoeff()));
    }
    const Eigen::VectorXd whiteA = Values(l, [&](double nm) { return a(nm); });
    CHECK((w * whiteA).y() == Approx((plain * whiteA).y()).epsilon(1e-12));
    // The relit white has D65's chromaticity.
    const Vec3 xyY = XyzToxyY(w * whiteA);
    const Vec3 d65xyY = XyzToxyY(IlluminantWhiteXyz(d65, Observer::CIE1931_2DEG));
    CHECK(xyY.x() == Approx(d65xyY.x()).margin(1e-4));
    CHECK(xyY.y() == Approx(d65xyY.y()).margin(1e-4));
    // S2 without S1 is refused.
    CHECK_THROWS_WITH(SpectralXyzWeights(l, Observer::CIE1931_2DEG, {Spectrum(), d65}),
                      Contains("needs the light it was lit by"));
}

TEST_CASE("Bucket weights integrate a spectrum constant within each bucket exactly", "[spectral]")
{
    // 16 buckets over 360–830 nm; the spectrum is the bucket value on each
    // bucket, so ∫ L·cmf is Σ v_b ∫_b cmf (the matching functions' linear
    // interpolant integrated exactly, here to 1e-6 by 0.1 nm trapezoids).
    std::vector<std::string> names;
    for (int i = 0; i < 16; ++i)
    {
        names.push_back(
            SpectralChannelName(SpectralKind::EMISSIVE, 360.0 + (i + 0.5) * 470.0 / 16));
    }
    SpectralLayoutOptions o;
    o.sampling = SpectralSampling::BUCKETS;
    const SpectralLayout l = FindSpectralLayout("", names, {}, o);
    const auto w = SpectralXyzWeights(l, Observer::CIE1931_2DEG, {});
    const MatchingFunctions& cmf = GetMatchingFunctions(Observer::CIE1931_2DEG);
    Eigen::VectorXd v(16);
    Vec3 exact = Vec3::Zero();
    for (int i = 0; i < 16; ++i)
    {
        v(i) = 0.5 + 0.4 * std::sin(i);
        const double a = 360.0 + i * 470.0 / 16, b = a + 470.0 / 16;
        exact += v(i) * Vec3(cmf.x.integrateLinear(a, b), cmf.y.integrateLinear(a, b),
                             cmf.z.integrateLinear(a, b));
    }
    exact /= cmf.y.integrateLinear(360.0, 830.0);
    CHECK(((w * v) - exact).cwiseAbs().maxCoeff() < 1e-5);
}

TEST_CASE("Channel wavelength files: pairs or sensitivities", "[spectral]")
{
    const std::string dir = BANDLIGHT_TEST_DATA;
    const auto pairs = ReadChannelWavelengths(dir + "/channel_wavelengths.csv");
    CHECK(pairs.at("band1_blue") == 450.0);
    CHECK(pairs.at("band3_red") == 650.0);
    const auto srf = ReadChannelWavelengths(dir + "/channel_sensitivities.csv");
    // Triangles symmetric about 450, 550 and 650 nm: the centroids.
    CHECK(srf.at("band1_blue") == Approx(450.0).epsilon(1e-12));
    CHECK(srf.at("band2_green") == Approx(550.0).epsilon(1e-12));
    CHECK_THROWS_WITH(ReadChannelWavelengths(dir + "/channel_wavelengths_bad.csv"),
                      Contains("channel_wavelengths_bad.csv:3: expected 'channel,wavelength_nm'"));
}
