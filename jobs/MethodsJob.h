// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// `methods`: every illuminant-change method of the registry, as it
// describes itself.

#include <string>
#include <vector>

namespace bandlight::jobs
{

/// One registry entry, as `bandlight methods` lists it.
struct MethodInfo
{
    std::string names;        ///< its names as help gives them: "rootpoly, rootpoly3"
    std::string exactness;    ///< "linear" (one 3x3), "non-linear" (an op per pixel) or "reference"
    bool native = false;      ///< `apply` runs its op itself, not its OCIO form
    bool needsCamera = false; ///< needs the camera that shot the plates
    bool takesTraining = false;  ///< a user's training set may replace its own
    size_t trainingSize = 0;     ///< its default training set's size (0: not fitted)
    std::vector<std::string> defaultIn;  ///< "config", "accuracy", "camera accuracy"
    std::string description;  ///< its own sentence, for its first name
};

/// Every method, in the registry's order.
std::vector<MethodInfo> ListMethods();

/// The list as JSON (an array of objects with the fields above, snake_case).
std::string MethodsDocument(const std::vector<MethodInfo>& methods);

}  // namespace bandlight::jobs
