// SPDX-License-Identifier: BSD-3-Clause
// One figure, three paths: the ΔE00 of a method on a set of remittances is
// the same whether the set is measured as a training set (MeasureAccuracy),
// read back from a spectral image of those remittances
// (ReflectanceSetFromSpectralImage) or mapped pixel by pixel over that image
// (WriteAccuracyHeatmaps). Each path summarises its sample with Summarise
// (spectral/Statistics.h); this checks they agree on what they summarise.
// Covers, through the entry points it calls: measure/SpectralAccuracy.cpp,
// measure/detail/AccuracySummary.cpp.
#include <catch2/catch.hpp>

#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "imaging/SpectralImages.h"
#include "measure/SpectralAccuracy.h"
#include "spectral/Illuminants.h"
#include "spectral/RgbSpaces.h"
#include "transforms/Accuracy.h"

using namespace bandlight;
using namespace bandlight::jobs;

namespace
{

/// The image module beside the build's tool.
const bool g_moduleFound = ::setenv("BANDLIGHT_IMAGE_MODULE", BANDLIGHT_IMAGE_MODULE_FILE, 0) == 0;

struct TempDir
{
    std::filesystem::path path;
    TempDir()
        : path(std::filesystem::temp_directory_path() /
               ("bandlight-onefigure-" + std::to_string(::getpid())))
    {
        std::filesystem::create_directories(path);
    }
    ~TempDir()
    {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

/// The held-out TCS (09–15) as a reflective spectral EXR, one pixel each,
/// 380–780 nm at 5 nm.
std::string WriteTcsImage(const std::string& path)
{
    const ReflectanceSet& set = HeldOutTcs();
    std::vector<double> wavelengths;
    for (double nm = 380.0; nm <= 780.0; nm += 5.0)
    {
        wavelengths.push_back(nm);
    }
    std::vector<float> spectra;
    for (const NamedSpectrum& s : set.samples)
    {
        const Spectrum r = s.spectrum.resampled(380.0, 5.0, wavelengths.size());
        for (size_t i = 0; i < wavelengths.size(); ++i)
        {
            spectra.push_back(float(r[i]));
        }
    }
    const int width = int(set.samples.size());
    std::vector<float> rgb(3 * size_t(width), 0.5f);
    const RgbSpace& acescg = FindRgbSpace("acescg");
    WriteSpectralImage(path, width, 1, SpectralKind::REFLECTIVE, wavelengths, spectra, rgb,
                       LinearImageDescription(acescg, "ACEScg"));
    return path;
}

}  // namespace

TEST_CASE("A method's ΔE00 on a set is one figure through the set, the image and its map",
          "[measure]")
{
    TempDir dir;
    const std::string image = WriteTcsImage((dir.path / "tcs.exr").string());
    const Light a{"A", BuiltinIlluminant("A")};
    const Light d65{"D65", BuiltinIlluminant("D65")};

    SpectralOptions o;
    o.from = a;
    o.to = d65;
    o.plates.plates = "lit";
    o.kind = "reflective";
    const ReflectanceSet fromImage = ReflectanceSetFromSpectralImage(image, o);
    REQUIRE(fromImage.samples.size() == HeldOutTcs().samples.size());

    AccuracyOptions options;
    options.lights = {a, d65};
    options.forwardOnly = true;
    options.methods = {"bradford"};
    options.sets = {HeldOutTcs(), fromImage};
    options.exposures = {1.0};
    options.plates = {Plates::Lit()};
    options.measureMismatch = false;
    const std::vector<AccuracyRow> rows = MeasureAccuracy(options);
    REQUIRE(rows.size() == 2);
    const AccuracyRow& asSet = rows[0].set == HeldOutTcs().name ? rows[0] : rows[1];
    const AccuracyRow& asImage = &asSet == &rows[0] ? rows[1] : rows[0];
    CHECK(asSet.mean > 0.5);  // bradford is not exact on saturated colours
    // The image holds the remittances as float: the same figure to float's
    // precision.
    CHECK(asImage.mean == Approx(asSet.mean).epsilon(1e-5));
    CHECK(asImage.p95 == Approx(asSet.p95).epsilon(1e-5));
    CHECK(asImage.max == Approx(asSet.max).epsilon(1e-5));

    OutputSet outputs;
    const std::vector<HeatmapSummary> maps = WriteAccuracyHeatmaps(
        image, o, {"bradford"}, dir.path.string(), "tcs", outputs);
    outputs.commit();
    REQUIRE(maps.size() == 1);
    CHECK(maps[0].mean == Approx(asSet.mean).epsilon(1e-4));
    CHECK(maps[0].p95 == Approx(asSet.p95).epsilon(1e-4));
    CHECK(maps[0].max == Approx(asSet.max).epsilon(1e-4));
}
