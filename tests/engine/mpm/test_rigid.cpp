// Rigid bodies (engine/mpm/rigid.hpp): closed-form sliding, momentum through contact, rigidity, the step.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "engine/verify/validate.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

template <int D> void run_to(Solver<D>& s, double end) {
  while (s.time() < end - 1e-12) s.step(s.stable_time_step(end - s.time()));
}

Vec2 mean_velocity(const Solver<2>& s, const Body& b) {
  const auto& P = s.scene().particles;
  Vec2 p = Vec2::Zero();
  double m = 0;
  for (Index i = b.begin; i < b.end; ++i) p += P.mass[i] * P.v[i], m += P.mass[i];
  return p / m;
}

// A rigid disc on a 30 degree incline (gravity rotated) with mu = 0.1 below tan(30)/3: it slides with
// a = g (sin 30 - mu cos 30) = 4.055 m/s^2 whatever its spin (the friction force is mu N while it slips).
// The wall must hold the whole body, not only the nodes it touches: it does not sink.
TEST(RigidBody, SlipsDownAFrictionInclineAsTheClosedForm) {
  json j = json::parse(embedded_examples().at("incline_sliding.json"));
  j["grid"]["cell_size"] = 0.025;
  j["bodies"] = json::array({{{"name", "disc"}, {"material", "rock"}, {"rigid", true}, {"particles_per_cell", 2},
                              {"shape", {{"type", "ball"}, {"center", {0.5, 0.2}}, {"radius", 0.2}}}}});
  j["walls"][0]["friction"] = 0.1;
  j.erase("output");
  Solver<2> s(build_scene<2>(parse_scenario(j, "incline.json")));
  run_to(s, 1.0);
  const Body& b = s.scene().bodies[0];
  EXPECT_NEAR(mean_velocity(s, b).x(), 4.905 - 0.1 * 8.49571, 0.01 * 4.055);
  EXPECT_LT(s.steps(), 500);  // no wave-speed limit: h / (|v| + sqrt(g h))
  double ymin = 1e9;
  for (Index i = b.begin; i < b.end; ++i) ymin = std::min(ymin, s.scene().particles.x[i].y());
  EXPECT_GT(ymin, -0.25 * 0.025);  // the lowest particle centre stays within a quarter cell of the incline
}

// A spinning, translating rigid disc meets an elastic one without gravity or walls: momentum is conserved to
// round-off through the contact and the rigid passes, and the rigid disc stays rigid (particle distances kept).
TEST(RigidBody, CollisionConservesMomentumAndKeepsTheBodyRigid) {
  json j = json::parse(embedded_examples().at("colliding_disks.json"));
  j["bodies"][0]["rigid"] = true;
  j["analysis"]["end_time"] = 2.5;
  Solver<2> s(build_scene<2>(parse_scenario(j, "disks.json")));
  const auto& P = s.scene().particles;
  const Body& b = s.scene().bodies[0];
  const Vec2 p0 = s.diagnostics().momentum;
  auto gap = [&] { return (P.x[P.slot[b.begin]] - P.x[P.slot[b.end - 1]]).norm(); };  // creation order: sorting moves particles
  const double d0 = gap();
  run_to(s, 2.5);
  const double pref = 1000 * 3.14159265358979 * 0.04 * 0.1;
  EXPECT_LT((s.diagnostics().momentum - p0).norm(), 1e-10 * pref);
  EXPECT_NEAR(gap(), d0, 1e-12);
  EXPECT_LT(mean_velocity(s, b).x(), 0.0);  // it rebounded
}

}  // namespace
}  // namespace dmi
