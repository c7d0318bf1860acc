// Pressure sensors (engine/mpm/sensor.hpp) by hand, and the geostatic initial state (engine/sim/geostatic.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "engine/mpm/sensor.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "engine/sim/geostatic.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

// A 4.5 mm sensor centred 3 mm above the floor on a wall at x = 1.61 (normal -x), cells of 10 mm, 2 m thick. The node
// at the foot of the wall has the tributary [-5, 5] mm, of which [0.75, 5] mm lies on the sensor: 4.25 / 10 of its
// force without the floor, 4.25 / 5 with it (the half behind the floor holds no material). The node 10 mm up,
// tributary [5, 15] mm, gives 0.25 / 10.
TEST(Sensor, NodeForcesSpreadOverTheirTributariesByHand) {
  PressurePatch<2> p = make_patch<2>("P1", Vec2(1.61, 0.003), Vec2(-1, 0), 0.0045, 2.0);
  EXPECT_DOUBLE_EQ(p.area, 0.0045 * 2.0);
  const double h = 0.01, F = 900.0;  // N on the wall, along +x (into it)
  EXPECT_NEAR(patch_weight(p, Vec2(1.61, 0.0), h), 0.425, 1e-12);
  EXPECT_NEAR(patch_weight(p, Vec2(1.61, 0.01), h), 0.025, 1e-12);
  EXPECT_EQ(patch_weight(p, Vec2(1.61, 0.02), h), 0.0);
  EXPECT_EQ(patch_weight(p, Vec2(1.61 - 1.5 * h, 0.0), h), 0.0);  // more than a cell in front of the face
  p.clips.push_back({Vec2(0, 0), Vec2(0, 1)});
  EXPECT_NEAR(patch_weight(p, Vec2(1.61, 0.0), h), 0.85, 1e-12);
  EXPECT_NEAR(patch_weight(p, Vec2(1.61, 0.01), h), 0.025, 1e-12);
  patch_add(p, Vec2(1.61, 0.0), Vec2(F, 0), h);
  EXPECT_NEAR(patch_pressure(p.force, p.area), 0.85 * F / 0.009, 1e-9);
  patch_add(p, Vec2(1.61, 0.0), Vec2(-F, 0), h);  // a pull is a negative pressure
  EXPECT_NEAR(p.force, 0.0, 1e-12);
}

// The nodes a wall holds reach 1.5 h behind its plane: a node one cell behind still loads the sensor; two and a half
// cells behind, or more than a cell in front, it does not.
TEST(Sensor, NodesBehindTheWallCount) {
  const double h = 0.01;
  const PressurePatch<2> p = make_patch<2>("P", Vec2(1.0, 0.5), Vec2(-1, 0), 0.02, 1.0);
  EXPECT_NEAR(patch_weight(p, Vec2(1.0 + h, 0.5), h), 1.0, 1e-12);      // one cell behind (normal -x: behind is +x)
  EXPECT_EQ(patch_weight(p, Vec2(1.0 + 2.5 * h, 0.5), h), 0.0);
  EXPECT_NEAR(patch_weight(p, Vec2(1.0 - h, 0.5), h), 1.0, 1e-12);      // one cell in front
  EXPECT_EQ(patch_weight(p, Vec2(1.0 - 1.5 * h, 0.5), h), 0.0);
}

// A rigid block resting on the floor presses on it through its hull contact, which the floor's sensor reads: a sensor
// wider than the block reads its weight over the sensor's area.
TEST(Sensor, RigidBlockOnTheFloorReadsItsWeight) {
  const json j = json::parse(R"({"schema_version": 1, "name": "block",
    "analysis": {"dimension": 2, "plane": "strain", "thickness": 2.0, "end_time": 0.2, "gravity": [0, -10]},
    "grid": {"origin": [-0.2, -0.2], "size": [1.4, 0.8], "cell_size": 0.05},
    "materials": [{"name": "rock", "density": 2500, "youngs_modulus": 1e9, "poisson_ratio": 0.2}],
    "bodies": [{"name": "b", "material": "rock", "rigid": true, "shape": {"type": "box", "min": [0.3, 0], "max": [0.7, 0.2]}}],
    "walls": [{"name": "floor", "type": "plane", "point": [0, 0], "normal": [0, 1], "condition": "slip"}],
    "output": {"history_interval": 0.01, "sensors": [{"name": "under", "wall": "floor", "point": [0.5, 0], "size": 0.8}]}})");
  const RunOutput out = run_quiet(parse_scenario(j, "block.json"));
  const Series& p = series(out.results, "sensors/under/pressure");
  const double weight = 2500 * 0.4 * 0.2 * 2.0 * 10, area = 0.8 * 2.0;
  EXPECT_NEAR(time_mean(out.results.time, p, 0, 0.1, 0.2) * area / weight, 1.0, 0.02);
}

// A sensor spanning whole cells reads force over area; in 3D the weight is the product of both axes' overlaps.
TEST(Sensor, LargePatchReadsForceOverAreaAndSquaresIn3D) {
  const double h = 0.1;
  PressurePatch<2> p = make_patch<2>("wide", Vec2(0, 0.5), Vec2(1, 0), 0.4, 1.0);
  double F = 0;
  for (double y : {0.3, 0.4, 0.5, 0.6, 0.7}) {
    patch_add(p, Vec2(0, y), Vec2(-100, 0), h);  // 100 N each into the wall (normal +x: the wall is behind)
    F += 100 * patch_weight(p, Vec2(0, y), h);
  }
  EXPECT_NEAR(F, 400.0, 1e-9);  // 4 tributaries' worth: half of the end nodes'
  EXPECT_NEAR(patch_pressure(p.force, p.area), 1000.0, 1e-9);
  PressurePatch<3> q = make_patch<3>("square", Vec3(0, 0, 0), Vec3(0, 0, 1), 0.05, 1.0);
  EXPECT_DOUBLE_EQ(q.area, 0.0025);
  EXPECT_NEAR(q.t1.dot(q.normal), 0.0, 1e-15);
  // tributary [-0.01, 0.09] along x meets [-0.025, 0.025] over 0.035; [-0.05, 0.05] along y over 0.05
  EXPECT_NEAR(patch_weight(q, Vec3(0.04, 0.0, 0.0), h), 0.035 / 0.1 * 0.05 / 0.1, 1e-12);
}

// The earth-pressure coefficients at rest: Jaky's 1 - sin(phi), nu / (1 - nu), 1 for a fluid, the given value first.
TEST(Geostatic, EarthPressureAtRestByMaterial) {
  MaterialConfig sand{.name = "sand", .model = "drucker_prager", .density = 1800};
  sand.friction_angle = 30;
  EXPECT_NEAR(earth_pressure_at_rest(sand, -1), 0.5, 1e-12);
  MaterialConfig rock{.name = "rock", .model = "linear_elastic", .density = 2700};
  rock.poisson_ratio = 0.25;
  EXPECT_NEAR(earth_pressure_at_rest(rock, -1), 1.0 / 3.0, 1e-12);
  MaterialConfig water{.name = "water", .model = "newtonian", .density = 1000};
  EXPECT_EQ(earth_pressure_at_rest(water, -1), 1.0);
  EXPECT_EQ(earth_pressure_at_rest(sand, 0.7), 0.7);
}

json column(const std::string& material) {
  return json::parse(R"({"schema_version": 1, "name": "column",
    "analysis": {"dimension": 2, "plane": "strain", "end_time": 0.1, "gravity": [0, -10]},
    "grid": {"origin": [-0.2, -0.2], "size": [1.4, 1.4], "cell_size": 0.1},
    "materials": [{"name": "water", "model": "newtonian", "density": 1000, "bulk_modulus": 1e6, "viscosity": 1e-3},
                  {"name": "sand", "model": "drucker_prager", "density": 2000, "youngs_modulus": 1e7, "poisson_ratio": 0.3,
                   "friction_angle": 30}],
    "bodies": [{"name": "b", "material": ")" + material + R"(", "particles_per_cell": 2, "initial_stress": "geostatic",
                "shape": {"type": "box", "min": [0, 0], "max": [0.6, 1.0]}}]})");
}

// A particle at depth d = 1.0 - y (the body's top at 1.0 m) starts from sigma_v = -rho g d, sigma_h = K0 sigma_v; water's
// volume ratio is K / (K + p), so its own law gives back p.
TEST(Geostatic, ParticlesStartFromTheWeightAbove) {
  const Scene<2> w = build_scene<2>(parse_scenario(column("water"), "water.json"));
  const auto& P = w.particles;
  for (Index i = 0; i < static_cast<Index>(P.size()); ++i) {
    const double p = 1000 * 10 * (1.0 - P.x[i].y());
    ASSERT_NEAR(-P.stress[i](1, 1), p, 1e-9 * 1e4) << i;
    ASSERT_NEAR(P.stress[i](0, 0), P.stress[i](1, 1), 1e-9);
    ASSERT_NEAR(P.F[i].determinant(), 1e6 / (1e6 + p), 1e-12);
    ASSERT_NEAR(1e6 * (1 / P.F[i].determinant() - 1), p, 1e-6);
  }
  const Scene<2> s = build_scene<2>(parse_scenario(column("sand"), "sand.json"));
  for (Index i = 0; i < static_cast<Index>(s.particles.size()); ++i) {
    const double sv = -2000 * 10 * (1.0 - s.particles.x[i].y());
    ASSERT_NEAR(s.particles.stress[i](1, 1), sv, 1e-9 * 2e4);
    ASSERT_NEAR(s.particles.stress[i](0, 0), 0.5 * sv, 1e-9 * 2e4);
    ASSERT_NEAR(s.particles.stress_zz[i], 0.5 * sv, 1e-9 * 2e4);
    ASSERT_NEAR(s.particles.stress[i](0, 1), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace dmi
