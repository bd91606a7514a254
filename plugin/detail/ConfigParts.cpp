// SPDX-License-Identifier: BSD-3-Clause
#include "plugin/detail/ConfigParts.h"

namespace bandlight::detail
{

OCIO::ColorSpaceRcPtr SceneSpace(const std::string& name, const std::string& family,
                                 const std::string& description, const std::string& encoding)
{
    OCIO::ColorSpaceRcPtr cs = OCIO::ColorSpace::Create(OCIO::REFERENCE_SPACE_SCENE);
    cs->setName(name.c_str());
    cs->setFamily(family.c_str());
    cs->setDescription(description.c_str());
    cs->setEncoding(encoding.c_str());
    return cs;
}

bool IsV1(const OCIO::Config& config)
{
    return config.getMajorVersion() < 2;
}

OCIO::TransformRcPtr AsLutFile(ConfigPackage& package, const std::string& name,
                               const OCIO::GroupTransformRcPtr& t)
{
    const std::string file = SafeName(name) + ".clf";
    package.lutFiles.emplace_back(std::string(kLutFolder) + "/" + file, t);
    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
    f->setSrc(file.c_str());
    f->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    return f;
}

}  // namespace bandlight::detail
