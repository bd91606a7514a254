// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The light-quality scores bandlight gives a light, each named once: its
// key (as `quality --json` writes it), its standard, what it means, and how
// it is computed from a spectrum. Every face (the `quality` table, JSON and
// CSV, Python, the farm) walks this registry; adding a score is one entry
// in LightScores.cpp with a test of its standard's published figures.
//
// A score's values are named fields of numbers ("Ra", "R" = R1–R15), so
// one serialiser writes every score: JSON objects, CSV columns ("cri.R9"),
// terminal rows.

#include <optional>
#include <string>
#include <vector>

#include "spectral/Spectrum.h"

namespace bandlight
{

/// One named value or list of values of a score.
struct ScoreField
{
    std::string name;            ///< "Ra", "R", "Rf_h"
    std::vector<double> values;  ///< one value, or the list
    bool list = false;           ///< written as a JSON array (even of one)
    /// The label of each list element in CSV columns and tables ("R1"…),
    /// empty for numbered from 1.
    std::vector<std::string> labels;
};

/// A score of one light.
struct Score
{
    std::string key;                    ///< the entry's key
    std::vector<ScoreField> fields;     ///< empty when the score has no value
    std::string reference;              ///< the light it compares with, if any
    std::vector<std::string> warnings;  ///< where its standard says it means less

    /// The field of `name`, or nullptr.
    const ScoreField* field(const std::string& name) const;
};

/// What a score may compare a light with.
struct ScoreContext
{
    /// A reference light the user named (`--reference`): TLMF needs one;
    /// SSI uses it instead of its own default reference when given.
    std::optional<Spectrum> reference;
    std::string referenceName;
};

/// One score of the registry.
struct LightScoreEntry
{
    const char* key;         ///< "cct", "cri", "cie2017", "tm30", "ssi", "tlci", "tlmf"
    const char* label;       ///< the short name tables head its value with ("SSI")
    const char* name;        ///< "CIE 13.3 colour rendering index"
    const char* standard;    ///< "CIE 13.3-1995", with the edition
    const char* definition;  ///< one sentence: what it measures, against what
    /// The values a one-line table shows for it, comma-separated, each
    /// "field[=Header][:decimals]": a field's name ("Ra") or the label of a
    /// list element ("R9"), headed by its name unless a header is given,
    /// with one decimal unless told; nullptr for none.
    const char* headline;
    /// Computed only when the context has a reference (TLMF).
    bool needsReference;
    /// Its fields belong to the light itself (CCT, Duv): JSON writes them
    /// beside "light", not in an object of their own.
    bool topLevel;
    /// The score of `light` (a spectrum in relative power, any grid).
    /// Throws Exception only for a light no score can be given for (no
    /// power in the visible range); a light a standard gives no value for
    /// (a CCT outside its range) gets a Score without fields and a warning.
    Score (*compute)(const Spectrum& light, const ScoreContext& context);
};

/// Every score, in the order tables and JSON list them.
const std::vector<LightScoreEntry>& LightScores();

/// The score of `key`; throws ParameterError listing the keys when there
/// is none.
const LightScoreEntry& FindLightScore(const std::string& key);

/// A light scored by every entry of the registry that applies.
struct LightQuality
{
    std::string light;          ///< its name, as the user gave it
    std::vector<Score> scores;  ///< in registry order

    /// The score of `key`, or nullptr when it was not computed.
    const Score* score(const std::string& key) const;
};

/// Scores `light` by every entry of LightScores() (those needing a
/// reference only when `context` has one).
LightQuality ScoreLight(const std::string& name, const Spectrum& light,
                        const ScoreContext& context = {});

}  // namespace bandlight
