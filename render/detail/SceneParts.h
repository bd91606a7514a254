// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The parts of the scene reader (render/SceneFile.cpp) that live in files of
// their own: the lights (render/SceneLights.cpp) and the materials
// (render/SceneMaterials.cpp). Internal to render/ (not installed).

#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "render/Scene.h"
#include "render/detail/YamlReader.h"

namespace bandlight::detail
{

/// Band values `{bands: [...]}`, one per render band; `name` gets them as
/// written. A light spectrum and a remittance may both be written so.
std::vector<double> BandValues(const YamlReader& r, const YAML::Node& v, const BandSet& bands,
                               std::string& name);

/// The lights, each named once. Returns the number of direct (not ambient)
/// lights.
int ReadLights(const YamlReader& r, const YAML::Node& ls, const BandSet& bands, Scene& s);

/// Material name → index into Scene::materials.
using MaterialIndex = std::map<std::string, int>;

/// The materials, each defined once; R_amb* only beside exactly one direct
/// light (`direct`, as ReadLights counts them).
MaterialIndex ReadMaterials(const YamlReader& r, const YAML::Node& ms, const BandSet& bands,
                            int direct, Scene& s);

}  // namespace bandlight::detail
