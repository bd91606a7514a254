// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "plugin/ConfigInputSpaces.h"
#include "plugin/OcioTransforms.h"
#include "spectral/AtomicFile.h"
#include "spectral/RgbSpaces.h"
#include "transforms/Defaults.h"

namespace bandlight
{

/// What goes into a config: the working space, the lights and the methods.
/// Every ordered pair of distinct lights gets one look per method, named
/// <method>_<FROM>_to_<TO>, and the same as a named transform relight_<look>.
struct ConfigOptions
{
    std::string workingSpace = defaults::WORKING_SPACE;
    std::vector<Light> lights;
    std::vector<std::string> methods;
    Observer observer = Observer::CIE1931_2DEG;
    /// Lattice size of the non-linear looks' 3D LUTs (upsample, rootpoly,
    /// rootpoly-camera; defaults::CONFIG_LUT_SIZE, 65): 65³ keeps the LUT's
    /// own error near 0.05 ΔE00 where 33³ adds up to 0.25 (docs/accuracy.md);
    /// a 65³ CLF file is about 12 MB.
    int lutSize = defaults::CONFIG_LUT_SIZE;
    /// Where the config will be written (ExtendConfig: the base's relative
    /// search paths are rewritten to reach the base's folder from here).
    std::string outputDir;
    /// ExtendConfig: how messages name the base (its file, when read from one).
    std::string baseName = "the base config";
    /// ExtendConfig: rewrite the base's relative search paths as absolute
    /// paths instead of paths relative to outputDir.
    bool absoluteBasePaths = false;
    /// What the pipeline's images are. Balanced (CAT02) by default: in an
    /// ACES pipeline every IDT white-balances, so a plate shot under
    /// tungsten arrives neutral (docs/plates.md).
    Plates plates{PlateConvention::BALANCED, AdaptationMethod::CAT02};
    /// rootpoly-camera: the camera that shot the plates and the light of
    /// its one fixed IDT (empty name: DEFAULT_IDT_LIGHT).
    std::shared_ptr<const SpectralCamera> camera;
    std::string idtLightName;
    Spectrum idtLight;

    /// Input colour spaces to add (camera IDTs). A config of input spaces
    /// alone has no lights and no methods, and so no looks.
    std::vector<InputSpace> inputSpaces;

    /// A method of these options: parsed, with the plates and camera set.
    MethodSpec method(const std::string& name) const;
};

/// A config with the LUT files its non-linear looks reference (paths
/// relative to the config's directory, "luts/<look>.clf").
struct ConfigPackage
{
    OCIO::ConfigRcPtr config;
    std::vector<std::pair<std::string, OCIO::GroupTransformRcPtr>> lutFiles;
    std::string evidence;  ///< ExtendConfig: what identified scene_linear's primaries
    bool v1 = false;       ///< ExtendConfig: the base (and so the result) is an OCIO v1 config
    /// ExtendConfig: the config's serialisation as checked (read back and
    /// compared with the base), which WriteConfigPackage writes; empty: it
    /// serialises the config itself. Clear it when changing the config.
    std::string text;
};

/// The band model's five illuminants: A, C, D65, F2, F11.
std::vector<Light> LectureLights();

/// A complete OCIO v2 config whose reference and scene_linear space is the
/// working space: linear spaces for every built-in primaries set, ACES2065-1
/// and CIE-XYZ-D65 interchange spaces, an sRGB-encoded space, a Non-Color
/// data space, the band model's band space, an sRGB display with Standard and
/// Raw views, every role ociocheck and Blender ask for, and the looks and
/// named transforms. Built with the OCIO Config API and validated. Linear
/// methods are inline matrices; upsample looks are FileTransforms of CLF
/// files (shaper + 33³ LUT + inverse shaper) in the package's luts/ folder.
ConfigPackage BuildConfig(const ConfigOptions& options);

/// Adds the same looks, named transforms and band space to a copy of an
/// existing config, leaving everything it had intact:
/// - the copy serialises to exactly the base's text (OpenColorIO 2.1's own
///   copy loses default_view_transform, which is restored; any other loss is
///   refused), before the additions;
/// - an OCIO v1 base stays v1 (OCIO 2.1 evaluates some v1 transforms
///   differently in a v2 config): the looks and the band space are CLF
///   files in luts/ referenced by FileTransforms, and there are no named
///   transforms (a v2 feature);
/// - every base colour space (both directions to scene_linear), display and
///   view, look and named transform is checked to give the same pixels in
///   the result;
/// - relative search paths are rewritten to reach the base's folder from
///   `options.outputDir` (relative, so the two trees move together; or
///   absolute with `options.absoluteBasePaths`).
/// The looks' process space is the base's scene_linear role. Its primaries
/// are identified by IdentifySceneLinear (interchange roles, or standard
/// colour spaces of the config, measured) unless `detect` is false and
/// `options.workingSpace` names them. Throws Exception when the space cannot
/// be identified, a new name clashes with the base, or the base would change.
ConfigPackage ExtendConfig(const OCIO::ConstConfigRcPtr& base, ConfigOptions options, bool detect,
                           std::string* identifiedSpace = nullptr);

/// The config as text: OCIO's serialisation, with what OCIO 2.1 leaves out
/// of a v1 config (its `environment:` section) put back.
std::string SerializeConfig(const OCIO::ConstConfigRcPtr& config);

/// Writes the package as DIR/config.ocio plus its LUT files (creating the
/// folders their paths name; each written by OCIO's GroupTransform::write as
/// CLF, or as OCIO's CTF when its path ends in .ctf), as one set of outputs:
/// all files are replaced together once all are written, or none is. With
/// `outputs`, the files join that set and the caller commits it.
void WriteConfigPackage(const ConfigPackage& package, const std::string& dir,
                        OutputSet* outputs = nullptr);

/// The named transform that carries the same transform as a look:
/// "relight_<look>" (OCIO does not let the two share a name).
std::string NamedTransformName(const std::string& lookName);

/// The sRGB piecewise curve (IEC 61966-2-1) as an OCIO transform, encoded →
/// linear (alpha unchanged); inverse direction to encode.
OCIO::TransformRcPtr SrgbDecode();

/// The name of the colour space that holds a built-in RGB space in configs
/// bandlight builds ("ACEScg", "Linear Rec.709 (sRGB)", ...).
std::string ColorSpaceName(const RgbSpace& space);

}  // namespace bandlight
