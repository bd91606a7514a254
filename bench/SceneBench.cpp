// SPDX-License-Identifier: BSD-3-Clause
// Cost of rendering the band model's Phong scenes, per mode, and how it grows
// with lights, spectral samples and pixels.
//   build/bench/bench_scene
#include <benchmark/benchmark.h>

#include "render/SceneRenderer.h"
#include "spectral/Illuminants.h"

using namespace bandlight;

namespace
{
/// The band model's seven materials as spheres on a floor, `lights` point
/// lights of distinct spectra (so none is merged), 1920×1080 unless given.
Scene MaterialScene(int lights, RenderSettings::Mode mode, double step, int width = 1920,
                    int height = 1080)
{
    Scene s;
    s.camera.position = Vec3(0, 1.2, 7.5);
    s.camera.lookAt = Vec3(0, 0.2, 0);
    s.camera.width = width;
    s.camera.height = height;
    for (const std::string& n : LectureMaterialNames())
    {
        s.materials.push_back(LectureMaterial(n));
    }
    for (int i = 0; i < 7; ++i)
    {
        s.spheres.push_back({Vec3(-4.2 + 1.4 * i, 0.5, 0), 0.6, i});
    }
    s.planes.push_back({Vec3(0, -0.1, 0), Vec3(0, 1, 0), 4});
    const char* names[] = {"D65", "A", "F2", "F11", "D50", "F7", "C", "F4"};
    for (int i = 0; i < lights; ++i)
    {
        SceneLight l;
        l.spectrum = {names[i % 8], BuiltinIlluminant(names[i % 8]), {}};
        l.position = Vec3(-4.0 + 2.0 * i, 6, 6);
        l.intensity = 1.0 / lights;
        s.lights.push_back(l);
    }
    s.settings.mode = mode;
    s.settings.stepNm = step;
    return s;
}

void Render(benchmark::State& state, const Scene& s, bool planned)
{
    const ScenePlan plan = PlanScene(s);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(planned ? RenderScene(s, plan, 0) : RenderSceneUnplanned(s, 0));
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * s.camera.width * s.camera.height);
}
}  // namespace

/// Planned rendering, 1920×1080, one light: band3 against spectral (5 nm).
static void BM_RenderBand3(benchmark::State& state)
{
    Render(state, MaterialScene(1, RenderSettings::Mode::BAND, 0.0), true);
}
BENCHMARK(BM_RenderBand3)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_RenderSpectral(benchmark::State& state)
{
    Render(state, MaterialScene(1, RenderSettings::Mode::SPECTRAL, 5.0), true);
}
BENCHMARK(BM_RenderSpectral)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Cost against the number of lights (planned, spectral 5 nm).
static void BM_RenderLights(benchmark::State& state)
{
    Render(state, MaterialScene(int(state.range(0)), RenderSettings::Mode::SPECTRAL, 5.0), true);
}
BENCHMARK(BM_RenderLights)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Cost against spectral samples, 480×270: the literal path (per pixel, per
/// light, per sample; range(1) = 0) against the planned one (range(1) = 1).
static void BM_RenderSamples(benchmark::State& state)
{
    Render(state,
           MaterialScene(1, RenderSettings::Mode::SPECTRAL, double(state.range(0)), 480, 270),
           state.range(1) != 0);
}
BENCHMARK(BM_RenderSamples)
    ->ArgsProduct({{20, 10, 5, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Cost against pixels (planned, band3).
static void BM_RenderPixels(benchmark::State& state)
{
    const int w = int(state.range(0));
    Render(state, MaterialScene(1, RenderSettings::Mode::BAND, 0.0, w, w * 9 / 16), true);
}
BENCHMARK(BM_RenderPixels)
    ->Arg(480)
    ->Arg(960)
    ->Arg(1920)
    ->Arg(3840)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
