// SPDX-License-Identifier: BSD-3-Clause
// The light-score registry (spectral/LightScores.h): every score named
// once, each light scored by every entry, and a light a standard gives no
// value for kept with a warning instead of failing the rest.
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/LightScores.h"

using namespace bandlight;
using Catch::Matchers::Contains;

TEST_CASE("Every light score is named once, with its standard and a definition",
          "[spectral][quality]")
{
    std::set<std::string> keys;
    for (const LightScoreEntry& e : LightScores())
    {
        INFO(e.key);
        CHECK(keys.insert(e.key).second);
        CHECK(std::string(e.standard).size() > 4);
        CHECK(std::string(e.definition).size() > 40);
        CHECK(&FindLightScore(e.key) == &e);
    }
    CHECK(keys.count("cct") == 1);
    CHECK(keys.count("cri") == 1);
    CHECK_THROWS_WITH(FindLightScore("cqs"),
                      Contains("unknown light score 'cqs'") && Contains("cct, cri"));
}

TEST_CASE("A Planckian light scores as its own reference", "[spectral][quality]")
{
    const LightQuality q = ScoreLight("3000K", Planckian(3000.0, 360.0, 5.0, 95));
    REQUIRE(q.score("cct"));
    CHECK(q.score("cct")->field("cct")->values[0] == Approx(3000.0).epsilon(1e-6));
    const Score* cri = q.score("cri");
    REQUIRE(cri);
    CHECK(cri->field("Ra")->values[0] == Approx(100.0).margin(1e-6));
    REQUIRE(cri->field("R")->values.size() == 15);  // R1–R15
    CHECK(cri->warnings.empty());
    // TLMF needs a reference: not scored without one.
    CHECK(q.score("tlmf") == nullptr);
}

TEST_CASE("A light a standard gives no value for keeps its other scores", "[spectral][quality]")
{
    // 30000 K lies outside CIE 13.3's 1000–25000 K: CRI has no value, says
    // why, and CCT is still given.
    const LightQuality q = ScoreLight("hot", Planckian(30000.0, 360.0, 5.0, 95));
    const Score* cri = q.score("cri");
    REQUIRE(cri);
    CHECK(cri->fields.empty());
    REQUIRE(cri->warnings.size() == 1);
    CHECK_THAT(cri->warnings[0], Contains("outside 1000–25000 K"));
    CHECK(q.score("cct")->field("cct")->values[0] == Approx(30000.0).epsilon(1e-4));
    // No power where the eye sees: no score at all, one line naming the light.
    CHECK_THROWS_WITH(ScoreLight("ir", Spectrum::Constant(900.0, 5.0, 20, 1.0)),
                      Contains("light 'ir' has no power in the visible range"));
}
