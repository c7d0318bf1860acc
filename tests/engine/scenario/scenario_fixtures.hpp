// Scenarios the parser tests break one key at a time: a minimal 2D block, a minimal 3D ball, the 2D block with a
// steel beam under it.
#pragma once
#include <nlohmann/json.hpp>

#include "engine/scenario/scenario.hpp"

namespace dmi::test {

using json = nlohmann::json;

// A small valid 2D scenario that the error cases below break one key at a time.
inline json minimal_2d() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "Block on a floor",
    "analysis": {"end_time": 0.1},
    "grid": {"origin": [0, 0], "size": [2, 1], "cell_size": 0.1},
    "materials": [{"name": "rock", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
    "bodies": [{"name": "block", "material": "rock", "shape": {"type": "box", "min": [0.5, 0.2], "max": [1.0, 0.6]}}]
  })");
}

inline json minimal_3d() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "Ball in a box",
    "analysis": {"dimension": 3, "end_time": 0.1},
    "grid": {"origin": [0, 0, 0], "size": [1, 1, 1], "cell_size": 0.1},
    "materials": [{"name": "rock", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
    "bodies": [{"name": "ball", "material": "rock", "shape": {"type": "ball", "center": [0.5, 0.5, 0.5], "radius": 0.2}}]
  })");
}

inline Scenario parse(const json& j) { return parse_scenario(j.dump(2), "good.json"); }

// minimal_2d() plus a steel beam under the block, pinned at A and on a roller at B, with only the
// required keys.
inline json frame_2d() {
  json j = minimal_2d();
  j["materials"].push_back({{"name", "steel"}, {"density", 7850}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}});
  j["structure"] = json::parse(R"({
    "nodes": [{"name": "A", "position": [0.2, 0.1]}, {"name": "B", "position": [1.8, 0.1]}],
    "members": [{"name": "beam", "start": "A", "end": "B", "material": "steel", "section": {"type": "rectangle", "width": 0.05, "depth": 0.1}}],
    "supports": [{"node": "A", "type": "pinned"}, {"node": "B", "type": "roller"}]
  })");
  return j;
}

}  // namespace dmi::test
