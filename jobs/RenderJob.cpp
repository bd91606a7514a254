// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/RenderJob.h"

#include "render/SceneFile.h"
#include "spectral/Exception.h"

namespace bandlight::jobs
{

Scene LoadScene(const std::string& path, const std::optional<std::string>& text,
                const std::string& source, const std::optional<std::string>& mode)
{
    if (path.empty() == !text.has_value())
    {
        throw ParameterError("give a scene file or {text=}YAML, one of the two");
    }
    const std::string name = text ? source : path;
    Scene scene = text ? ReadSceneText(*text, source) : ReadSceneFile(path);
    if (mode)
    {
        if (ModeBandCount(*mode) == 0 && scene.settings.output == "bands")
        {
            throw ParameterError("{mode} " + OneLine(*mode, 80) + ": " + name +
                                 " asks for output 'bands' (band values), which only band mode "
                                 "writes; set render: {output: acescg} (or another working "
                                 "space) to render it spectrally");
        }
        SetRenderMode(scene.settings, *mode);
    }
    return scene;
}

}  // namespace bandlight::jobs
