// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "transforms/IlluminantChange.h"

namespace bandlight::test
{

/// A method for lit plates: the physical change between two lights, which
/// the tests of the methods' physics check (a MethodSpec's default plates
/// are balanced, as every face of bandlight has them).
inline MethodSpec LitMethod(const std::string& name)
{
    MethodSpec m = ParseMethod(name);
    m.plates = Plates::Lit();
    return m;
}

}  // namespace bandlight::test
