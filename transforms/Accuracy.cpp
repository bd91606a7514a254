// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/Accuracy.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "spectral/Illuminants.h"
#include "spectral/Parallel.h"

namespace bandlight
{

AccuracyOptions DefaultAccuracyOptions()
{
    AccuracyOptions o;
    for (const char* n : {"A", "C", "D50", "D65", "E", "F1", "F2", "F3", "F4", "F5", "F6", "F7",
                          "F8", "F9", "F10", "F11", "F12"})
    {
        o.lights.push_back({n, BuiltinIlluminant(n)});
    }
    o.methods = AllMethodNames();
    o.sets = {AllTcs(), HeldOutTcs(), RandomSmoothSet(100, 2, "random")};
    return o;
}

double Percentile(std::vector<double> values, double p)
{
    if (values.empty())
    {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    const size_t rank = size_t(std::ceil(p * double(values.size())));
    return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

std::vector<AccuracyRow> MeasureAccuracy(const AccuracyOptions& o,
                                         const std::function<void(double)>& progress)
{
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        methods.push_back(ParseMethod(m));
    }
    struct Pair
    {
        size_t from, to;
    };
    std::vector<Pair> pairs;
    for (size_t i = 0; i < o.lights.size(); ++i)
    {
        for (size_t j = 0; j < o.lights.size(); ++j)
        {
            if (i != j)
            {
                pairs.push_back({i, j});
            }
        }
    }
    // Remittances sampled once.
    std::vector<std::vector<SurfaceRenderer::Samples>> samples(o.sets.size());
    for (size_t s = 0; s < o.sets.size(); ++s)
    {
        for (const NamedSpectrum& r : o.sets[s].samples)
        {
            samples[s].push_back(SurfaceRenderer::Sample(r.spectrum));
        }
    }

    const size_t perPair = methods.size() * o.sets.size();
    std::vector<AccuracyRow> rows(pairs.size() * perPair);
    std::atomic<size_t> next{0}, done{0};
    auto work = [&]
    {
        for (size_t p; (p = next++) < pairs.size();)
        {
            const Light& from = o.lights[pairs[p].from];
            const Light& to = o.lights[pairs[p].to];
            const SurfaceRenderer r1(from.spectrum, working, o.observer);
            const SurfaceRenderer r2(to.spectrum, working, o.observer);
            const Vec3 white = r2.rgbToXyz() * r2.white();
            for (size_t m = 0; m < methods.size(); ++m)
            {
                const MethodSpec& method = methods[m];
                const bool spectral = method.method == ChangeMethod::SPECTRAL;
                std::unique_ptr<Relighter> relight;
                if (!spectral)
                {
                    relight = std::make_unique<Relighter>(from, to, method, working, o.observer);
                }
                for (size_t s = 0; s < o.sets.size(); ++s)
                {
                    std::vector<double> de;
                    double worst = -1.0;
                    std::string worstName;
                    for (size_t k = 0; k < samples[s].size(); ++k)
                    {
                        const Vec3 reference = r2.render(samples[s][k]);
                        const Vec3 predicted =
                            spectral ? reference : relight->apply(r1.render(samples[s][k]));
                        const double e = DeltaE2000(XyzToLab(r2.rgbToXyz() * predicted, white),
                                                    XyzToLab(r2.rgbToXyz() * reference, white));
                        de.push_back(e);
                        if (e > worst)
                        {
                            worst = e;
                            worstName = o.sets[s].samples[k].name;
                        }
                    }
                    AccuracyRow& row = rows[p * perPair + m * o.sets.size() + s];
                    row.method = method.name;
                    row.from = from.name;
                    row.to = to.name;
                    row.set = o.sets[s].name;
                    double sum = 0.0;
                    for (double e : de)
                    {
                        sum += e;
                    }
                    row.mean = de.empty() ? 0.0 : sum / double(de.size());
                    row.p95 = Percentile(de, 0.95);
                    row.max = std::max(worst, 0.0);
                    row.worstSample = worstName;
                }
            }
            const size_t d = ++done;
            if (progress)
            {
                progress(double(d) / double(pairs.size()));
            }
        }
    };
    ParallelRun(0, pairs.size(), work);
    return rows;
}

}  // namespace bandlight
