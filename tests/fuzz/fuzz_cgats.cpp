// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes the CGATS reader directly (ArgyllCMS and colord .sp, .cmf, .ti3),
// whatever the input holds.
#include <sstream>

#include "FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    return bandlight::fuzz::FuzzSpectrumReader(
        data, size, "fuzz.sp",
        [](const std::string& text, const std::string& source)
        {
            std::istringstream in(text);
            return bandlight::ReadCgatsSpectra(in, source);
        });
}
