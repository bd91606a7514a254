// SPDX-License-Identifier: BSD-3-Clause
// How a config holds its input colour spaces (camera IDTs).
#include "plugin/ConfigInputSpaces.h"

#include "plugin/detail/ConfigParts.h"
#include "spectral/Exception.h"

namespace bandlight::detail
{

void AddInputSpaces(ConfigPackage& package, const std::vector<InputSpace>& spaces,
                    const RgbSpace& working, const OCIO::ConstTransformRcPtr& workingToReference)
{
    OCIO::Config& config = *package.config;
    for (const InputSpace& in : spaces)
    {
        if (config.getColorSpace(in.name.c_str()))
        {
            throw Exception("the config already has a colour space named '" + in.name + "'");
        }
        OCIO::ColorSpaceRcPtr cs = SceneSpace(in.name, "Input", in.description, "scene-linear");
        const Mat3 m = SpaceToSpace(FindRgbSpace(in.space), working) * in.toSpace;
        OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
        const OCIO::GroupTransformRcPtr matrix = GuardedMatrixTransform(m);
        if (IsV1(config))
        {
            g->appendTransform(AsLutFile(package, in.name, matrix));
        }
        else
        {
            g->appendTransform(matrix);
            OCIO::GroupTransformRcPtr file = GuardedMatrixTransform(in.toSpace);
            file->getFormatMetadata().addChildElement(OCIO::METADATA_DESCRIPTION,
                                                      in.description.c_str());
            package.lutFiles.emplace_back(
                std::string(kLutFolder) + "/" + SafeName(in.name) + ".clf", file);
        }
        if (workingToReference)
        {
            g->appendTransform(workingToReference->createEditableCopy());
        }
        cs->setTransform(g, OCIO::COLORSPACE_DIR_TO_REFERENCE);
        config.addColorSpace(cs);
    }
}

}  // namespace bandlight::detail
