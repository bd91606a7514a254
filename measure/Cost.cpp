// SPDX-License-Identifier: BSD-3-Clause
#include "measure/Cost.h"

#include <algorithm>
#include <chrono>
#include <random>

#include "imaging/ImageApply.h"
#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"
#include "transforms/Defaults.h"
#include "transforms/PixelKernels.h"
#include "transforms/SurfaceRenderer.h"

namespace bandlight::jobs
{

namespace
{
using Clock = std::chrono::steady_clock;

template <typename F>
double BestSeconds(F&& f, int runs = 3)
{
    double best = 1e30;
    for (int i = 0; i < runs; ++i)
    {
        const auto t0 = Clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    return best;
}

std::vector<float> TestPixels(long pixels, int channels)
{
    std::vector<float> px(size_t(pixels) * size_t(channels));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f);
    for (float& v : px)
    {
        v = std::exp2(u(rng));
    }
    return px;
}

int AllThreads()
{
    return CoreCount();
}

Light L(const char* n)
{
    return {n, BuiltinIlluminant(n)};
}
}  // namespace

std::vector<CostRow> MeasureCost(const std::vector<std::string>& methods,
                                 const std::string& workingSpace, long pixels,
                                 const std::shared_ptr<const SpectralCamera>& camera,
                                 const Light& idtLight)
{
    const RgbSpace& ws = FindRgbSpace(workingSpace);
    std::vector<CostRow> rows;
    const std::vector<float> source = TestPixels(pixels, 4);
    const int rgb[3] = {0, 1, 2};
    for (const std::string& name : methods)
    {
        MethodSpec method = ParseMethod(name);
        if (method.entry().needsCamera && !camera)
        {
            continue;
        }
        method = WithCamera(std::move(method), camera, idtLight);
        if (method.entry().isReference())
        {
            // The exact answer needs a spectrum per pixel: 81 samples through
            // the 3 × 81 (illuminant × matching functions) weights, by the
            // kernel `spectral` integrates spectral images with (SpectralDot).
            const SurfaceRenderer r(BuiltinIlluminant("D65"), ws);
            const size_t k = SurfaceRenderer::kSamples;
            const long n = std::min<long>(pixels, 1 << 20);
            const std::vector<float> spectra = TestPixels(n, int(k));
            std::vector<float> weights(3 * k);
            for (size_t c = 0; c < 3; ++c)
            {
                for (size_t j = 0; j < k; ++j)
                {
                    weights[c * k + j] = float(r.matrix()(Eigen::Index(c), Eigen::Index(j)));
                }
            }
            for (int threads : {1, AllThreads()})
            {
                std::vector<float> out(3 * size_t(n));
                const double s = BestSeconds(
                    [&]
                    {
                        ParallelFor(size_t(n), threads,
                                    [&](size_t a, size_t b)
                                    {
                                        SpectralDot(weights.data(), k, spectra.data() + a * k,
                                                    b - a, k, out.data() + 3 * a, 3);
                                    });
                    });
                rows.push_back({name, CostForm::SPECTRAL, threads, s * 1e9 / double(n)});
            }
            continue;
        }
        // As a config's look: the LUT size configs use for non-linear methods.
        const OCIO::GroupTransformRcPtr t = IlluminantChangeTransform(
            L("A"), L("D65"), method, ws, Observer::CIE1931_2DEG, defaults::CONFIG_LUT_SIZE);
        const OCIO::ConstCPUProcessorRcPtr cpu =
            OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
                OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT);
        for (int threads : {1, AllThreads()})
        {
            std::vector<float> px = source;
            const double s = BestSeconds(
                [&] { ApplyToBuffer(cpu, px.data(), 1920, pixels / 1920, 4, rgb, threads); });
            rows.push_back({name, method.isLinear() ? CostForm::OCIO_MATRIX : CostForm::OCIO_LUT,
                            threads, s * 1e9 / double(pixels)});
        }
        if (const DirectForm form = method.entry().directForm; form != DirectForm::NONE)
        {
            const long n = std::min<long>(pixels, 20000);
            for (int threads : {1, AllThreads()})
            {
                // A Relighter of its own for each timing: upsample's fits are
                // shared by the live Relighters of one source light, and a
                // timing must not reuse the previous one's.
                const Relighter direct(L("A"), L("D65"), method, ws);
                std::vector<float> px(size_t(n) * 3);
                const double s = BestSeconds(
                    [&]
                    {
                        for (long i = 0; i < n; ++i)
                        {
                            std::copy_n(&source[size_t(i) * 4], 3, &px[size_t(i) * 3]);
                        }
                        direct.apply(px.data(), size_t(n), threads);
                    },
                    1);
                rows.push_back({name,
                                form == DirectForm::NATIVE ? CostForm::NATIVE
                                                           : CostForm::DIRECT_FIT,
                                threads, s * 1e9 / double(n)});
            }
        }
    }
    return rows;
}

std::string CostRow::formName() const
{
    switch (form)
    {
    case CostForm::OCIO_MATRIX:
        return "ocio-matrix";
    case CostForm::OCIO_LUT:
        return "ocio-lut" + std::to_string(defaults::CONFIG_LUT_SIZE);
    case CostForm::DIRECT_FIT:
        return "direct-fit";
    case CostForm::NATIVE:
        return "native";
    case CostForm::SPECTRAL:
        return "spectral-" + std::to_string(SurfaceRenderer::kSamples);
    }
    return "?";
}

std::vector<SetupCost> MeasureSetupCost(const std::string& workingSpace)
{
    const RgbSpace& ws = FindRgbSpace(workingSpace);
    std::vector<SetupCost> out;
    // Each method fitted on training remittances (by the first name of its
    // defaults): fitting one pair.
    for (const MethodEntry& e : Methods())
    {
        if (!e.defaultTraining || e.needsCamera || e.accuracyDefaults.empty())
        {
            continue;
        }
        const MethodSpec m = ParseMethod(e.accuracyDefaults.front());
        out.push_back({m.name + ": fitting one pair (" + std::to_string(TrainingOf(m).size()) +
                           " training remittances)",
                       BestSeconds([&] { Relighter(L("A"), L("D65"), m, ws); })});
    }
    // Each method whose ops fit every pixel (their fits shared per light):
    // baking a config's LUT, the one-off cost of its look.
    for (const MethodEntry& e : Methods())
    {
        if (!e.sharedPerLight || e.accuracyDefaults.empty())
        {
            continue;
        }
        const MethodSpec m = ParseMethod(e.accuracyDefaults.front());
        for (int size : {17, 33, 65})
        {
            // Fresh fits for each size (see MeasureCost).
            const Relighter op(L("A"), L("D65"), m, ws);
            out.push_back({m.name + ": baking a " + std::to_string(size) + "^3 LUT, all threads",
                           BestSeconds(
                               [&]
                               {
                                   BakeLattice([&](float* p, size_t n) { op.apply(p, n); },
                                               ShaperSpec::ForNonLinear(), size, true);
                               },
                               1)});
        }
    }
    return out;
}

}  // namespace bandlight::jobs
