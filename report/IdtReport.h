// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `idt`'s result as a JSON document and as the text report.

#include <string>

#include "requests/Idt.h"

namespace bandlight::jobs
{

/// The JSON document of a result (`idt --json`): {"camera", "working_space",
/// "idts": [{"light", "cct", "duv", "gains", "matrix", "first_order_matrix",
/// "error": {SET: {"mean", "p95", "max"}}, ...}], "as_shot": {...},
/// "interpolation": {...}}.
std::string IdtDocument(const IdtResult& result);

/// The text report of a result.
std::string IdtReport(const IdtResult& result);

/// One IDT as the description of its input colour space in a config: the
/// camera, the light, the matrix and its errors.
std::string IdtDescription(const IdtEntry& entry, const std::string& camera,
                           const IdtResult& result);

}  // namespace bandlight::jobs
