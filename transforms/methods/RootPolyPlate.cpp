// SPDX-License-Identifier: BSD-3-Clause
// rootpoly-plate, rootpoly3-plate: root-polynomial regression (Finlayson,
// Mackiewicz & Hurlbert 2015) from a camera's plates under the source light
// to the same camera's plates under the target, both read through the
// camera's one IDT. rootpoly-camera relights plates to what the observer
// sees under the target; this method to what the camera records there, its
// own rendering (and its IDT's error) kept: the correction a plate shot
// under one light needs to match plates shot under another on the same
// camera — an LED wall's post-camera look (camera/Wall.h) is one. White
// maps exactly onto white; under that constraint the root polynomial of
// least mean ΔE00 on the training plates (FitRootPolynomialDe00: reweighted
// least squares, never worse there than the plain constrained fit).
//
// Plates: balanced, the camera white-balanced for the light it is under
// (the perfect reflector records 1, 1, 1 before the IDT); lit, balanced
// once for the IDT's light and each light at the same luminance (CIE Y of
// the perfect reflector on SurfaceRenderer's grid), so that the plates keep
// the lights' colour casts but not their levels.
#include <string>

#include "spectral/CieData.h"
#include "spectral/Illuminants.h"
#include "transforms/Camera.h"
#include "transforms/De00Fit.h"
#include "transforms/RootPolynomial.h"
#include "transforms/SurfaceRenderer.h"
#include "transforms/detail/MethodFits.h"
#include "transforms/methods/PixelOp.h"

namespace bandlight
{

namespace
{

bool Parse(const std::string& name, MethodSpec& spec)
{
    for (const int degree : {2, 3})
    {
        const std::string numbered = "rootpoly" + std::to_string(degree) + "-plate";
        if (name == numbered || (degree == 2 && name == "rootpoly-plate"))
        {
            spec.degree = degree;
            spec.name = degree == 3 ? numbered : "rootpoly-plate";
            return true;
        }
    }
    return false;
}

std::string Describe(const MethodSpec& m)
{
    return std::string("For plates of camera ") + (m.camera ? m.camera->name() : "(none)") +
           " read through one " + (m.idt ? "given" : m.idtLightName) +
           " IDT: a root polynomial of degree " + (m.degree == 3 ? "3" : "2") +
           " from the camera's plates under the source light to its plates under the target "
           "(the camera's rendering kept, not the observer's), exact on white, of least mean dE00 "
           "on " +
           std::to_string(TrainingOf(m).size()) +
           " measured remittances: not linear, baked into a 3D LUT with a log2 shaper.";
}

/// The luminance of a light on the renderer's grid: ȳ · light, the light
/// sampled as CameraShot samples it (zero outside its data).
double GridLuminance(const Spectrum& light, Observer observer)
{
    const Spectrum& y = GetMatchingFunctions(observer).y;
    double sum = 0.0;
    for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
    {
        const double nm = SurfaceRenderer::Wavelength(i);
        sum += y(nm) * light(nm);
    }
    return sum;
}

/// Balanced camera RGB of remittances under one light, in the plate
/// convention of `balanced`: the light's own balance, or the fixed one
/// (`fixedGains`) with the light at luminance 1.
class PlateCamera
{
public:
    PlateCamera(const SpectralCamera& camera, const Spectrum& light, bool balanced,
                const Vec3& fixedGains, Observer observer)
        : m_shot(camera, light)
    {
        m_scale =
            balanced
                ? Vec3::Ones()
                : Vec3(fixedGains.cwiseQuotient(m_shot.gains()) / GridLuminance(light, observer));
    }
    Vec3 record(const SurfaceRenderer::Samples& r) const
    {
        return m_scale.cwiseProduct(m_shot.record(r));
    }
    /// The perfect white reflector.
    Vec3 white() const { return m_scale; }

private:
    CameraShot m_shot;
    Vec3 m_scale;
};

std::unique_ptr<PixelOp> MakeOp(const Light& from, const Light& to, const MethodSpec& method,
                                const RgbSpace& working, Observer observer)
{
    RequireCamera(method);
    const SpectralCamera& camera = *method.camera;
    const Spectrum idtLight =
        method.idtLight.empty() ? BuiltinIlluminant(method.idtLightName) : method.idtLight;
    const Mat3 idt = method.idt
                         ? *method.idt
                         : FitIdt(camera, idtLight, working, method.plates.adaptation, observer);
    const bool balanced = method.plates.balanced();
    const Vec3 fixedGains = CameraShot(camera, idtLight).gains();
    const PlateCamera under(camera, from.spectrum, balanced, fixedGains, observer);
    const PlateCamera target(camera, to.spectrum, balanced, fixedGains, observer);
    const SurfaceRenderer eye(to.spectrum, working, observer);
    ColourFit fit;
    for (const NamedSpectrum& t : TrainingOf(method))
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        fit.input.push_back(idt * under.record(r));
        fit.target.push_back(idt * target.record(r));
    }
    fit.whiteIn = idt * under.white();
    fit.whiteOut = idt * target.white();
    fit.rgbToXyz = eye.rgbToXyz();
    // The data at the target white's Y = 1, where the fits are conditioned
    // as for every other method: a root polynomial is homogeneous of degree
    // one, so its map is the same at any common scale.
    const double scale = 1.0 / (fit.rgbToXyz * fit.whiteOut).y();
    for (size_t i = 0; i < fit.input.size(); ++i)
    {
        fit.input[i] *= scale;
        fit.target[i] *= scale;
    }
    fit.whiteIn *= scale;
    fit.whiteOut *= scale;
    fit.labWhite = fit.rgbToXyz * fit.whiteOut;
    const RootPolynomial plate = FitRootPolynomialDe00(fit, method.degree);
    return detail::RootPolynomialOp(method.degree, plate.matrix());
}

}  // namespace

MethodEntry RootPolyPlateMethod(ChangeMethod key)
{
    MethodEntry e;
    e.methods = {key};
    e.syntax = "rootpoly-plate, rootpoly3-plate";
    e.exactness = MethodExactness::NONLINEAR;
    e.parse = &Parse;
    e.describe = &Describe;
    e.makeOp = &MakeOp;
    e.native = true;
    e.directForm = DirectForm::NATIVE;
    e.defaultTraining = &RootPolynomialTraining;
    e.takesTraining = true;
    e.needsCamera = true;
    e.wallLookDefaults = {"rootpoly-plate"};
    return e;
}

}  // namespace bandlight
