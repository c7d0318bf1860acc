// Permanent pressure loads on members (earth and water behind a dam) held from t = 0: a vertical cantilever in static
// equilibrium under a triangular pressure carries the hand-calculated base shear and moment, and stays there.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "design/design.hpp"
#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

using J = nlohmann::json;

// A 4 m concrete cantilever (fixed at y = 0) with pressure gradient g = 20 kN/m^2 per m up to a surface at s = 3 m:
// base shear g s^2 / 2 = 90 kN, base moment g s^3 / 6 = 90 kN m (the resultant at s/3 = 1 m above the base).
J cantilever(double surface) {
  return J::parse(R"({"schema_version": 1, "name": "wall",
    "analysis": {"dimension": 2, "end_time": 0.02, "gravity": [0, -9.81]},
    "grid": {"origin": [-2.0, -0.5], "size": [6.0, 5.5], "cell_size": 0.25},
    "materials": [{"name": "concrete", "density": 2400, "youngs_modulus": 25e9, "poisson_ratio": 0.2},
                  {"name": "soft", "density": 1000, "youngs_modulus": 1e6, "poisson_ratio": 0.3}],
    "bodies": [{"name": "block", "material": "soft", "shape": {"type": "box", "min": [2.5, 0.0], "max": [2.75, 0.25]}}],
    "walls": [{"name": "floor", "type": "plane", "point": [0, 0], "normal": [0, 1], "condition": "stick"}],
    "structure": {"integrator": "newmark",
      "nodes": [{"name": "A", "position": [0, 0]}, {"name": "B", "position": [0, 4]}],
      "members": [{"name": "wall", "start": "A", "end": "B", "material": "concrete", "elements": 8,
                   "section": {"type": "rectangle", "width": 1.0, "depth": 0.8}}],
      "supports": [{"node": "A", "type": "fixed"}],
      "pressure_loads": [{"member": "wall", "direction": [1, 0], "surface": )" + std::to_string(surface) + R"(, "gradient": 20000}]},
    "output": {"history_interval": 0.005}})");
}

TEST(PressureLoads, ACantileverCarriesTheTriangularPressureFromTheStart) {
  const RunOutput out = run_quiet(parse_scenario(cantilever(3.0).dump(), "test"));
  const Series* r = out.results.find("supports/A/reaction");
  ASSERT_NE(r, nullptr);
  for (std::size_t k = 0; k < out.results.time.size(); ++k) {  // in equilibrium from t = 0: it does not ring
    EXPECT_NEAR(r->data[3 * k], -90e3, 1e-6 * 90e3) << k;        // the support pushes back upstream
    EXPECT_NEAR(r->data[3 * k + 1], 2400 * 9.81 * 0.8 * 4.0, 1e-6 * 75e3) << k;
    EXPECT_NEAR(r->data[3 * k + 2], 90e3, 1e-6 * 90e3) << k;    // resisting the overturning of the load at 1 m
  }
}

// The surface inside an element (3.2 m, elements of 0.5 m): g s^2 / 2 = 102.4 kN, g s^3 / 6 = 109.227 kN m, exact.
TEST(PressureLoads, TheSurfaceInsideAnElementKeepsTheResultants) {
  const RunOutput out = run_quiet(parse_scenario(cantilever(3.2).dump(), "test"));
  const Series* r = out.results.find("supports/A/reaction");
  ASSERT_NE(r, nullptr);
  EXPECT_NEAR(r->data[0], -20e3 * 3.2 * 3.2 / 2, 1e-6 * 102.4e3);
  EXPECT_NEAR(r->data[2], 20e3 * 3.2 * 3.2 * 3.2 / 6, 1e-6 * 109.2e3);
}

// The same cantilever as a space frame (z up, the pressure along x): the same reactions, Fx -90 kN and a moment about
// +y of -90 kN m (the support turns the wall back upstream: about +y, z towards x is positive).
TEST(PressureLoads, ASpaceFrameCarriesTheSamePressure) {
  J j = cantilever(3.0);
  j["analysis"] = J{{"dimension", 3}, {"end_time", 0.02}, {"gravity", {0, 0, -9.81}}};
  j["grid"] = J{{"origin", {-2.0, -1.0, -0.5}}, {"size", {6.0, 2.0, 5.5}}, {"cell_size", 0.25}};
  j["bodies"][0]["shape"] = J{{"type", "box"}, {"min", {2.5, -0.125, 0.0}}, {"max", {2.75, 0.125, 0.25}}};
  j["walls"][0]["point"] = {0, 0, 0};
  j["walls"][0]["normal"] = {0, 0, 1};
  j["structure"]["nodes"] = J::parse(R"([{"name": "A", "position": [0, 0, 0]}, {"name": "B", "position": [0, 0, 4]}])");
  j["structure"]["pressure_loads"][0]["direction"] = {1, 0, 0};
  const RunOutput out = run_quiet(parse_scenario(j.dump(), "test"));
  const Series* r = out.results.find("supports/A/reaction");
  ASSERT_NE(r, nullptr);
  for (std::size_t k = 0; k < out.results.time.size(); ++k) {
    EXPECT_NEAR(r->data[6 * k], -90e3, 1e-6 * 90e3) << k;
    EXPECT_NEAR(r->data[6 * k + 2], 2400 * 9.81 * 0.8 * 4.0, 1e-6 * 75e3) << k;
    EXPECT_NEAR(r->data[6 * k + 4], -90e3, 1e-6 * 90e3) << k;
  }
}

// The persistent design situation by hand (EN 1990 eq. 6.10, gamma_G 1.35, a relieving compression at 1.0) at the
// base of the cantilever: N = -rho g A L = -2400 x 9.81 x 0.8 x 4 = -75 340.8 N (N/A = -94 176 Pa), M = 90 kN m
// (M c / I = 90e3 x 0.4 / 0.0426667 = 843 750 Pa), V = 90 kN: tension -94 176 + 1.35 x 843 750 = 1 044 886 Pa,
// compression 1.35 x (94 176 + 843 750) = 1 266 200 Pa, shear 1.35 x 90 kN = 121.5 kN; each in the persistent verdict.
TEST(PressureLoads, PersistentSituationChecksByHand) {
  const RunOutput out = run_quiet(parse_scenario(cantilever(3.0).dump(), "test"));
  const nlohmann::json run = design::to_json(design::design_run(out.results, design::Limits{}, "w.h5"));
  auto check = [&](const std::string& id) -> nlohmann::json {
    for (const auto& c : run["checks"])
      if (c["id"] == id) return c;
    ADD_FAILURE() << "no check " << id;
    return nlohmann::json::object();
  };
  const double NA = -2400 * 9.81 * 0.8 * 4.0 / 0.8, Mc = 90e3 * 0.4 / (0.8 * 0.8 * 0.8 / 12);
  EXPECT_NEAR(check("concrete_flexural_tension_persistent")["demand"].get<double>(), NA + 1.35 * Mc, 1e-6 * Mc);
  EXPECT_NEAR(check("concrete_compression_persistent")["demand"].get<double>(), 1.35 * (-NA + Mc), 1e-6 * Mc);
  EXPECT_NEAR(check("concrete_shear_persistent")["demand"].get<double>(), 1.35 * 90e3, 1e-6 * 90e3);
  EXPECT_EQ(check("concrete_shear_persistent")["situation"], "persistent");
  EXPECT_EQ(check("concrete_shear")["situation"], "accidental");
  EXPECT_EQ(run["verdict"]["situations"]["persistent"]["checks"].get<int>(), 3);
}

TEST(PressureLoads, ErrorsNameTheKey) {
  J j = cantilever(3.0);
  j["structure"]["pressure_loads"][0]["member"] = "dam";
  try {
    parse_scenario(j.dump(), "w.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("w.json: /structure/pressure_loads/0/member = \"dam\": expected the name of a member"), std::string::npos) << e.what();
  }
  j = cantilever(3.0);
  j["structure"]["pressure_loads"][0]["gradient"] = 0;
  EXPECT_THROW(parse_scenario(j.dump(), "w.json"), InputError);
}

}  // namespace
}  // namespace dmi
