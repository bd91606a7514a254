// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "render/Scene.h"

namespace bandlight
{

/// Reads a YAML scene (format: docs/scenes.md). Every error — unknown or
/// unused key, wrong type, negative size, missing file, unknown name — is an
/// Exception "FILE:LINE: what" pointing at the offending key or value.
/// Relative spectrum file paths are relative to the scene file.
Scene ReadSceneFile(const std::string& path);

/// The same for scene text already in memory; `path` names it in messages
/// and anchors its relative file names.
Scene ReadSceneText(const std::string& text, const std::string& path);

}  // namespace bandlight
