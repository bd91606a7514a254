// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/Metrics.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "spectral/Exception.h"
#include "spectral/RgbSpaces.h"

namespace bandlight
{

namespace
{

Vec3 Lab(const Vec3& rgb, const MetricContext& c)
{
    return XyzToLab(c.rgbToXyz * rgb, c.whiteXyz);
}

double De00(const Vec3& rgb, const Vec3& reference, const MetricContext& c)
{
    return DeltaE2000(Lab(rgb, c), Lab(reference, c));
}

double De76(const Vec3& rgb, const Vec3& reference, const MetricContext& c)
{
    return DeltaE76(Lab(rgb, c), Lab(reference, c));
}

/// ITU-R BT.2124: 720 √(ΔI² + ΔT² + ΔP²), T = Ct/2, P = Cp, on absolute
/// light (the white at `whiteLuminance` cd/m²).
double DeItp(const Vec3& rgb, const Vec3& reference, const MetricContext& c)
{
    const double scale = c.whiteLuminance / c.whiteXyz.y();
    const Vec3 a = XyzToICtCp(scale * (c.rgbToXyz * rgb));
    const Vec3 b = XyzToICtCp(scale * (c.rgbToXyz * reference));
    const Vec3 d(a[0] - b[0], 0.5 * (a[1] - b[1]), a[2] - b[2]);
    return 720.0 * d.norm();
}

/// ‖rgb − reference‖ / ‖reference‖ (Euclidean, working-space RGB); 0 for
/// two blacks.
double RgbRelative(const Vec3& rgb, const Vec3& reference, const MetricContext&)
{
    const double difference = (rgb - reference).norm();
    return difference == 0.0 ? 0.0 : difference / std::max(reference.norm(), 1e-300);
}

/// SMPTE ST 2084 (PQ) of a luminance in cd/m².
double Pq(double candela) noexcept
{
    constexpr double m1 = 2610.0 / 16384.0;
    constexpr double m2 = 2523.0 / 4096.0 * 128.0;
    constexpr double c1 = 3424.0 / 4096.0;
    constexpr double c2 = 2413.0 / 4096.0 * 32.0;
    constexpr double c3 = 2392.0 / 4096.0 * 32.0;
    const double y = std::pow(std::max(candela, 0.0) / 10000.0, m1);
    return std::pow((c1 + c2 * y) / (1.0 + c3 * y), m2);
}

}  // namespace

Vec3 XyzToICtCp(const Vec3& xyz) noexcept
{
    static const Mat3 toRec2020 = RgbToXyzMatrix(Rec2020Space().chromaticities).inverse();
    // BT.2100's LMS of linear BT.2020 RGB, then PQ per cone.
    static const Mat3 toLms = (Mat3() << 1688, 2146, 262, 683, 2951, 462, 99, 309, 3688)
                                  .finished() /
                              4096.0;
    const Vec3 lms = toLms * (toRec2020 * xyz);
    const Vec3 p(Pq(lms[0]), Pq(lms[1]), Pq(lms[2]));
    return {0.5 * p[0] + 0.5 * p[1], (6610.0 * p[0] - 13613.0 * p[1] + 7003.0 * p[2]) / 4096.0,
            (17933.0 * p[0] - 17390.0 * p[1] - 543.0 * p[2]) / 4096.0};
}

const std::vector<MetricEntry>& Metrics()
{
    static const std::vector<MetricEntry> metrics = {
        {"de00", "CIEDE2000", "ΔE00",
         "CIE 142-2001 / ISO/CIE 11664-6 colour difference of CIE L*a*b* (relative to the "
         "white), kL = kC = kH = 1",
         De00},
        {"de76", "CIE 1976", "ΔE76",
         "Euclidean distance in CIE L*a*b* (relative to the white), CIE 15:2018", De76},
        {"deitp", "ΔE ITP", "ΔE ITP",
         "ITU-R BT.2124-0: 720 √(ΔI² + (ΔCt/2)² + ΔCp²) in BT.2100 ICtCp (PQ) of absolute "
         "light, the white at 100 cd/m² unless stated; 1 is about a just-noticeable difference",
         DeItp},
        {"rgbrel", "RGB relative error", "relative",
         "‖RGB − RGB_reference‖ / ‖RGB_reference‖, Euclidean, in the working space's linear RGB",
         RgbRelative},
    };
    return metrics;
}

const MetricEntry& FindMetric(const std::string& key)
{
    std::string keys;
    for (const MetricEntry& m : Metrics())
    {
        if (key == m.key)
        {
            return m;
        }
        keys += (keys.empty() ? "" : ", ") + std::string(m.key);
    }
    throw ParameterError("{metric} '" + OneLine(key, 80) + "' is none of " + keys);
}

std::vector<double> MetricValues(const MetricEntry& metric, const std::vector<Vec3>& rgb,
                                 const std::vector<Vec3>& reference, const MetricContext& context)
{
    if (rgb.size() != reference.size())
    {
        throw Exception("a metric compares pairs: " + std::to_string(rgb.size()) +
                        " colours against " + std::to_string(reference.size()) + " references");
    }
    std::vector<double> values(rgb.size());
    for (size_t i = 0; i < rgb.size(); ++i)
    {
        values[i] = metric.compute(rgb[i], reference[i], context);
    }
    return values;
}

}  // namespace bandlight
