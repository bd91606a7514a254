// SPDX-License-Identifier: BSD-3-Clause
// What the accuracy measures share (declared in transforms/detail/AccuracyParts.h):
// the pairs of lights they run over, on all cores; each pair's plate
// matrices; the ΔE00 score of predictions and the row it makes.
#include "transforms/detail/AccuracyParts.h"

#include <atomic>
#include <mutex>

#include "spectral/Parallel.h"

namespace bandlight
{

namespace
{

struct Pair
{
    size_t from, to;
};

std::vector<Pair> Pairs(const AccuracyOptions& o)
{
    std::vector<Pair> pairs;
    for (size_t i = 0; i < o.lights.size(); ++i)
    {
        for (size_t j = 0; j < o.lights.size(); ++j)
        {
            if (o.forwardOnly ? i < j : i != j)
            {
                pairs.push_back({i, j});
            }
        }
    }
    return pairs;
}

}  // namespace

namespace detail
{

Judge LitJudge(const SurfaceRenderer& to)
{
    return {to.rgbToXyz(), to.rgbToXyz() * to.white()};
}

Errors Score(const Judge& judge, const std::vector<Vec3>& predicted,
             const std::vector<Vec3>& reference, const std::vector<NamedSpectrum>& names)
{
    const Vec3& white = judge.white;
    std::vector<double> de;
    Errors e;
    double worst = -1.0;
    for (size_t k = 0; k < reference.size(); ++k)
    {
        const Vec3 p = predicted[k].allFinite() ? predicted[k] : Vec3(1e6, -1e6, 1e6);
        const double d = DeltaE2000(XyzToLab(judge.rgbToXyz * p, white),
                                    XyzToLab(judge.rgbToXyz * reference[k], white));
        de.push_back(d);
        if (d > worst)
        {
            worst = d;
            e.worst = names[k].name;
        }
    }
    const Statistics s = Summarise(std::move(de));
    e.mean = s.mean;
    e.p95 = s.p95;
    e.max = s.max;
    return e;
}

AccuracyRow MakeRow(const std::string& method, const Light& from, const Light& to,
                    const std::string& set, double exposure, bool shipped, const Errors& e,
                    const std::string& plates, PlateSource source)
{
    AccuracyRow r;
    r.plates = plates;
    r.source = source;
    r.method = method;
    r.from = from.name;
    r.to = to.name;
    r.set = set;
    r.exposure = exposure;
    r.shipped = shipped;
    r.mean = e.mean;
    r.p95 = e.p95;
    r.max = e.max;
    r.worstSample = e.worst;
    return r;
}

/// Runs `perPair(pair, rows)` for every pair on all cores, rows in pair order.
std::vector<AccuracyRow> ForEachPair(
    const AccuracyOptions& o, const std::function<void(double)>& progress,
    const std::function<void(const Light&, const Light&, std::vector<AccuracyRow>&)>& perPair)
{
    const std::vector<Pair> pairs = Pairs(o);
    std::vector<std::vector<AccuracyRow>> byPair(pairs.size());
    std::atomic<size_t> next{0};
    // Counted and reported under one lock, so progress arrives as 1/n, 2/n,
    // ... in order whichever thread finishes first (counted apart from the
    // report, two threads' reports could cross, and a step be lost).
    std::mutex reportMutex;
    size_t done = 0;
    ParallelRun(0, pairs.size(),
                [&]
                {
                    for (size_t p; (p = next++) < pairs.size();)
                    {
                        perPair(o.lights[pairs[p].from], o.lights[pairs[p].to], byPair[p]);
                        std::lock_guard<std::mutex> lock(reportMutex);
                        ++done;
                        if (progress)
                        {
                            progress(double(done) / double(pairs.size()));
                        }
                    }
                });
    std::vector<AccuracyRow> rows;
    for (auto& r : byPair)
    {
        rows.insert(rows.end(), r.begin(), r.end());
    }
    return rows;
}

PairPlates MakePairPlates(const Plates& p, const Light& from, const Light& to,
                          const SurfaceRenderer& r2, const RgbSpace& working, Observer observer)
{
    PairPlates out{p, Mat3::Identity(), Mat3::Identity(), LitJudge(r2)};
    if (p.balanced())
    {
        out.balanceFrom = BalanceMatrix(from.spectrum, working, p.adaptation, observer);
        out.balanceTo = BalanceMatrix(to.spectrum, working, p.adaptation, observer);
        out.judge = {r2.rgbToXyz(), WorkingWhiteXyz(working)};
    }
    return out;
}

MethodSpec WithPlates(MethodSpec m, const Plates& p, const AccuracyOptions& o)
{
    m.plates = p;
    m.camera = o.camera;
    m.idtLightName = o.idtLightName;
    m.idtLight = o.idtLight;
    return m;
}

}  // namespace detail

size_t PairCount(const AccuracyOptions& options)
{
    return Pairs(options).size();
}

}  // namespace bandlight
