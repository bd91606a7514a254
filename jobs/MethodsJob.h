// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// `methods`: every illuminant-change method of the registry, as it
// describes itself.

#include <string>
#include <vector>

#include <bandlight/Types.h>

namespace bandlight::jobs
{

/// One registry entry, as `bandlight methods` lists it (a public type).
using MethodInfo = bandlight::MethodInfo;

/// Every method, in the registry's order.
std::vector<MethodInfo> ListMethods();

/// The list as JSON (an array of objects with the fields above, snake_case).
std::string MethodsDocument(const std::vector<MethodInfo>& methods);

}  // namespace bandlight::jobs
