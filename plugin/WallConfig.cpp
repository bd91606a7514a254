// SPDX-License-Identifier: BSD-3-Clause
// An LED wall's transforms as an OCIO config, one set of files per camera
// white balance, chosen by a context variable.
#include "plugin/WallConfig.h"

#include <algorithm>

#include "plugin/detail/ConfigParts.h"
#include "spectral/Exception.h"
#include "transforms/Idt.h"

namespace bandlight
{

namespace
{

/// A transform with its description, as its file's metadata carries it.
OCIO::GroupTransformRcPtr Described(const OCIO::TransformRcPtr& t, const std::string& description)
{
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    g->appendTransform(InfinityGuard());
    g->appendTransform(t);
    g->getFormatMetadata().addChildElement(OCIO::METADATA_DESCRIPTION, description.c_str());
    return g;
}

OCIO::FileTransformRcPtr File(const std::string& src)
{
    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
    f->setSrc(src.c_str());
    f->setInterpolation(OCIO::INTERP_BEST);
    return f;
}

}  // namespace

std::string WallFile(const std::string& key, const std::string& name, bool alpha)
{
    return std::string(detail::kLutFolder) + "/wall/" + key + "/" + name +
           (alpha ? ".ctf" : ".clf");
}

std::string WallFileTemplate(const std::string& variable, const std::string& name, bool alpha)
{
    return "wall/${" + variable + "}/" + name + (alpha ? ".ctf" : ".clf");
}

OCIO::MatrixTransformRcPtr DriveMatrixTransform(const Eigen::MatrixXd& m)
{
    const Eigen::Index n = m.rows();
    if (n < 3 || n > 4 || (m.cols() != 3 && m.cols() != n))
    {
        throw Exception("an OCIO matrix holds at most four drive channels, not " +
                        std::to_string(n));
    }
    // OCIO's 4×4, row-major; with three channels alpha passes unchanged
    // (CLF can hold that), with four the fourth drive is the alpha row and
    // the content's own alpha is not read.
    double v[16] = {};
    for (Eigen::Index r = 0; r < n; ++r)
    {
        for (Eigen::Index c = 0; c < m.cols(); ++c)
        {
            v[4 * r + c] = m(r, c);
        }
    }
    if (n == 3)
    {
        v[15] = 1.0;
    }
    OCIO::MatrixTransformRcPtr t = OCIO::MatrixTransform::Create();
    t->setMatrix(v);
    return t;
}

ConfigPackage BuildWallConfig(const WallConfigOptions& o)
{
    if (o.balances.empty())
    {
        throw Exception("a wall config needs at least one white balance");
    }
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    const RgbSpace& content = FindRgbSpace(o.contentSpace);
    ConfigOptions base;
    base.workingSpace = working.name;
    for (const WallConfigBalance& b : o.balances)
    {
        base.inputSpaces.push_back(
            {IdtColorSpaceName(o.camera, b.key), b.idtDescription, b.idt, working.name});
    }
    ConfigPackage package = BuildConfig(base);
    OCIO::Config& config = *package.config;
    config.setDescription(o.description.c_str());
    config.addEnvironmentVar(o.variable.c_str(), o.balances.front().key.c_str());

    const bool nonLinear =
        std::all_of(o.balances.begin(), o.balances.end(),
                    [](const WallConfigBalance& b) { return b.postNonLinear != nullptr; });
    const Eigen::Index n = o.balances.front().inFrustum.rows();
    const bool drives = n == 3 || n == 4;
    const bool alpha = n == 4;
    for (const WallConfigBalance& b : o.balances)
    {
        package.lutFiles.emplace_back(WallFile(b.key, "idt", false),
                                      Described(MakeMatrixTransform(b.idt), b.idtDescription));
        package.lutFiles.emplace_back(WallFile(b.key, "post_camera", false),
                                      Described(MakeMatrixTransform(b.post), b.postDescription));
        if (nonLinear)
        {
            OCIO::TransformRcPtr look = b.postNonLinear->createEditableCopy();
            OCIO::GroupTransformRcPtr g = OCIO::DynamicPtrCast<OCIO::GroupTransform>(look);
            if (!g)
            {
                g = OCIO::GroupTransform::Create();
                g->appendTransform(look);
            }
            g->getFormatMetadata().addChildElement(OCIO::METADATA_DESCRIPTION,
                                                   b.postNonLinearDescription.c_str());
            package.lutFiles.emplace_back(WallFile(b.key, "post_camera_rootpoly", false), g);
        }
        if (drives)
        {
            package.lutFiles.emplace_back(
                WallFile(b.key, "in_frustum", alpha),
                Described(DriveMatrixTransform(b.inFrustum), b.inFrustumDescription));
            package.lutFiles.emplace_back(
                WallFile(b.key, "pre_correction", alpha),
                Described(DriveMatrixTransform(b.preCorrection), b.preDescription));
        }
    }
    const std::string var = "$" + o.variable;
    OCIO::ColorSpaceRcPtr input =
        detail::SceneSpace(IdtColorSpaceName(o.camera, "wall white balance"), "Input",
                           "Camera " + o.camera + " raw RGB to " + working.displayName +
                               " through bandlight's IDT for "
                               "the white balance " +
                               var + " names (its gains folded in).",
                           "scene-linear");
    input->setTransform(File(WallFileTemplate(o.variable, "idt", false)),
                        OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config.addColorSpace(input);
    if (drives)
    {
        const std::string channels = alpha ? "R, G, B and alpha the four emitters' drives"
                                           : "R, G, B the three emitters' drives";
        const auto driveSpace = [&](const char* name, bool lighting)
        {
            OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
            g->appendTransform(GuardedMatrixTransform(SpaceToSpace(working, content)));
            g->appendTransform(File(WallFileTemplate(o.variable, "in_frustum", alpha)));
            if (lighting)
            {
                g->appendTransform(File(WallFileTemplate(o.variable, "pre_correction", alpha)));
            }
            OCIO::ColorSpaceRcPtr cs = detail::SceneSpace(
                name, "Wall",
                std::string(lighting ? "Out of the frustum: the wall's drive for lighting "
                                       "content, pre-corrected so that surfaces it lights look to "
                                       "the camera as under the light the content shows. "
                                     : "In the frustum: the wall's drive that makes the camera "
                                       "record the content as intended. ") +
                    "From " + ColorSpaceName(content) + " content; " + channels +
                    "; for the camera white balance " + var + " names.",
                "");
            cs->setTransform(g, OCIO::COLORSPACE_DIR_FROM_REFERENCE);
            config.addColorSpace(cs);
        };
        driveSpace(kWallDriveSpace, false);
        driveSpace(kWallLightingSpace, true);
    }
    OCIO::LookRcPtr look = OCIO::Look::Create();
    look->setName(kWallPostLook);
    look->setProcessSpace(ColorSpaceName(working).c_str());
    look->setTransform(File(WallFileTemplate(o.variable, "post_camera", false)));
    look->setDescription(("The plate of a scene lit by the wall made to look as under the light "
                          "the wall shows, for the camera white balance " +
                          var + " names.")
                             .c_str());
    config.addLook(look);
    if (nonLinear)
    {
        OCIO::LookRcPtr rootpoly = OCIO::Look::Create();
        rootpoly->setName(kWallPostRootPolyLook);
        rootpoly->setProcessSpace(ColorSpaceName(working).c_str());
        rootpoly->setTransform(File(WallFileTemplate(o.variable, "post_camera_rootpoly", false)));
        rootpoly->setDescription(
            ("The same correction as " + std::string(kWallPostLook) +
             " by the method registry's rootpoly-plate op (a degree-2 root polynomial, lower "
             "error on the training set; a 3D LUT with a shaper), for the camera white balance " +
             var + " names.")
                .c_str());
        config.addLook(rootpoly);
    }
    config.validate();
    return package;
}

}  // namespace bandlight
