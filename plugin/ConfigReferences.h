// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

namespace bandlight
{
namespace OCIO = OCIO_NAMESPACE;

/// Checks that no colour space, look, named transform or view transform of
/// `config` refers to itself, directly or through others (a
/// ColorSpaceTransform whose source is the space that holds it, a look that
/// applies itself, a display view through a space that uses that view...).
/// OpenColorIO 2.1 follows such references without a limit and overflows
/// the stack when it builds a processor, so bandlight refuses them first.
/// Throws Exception "FILE: the config refers to itself: colour space 'a' ->
/// colour space 'b' -> colour space 'a'" (names as the config spells them;
/// `file` names the config in the message).
void CheckConfigReferences(const OCIO::ConstConfigRcPtr& config, const std::string& file);

/// Every colour space of a config, active and inactive, in the config's
/// order, in time linear in their number (OpenColorIO 2.1's lookup by name
/// scans every colour space, so looking each up by name is quadratic).
std::vector<OCIO::ConstColorSpaceRcPtr> AllColorSpaces(const OCIO::ConstConfigRcPtr& config);

}  // namespace bandlight
