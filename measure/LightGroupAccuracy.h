// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "farm/Reporter.h"
#include "imaging/SpectralImages.h"

namespace bandlight::jobs
{

/// `accuracy --image SHOT.exr --light-group NAME=FROM:TO …`: on a render
/// with spectral light groups (`render --spectra --light-groups`), what one
/// global look on the beauty costs against relighting each group, for each
/// method, measured against the exact spectral relight of the groups.
struct LightGroupAccuracyRequest
{
    std::string image;
    std::vector<SpectralLightGroup> changes;  ///< every group of the image, FROM:TO
    std::vector<std::string> methods;         ///< empty: bradford, cat02, fit3x3, rootpoly
    std::string workingSpace = defaults::WORKING_SPACE;
    int threads = defaults::THREADS;
};

struct LightGroupAccuracyRow
{
    std::string method;
    double globalMean = 0.0;  ///< ΔE00 of one look on the beauty, mean over the pixels hit
    double globalP95 = 0.0;
    double groupsMean = 0.0;  ///< ΔE00 with each group relit on its own
    double groupsP95 = 0.0;
    double globalSeconds = 0.0;  ///< wall time of the relight in memory
    double groupsSeconds = 0.0;
};

struct LightGroupAccuracyResult
{
    std::vector<LightGroupAccuracyRow> rows;
    double noChangeMean = 0.0;     ///< ΔE00 of the beauty as it is
    double spectralSeconds = 0.0;  ///< the exact relight: spectra read and relit
    size_t pixels = 0;             ///< pixels measured (those with light)
    std::string globalFrom;        ///< the mixes the global look goes between
    std::string globalTo;
};

/// Measures `request`. The global look goes from the mix of the groups'
/// lights to the mix of their new lights, each light weighed by its group's
/// share of the image's luminance (what the beauty shows on average); the
/// reference is the spectral relight (exact). L*a*b* is taken relative to
/// the equal-energy white at the reference's brightest luminance. Throws
/// Exception naming the image when it has no spectral light groups or a
/// group is not given a change.
LightGroupAccuracyResult MeasureLightGroups(const LightGroupAccuracyRequest& request,
                                            Reporter& reporter = SilentReporter());

}  // namespace bandlight::jobs
