// Box walls and prescribed-velocity regions.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

// A bar thrown at a rigid box obstacle bounces off it like off a plane wall: stress rho c v, time 2L/c.
TEST(Boundaries, BoxWallActsLikeAPlaneWall) {
  json j = json::parse(embedded_examples().at("wall_impact.json"));
  j["walls"] = json::array({{{"name", "wall"}, {"type", "box"}, {"min", {-0.1, -0.1}}, {"max", {0, 0.3}}, {"condition", "slip"}}});
  const RunOutput out = run_quiet(parse_scenario(j, "box.json"));
  const auto& f = series(out.results, "walls/wall/force");
  const double stress = -time_mean(out.results.time, f, 0, 0.004, 0.016) / 0.2;
  EXPECT_NEAR(stress / 1e5, 1.0, 0.03);
}

// Nodes in a prescribed-velocity region move with the given velocity while it is active; a body in
// the region is carried along and keeps that speed after the window closes. The region reports the
// force it needed: its time integral is the momentum given, 200 kg x 0.5 m/s.
TEST(Boundaries, PrescribedVelocityRegionDrivesTheBody) {
  json j = json::parse(embedded_examples().at("wall_impact.json"));
  j["walls"] = json::array();
  j["bodies"][0]["velocity"] = {0, 0};
  j["prescribed_velocity"] = json::array(
      {{{"name", "carrier"}, {"min", {-0.1, -0.1}}, {"max", {1.2, 0.3}}, {"velocity", {0.5, 0}}, {"start", 0.0}, {"end", 0.02}}});
  j["analysis"]["end_time"] = 0.04;
  j["output"]["snapshot_interval"] = 0;
  const RunOutput out = run_quiet(parse_scenario(j, "carrier.json"));
  const auto& t = out.results.time;
  const auto& v = series(out.results, "probes/bar/velocity");
  EXPECT_NEAR(time_mean(t, v, 0, 0.005, 0.02), 0.5, 1e-6);
  EXPECT_NEAR(time_mean(t, v, 0, 0.025, 0.04), 0.5, 1e-3);  // free flight afterwards
  const auto& f = series(out.results, "regions/carrier/force");
  double impulse = 0;
  const auto& dt = series(out.results, "dt");
  for (std::size_t i = 0; i < f.samples(); ++i) impulse += f.data[2 * i] * dt.data[i];
  EXPECT_NEAR(-impulse, 0.5 * 200, 1e-6 * 100);
}
// A block sliding on a Coulomb wall stops after v0^2 / (2 mu g) (0.4077 m for 2 m/s, mu 0.5), also when it is only
// half a cell thick: the friction acts on the bed node row with the node's full normal force. Tolerance: one percent,
// the distance covered in the last step of deceleration is far below it.
TEST(Boundaries, CoulombBaseStopsASlidingBlock) {
  for (const double thick : {0.1, 0.025}) {
    const json j = json::parse(R"({"schema_version": 1, "name": "slide",
      "analysis": {"dimension": 2, "plane": "strain", "end_time": 0.5, "gravity": [0, -9.81]},
      "mpm": {"shape_function": "bspline2", "transfer": "apic"},
      "grid": {"origin": [-0.1, -0.2], "size": [1.2, 0.5], "cell_size": 0.05},
      "materials": [{"name": "m", "model": "linear_elastic", "density": 2000, "youngs_modulus": 2e7, "poisson_ratio": 0.3}],
      "bodies": [{"name": "b", "material": "m", "velocity": [2, 0], "shape": {"type": "box", "min": [0, 0], "max": [0.4, 0.1]}}],
      "walls": [{"name": "bed", "type": "plane", "point": [0, 0], "normal": [0, 1], "condition": "friction", "friction": 0.5}],
      "output": {"history_interval": 0.01, "probes": [{"name": "b", "type": "body", "body": "b", "quantities": ["position"]}]}})");
    json k = j;
    k["bodies"][0]["shape"]["max"][1] = thick;
    const RunOutput out = run_quiet(parse_scenario(k, "slide.json"));
    const auto& x = series(out.results, "probes/b/position");
    const double slide = x.data[2 * (x.samples() - 1)] - x.data[0];
    EXPECT_NEAR(slide / (4 / (2 * 0.5 * 9.81)), 1.0, 0.01) << "thickness " << thick;
  }
}

// Water at rest in a tank 0.6 m wide, 0.5 m deep (slip walls): each side wall carries rho g H^2 / 2 (time means over
// the last second of 2 s), the bed's impulse is the weight's plus the water's change of vertical momentum (to
// round-off: the slip walls take no vertical force), and no particle passes a wall (keep_in_front_of_walls; before it
// the corner particles settled half a cell behind the walls). Tolerance of the thrust: the free surface is known to a
// quarter cell, h/4 of H = 0.5 m at h 0.05 m gives 2 h/(4H) = 5 %.
TEST(Boundaries, WaterInATankLoadsItsWallsHydrostatically) {
  const json j = json::parse(R"({"schema_version": 1, "name": "tank",
    "analysis": {"dimension": 2, "plane": "strain", "end_time": 2.0, "gravity": [0, -9.81]},
    "mpm": {"shape_function": "bspline2", "transfer": "apic"},
    "grid": {"origin": [-0.4, -0.4], "size": [1.8, 1.8], "cell_size": 0.05},
    "materials": [{"name": "water", "model": "newtonian", "density": 1000, "bulk_modulus": 4e5, "viscosity": 1e-3}],
    "bodies": [{"name": "w", "material": "water", "shape": {"type": "box", "min": [0, 0], "max": [0.6, 0.5]}}],
    "walls": [{"name": "bed", "type": "plane", "point": [0, 0], "normal": [0, 1], "condition": "slip"},
              {"name": "left", "type": "plane", "point": [0, 0], "normal": [1, 0], "condition": "slip"},
              {"name": "right", "type": "plane", "point": [0.6, 0], "normal": [-1, 0], "condition": "slip"}],
    "output": {"history_interval": 0.01}})");
  Solver<2> s(build_scene<2>(parse_scenario(j, "tank.json")));
  Vec2 impulse[3] = {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};  // of the walls over the last second
  double py1 = 0, t1 = 0;
  while (s.time() < 2.0 - 1e-12) {
    const double dt = s.stable_time_step(2.0 - s.time());
    if (s.time() >= 1.0 && t1 == 0) py1 = s.diagnostics().momentum.y(), t1 = s.time();
    s.step(dt);
    if (t1 > 0)
      for (int w = 0; w < 3; ++w) impulse[w] += dt * s.scene().walls[w].force;
  }
  const double thrust = 0.5 * 1000 * 9.81 * 0.25, weight = 1000 * 9.81 * 0.3;
  const double dpy = s.diagnostics().momentum.y() - py1;  // = -weight (2 - t1) - impulse on the bed
  EXPECT_NEAR(-impulse[0].y(), dpy + weight * (2.0 - t1), 1e-9 * weight);
  EXPECT_NEAR(-impulse[1].x() / thrust, 1.0, 0.05);
  EXPECT_NEAR(impulse[2].x() / thrust, 1.0, 0.05);
  const auto& P = s.scene().particles;
  for (std::size_t i = 0; i < P.size(); ++i) {
    ASSERT_GE(P.x[i].y(), 0.0);
    ASSERT_GE(P.x[i].x(), 0.0);
    ASSERT_LE(P.x[i].x(), 0.6);
  }
}

// Sparse histories keep the impulse: wall forces are interval means, so sum F_i (t_i - t_{i-1}) is the
// same as with a sample every step, and equals the momentum the wall took: ~2 m v for an elastic rebound.
TEST(Boundaries, SparseHistoryKeepsWallImpulse) {
  auto impulse = [](double interval) {
    json j = json::parse(embedded_examples().at("wall_impact.json"));
    j["output"]["history_interval"] = interval;
    const RunOutput out = run_quiet(parse_scenario(j, "impulse.json"));
    const auto& t = out.results.time;
    const auto& f = series(out.results, "walls/wall/force");
    double I = 0;
    for (std::size_t i = 1; i < t.size(); ++i) I += f.data[2 * i] * (t[i] - t[i - 1]);
    return std::make_pair(I, t.size());
  };
  const auto every = impulse(0.0), sparse = impulse(0.002);
  EXPECT_LT(sparse.second, every.second / 5);
  EXPECT_NEAR(sparse.first / every.first, 1.0, 1e-9);
  EXPECT_NEAR(-every.first / (2 * 200 * 1.0), 1.0, 0.05);  // m = 200 kg, v = 1 m/s, nearly elastic
}


// Seeding: a particle next to the shape's surface carries the distance to it along each axis (the body's real
// outline, not the staircase of particle domains); inside the body the reach is half the particle spacing.
TEST(SurfaceDetection, SeededParticlesReachTheShapeSurface) {
  json j = json::parse(embedded_examples().at("cylinder_on_wall.json"));
  const Scene<2> sc = build_scene<2>(parse_scenario(j, "cyl.json"));
  const auto& P = sc.particles;
  const double cx = 0.55, cy = 0.417, R = 0.4, dx = 0.01;
  int boundary = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i][0], y = P.x[i][1];
    const double below = y - (cy - std::sqrt(R * R - (x - cx) * (x - cx)));  // distance down to the circle
    if (below < dx) {
      EXPECT_NEAR(P.reach_lo[i][1], below, 1e-5 * dx) << "particle at " << x << ", " << y;
      ++boundary;
    } else {
      EXPECT_DOUBLE_EQ(P.reach_lo[i][1], 0.5 * dx);
    }
  }
  EXPECT_GT(boundary, 10);
}

// A slip wall with surface detection acts when the body's surface reaches it, not when the body's grid support
// does: the cylinder 0.017 m above the wall at 5 m/s touches when the surface under its lowest particle column
// (c off the centre line, R - sqrt(R^2 - c^2) higher than the bottom) arrives, within a step. Node detection
// holds the nodes on the wall as soon as the stencil (1.5 h = 0.03 m) reaches them: at once.
TEST(SurfaceDetection, SlipWallActsWhenTheSurfaceArrives) {
  auto first_contact = [](const std::string& detection, double& dt) {
    json j = json::parse(embedded_examples().at("cylinder_on_wall.json"));
    j["walls"][0]["detection"] = detection;
    j["grid"]["cell_size"] = 0.04;
    j["analysis"]["end_time"] = 0.0036;
    const RunOutput out = run_quiet(parse_scenario(j, "cyl.json"));
    const auto& t = out.results.time;
    const auto& f = series(out.results, "walls/wall/force");
    dt = t[1] - t[0];
    for (std::size_t k = 1; k < t.size(); ++k)
      if (f.data[2 * k + 1] != 0) return t[k - 1];  // the interval in which the wall first pushed
    return 1.0;
  };
  double dt = 0;
  const double surface = first_contact("surface", dt);
  const double R = 0.4, dx = 0.02, u = (0.55 - -0.4) / dx - 0.5;  // particle columns at x = -0.4 + (k + 1/2) dx
  const double c = std::abs(u - std::round(u)) * dx, arrival = (0.017 + R - std::sqrt(R * R - c * c)) / 5;
  EXPECT_GE(surface, arrival - dt);
  EXPECT_LE(surface, arrival + dt);
  EXPECT_LT(first_contact("node", dt), 0.001);
}

}  // namespace
}  // namespace dmi
