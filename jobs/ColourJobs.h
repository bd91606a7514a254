// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The jobs that only compute: the band model's band tables, colorimetry of a
// light or of surfaces under it, and colour rendering.

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "requests/Inputs.h"
#include "spectral/ColourRendering.h"
#include "transforms/BandModel.h"
#include "requests/Defaults.h"

namespace bandlight::jobs
{

/// `tables`: band means of the matching functions (rows normalised to sum
/// 1), the standard illuminants (largest band 1) and the test colours.
struct TablesRequest
{
    std::string bands = defaults::BANDS;  ///< edges in nm
    std::string observer = defaults::OBSERVER;
    std::string rule = defaults::BAND_RULE;  ///< "lecture" (sample average) or "exact"
};

struct TablesResult
{
    BandSet bands = BandSet::Lecture();
    Observer observer = Observer::CIE1931_2DEG;
    BandRule rule = BandRule::SAMPLE_MEAN;
    Eigen::MatrixXd xyz;  ///< 3 × bands: x̄, ȳ, z̄
    Eigen::MatrixXd rgb;  ///< 3 × bands: EBU r̄, ḡ, b̄
    std::vector<std::pair<std::string, std::vector<double>>> illuminants;
    std::vector<std::pair<std::string, std::vector<double>>> remittances;
};

TablesResult MakeTables(const TablesRequest& request);
/// `tables --json`.
std::string TablesDocument(const TablesResult& result);

/// `xyz`: XYZ (white reflector Y = 100), xy and L*a*b* (relative to the
/// light's white) of a light, or of surfaces lit by it.
struct XyzRequest
{
    Light illuminant;
    std::vector<NamedSpectrum> reflectances;  ///< empty: the light itself
    std::string observer = defaults::OBSERVER;
};

struct XyzSample
{
    std::string id;
    Vec3 xyz;
    Vec3 xyY;
    Vec3 lab;
};

struct XyzResult
{
    std::string illuminant;
    Observer observer = Observer::CIE1931_2DEG;
    Vec3 white;
    std::vector<XyzSample> samples;
};

/// Throws Exception when a result is not finite (an out-of-range input).
XyzResult MakeXyz(const XyzRequest& request);
/// `xyz --json`.
std::string XyzDocument(const XyzResult& result);

/// `cri`: CCT, Duv and the CIE 13.3 colour rendering indices of a light.
struct CriResult
{
    std::string illuminant;
    ColourRendering rendering;
};

/// Throws Exception when a result is not finite.
CriResult MakeCri(const Light& illuminant);
/// `cri --json`.
std::string CriDocument(const CriResult& result);

}  // namespace bandlight::jobs
