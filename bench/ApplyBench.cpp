// SPDX-License-Identifier: BSD-3-Clause
// In-process cost of applying an illuminant change to a UHD float RGBA image,
// against a plain copy of the same buffer (the memory-bandwidth ceiling).
//   build/bench/bench_apply --benchmark_min_time=1
#include <cstdint>
#include <cstring>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "imaging/ImageApply.h"
#include "jobs/SpectralJob.h"
#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"
#include "spectral/SpectralImage.h"
#include "transforms/IlluminantChange.h"
#include "transforms/PixelKernels.h"
#include "transforms/SurfaceRenderer.h"

using namespace bandlight;

namespace
{
constexpr long kWidth = 3840;
constexpr long kHeight = 2160;
constexpr size_t kFloats = size_t(kWidth) * size_t(kHeight) * 4;

std::vector<float>& Image()
{
    static std::vector<float> px = []
    {
        std::vector<float> v(kFloats);
        for (size_t i = 0; i < v.size(); ++i)
        {
            v[i] = float((i * 2654435761u) % 1000u) * 0.01f;
        }
        return v;
    }();
    return px;
}

OCIO::ConstCPUProcessorRcPtr Processor(bool lattice)
{
    OCIO::GroupTransformRcPtr t =
        IlluminantChangeTransform({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")},
                                  ParseMethod("band3"), FindRgbSpace("acescg"));
    OCIO::ConstTransformRcPtr use = t;
    if (lattice)
    {
        use = LatticeTransform(t, ShaperSpec(), 33);
    }
    return OCIO::Config::CreateRaw()->getProcessor(use)->getOptimizedCPUProcessor(
        OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT);
}

void Report(benchmark::State& state);

/// Applies `cpu` to the UHD image on state.range(0) threads, per iteration.
void ApplyImage(benchmark::State& state, const OCIO::ConstCPUProcessorRcPtr& cpu)
{
    std::vector<float> px = Image();
    const int rgb[3] = {0, 1, 2};
    for (auto _ : state)
    {
        jobs::ApplyToBuffer(cpu, px.data(), kWidth, kHeight, 4, rgb, int(state.range(0)));
        benchmark::ClobberMemory();
    }
    Report(state);
}

void Report(benchmark::State& state)
{
    state.SetItemsProcessed(int64_t(state.iterations()) * kWidth * kHeight);
    // Read and write of every byte, as a copy does.
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kFloats * sizeof(float)) * 2);
}
}  // namespace

/// The ceiling: copying the image once (read + write).
static void BM_Memcpy(benchmark::State& state)
{
    std::vector<float>& src = Image();
    std::vector<float> dst(kFloats);
    const int threads = int(state.range(0));
    for (auto _ : state)
    {
        std::vector<std::thread> pool;
        const size_t chunk = kFloats / size_t(threads);
        for (int t = 0; t < threads; ++t)
        {
            pool.emplace_back(
                [&, t]
                {
                    std::memcpy(dst.data() + chunk * size_t(t), src.data() + chunk * size_t(t),
                                chunk * sizeof(float));
                });
        }
        for (auto& th : pool)
        {
            th.join();
        }
        benchmark::ClobberMemory();
    }
    Report(state);
}
BENCHMARK(BM_Memcpy)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The band3 A → D65 look as OCIO applies it: one 3×3 matrix per pixel.
static void BM_ApplyMatrix(benchmark::State& state)
{
    ApplyImage(state, Processor(false));
}
BENCHMARK(BM_ApplyMatrix)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The same as a 33³ LUT with the log2 shaper (shaper, tetrahedral 3D LUT, inverse shaper).
static void BM_ApplyLattice33(benchmark::State& state)
{
    ApplyImage(state, Processor(true));
}
BENCHMARK(BM_ApplyLattice33)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// A UHD float image of `channels` channels, filled once.
std::vector<float>& UhdImage(size_t channels)
{
    static std::vector<float> rgb, rgba;
    std::vector<float>& v = channels == 3 ? rgb : rgba;
    if (v.empty())
    {
        v.resize(size_t(kWidth) * size_t(kHeight) * channels);
        for (size_t i = 0; i < v.size(); ++i)
        {
            v[i] = float((i * 2654435761u) % 1000u) * 0.001f;
        }
    }
    return v;
}

/// The ceiling for the native kernels: copying the same UHD buffer (3 or
/// 4 channels) on state.range(0) threads, in the same run.
static void CopyUhd(benchmark::State& state, size_t channels)
{
    const std::vector<float>& src = UhdImage(channels);
    std::vector<float> dst(src.size());
    const size_t threads = size_t(state.range(0));
    for (auto _ : state)
    {
        std::vector<std::thread> pool;
        const size_t chunk = src.size() / threads;
        for (size_t t = 0; t < threads; ++t)
        {
            pool.emplace_back([&, t] { std::memcpy(&dst[chunk * t], &src[chunk * t], chunk * 4); });
        }
        for (auto& th : pool)
        {
            th.join();
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * kWidth * kHeight);
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(src.size()) * 4 * 2);
}
static void BM_CopyUhdRgb(benchmark::State& state)
{
    CopyUhd(state, 3);
}
BENCHMARK(BM_CopyUhdRgb)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
static void BM_CopyUhdRgba(benchmark::State& state)
{
    CopyUhd(state, 4);
}
BENCHMARK(BM_CopyUhdRgba)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// A method applied natively (Relighter::apply: the SIMD kernel chosen for
/// this CPU, in place) to the UHD float image of `channels` channels, on
/// state.range(0) threads.
static void ApplyNative(benchmark::State& state, const char* method, bool balanced,
                        size_t channels = 3)
{
    MethodSpec spec = ParseMethod(method);
    spec.plates = balanced ? ParsePlates("balanced", "cat02") : Plates::Lit();
    const Relighter r({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}, spec,
                      FindRgbSpace("acescg"));
    std::vector<float> px = UhdImage(channels);
    const size_t pixels = size_t(kWidth) * size_t(kHeight);
    for (auto _ : state)
    {
        r.apply(px.data(), pixels, channels, int(state.range(0)));
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(pixels));
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(px.size()) * 4 * 2);
    state.SetLabel(PixelKernelTarget());
}

/// rootpoly applied natively (what `bandlight apply --method rootpoly` and
/// the C++ API do): the guard and the degree-2 root polynomial.
static void BM_NativeRootPoly(benchmark::State& state)
{
    ApplyNative(state, "rootpoly", false);
}
BENCHMARK(BM_NativeRootPoly)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The same for white-balanced plates: the inverse balance (one more 3×3)
/// in front; the balance for the target is folded into the polynomial.
static void BM_NativeRootPolyBalanced(benchmark::State& state)
{
    ApplyNative(state, "rootpoly", true);
}
BENCHMARK(BM_NativeRootPolyBalanced)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Degree 3: three cube roots (Newton in float) and 13 terms.
static void BM_NativeRootPoly3(benchmark::State& state)
{
    ApplyNative(state, "rootpoly3", false);
}
BENCHMARK(BM_NativeRootPoly3)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The guarded 3×3 (bradford), RGB and RGBA.
static void BM_NativeMatrixRgb(benchmark::State& state)
{
    ApplyNative(state, "bradford", false);
}
BENCHMARK(BM_NativeMatrixRgb)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
static void BM_NativeMatrixRgba(benchmark::State& state)
{
    ApplyNative(state, "bradford", false, 4);
}
BENCHMARK(BM_NativeMatrixRgba)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// rootpoly as a config's look: log2 shaper, 65³ LUT, inverse shaper.
static void BM_ApplyRootPolyLut65(benchmark::State& state)
{
    const OCIO::GroupTransformRcPtr t = IlluminantChangeTransform(
        {"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}, ParseMethod("rootpoly"),
        FindRgbSpace("acescg"), Observer::CIE1931_2DEG, 65);
    ApplyImage(state, OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
                          OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT));
}
BENCHMARK(BM_ApplyRootPolyLut65)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// upsample as applied to images: log2 shaper, 33³ LUT baked from the
/// per-pixel spectral fit, inverse shaper.
static void BM_ApplyUpsampleLut33(benchmark::State& state)
{
    const OCIO::GroupTransformRcPtr t =
        IlluminantChangeTransform({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")},
                                  ParseMethod("upsample"), FindRgbSpace("acescg"));
    ApplyImage(state, OCIO::Config::CreateRaw()->getProcessor(t)->getOptimizedCPUProcessor(
                          OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_DEFAULT));
}
BENCHMARK(BM_ApplyUpsampleLut33)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// upsample's per-pixel fit itself (what the LUT saves), on 20000 pixels.
static void BM_UpsampleDirectFit(benchmark::State& state)
{
    const Relighter relight({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")},
                            ParseMethod("upsample"), FindRgbSpace("acescg"));
    std::vector<float> src(20000 * 3);
    for (size_t i = 0; i < src.size(); ++i)
    {
        src[i] = 0.05f + 0.9f * float((i * 2654435761u) % 1000u) / 1000.0f;
    }
    for (auto _ : state)
    {
        std::vector<float> px = src;
        relight.apply(px.data(), 20000, int(state.range(0)));
        benchmark::DoNotOptimize(px.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * 20000);
}
BENCHMARK(BM_UpsampleDirectFit)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The exact answer for a spectral image: 81 samples per pixel through the
/// 3 × 81 (illuminant × matching functions) weights, 1 Mpixel.
static void BM_SpectralIntegration81(benchmark::State& state)
{
    const SurfaceRenderer r(BuiltinIlluminant("D65"), FindRgbSpace("acescg"));
    const Eigen::Matrix<float, 3, SurfaceRenderer::kSamples> a = r.matrix().cast<float>();
    const long n = 1 << 20;
    const Eigen::MatrixXf spectra = Eigen::MatrixXf::Random(SurfaceRenderer::kSamples, n);
    Eigen::MatrixXf out(3, n);
    for (auto _ : state)
    {
        out.noalias() = a * spectra;
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
}
BENCHMARK(BM_SpectralIntegration81)->Unit(benchmark::kMillisecond)->UseRealTime();

/// A spectral image in memory as `bandlight spectral` holds it: 1280×720
/// pixels of R, G, B, A and 81 radiance samples (380–780 nm at 5 nm),
/// 85 floats a pixel, 313 MB.
constexpr size_t kSpectralPixels = 1280 * 720;
constexpr size_t kSpectralChannels = 85;
std::vector<float>& SpectralImageBuffer()
{
    static std::vector<float> v = []
    {
        std::vector<float> px(kSpectralPixels * kSpectralChannels);
        for (size_t i = 0; i < px.size(); ++i)
        {
            px[i] = float((i * 2654435761u) % 1000u) * 0.001f;
        }
        return px;
    }();
    return v;
}

void ReportSpectral(benchmark::State& state)
{
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(kSpectralPixels));
    state.SetBytesProcessed(int64_t(state.iterations()) *
                            int64_t(kSpectralPixels * kSpectralChannels * sizeof(float)));
}

/// The read bandwidth: every byte of the spectral image read once, on
/// state.range(0) threads. Its bits are XORed into four 16-byte vectors
/// (integer operations, so no rounding order holds the compiler back, and
/// four independent chains so no latency does): one load and one XOR per 16
/// bytes, far below what memory can deliver, so what this measures is the
/// memory. (A float sum in an array of 16, as this once was, compiled to
/// scalar adds with a store each: a third of the read speed on some machines.)
static void BM_SpectralReadOnly(benchmark::State& state)
{
    using V = std::uint64_t __attribute__((vector_size(16)));
    const std::vector<float>& src = SpectralImageBuffer();
    const size_t threads = size_t(state.range(0));
    const size_t blocks = src.size() * sizeof(float) / 64;
    const char* bytes = reinterpret_cast<const char*>(src.data());
    for (auto _ : state)
    {
        ParallelFor(blocks, int(threads),
                    [&](size_t a, size_t b)
                    {
                        const auto load = [](const char* p)
                        {
                            V v;
                            std::memcpy(&v, p, sizeof v);
                            return v;
                        };
                        V a0 = {}, a1 = {}, a2 = {}, a3 = {};
                        for (size_t i = a; i < b; ++i)
                        {
                            const char* p = bytes + 64 * i;
                            a0 ^= load(p);
                            a1 ^= load(p + 16);
                            a2 ^= load(p + 32);
                            a3 ^= load(p + 48);
                        }
                        V all = a0 ^ a1 ^ a2 ^ a3;
                        benchmark::DoNotOptimize(all);
                    });
        benchmark::ClobberMemory();
    }
    ReportSpectral(state);
}
BENCHMARK(BM_SpectralReadOnly)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// A copy of the same bytes (read + write), as the other kernels compare with.
static void BM_SpectralCopy(benchmark::State& state)
{
    const std::vector<float>& src = SpectralImageBuffer();
    std::vector<float> dst(src.size());
    const size_t threads = size_t(state.range(0));
    for (auto _ : state)
    {
        ParallelFor(src.size(), int(threads),
                    [&](size_t a, size_t b)
                    { std::memcpy(&dst[a], &src[a], (b - a) * sizeof(float)); });
        benchmark::ClobberMemory();
    }
    ReportSpectral(state);
}
BENCHMARK(BM_SpectralCopy)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// `bandlight spectral`'s integration: A → D65 relit, balanced, into
/// ACEScg: one SIMD dot product of 81 samples per output channel and pixel.
static void BM_SpectralIntegrate(benchmark::State& state)
{
    const std::vector<float>& src = SpectralImageBuffer();
    std::vector<std::string> names = {"A", "B", "G", "R"};
    for (int i = 0; i < 81; ++i)
    {
        names.push_back(SpectralChannelName(SpectralKind::EMISSIVE, 380.0 + 5.0 * i));
    }
    jobs::SpectralOptions o;
    o.from = {"A", BuiltinIlluminant("A")};
    o.to = {"D65", BuiltinIlluminant("D65")};
    const jobs::SpectralConversion c = jobs::MakeSpectralConversion(
        FindSpectralLayout("bench", names, {}), int(kSpectralChannels), o);
    std::vector<float> rgb(3 * kSpectralPixels);
    for (auto _ : state)
    {
        jobs::IntegrateSpectralPixels(c, src.data(), kSpectralPixels, int(kSpectralChannels),
                                      rgb.data(), int(state.range(0)));
        benchmark::ClobberMemory();
    }
    ReportSpectral(state);
}
BENCHMARK(BM_SpectralIntegrate)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// One-off: baking upsample's LUT (all threads).
static void BM_BakeUpsampleLut(benchmark::State& state)
{
    const Relighter relight({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")},
                            ParseMethod("upsample"), FindRgbSpace("acescg"));
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(BakeLattice([&](float* p, size_t n) { relight.apply(p, n); },
                                             ShaperSpec::ForNonLinear(), int(state.range(0)),
                                             true));
    }
}
BENCHMARK(BM_BakeUpsampleLut)
    ->Arg(17)
    ->Arg(33)
    ->Arg(65)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
