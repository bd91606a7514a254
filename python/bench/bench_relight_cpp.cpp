// SPDX-License-Identifier: BSD-3-Clause
// The C++ side of python/bench/bench_relight.py: Relighter::apply (the C++ API)
// on a packed 3840×2160 float RGB buffer in place, the pixels of
// bench/ApplyBench.cpp, reset before each timed run; prints the median
// ns/pixel. python/bench/bench_relight.py times bandlight.Relighter.apply on the
// same buffer and runs this program beside it.
//   bench_relight_cpp [METHOD [THREADS [RUNS]]]     (band3 1 7)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "spectral/Illuminants.h"
#include "transforms/IlluminantChange.h"

int main(int argc, char** argv)
{
    using namespace bandlight;
    const std::string method = argc > 1 ? argv[1] : "band3";
    const int threads = argc > 2 ? std::atoi(argv[2]) : 1;
    const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 7;
    constexpr size_t kPixels = size_t(3840) * 2160;
    try
    {
        // Lit plates, as the Python side asks for them (plates="lit").
        MethodSpec spec = ParseMethod(method);
        spec.plates = Plates::Lit();
        const Relighter r({"A", BuiltinIlluminant("A")}, {"D65", BuiltinIlluminant("D65")}, spec,
                          FindRgbSpace("acescg"));
        std::vector<float> pristine(3 * kPixels);
        for (size_t i = 0; i < pristine.size(); ++i)
        {
            pristine[i] = float((i * 2654435761u) % 1000u) * 0.001f;
        }
        std::vector<float> px(pristine.size());
        std::vector<double> ns;
        for (int run = 0; run < runs; ++run)
        {
            px = pristine;
            const auto t0 = std::chrono::steady_clock::now();
            r.apply(px.data(), kPixels, threads);
            const auto t1 = std::chrono::steady_clock::now();
            ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() /
                         double(kPixels));
        }
        std::sort(ns.begin(), ns.end());
        // A checksum keeps the work observable (and lets the Python side
        // confirm it computed the same pixels).
        double sum = 0.0;
        for (size_t i = 0; i < px.size(); i += 4099)
        {
            sum += px[i];
        }
        std::printf("cpp method=%s threads=%d pixels=%zu ns_per_pixel=%.3f checksum=%.6f\n",
                    method.c_str(), threads, kPixels, ns[ns.size() / 2], sum);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "bench_relight_cpp: %s\n", e.what());
        return 2;
    }
    return 0;
}
