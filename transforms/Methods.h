// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The illuminant-change methods, one registry entry each: its name and
// syntax, how exact it is (one 3×3, an op per pixel, the reference), how it
// is fitted and on what, the op it makes for a change of light, whether it
// needs a camera, what it costs and where it appears in default lists and
// reports. Adding a method is one file in transforms/methods/ (its entry,
// parser, fit and op, as OpenColorIO keeps an op in one folder) and one line
// in transforms/methods/List.h; nothing outside the registry compares a
// method's enum or name.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spectral/ChromaticAdaptation.h"
#include "spectral/Colorimetry.h"
#include "spectral/RgbSpaces.h"
#include "spectral/Spectrum.h"
#include "spectral/SpectrumIO.h"
#include "transforms/BandSet.h"
#include "transforms/Camera.h"
#include "transforms/Plates.h"
#include "transforms/RootPolynomial.h"

namespace bandlight
{

/// A way of changing the illuminant an image appears lit by: the registry's
/// key. Only transforms/Methods.cpp compares these values.
enum class ChangeMethod
{
    NONE,       ///< identity: the reference for "doing nothing"
    VON_KRIES,  ///< von Kries scaling of XYZ by the ratio of the whites
    BRADFORD,   ///< linearised Bradford chromatic adaptation
    CAT02,      ///< CIECAM02 chromatic adaptation
    BAND,       ///< the band model: band ratios of the two lights
    BAND_WP,    ///< band model whose ratios come from the two whites: exact on white
    FIT3X3,     ///< least-squares 3×3 on training remittances, white-preserving
    PREFILTER,  ///< von Kries in sharpened primaries (Ward & Eydelberg-Vileshin 2002)
    METAMER,    ///< smoothest remittance reproducing the pixel under S1, re-lit
    UPSAMPLE,   ///< sigmoid-polynomial remittance (Jakob & Hanika 2019), re-lit: not linear
    ROOTPOLY,   ///< root-polynomial regression (Finlayson et al. 2015) on measured remittances
    /// rootpoly fitted from a camera's own record: for plates made with one
    /// fixed daylight IDT and white-balance gains
    ROOTPOLY_CAMERA,
    SPECTRAL,  ///< the exact answer for known spectra: the reference, not an image transform
// The methods of transforms/methods/ that register themselves, one line each.
#define BANDLIGHT_METHOD(KEY, MAKE) KEY,
#include "transforms/methods/List.h"
#undef BANDLIGHT_METHOD
};

struct MethodEntry;

/// How a method is applied outside OCIO, when it has such a form: the cost
/// table times it beside the OCIO processor.
enum class DirectForm
{
    NONE,
    DIRECT_FIT,  ///< a fit per pixel (upsample), without the LUT a config bakes
    NATIVE,      ///< bandlight's own kernel of the exact map (rootpoly)
};

/// A method with its parameters, parsed from its name (ParseMethod):
/// "none", "vonkries", "bradford", "cat02", "band3" (the band model's
/// VB/VG/VR), "band3-wp", "bandN" / "bandN-wp" (N equal bands over
/// 400–700 nm), any band set as "bands380-480-560-780" (edges in nm, "-wp"
/// appended for the white-preserving form: no ':' or '=' so it can name
/// looks), "fit3x3", "prefilter", "metamer", "upsample", "rootpoly"
/// (degree 2), "rootpoly3" (degree 3), "rootpoly-camera" /
/// "rootpoly3-camera", "rootpoly-plate" / "rootpoly3-plate" (need
/// `camera`), "spectral".
struct MethodSpec
{
    ChangeMethod method = ChangeMethod::NONE;
    BandSet bands = BandSet::Lecture();
    /// Band methods: ratios from the band coordinates of the two whites
    /// (band-wp, exact on white) rather than from the lights' band means.
    bool whitePreserving = false;
    std::string name;  ///< canonical name, used in look names: "band3-wp"
    /// The training remittances of a fitted method (empty: its registry
    /// entry's default set; TrainingOf gives the set in use).
    std::vector<NamedSpectrum> training;
    int degree = 2;  ///< rootpoly's degree
    /// What the images are: white-balanced to the working white (the
    /// default, defaults::PLATES), in which case the method is wrapped in the
    /// inverse balance for `from` and the balance for `to`, or lit by the
    /// source light (Plates::Lit(): the physical change between two lights).
    /// `none` stays the identity in both conventions: it is what doing
    /// nothing does.
    Plates plates;
    /// Camera methods: the camera that shot the plates, and the light its
    /// one fixed IDT was fitted for (empty spectrum: the built-in light of
    /// that name).
    std::shared_ptr<const SpectralCamera> camera;
    std::string idtLightName = DEFAULT_IDT_LIGHT;
    Spectrum idtLight;
    /// Camera methods: that IDT itself (balanced camera RGB → working RGB)
    /// when the plates were read through another than bandlight's fit for
    /// the light (FitIdt): a vendor's, or `idt`'s optimum. Empty: FitIdt.
    std::optional<Mat3> idt;

    /// This method's registry entry.
    const MethodEntry& entry() const;
    /// The band methods (band3, bandN, bands…, their -wp forms).
    bool usesBands() const;
    /// One 3×3 in the working space: its registry entry is LINEAR.
    bool isLinear() const noexcept;
};

/// An illuminant with the name it is known by.
struct Light
{
    std::string name;
    Spectrum spectrum;
};

/// How exact a method's change of light is, which decides its OCIO form.
enum class MethodExactness
{
    LINEAR,     ///< one 3×3 in the working space (with the pixel guard): a MatrixTransform
    NONLINEAR,  ///< an op per pixel (PixelOp): a 3D LUT with a shaper in OCIO
    REFERENCE,  ///< spectra, not pixels: the exact answer the others are measured against
};

/// "linear", "non-linear", "reference": as `methods` lists them.
const char* MethodExactnessName(MethodExactness exactness);

class PixelOp;

/// The lit 3×3 of a linear method: working RGB under `from` → under `to`.
using LitMatrixFit = Mat3 (*)(const Light& from, const Light& to, const MethodSpec& method,
                              const RgbSpace& working, Observer observer);
/// The op of a non-linear method for the plates `method.plates`
/// (transforms/methods/PixelOp.h).
using PixelOpFit = std::unique_ptr<PixelOp> (*)(const Light& from, const Light& to,
                                                const MethodSpec& method, const RgbSpace& working,
                                                Observer observer);
/// What a method's ops share over a run for one source light (upsample's
/// fits per chromaticity), held by a caller that makes many of them.
using SharedPerLight = std::shared_ptr<void> (*)(const Light& from, const RgbSpace& working,
                                                  Observer observer);
/// A fitted method's default training remittances.
using TrainingSetFn = const std::vector<NamedSpectrum>& (*)();

struct MethodEntry
{
    /// The method of this entry (one enum value; a family such as band and
    /// band-wp shares an entry when its names parse together).
    std::vector<ChangeMethod> methods;
    /// How the entry's names read in help ("bandN, bandN-wp, ...").
    const char* syntax;
    MethodExactness exactness;
    /// Parses a lower-case name into `spec`; false when the name is not of
    /// this entry (throws Exception when it is, but malformed). An entry of
    /// one method need not set `spec.method`: ParseMethod sets its key.
    bool (*parse)(const std::string& name, MethodSpec& spec);
    /// One sentence on what the method does and how accurate it is.
    std::string (*describe)(const MethodSpec& spec);
    /// LINEAR methods: the fit (nullptr otherwise).
    LitMatrixFit litMatrix = nullptr;
    /// NONLINEAR methods: the maker of their op.
    PixelOpFit makeOp = nullptr;
    /// NONLINEAR methods whose ops share work per source light (nullptr: none).
    SharedPerLight sharedPerLight = nullptr;
    /// Applied to images by its op itself rather than through the OCIO
    /// processor of its baked LUT (the op is exact where a LUT is not, and
    /// fast: the root polynomials).
    bool native = false;
    /// Fitted methods: their default training set (nullptr: not fitted).
    TrainingSetFn defaultTraining = nullptr;
    /// Whether a user's training set may replace the default (fit3x3,
    /// rootpoly); cross-validation runs over these.
    bool takesTraining = false;
    /// Needs the camera that shot the plates (RequireCamera).
    bool needsCamera = false;
    /// The von Kries family: the chromatic adaptation transform it applies.
    AdaptationMethod adaptation = AdaptationMethod::CAT02;
    /// Doing nothing: the identity on lit and balanced plates alike.
    bool identity = false;
    /// Works in a band set (MethodSpec::bands): band tables and band spaces
    /// are written for it.
    bool usesBands = false;
    /// The form the cost table times besides the OCIO processor.
    DirectForm directForm = DirectForm::NONE;
    /// The names this entry gives a config's default looks and the
    /// accuracy report's default methods.
    std::vector<const char*> configDefaults;
    std::vector<const char*> accuracyDefaults;
    /// The names the accuracy report measures by default when a camera is
    /// given and no methods are named.
    std::vector<const char*> cameraDefaults;
    /// The names `accuracy --light-group` compares (one global look against
    /// a look per group) when no methods are named.
    std::vector<const char*> lightGroupDefaults;
    /// The name of the op an LED wall's post-camera look is (a camera's
    /// plates under one light to its plates under another), and of the
    /// op aimed at the observer's colours it is compared with.
    std::vector<const char*> wallLookDefaults;
    std::vector<const char*> wallComparisonDefaults;
    /// The names whose looks `package` applies to its sample chart, and
    /// where they come in its list (1 first): the band model, then bradford.
    std::vector<const char*> packageDefaults;
    int packageRank = 0;

    /// The exact spectral answer, which the others are measured against.
    bool isReference() const noexcept { return exactness == MethodExactness::REFERENCE; }
    /// A method applied to pixels by its own op rather than through an OCIO
    /// processor (`native`).
    bool appliesNatively() const noexcept { return native; }
};

/// Every method, in the order help texts and default lists give them.
const std::vector<MethodEntry>& Methods();

/// The entry of a method.
const MethodEntry& FindMethod(ChangeMethod method);

/// The entry of a method name (parsed with ParseMethod: throws for unknown names).
const MethodEntry& FindMethod(const std::string& name);

/// Parses a method name (case-insensitive); throws Exception listing the choices.
MethodSpec ParseMethod(const std::string& name);

/// The name of the reference method (the exact spectral answer).
std::string ReferenceMethodName();

/// Throws ParameterError when `method` needs the camera that shot the plates
/// and `haveCamera` is false: the one place that requirement is stated.
void RequireCamera(const MethodSpec& method, bool haveCamera);
/// The same for the camera the spec itself carries.
void RequireCamera(const MethodSpec& method);

/// `method` with the camera that shot the plates and the light of its one
/// fixed IDT, for the methods that need a camera (others are returned as
/// they are); throws ParameterError through RequireCamera when such a
/// method has no camera.
MethodSpec WithCamera(MethodSpec method, const std::shared_ptr<const SpectralCamera>& camera,
                      const Light& idtLight);

/// The training remittances a fitted method uses: its own, or its entry's
/// default; empty for methods that are not fitted.
const std::vector<NamedSpectrum>& TrainingOf(const MethodSpec& method);

/// The linear methods a config gets by default: none, vonkries, bradford,
/// cat02, band3, band3-wp.
const std::vector<std::string>& LinearMethodNames();

/// Every image method compared by `bandlight accuracy`: the linear ones,
/// band6, band6-wp, fit3x3, prefilter, metamer, upsample, rootpoly and
/// rootpoly3.
const std::vector<std::string>& AllMethodNames();

/// The methods the accuracy report measures when a camera is given and no
/// methods are named: rootpoly-camera.
const std::vector<std::string>& CameraMethodNames();

/// The methods `accuracy --light-group` measures when none are named:
/// bradford, cat02, fit3x3, rootpoly.
const std::vector<std::string>& LightGroupMethodNames();

/// The method an LED wall's post-camera look is (rootpoly-plate), and the
/// one it is compared with (rootpoly-camera): `wall` names neither.
const std::string& WallLookMethodName();
const std::string& WallComparisonMethodName();

/// The methods whose looks `package` applies to its sample chart: band3
/// (the band model) and bradford.
const std::vector<std::string>& PackageMethodNames();

/// Every method name a user can give, as help text: "none, vonkries, ...,
/// rootpoly-camera (with {camera})" (a ParameterError template).
std::string MethodSyntax();

/// One sentence on what a method does and how accurate it is, for look
/// descriptions and --help.
std::string DescribeMethod(const MethodSpec& method);

}  // namespace bandlight
