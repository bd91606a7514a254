// SPDX-License-Identifier: BSD-3-Clause
// How close a shaper + 3D LUT comes to the exact transform it was baked from.
//   build/bench/lut_accuracy [--json]
// For lit and for white-balanced plates (the looks differ: a balanced band3
// look is not neutral, and its LUT errs differently). For greys from 1e-4 to 65504 and for random
// colours (each channel 0.2–1 of a level drawn log-uniformly from 1e-3 to 65504), the relative
// error max|lut - exact| / max|exact| per pixel: median, 95th percentile and max (nearest rank).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "luts/LutWriter.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"
#include "spectral/Statistics.h"

using namespace bandlight;

namespace
{
double Error(const OCIO::ConstCPUProcessorRcPtr& exact, const OCIO::ConstCPUProcessorRcPtr& lut,
             const float in[3])
{
    float a[3] = {in[0], in[1], in[2]}, b[3] = {in[0], in[1], in[2]};
    exact->applyRGB(a);
    lut->applyRGB(b);
    const double m = std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
    double e = 0.0;
    for (int c = 0; c < 3; ++c)
    {
        e = std::max(e, std::abs(double(a[c]) - double(b[c])) / m);
    }
    return e;
}

}  // namespace

int main(int argc, char** argv)
{
    const bool json = argc > 1 && std::strcmp(argv[1], "--json") == 0;
    if (argc > 2 || (argc == 2 && !json))
    {
        std::fprintf(stderr, "usage: lut_accuracy [--json]\n");
        return 2;
    }
    const OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateRaw();
    if (json)
    {
        std::printf("{\"rows\": [");
    }
    else
    {
        std::printf("%-24s %-8s %4s  %10s  %10s %10s %10s\n", "transform", "plates", "size",
                    "grey max", "col median", "col p95", "col max");
    }
    bool firstRow = true;
    for (const Plates& plates : {Plates::Lit(), Plates{}})
    {
        for (const char* method : {"bradford", "band3"})
        {
            for (const char* from : {"A", "F11"})
            {
                MethodSpec spec = ParseMethod(method);
                spec.plates = plates;
                const OCIO::GroupTransformRcPtr t = IlluminantChangeTransform(
                    {from, BuiltinIlluminant(from)}, {"D65", BuiltinIlluminant("D65")}, spec,
                    FindRgbSpace("acescg"));
                const auto exact = raw->getProcessor(t)->getDefaultCPUProcessor();
                for (int size : {17, 33, 65})
                {
                    const auto lut = raw->getProcessor(LatticeTransform(t, ShaperSpec(), size))
                                         ->getDefaultCPUProcessor();
                    double grey = 0.0;
                    for (double x = 1e-4; x <= 65504.0; x *= 1.01)
                    {
                        const float v[3] = {float(x), float(x), float(x)};
                        grey = std::max(grey, Error(exact, lut, v));
                    }
                    std::mt19937 rng(1);
                    std::uniform_real_distribution<double> u(0.0, 1.0);
                    std::vector<double> errors;
                    for (int i = 0; i < 20000; ++i)
                    {
                        const double level = 1e-3 * std::exp2(std::log2(65504.0 / 1e-3) * u(rng));
                        const float v[3] = {float(level * (0.2 + 0.8 * u(rng))),
                                            float(level * (0.2 + 0.8 * u(rng))),
                                            float(level * (0.2 + 0.8 * u(rng)))};
                        errors.push_back(Error(exact, lut, v));
                    }
                    const char* convention = plates.balanced() ? "balanced" : "lit";
                    if (json)
                    {
                        std::printf(
                            "%s\n  {\"method\": \"%s\", \"from\": \"%s\", \"to\": \"D65\", "
                            "\"plates\": \"%s\", \"size\": %d, \"grey_max\": %.3e, "
                            "\"median\": %.3e, \"p95\": %.3e, \"max\": %.3e}",
                            firstRow ? "" : ",", method, from, convention, size, grey,
                            Percentile(errors, 0.5), Percentile(errors, 0.95),
                            Percentile(errors, 1.0));
                        firstRow = false;
                        continue;
                    }
                    char name[64];
                    std::snprintf(name, sizeof name, "%s %s->D65", method, from);
                    std::printf("%-24s %-8s %4d  %10.2e  %10.2e %10.2e %10.2e\n", name, convention,
                                size, grey, Percentile(errors, 0.5), Percentile(errors, 0.95),
                                Percentile(errors, 1.0));
                }
            }
        }
    }
    if (json)
    {
        std::printf("\n]}\n");
    }
    return 0;
}
