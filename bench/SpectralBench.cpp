// SPDX-License-Identifier: BSD-3-Clause
// Cost of the spectral core's inner operations, per spectrum.
//   build/bench/bench_spectral --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/ColourFidelity.h"
#include "spectral/ColourRendering.h"
#include "spectral/Illuminants.h"
#include "spectral/LightScores.h"
#include "spectral/SpectralSimilarity.h"
#include "transforms/BandModel.h"

using namespace bandlight;

namespace
{
/// TCS01 on the 380–780 nm, 5 nm grid: 81 samples, the CIE's usual spectrum.
Spectrum Tcs01On81()
{
    return TestColourSamples()[0].spectrum.resampled(380.0, 5.0, 81);
}
}  // namespace

/// Fast path: XYZ of an 81-sample remittance under D65 as three dot products
/// with precomputed (illuminant × matching function) weights.
static void BM_XyzIntegrator81(benchmark::State& state)
{
    const Spectrum d65 = BuiltinIlluminant("D65").resampled(380.0, 5.0, 81);
    const XyzIntegrator integrate(d65, Observer::CIE1931_2DEG);
    const Spectrum r = Tcs01On81();
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(integrate.integrate(r.values().data()));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_XyzIntegrator81);

/// Reference path: the product spectrum and the interpolated matching functions
/// built for every call.
static void BM_SurfaceXyzReference81(benchmark::State& state)
{
    const Spectrum d65 = BuiltinIlluminant("D65").resampled(380.0, 5.0, 81);
    const Spectrum r = Tcs01On81();
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(SurfaceXyz(r, d65, Observer::CIE1931_2DEG));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SurfaceXyzReference81);

/// Emission spectrum → XYZ (unnormalised), 81 samples, interpolating the CMFs.
static void BM_IntegrateXyzEmission81(benchmark::State& state)
{
    const Spectrum d65 = BuiltinIlluminant("D65").resampled(380.0, 5.0, 81);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(IntegrateXyz(d65, Observer::CIE1931_2DEG));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_IntegrateXyzEmission81);

/// Band means of one 81-sample spectrum over the band model's three bands.
static void BM_BandMeansLecture(benchmark::State& state)
{
    const Spectrum r = Tcs01On81();
    const BandSet bands = BandSet::Lecture();
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(BandMeans(r, bands, BandRule::SAMPLE_MEAN));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BandMeansLecture);

static void BM_BandMeansExact(benchmark::State& state)
{
    const Spectrum r = Tcs01On81();
    const BandSet bands = BandSet::Lecture();
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(BandMeans(r, bands, BandRule::EXACT));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BandMeansExact);

static void BM_ColourRenderingIndex(benchmark::State& state)
{
    const Spectrum f2 = BuiltinIlluminant("F2");
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(ComputeColourRendering(f2));
    }
}
BENCHMARK(BM_ColourRenderingIndex);

/// CIE 224 / TM-30 figures of a light: `F2` as tabulated (5 nm, evaluated at
/// 5 nm) and the same light at 1 nm (401 samples, as measured lights are).
static void BM_ColourFidelity(benchmark::State& state)
{
    const Spectrum f2 = BuiltinIlluminant("F2");
    const Spectrum light = state.range(0) == 5 ? f2 : f2.resampled(380.0, 1.0, 401);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(ComputeColourFidelity(light));
    }
}
BENCHMARK(BM_ColourFidelity)->Arg(5)->Arg(1);

/// The Academy SSI of a 1 nm light against the default reference at its CCT.
static void BM_SpectralSimilarity(benchmark::State& state)
{
    const Spectrum light = BuiltinIlluminant("F2").resampled(380.0, 1.0, 401);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(ComputeSpectralSimilarity(light));
    }
}
BENCHMARK(BM_SpectralSimilarity);

/// Every score of the registry (`quality`: CCT, CRI, CIE 224, TM-30, SSI,
/// TLCI) of one light at 1 nm, as a spectrometer gives it.
static void BM_ScoreLight(benchmark::State& state)
{
    const Spectrum light = BuiltinIlluminant("F2").resampled(380.0, 1.0, 401);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(ScoreLight("F2", light));
    }
}
BENCHMARK(BM_ScoreLight);

BENCHMARK_MAIN();
