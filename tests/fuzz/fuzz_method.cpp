// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes method names ("band3-wp", "bands380-480-560-780", ...) and band
// sets: a name either parses into a method whose A → D65 matrix is finite,
// or is refused with an Exception — singular band sets included.
#include "FuzzCheck.h"
#include "spectral/Illuminants.h"
#include "spectral/RgbSpaces.h"
#include "transforms/IlluminantChange.h"

using namespace bandlight;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size > 256)
    {
        return 0;  // names are short; long ones only slow the search
    }
    const std::string text = fuzz::Text(data, size);
    try
    {
        const BandSet bands = BandSet::Parse(text);
        fuzz::Check(bands.size() >= 1, "a parsed band set with no bands");
    }
    catch (const Exception&)
    {
    }
    MethodSpec method;
    try
    {
        method = ParseMethod(text);
    }
    catch (const Exception&)
    {
        return 0;
    }
    if (!method.isLinear() || method.method == ChangeMethod::FIT3X3 ||
        method.method == ChangeMethod::METAMER)
    {
        return 0;  // fixed names: nothing parsed from the input reaches them
    }
    static const Light a{"A", BuiltinIlluminant("A")};
    static const Light d65{"D65", BuiltinIlluminant("D65")};
    try
    {
        const Mat3 m = IlluminantChangeMatrix(a, d65, method, FindRgbSpace("acescg"));
        fuzz::Check(m.allFinite(), "matrix of method '" + method.name + "' is not finite");
    }
    catch (const Exception&)
    {
    }
    return 0;
}
