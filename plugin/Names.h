// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The names bandlight gives what it writes into configs — looks, named
// transforms, context-variable values — apart from OpenColorIO's headers,
// so code that only names things does not parse them (defined in
// plugin/OcioTransforms.cpp).

#include <string>

namespace bandlight
{

/// "band3-wp_A_to_D65": a look / named-transform name without characters
/// that hosts' option syntax reserves (anything but letters, digits, '.',
/// '_' and '-' becomes '_').
std::string LookName(const std::string& method, const std::string& from, const std::string& to);

/// A name made safe for OCIO and for hosts' option syntax (see LookName).
std::string SafeName(const std::string& text);

}  // namespace bandlight
