// A scenario's identity: the low-level scenario in canonical JSON and the variant, whatever the spacing and key
// order of the text; the hash itself is FIPS 180-4 SHA-256 (known answers).
#include <gtest/gtest.h>

#include "engine/scenario/identity.hpp"
#include "engine/scenario/sha256.hpp"

namespace dmi {
namespace {

TEST(ScenarioIdentity, SameLowLevelScenarioWhateverItsSpacingAndKeyOrder) {
  const std::string a = R"({"name": "x", "grid": {"cell_size": 0.1, "origin": [0, 0]}})";
  const std::string b = "{\"grid\":{\"origin\":[0,0],\"cell_size\":0.1},\n  \"name\":\"x\"}";
  EXPECT_EQ(scenario_identity(a, "", ""), scenario_identity(b, "", ""));
  // With presets the expansion is the scenario run: two files expanding alike are one run.
  EXPECT_EQ(scenario_identity(R"({"preset": 1})", a, "with_buffer"), scenario_identity(R"({"preset": 2})", b, "with_buffer"));
}

TEST(ScenarioIdentity, ChangesWithAValueOrTheVariant) {
  const std::string a = R"({"name": "x", "grid": {"cell_size": 0.1}})";
  EXPECT_NE(scenario_identity(a, "", ""), scenario_identity(R"({"name": "x", "grid": {"cell_size": 0.05}})", "", ""));
  EXPECT_NE(scenario_identity("{}", a, "with_buffer"), scenario_identity("{}", a, "without_buffer"));
  EXPECT_EQ(scenario_identity(a, "", "").size(), 64u);
  // The identity is the digest of the canonical text and the label: json's dump() sorts keys, no spaces.
  EXPECT_EQ(scenario_identity(a, "", "v"), sha256_hex(R"({"grid":{"cell_size":0.1},"name":"x"})" + std::string("\nv")));
}

}  // namespace
}  // namespace dmi
