// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Lights' scores (spectral/LightScores.h) written once for every face: the
// terminal table, JSON and CSV, each walking the scores' named fields, so
// a score added to the registry appears in all three.

#include <string>
#include <vector>

#include "spectral/LightScores.h"

namespace bandlight
{

/// A JSON list, one object per light: "light", the top-level scores'
/// fields ("cct", "duv"), then an object per score ({"Ra", "R": [...]},
/// "reference" when it has one; null when its standard gives it no value),
/// and "warnings", each naming its score.
std::string QualityJson(const std::vector<LightQuality>& lights);

/// CSV with a header row: light, then a column per value ("cri.Ra",
/// "cri.R9", "tm30.Rf_h3", "ssi.reference"), the union of every light's
/// columns in registry order (empty cells where a light has no value), and
/// "warnings" joined by " | ". RFC 4180 quoting.
std::string QualityCsv(const std::vector<LightQuality>& lights);

/// The terminal table: a row per light with each score's headline values
/// (CCT, Duv, Ra, R9, Rf, Rg, SSI, Qa, TLMF), then the warnings, numbered
/// by light.
std::string QualityText(const std::vector<LightQuality>& lights);

}  // namespace bandlight
