// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Statistics.h"

#include <algorithm>
#include <cmath>

namespace bandlight
{

namespace
{
/// The nearest-rank percentile of sorted, non-empty values.
double RankOf(const std::vector<double>& sorted, double p)
{
    const size_t rank = size_t(std::ceil(p * double(sorted.size())));
    return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}
}  // namespace

double Percentile(std::vector<double> values, double p)
{
    if (values.empty())
    {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    return RankOf(values, p);
}

Statistics Summarise(std::vector<double> values)
{
    Statistics s;
    s.count = values.size();
    if (values.empty())
    {
        return s;
    }
    double sum = 0.0;
    for (const double v : values)
    {
        sum += v;
    }
    s.mean = sum / double(values.size());
    std::sort(values.begin(), values.end());
    s.median = RankOf(values, 0.5);
    s.p95 = RankOf(values, 0.95);
    s.max = values.back();
    return s;
}

}  // namespace bandlight
