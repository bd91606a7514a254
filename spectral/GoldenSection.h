// SPDX-License-Identifier: BSD-3-Clause
// Golden-section search for the minimum of a function of one variable.
#pragma once

#include <cmath>

namespace bandlight
{

/// Where a golden-section search ended: its last bracket and the better of
/// its two last probes.
struct GoldenSectionResult
{
    double lo = 0.0, hi = 0.0;  ///< the last bracket
    double x = 0.0;             ///< the better probe
    double value = 0.0;         ///< f(x)
};

/// Narrows [lo, hi] around the minimum of `f`, which must be unimodal on it
/// (Kiefer 1953): each step keeps the part of the bracket holding the lower
/// of two probes placed at the golden ratio, so one new value of `f` is
/// computed per step. Stops when the bracket is no wider than `tolerance` or
/// after `maxSteps` steps.
template <class F>
GoldenSectionResult GoldenSectionMinimum(F&& f, double lo, double hi, double tolerance,
                                         int maxSteps = 1 << 30)
{
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    double fa = f(a), fb = f(b);
    for (int i = 0; i < maxSteps && hi - lo > tolerance; ++i)
    {
        if (fa < fb)
        {
            hi = b;
            b = a;
            fb = fa;
            a = hi - g * (hi - lo);
            fa = f(a);
        }
        else
        {
            lo = a;
            a = b;
            fa = fb;
            b = lo + g * (hi - lo);
            fb = f(b);
        }
    }
    return fa < fb ? GoldenSectionResult{lo, hi, a, fa} : GoldenSectionResult{lo, hi, b, fb};
}

}  // namespace bandlight
