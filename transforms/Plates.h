// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Colorimetry.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Spectrum.h"
#include "transforms/Defaults.h"

namespace bandlight
{

/// What a pipeline's images are, as far as the light's colour goes.
enum class PlateConvention
{
    /// Lit by the source light as the eye would record it without adapting:
    /// a tungsten plate is orange, and the look takes the cast away.
    LIT,
    /// White-balanced to the working space's white (the ACES convention: a
    /// camera's IDT, rawtoaces' and the vendors' alike, balances): a
    /// tungsten plate's white is neutral and only the light's colour
    /// rendering is left in it. The look undoes the balance with the
    /// adaptation's inverse, changes the light, and balances again: for a
    /// method exact on white a neutral stays neutral and only the change in
    /// colour rendering is applied (the band model is not exact on white).
    BALANCED,
};

/// A plate convention with the chromatic adaptation that did the balancing.
/// The default is defaults::PLATES (balanced, CAT02), as every face has it.
struct Plates
{
    PlateConvention convention = PlateConvention::BALANCED;
    /// CAT02 is what rawtoaces balances with; Bradford is common in
    /// camera vendors' IDTs and ICC profiles.
    AdaptationMethod adaptation = AdaptationMethod::CAT02;

    /// Lit plates: the physical change between two lights, no balance.
    static Plates Lit() noexcept { return {PlateConvention::LIT, AdaptationMethod::CAT02}; }

    bool balanced() const noexcept { return convention == PlateConvention::BALANCED; }
    /// "lit" or "balanced-cat02" / "balanced-bradford": for reports and JSON.
    std::string key() const;
    /// One sentence on the plates a look is for. For balanced plates it
    /// says what becomes of a neutral: `grey` is what the look makes of
    /// 0.18 grey (nullptr: not said).
    std::string describe(const std::string& workingSpaceName, const Vec3* grey = nullptr) const;
};

/// One row of the plate-convention table: the convention, its name in
/// options, files and reports, and what it means to a user (help texts).
struct PlateConventionEntry
{
    PlateConvention convention;
    const char* key;   ///< "balanced"
    const char* help;  ///< "white-balanced to the working white, ..."
};

/// Every plate convention, in the order they are listed to users.
const std::vector<PlateConventionEntry>& PlateConventions();

/// The adaptations plates are balanced with (a part of AdaptationMethods()),
/// in the order they are listed; the first is the default.
const std::vector<AdaptationEntry>& PlateAdaptations();

/// "balanced, lit": the conventions' keys, for help and errors.
std::string PlateConventionChoices();

/// "cat02, bradford": the plates' adaptations' keys, for help and errors.
std::string PlateAdaptationChoices();

/// Parses --plates and --adaptation from the tables above (any case);
/// throws Exception naming the choices otherwise.
Plates ParsePlates(const std::string& convention, const std::string& adaptation = defaults::ADAPTATION);

/// The balancing matrix in working RGB: a colour seen under `light` (its
/// white reflector at Y = 1) → the same colour balanced to the working
/// space's white, M⁻¹ · CAT(W_light → W_working) · M. It maps the light's
/// white exactly onto RGB (1, 1, 1). Whites are the perfect reflector
/// rendered on SurfaceRenderer's grid, as every method sees them.
Mat3 BalanceMatrix(const Spectrum& light, const RgbSpace& working, AdaptationMethod adaptation,
                   Observer observer = Observer::CIE1931_2DEG);

/// XYZ of the working space's white with Y = 1: the L*a*b* reference white
/// of balanced images.
Vec3 WorkingWhiteXyz(const RgbSpace& working);

}  // namespace bandlight
