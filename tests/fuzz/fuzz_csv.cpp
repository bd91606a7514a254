// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes a spectrum file as bandlight reads one: the text checks (UTF-8,
// byte-order marks), the choice of reader by content, the CSV reader.
#include "FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    return bandlight::fuzz::FuzzSpectrumReader(data, size, "fuzz.csv", &bandlight::ReadSpectraText);
}
