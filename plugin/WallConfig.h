// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An LED wall's transforms as an OCIO config: for each camera white
// balance the in-frustum drive, the lighting pre-correction, the
// post-camera look and the camera's IDT, files selected at run time by one
// context variable (wall/${WALL_WB}/...), so a host switches with the
// camera's setting.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "plugin/ConfigBuilder.h"

namespace bandlight
{

/// One white balance's transforms, as the files of the config carry them.
struct WallConfigBalance
{
    /// The context variable's value for it, and the folder of its files.
    std::string key;
    /// Raw camera RGB → working RGB: the IDT, white-balance gains folded in.
    Mat3 idt = Mat3::Identity();
    /// N × 3, content RGB → drive (N = 3 or 4; empty: no drive in the config).
    Eigen::MatrixXd inFrustum;
    /// N × N on the drive.
    Eigen::MatrixXd preCorrection;
    /// Working RGB → working RGB.
    Mat3 post = Mat3::Identity();
    /// The same correction's non-linear form as its op gives it in OCIO
    /// (IlluminantChangeTransform: shaper, 3D LUT, inverse shaper), its
    /// description added. Null: no such look.
    OCIO::ConstTransformRcPtr postNonLinear;
    /// What each file says it was made from.
    std::string idtDescription;
    std::string inFrustumDescription;
    std::string preDescription;
    std::string postDescription;
    std::string postNonLinearDescription;
};

struct WallConfigOptions
{
    std::string workingSpace;                 ///< the reference and the plates' space
    std::string contentSpace;                 ///< the wall's content
    std::string camera;                       ///< the camera's name
    std::string variable;                     ///< the context variable: WALL_WB
    std::vector<WallConfigBalance> balances;  ///< the first is the variable's default
    std::string description;
};

/// The names of the config's colour spaces and look.
inline constexpr const char* kWallDriveSpace = "LED wall drive";
inline constexpr const char* kWallLightingSpace = "LED wall drive - lighting";
inline constexpr const char* kWallPostLook = "wall_post_camera";
inline constexpr const char* kWallPostRootPolyLook = "wall_post_camera_rootpoly";

/// Where a white balance's file lives in the package: luts/wall/KEY/NAME.EXT
/// (CLF for three-channel transforms; OCIO's CTF where a drive is in
/// alpha, which CLF cannot hold), and the FileTransform path that reaches
/// it through the context variable: wall/${VAR}/NAME.EXT.
std::string WallFile(const std::string& key, const std::string& name, bool alpha);
std::string WallFileTemplate(const std::string& variable, const std::string& name, bool alpha);

/// A complete OCIO v2 config (BuildConfig's spaces, display and roles, the
/// reference being the working space) with an input colour space per white
/// balance (idt's), and, selected by the context variable (its default the
/// first balance's key, declared in the config's environment):
/// - "Input - <camera> - wall white balance": raw camera RGB → working;
/// - kWallDriveSpace (N ≤ 4): the reference → content → in-frustum drive
///   (RGB, or RGBA with the fourth emitter in alpha);
/// - kWallLightingSpace (N ≤ 4): the same, then the lighting pre-correction;
/// - the look kWallPostLook in the working space: the post-camera correction;
/// - the look kWallPostRootPolyLook (when every balance has postNonLinear):
///   the same correction's non-linear form.
/// Every transform is also a file of the package (the FileTransforms' targets).
/// Built with the Config API and validated.
ConfigPackage BuildWallConfig(const WallConfigOptions& options);

/// A drive matrix (N × 3 content → drive, or N × N on the drive; N ≤ 4) as
/// OCIO's 4×4: RGB(A) in, RGB(A) out; the content's alpha is not read.
OCIO::MatrixTransformRcPtr DriveMatrixTransform(const Eigen::MatrixXd& m);

}  // namespace bandlight
