// SPDX-License-Identifier: BSD-3-Clause
// rootpoly-plate (transforms/methods/RootPolyPlate.cpp): a camera's plates
// under one light relit to that camera's plates under another. The plates
// are made here from the camera file, the lights and the remittances alone
// (raw = Σ sensitivity · light · remittance on the 5 nm grid, balanced,
// through the IDT), and the op is checked on them: white exact, exposure
// invariant, the identity between equal lights, never worse on its training
// plates than the plain least-squares root polynomial, better than
// rootpoly-camera at the camera's own plates on remittances it was not
// fitted on, and the IDT it is given honoured.
// Covers, through the entry points it calls: transforms/De00Fit.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "spectral/CameraFile.h"
#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "transforms/Camera.h"
#include "transforms/De00Fit.h"
#include "transforms/IlluminantChange.h"
#include "transforms/SurfaceRenderer.h"

using namespace bandlight;

namespace
{

const RgbSpace& Working()
{
    return FindRgbSpace("aces2065-1");
}

std::shared_ptr<const SpectralCamera> D21()
{
    static const auto camera = std::make_shared<const SpectralCamera>(
        ReadCameraFile(BANDLIGHT_TEST_DATA_ROOT "/rawtoaces/arri_d21_380_780_5.json"));
    return camera;
}

Light L(const char* name)
{
    return {name, BuiltinIlluminant(name)};
}

/// Lit plates of one camera with one fixed balance and IDT (those of
/// `idtLight`), each light brought to luminance 1 (CIE 1931 Y of the
/// perfect reflector on the 5 nm grid).
class CameraPlates
{
public:
    CameraPlates(const Spectrum& light, const Spectrum& idtLight, const Mat3& idt)
        : m_light(light), m_idt(idt)
    {
        m_gains = Raw(idtLight, Ones()).cwiseInverse();
        const Spectrum& y = GetMatchingFunctions(Observer::CIE1931_2DEG).y;
        for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
        {
            const double nm = SurfaceRenderer::Wavelength(i);
            m_luminance += y(nm) * light(nm);
        }
    }
    Vec3 operator()(const SurfaceRenderer::Samples& r) const
    {
        return m_idt * m_gains.cwiseProduct(Raw(m_light, r)) / m_luminance;
    }
    static SurfaceRenderer::Samples Ones() { return SurfaceRenderer::Samples::Ones(); }

private:
    static Vec3 Raw(const Spectrum& light, const SurfaceRenderer::Samples& r)
    {
        Vec3 raw = Vec3::Zero();
        for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
        {
            raw += D21()->sensitivities().col(i) * light(SurfaceRenderer::Wavelength(i)) * r(i);
        }
        return raw;
    }
    Spectrum m_light;
    Mat3 m_idt;
    Vec3 m_gains;
    double m_luminance = 0.0;
};

MethodSpec PlateMethod(const char* name, const Light& idtLight)
{
    MethodSpec m = WithCamera(ParseMethod(name), D21(), idtLight);
    m.plates = bandlight::Plates::Lit();
    return m;
}

double De00(const Vec3& rgb, const Vec3& reference, const Vec3& whiteRgb)
{
    const SurfaceRenderer eye(BuiltinIlluminant("D65"), Working());
    const Vec3 white = eye.rgbToXyz() * whiteRgb;
    return DeltaE2000(XyzToLab(eye.rgbToXyz() * rgb, white),
                      XyzToLab(eye.rgbToXyz() * reference, white));
}

}  // namespace

TEST_CASE("rootpoly-plate maps the camera's white exactly and is exposure invariant",
          "[transforms][methods]")
{
    const Light idtLight = L("D55");
    const Mat3 idt = FitIdt(*D21(), idtLight.spectrum, Working(), AdaptationMethod::CAT02);
    for (const auto& [from, to] : {std::pair{"F11", "D55"}, {"A", "D65"}, {"D65", "F2"}})
    {
        INFO(from << " -> " << to);
        const Relighter op(L(from), L(to), PlateMethod("rootpoly-plate", idtLight), Working());
        const CameraPlates under(BuiltinIlluminant(from), idtLight.spectrum, idt);
        const CameraPlates target(BuiltinIlluminant(to), idtLight.spectrum, idt);
        const Vec3 white = target(CameraPlates::Ones());
        CHECK((op.apply(under(CameraPlates::Ones())) - white).norm() < 1e-9 * white.norm());
        const Vec3 skin = under(SurfaceRenderer::Sample(Rawtoaces190().at(20).spectrum));
        for (const double k : {1e-3, 0.18, 40.0})
        {
            CHECK((op.apply(Vec3(k * skin)) - k * op.apply(skin)).norm() <
                  1e-9 * k * op.apply(skin).norm());
        }
    }
    // The same light on both sides: the plates are left as they are.
    const Relighter same(L("F11"), L("F11"), PlateMethod("rootpoly-plate", idtLight), Working());
    const CameraPlates f11(BuiltinIlluminant("F11"), idtLight.spectrum, idt);
    for (const NamedSpectrum& t : HeldOutTcs().samples)
    {
        const Vec3 p = f11(SurfaceRenderer::Sample(t.spectrum));
        CHECK((same.apply(p) - p).norm() < 1e-7 * p.norm());
    }
}

TEST_CASE(
    "rootpoly-plate fits the camera's own plates: no worse than least squares, better "
    "than rootpoly-camera there",
    "[transforms][methods]")
{
    const Light idtLight = L("D55");
    const Mat3 idt = FitIdt(*D21(), idtLight.spectrum, Working(), AdaptationMethod::CAT02);
    const CameraPlates under(BuiltinIlluminant("F11"), idtLight.spectrum, idt);
    const CameraPlates target(BuiltinIlluminant("D55"), idtLight.spectrum, idt);
    const Vec3 white = target(CameraPlates::Ones());
    const Relighter plate(L("F11"), L("D55"), PlateMethod("rootpoly-plate", idtLight), Working());
    const Relighter camera(L("F11"), L("D55"), PlateMethod("rootpoly-camera", idtLight), Working());
    // On its training plates (the 205 of rootpoly): the plain least-squares
    // root polynomial of the same plates, and no correction, as De00Fit
    // measures them.
    ColourFit data;
    for (const NamedSpectrum& t : RootPolynomialTraining())
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        data.input.push_back(under(r));
        data.target.push_back(target(r));
    }
    data.whiteIn = under(CameraPlates::Ones());
    data.whiteOut = white;
    data.rgbToXyz = SurfaceRenderer(BuiltinIlluminant("D55"), Working()).rgbToXyz();
    data.labWhite = data.rgbToXyz * white;
    De00FitFigures figures;
    FitRootPolynomialDe00(data, 2, &figures);
    double sum = 0.0;
    for (size_t i = 0; i < data.input.size(); ++i)
    {
        sum += De00(plate.apply(data.input[i]), data.target[i], white);
    }
    const double mean = sum / double(data.input.size());
    INFO("training: rootpoly-plate " << mean << ", plain least squares (white kept) "
                                     << figures.leastSquares.mean << ", none "
                                     << figures.before.mean);
    CHECK(mean == Approx(figures.after.mean).epsilon(1e-6));
    CHECK(mean <= figures.leastSquares.mean + 1e-12);
    CHECK(mean < 0.5 * figures.before.mean);
    // On remittances neither was fitted on (CIE 13.3's TCS09–14), against
    // the camera's own plates under the target: rootpoly-camera aims at the
    // observer's colours instead, so it is further from them.
    double plateSum = 0.0;
    double cameraSum = 0.0;
    for (const NamedSpectrum& t : HeldOutTcs().samples)
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        plateSum += De00(plate.apply(under(r)), target(r), white);
        cameraSum += De00(camera.apply(under(r)), target(r), white);
    }
    INFO("held out: rootpoly-plate " << plateSum << ", rootpoly-camera " << cameraSum);
    CHECK(plateSum < cameraSum);
}

TEST_CASE("rootpoly-plate reads the plates through the IDT it is given, and needs a camera",
          "[transforms][methods]")
{
    // Another IDT than bandlight's fit for the light: the plates as that
    // IDT makes them, white still exact.
    const Light idtLight = L("D55");
    Mat3 vendor;
    vendor << 0.9, 0.15, -0.05, 0.05, 1.0, -0.05, 0.0, -0.1, 1.1;
    MethodSpec m = PlateMethod("rootpoly3-plate", idtLight);
    m.idt = vendor;
    CHECK(m.degree == 3);
    const Relighter op(L("A"), L("D55"), m, Working());
    const CameraPlates under(BuiltinIlluminant("A"), idtLight.spectrum, vendor);
    const CameraPlates target(BuiltinIlluminant("D55"), idtLight.spectrum, vendor);
    const Vec3 white = target(CameraPlates::Ones());
    CHECK((op.apply(under(CameraPlates::Ones())) - white).norm() < 1e-9 * white.norm());
    CHECK(op.rootPolynomial()->degree() == 3);
    // Without a camera there are no plates to fit.
    CHECK_THROWS_WITH(Relighter(L("A"), L("D55"), ParseMethod("rootpoly-plate"), Working()),
                      Catch::Contains("camera"));
}
