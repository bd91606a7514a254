// SPDX-License-Identifier: BSD-3-Clause
// In-process cost of applying an illuminant change to a UHD float RGBA image,
// against a plain copy of the same buffer (the memory-bandwidth ceiling).
//   build/bench/bench_apply --benchmark_min_time=1
#include <cstring>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "cli/ImageApply.h"
#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"

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
    const auto cpu = Processor(false);
    std::vector<float> px = Image();
    const int rgb[3] = {0, 1, 2};
    for (auto _ : state)
    {
        cli::ApplyToBuffer(cpu, px.data(), kWidth, kHeight, 4, rgb, int(state.range(0)));
        benchmark::ClobberMemory();
    }
    Report(state);
}
BENCHMARK(BM_ApplyMatrix)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The same as a 33³ LUT with the log2 shaper (shaper, tetrahedral 3D LUT, inverse shaper).
static void BM_ApplyLattice33(benchmark::State& state)
{
    const auto cpu = Processor(true);
    std::vector<float> px = Image();
    const int rgb[3] = {0, 1, 2};
    for (auto _ : state)
    {
        cli::ApplyToBuffer(cpu, px.data(), kWidth, kHeight, 4, rgb, int(state.range(0)));
        benchmark::ClobberMemory();
    }
    Report(state);
}
BENCHMARK(BM_ApplyLattice33)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
