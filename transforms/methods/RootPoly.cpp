// SPDX-License-Identifier: BSD-3-Clause
// rootpoly, rootpoly3 and their camera forms: root-polynomial regression
// (Finlayson, Mackiewicz & Hurlbert 2015) fitted on measured remittances,
// applied by bandlight's own SIMD kernel (transforms/PixelKernels.h).
#include <cstring>
#include <utility>

#include <Eigen/LU>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"
#include "transforms/Idt.h"
#include "transforms/PixelKernels.h"
#include "transforms/RootPolynomial.h"
#include "transforms/detail/MethodFits.h"
#include "transforms/methods/PixelOp.h"

namespace bandlight
{

namespace
{

class RootPoly final : public PixelOp
{
public:
    RootPoly(int degree, Eigen::MatrixXd matrix, bool hasIn, const Mat3& in)
        : m_rootpoly(degree, std::move(matrix))
    {
        hasInput = hasIn;
        input = in;
        // The kernel's form: the input matrix folded in as its input step.
        for (int r = 0; r < 3; ++r)
        {
            for (int c = 0; c < 3; ++c)
            {
                m_kernel.input.m[3 * r + c] = float(input(r, c));
            }
        }
        m_kernel.hasInput = hasInput;
        m_kernel.degree = m_rootpoly.degree();
        std::memcpy(m_kernel.coefficients, m_rootpoly.floats(), sizeof m_kernel.coefficients);
    }

    Vec3 apply(const Vec3& in) const override { return m_rootpoly.apply(in); }

    void applyAfterInput(float* rgb, size_t count, int threads) const override
    {
        // A few ns a pixel: the vectorised root polynomial.
        ParallelFor(count, count < 65536 ? 1 : threads,
                    [&](size_t begin, size_t end)
                    { m_rootpoly.apply(rgb + 3 * begin, end - begin); });
    }

    bool applyWhole(float* pixels, size_t count, size_t stride, int threads) const override
    {
        ParallelFor(count, count < 65536 ? 1 : threads,
                    [&](size_t begin, size_t end)
                    { RootPolyPixels(m_kernel, pixels + begin * stride, end - begin, stride); });
        return true;
    }

    const RootPolynomial* rootPolynomial() const override { return &m_rootpoly; }

private:
    RootPolynomial m_rootpoly;
    RootPolyKernelData m_kernel;
};

}  // namespace

namespace detail
{

std::unique_ptr<PixelOp> RootPolynomialOp(int degree, Eigen::MatrixXd matrix, const Mat3* input)
{
    return std::make_unique<RootPoly>(degree, std::move(matrix), input != nullptr,
                                      input ? *input : Mat3::Identity());
}

std::unique_ptr<PixelOp> RootPolyOp(const Light& from, const Light& to, const MethodSpec& method,
                                    const RgbSpace& working, Observer observer)
{
    const PlateBalance balance = BalanceOf(from, to, method, working, observer);
    const SurfaceRenderer r1(from.spectrum, working, observer);
    const SurfaceRenderer r2(to.spectrum, working, observer);
    const RootPolynomial lit = FitRootPolynomial(r1, r2, TrainingOf(method), method.degree);
    return std::make_unique<RootPoly>(method.degree, balance.to * lit.matrix(), balance.balanced,
                                      balance.from.inverse());
}

std::unique_ptr<PixelOp> RootPolyCameraOp(const Light& from, const Light& to,
                                          const MethodSpec& method, const RgbSpace& working,
                                          Observer observer)
{
    RequireCamera(method);
    const PlateBalance balance = BalanceOf(from, to, method, working, observer);
    const AdaptationMethod adaptation = method.plates.adaptation;
    const SurfaceRenderer r2(to.spectrum, working, observer);
    // The plates: camera RGB balanced for `from` by gains, through one IDT
    // fitted for the daylight. Back through that IDT to the camera's
    // balanced record, then to the colour under `from` as the camera's own
    // IDT for `from` sees it (for the observer as camera, exactly the plain
    // path's input); the root polynomial, fitted from those records to the
    // truth under `to`, corrects the rest.
    const Spectrum daylight =
        method.idtLight.empty() ? BuiltinIlluminant(method.idtLightName) : method.idtLight;
    const SpectralCamera& camera = *method.camera;
    const Mat3 idtDaylight =
        method.idt ? *method.idt : FitIdt(camera, daylight, working, adaptation, observer);
    const Mat3 cameraLit = BalanceMatrix(from.spectrum, working, adaptation, observer).inverse() *
                           FitIdt(camera, from.spectrum, working, adaptation, observer);
    const CameraShot shot(camera, from.spectrum);
    ColourFit fit;
    for (const NamedSpectrum& t : TrainingOf(method))
    {
        const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
        fit.input.push_back(cameraLit * shot.record(r));
        fit.target.push_back(r2.render(r));
    }
    fit.whiteIn = cameraLit * Vec3::Ones();
    fit.whiteOut = r2.white();
    fit.rgbToXyz = r2.rgbToXyz();
    fit.labWhite = r2.rgbToXyz() * r2.white();
    const RootPolynomial lit = FitRootPolynomial(fit, method.degree);
    // Lit plates are the balanced ones with the cast put back.
    const Mat3 plateToBalanced =
        balance.balanced ? Mat3::Identity()
                         : BalanceMatrix(from.spectrum, working, adaptation, observer);
    return std::make_unique<RootPoly>(method.degree, balance.to * lit.matrix(), true,
                                      cameraLit * idtDaylight.inverse() * plateToBalanced);
}

}  // namespace detail

}  // namespace bandlight
