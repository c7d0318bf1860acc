// The dry run's estimate (engine/sim/run_estimate.hpp) by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "engine/sim/run_estimate.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

// A water block of 20 x 10 cells, 2 x 2 particles each (800 particles): steps = end / first step, and per step
// 800 x 100 ns + 5 us = 85 us.
TEST(RunEstimate, WaterBlockByHand) {
  const json j = json::parse(R"({"schema_version": 1, "name": "block",
    "analysis": {"dimension": 2, "plane": "strain", "end_time": 0.1, "gravity": [0, -9.81]},
    "grid": {"origin": [-0.1, -0.1], "size": [1.2, 0.8], "cell_size": 0.05},
    "materials": [{"name": "water", "model": "newtonian", "density": 1000, "bulk_modulus": 1e6, "viscosity": 1e-3}],
    "bodies": [{"name": "w", "material": "water", "shape": {"type": "box", "min": [0, 0], "max": [1.0, 0.5]}}]})");
  const Scenario s = parse_scenario(j, "block.json");
  const Solver<2> solver(build_scene<2>(s));
  ASSERT_EQ(solver.scene().particles.size(), 800u);
  const RunEstimate e = estimate_run(solver, s, solver.stable_time_step(0.1), 800);
  EXPECT_NEAR(e.steps, 0.1 / solver.stable_time_step(0.1), 1e-9 * e.steps);
  EXPECT_NEAR(e.wall_s / e.steps, 800 * 100e-9 + 5e-6, 1e-15);
}

// A boulder rigid in free flight alone in the scene: 6 h / v of the run at its elastic step, the rest at the history
// interval, which then bounds the step.
TEST(RunEstimate, BoulderRigidInFlight) {
  const json j = json::parse(R"({"schema_version": 1, "name": "boulder",
    "analysis": {"dimension": 2, "plane": "strain", "end_time": 0.2},
    "grid": {"origin": [-0.1, -0.1], "size": [3.2, 1.2], "cell_size": 0.05},
    "materials": [{"name": "rock", "density": 2650, "youngs_modulus": 5e10, "poisson_ratio": 0.25}],
    "bodies": [{"name": "b", "material": "rock", "rigid_when_free": true, "velocity": [5, 0],
                "shape": {"type": "ball", "center": [0.5, 0.5], "radius": 0.3}}],
    "walls": [{"name": "w", "type": "plane", "point": [2.5, 0], "normal": [-1, 0], "condition": "slip"}],
    "output": {"history_interval": 0.001}})");
  const Scenario s = parse_scenario(j, "boulder.json");
  const Solver<2> solver(build_scene<2>(s));
  const double dt0 = solver.stable_time_step(0.2), near = 6 * 0.05 / 5.0;
  const RunEstimate e = estimate_run(solver, s, dt0, static_cast<double>(solver.scene().particles.size()));
  EXPECT_NEAR(e.steps, near / dt0 + (0.2 - near) / 0.001, 1e-6 * e.steps);
}

}  // namespace
}  // namespace dmi
