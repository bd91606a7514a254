// SPDX-License-Identifier: BSD-3-Clause
#include "measure/detail/AccuracySummary.h"

#include <algorithm>
#include <cmath>

namespace bandlight::detail
{

const Pairs& LecturePairs()
{
    static const Pairs pairs = {{"A", "D65"}, {"F2", "D65"}, {"F11", "D65"}};
    return pairs;
}

Summary Summarise(const std::vector<AccuracyRow>& rows, const std::string& method,
                  const std::string& set, Filter f, const Pairs& onlyPairs)
{
    Summary s;
    std::vector<double> p95s;
    int n = 0;
    for (const AccuracyRow& r : rows)
    {
        if (r.method != method || r.set != set || r.shipped != f.shipped || r.plates != f.plates ||
            r.source != f.source || (f.exposure > 0.0 && r.exposure != f.exposure))
        {
            continue;
        }
        if (!onlyPairs.empty() && std::find(onlyPairs.begin(), onlyPairs.end(),
                                            std::pair{r.from, r.to}) == onlyPairs.end())
        {
            continue;
        }
        s.mean += r.mean;
        p95s.push_back(r.p95);
        if (r.max > s.max)
        {
            s.max = r.max;
            s.worst = r.worstSample + " " + r.from + "->" + r.to;
        }
        ++n;
    }
    s.mean = n ? s.mean / n : 0.0;
    s.p95 = Percentile(p95s, 0.95);
    return s;
}

std::pair<double, double> WorstExposure(const std::vector<AccuracyRow>& rows,
                                        const std::string& method, const std::string& set, Filter f,
                                        const std::vector<double>& exposures,
                                        const Pairs& onlyPairs)
{
    std::pair<double, double> worst{1.0, -1.0};
    for (const double k : exposures)
    {
        f.exposure = k;
        const double m = Summarise(rows, method, set, f, onlyPairs).mean;
        if (m > worst.second)
        {
            worst = {k, m};
        }
    }
    return worst;
}

std::string Stops(double k)
{
    const int e = int(std::lround(std::log2(k)));
    return e == 0 ? "1" : "2^" + std::to_string(e);
}

}  // namespace bandlight::detail
