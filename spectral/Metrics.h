// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The colour-difference metrics bandlight measures with, each named once:
// its key (as `--metric` and JSON write it), its name, units and
// definition, and how it is computed from a pair of colours. Every accuracy
// table summarises a metric's values with Summarise (spectral/Statistics.h).
//
// Adding a metric is one entry in Metrics.cpp's table, with a test of a
// published value.

#include <string>
#include <vector>

#include "spectral/Colorimetry.h"

namespace bandlight
{

/// What a metric compares: a colour and its reference, as working-space
/// RGB with the space's RGB→XYZ matrix, and the white that L*a*b* and the
/// absolute luminance of ΔE ITP are relative to.
struct MetricContext
{
    Mat3 rgbToXyz = Mat3::Identity();
    Vec3 whiteXyz = Vec3::Ones();
    /// The luminance of whiteXyz in cd/m², for the metrics on absolute
    /// light (ΔE ITP): 100, the white of an SDR reference display (ITU-R
    /// BT.2035), unless the caller knows better.
    double whiteLuminance = 100.0;
};

/// One metric of the registry.
struct MetricEntry
{
    const char* key;         ///< "de00", "de76", "deitp", "rgbrel"
    const char* name;        ///< "CIEDE2000"
    const char* units;       ///< "ΔE00", "ΔE ITP", "relative"
    const char* definition;  ///< one sentence, with its source
    /// The difference of `rgb` from `reference` (both working-space RGB).
    double (*compute)(const Vec3& rgb, const Vec3& reference, const MetricContext& context);
};

/// Every metric, in the order tables list them (ΔE00 first: the default).
const std::vector<MetricEntry>& Metrics();

/// The metric of `key`; throws ParameterError listing the keys when there
/// is none.
const MetricEntry& FindMetric(const std::string& key);

/// The metric's value for each pair (`rgb[i]` against `reference[i]`).
std::vector<double> MetricValues(const MetricEntry& metric, const std::vector<Vec3>& rgb,
                                 const std::vector<Vec3>& reference, const MetricContext& context);

/// ICtCp (ITU-R BT.2100, PQ) of CIE XYZ in cd/m²: the coordinates ΔE ITP
/// (ITU-R BT.2124) is measured in, before its scaling of Ct by 1/2.
Vec3 XyzToICtCp(const Vec3& xyzCandela) noexcept;

}  // namespace bandlight
