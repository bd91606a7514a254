// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The scene model of `bandlight render`: lights with spectra, Phong
// materials with remittances, spheres, planes, a camera and the render
// settings (docs/science.md §1.3; docs/scenes.md). Plain values; the reader is
// render/SceneFile.h, the planner render/ScenePlan.h.

#include <string>
#include <vector>

#include "spectral/Colorimetry.h"
#include "spectral/Spectrum.h"
#include "transforms/BandSet.h"
#include "transforms/Defaults.h"

namespace bandlight
{

/// Light or remittance as the scene gives it: a sampled spectrum, emission
/// lines, or both (a band-valued one is a step spectrum over its bands).
struct SceneSpectrum
{
    std::string name;  ///< what it was given as ("D65", "TCS09", "bands 400,500,600,700"), for
                       ///< messages only: the planner groups lights by their values
    Spectrum continuous;
    LineSpectrum lines;

    bool isZero() const noexcept;
    bool hasLines() const noexcept { return !lines.empty(); }
    /// The same values: the same grid and samples and the same lines, exactly
    /// (names are not compared). Lights for which this holds share one
    /// spectral term in the plan.
    bool sameValues(const SceneSpectrum& other) const noexcept;
};

/// A step spectrum with value v[b] over band b (zero outside): how band
/// values enter spectral mode.
Spectrum StepSpectrum(const BandSet& bands, const std::vector<double>& values);

/// A constant remittance over the visible range.
Spectrum ConstantRemittance(double value);

struct SceneLight
{
    enum class Kind
    {
        AMBIENT,
        POINT,
        DIRECTIONAL,
    };
    Kind kind = Kind::POINT;
    /// The light's name (the scene's `name:`, else "light1", "light2", …
    /// in file order) and its light group (`group:`, else its name): lights
    /// sharing a group share a layer of `render --light-groups`.
    std::string name;
    std::string group;
    SceneSpectrum spectrum;  ///< scaled so its largest band mean is 1 (the band model's I)
    double intensity = 1.0;
    Vec3 position = Vec3::Zero();     ///< POINT
    Vec3 direction = Vec3(0, -1, 0);  ///< DIRECTIONAL: the direction the light travels
    /// f_att = 1 / (c1 + c2·d + c3·d²), capped at 1; (1, 0, 0) is none.
    Vec3 attenuation = Vec3(1, 0, 0);

    bool attenuates() const noexcept { return attenuation != Vec3(1, 0, 0); }
};

/// The compact Phong material of docs/science.md §1.3: R_amb, R_diff, R_spek and n
/// (the full form k_a·O_a, k_d·O_d, k_s·O_s is folded into these).
struct SceneMaterial
{
    std::string name;
    SceneSpectrum ambient;
    SceneSpectrum diffuse;
    SceneSpectrum specular;
    /// R_amb* of the single-source form I = I_0 (R_amb* + R_diff cos α +
    /// R_spek cosⁿψ): an ambient term lit by the scene's one direct light.
    SceneSpectrum ambientStar;
    double exponent = 1.0;
};

/// The band model's material table (docs/science.md §1.3), as band values over VB/VG/VR:
/// copper, gold, silver, aluminium, tin, matte lacquer, gloss lacquer.
/// R_amb is taken equal to R_diff (the table has no ambient column). Throws
/// Exception for another name.
SceneMaterial LectureMaterial(const std::string& name);
const std::vector<std::string>& LectureMaterialNames();

struct Sphere
{
    Vec3 center;
    double radius = 1.0;
    int material = 0;
};

struct Plane
{
    Vec3 point;
    Vec3 normal = Vec3(0, 1, 0);
    int material = 0;
};

struct Camera
{
    enum class Projection
    {
        PINHOLE,       ///< rays from `position` through the image plane, `fovDeg` apart
        ORTHOGRAPHIC,  ///< parallel rays along the view direction, as the band model's figures
    };
    Projection projection = Projection::PINHOLE;
    Vec3 position = Vec3(0, 0, 5);
    Vec3 lookAt = Vec3::Zero();
    Vec3 up = Vec3(0, 1, 0);
    double fovDeg = 40.0;  ///< PINHOLE: vertical field of view, degrees (0–180)
    /// ORTHOGRAPHIC: the height of the view in scene units (its width is
    /// size × width / height); rays start on the plane through `position`
    /// facing `lookAt`.
    double size = 2.0;
    int width = 320;
    int height = 240;
};

struct RenderSettings
{
    enum class Mode
    {
        BAND,
        SPECTRAL,
    };
    Mode mode = Mode::BAND;
    BandSet bands = BandSet::Lecture();
    double stepNm = 0.0;  ///< spectral grid; 0: chosen by the planner
    /// The spectral integration range, nm: samples at rangeMinNm + i·step up
    /// to rangeMaxNm, and the emission lines inside it. The default is SPEC
    /// §1.1's and the band model's 380–780 nm (the spectral reference of
    /// transforms/ sums the same); 360–830 nm, the matching functions' full
    /// range (CIE 15:2004), is the widest allowed.
    double rangeMinNm = kDefaultRangeMinNm;
    double rangeMaxNm = kDefaultRangeMaxNm;
    std::string output = defaults::WORKING_SPACE;  ///< a working space, or "bands" (band mode: band values)

    static constexpr double kDefaultRangeMinNm = 380.0;
    static constexpr double kDefaultRangeMaxNm = 780.0;
    static constexpr double kWidestRangeMinNm = 360.0;
    static constexpr double kWidestRangeMaxNm = 830.0;
};

struct Scene;

/// The light groups of a scene, in the order their first light comes.
std::vector<std::string> LightGroupNames(const Scene& scene);

/// The scene lit by the lights of `group` alone (R_amb*, the single direct
/// light's ambient term, goes with that light's group): what its layer of
/// `render --light-groups` holds.
Scene SceneOfLightGroup(const Scene& scene, const std::string& group);

/// Throws Exception when `name` cannot name a light group's layer: it must
/// be letters, digits, '_' and '-', and not a channel name of its own (R, G,
/// B, A, the spectral S0–S3 and T).
void CheckLightGroupName(const std::string& name);

/// Sets the mode from its name: "band3" (the band model's VB/VG/VR), "bandN"
/// (N equal bands over 400–700 nm, 3 ≤ N ≤ 300) or "spectral" (the bands
/// are kept: they normalise the lights). Throws Exception otherwise.
void SetRenderMode(RenderSettings& settings, const std::string& mode);

/// The number of bands a mode name asks for ("band6": 6), 0 for "spectral";
/// throws Exception for anything else.
size_t ModeBandCount(const std::string& mode);

struct Scene
{
    Camera camera;
    std::vector<SceneLight> lights;
    std::vector<SceneMaterial> materials;
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    RenderSettings settings;
};

}  // namespace bandlight
