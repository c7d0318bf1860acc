// Rigid bodies (engine/mpm/rigid.hpp): closed-form sliding, momentum through contact, rigidity, the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/mpm/clearance.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "verify/validate.hpp"

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

// With mu = 0.5 above tan(30)/3 the rigid disc rolls: a = 2/3 g sin 30 = 3.270 m/s^2 (a uniform disc, I = M R^2 / 2).
// The plane wall meets the disc at its surface (RigidBodies::wall_contact), a single point, so nothing brakes the
// rotation; the grid's nodes carry the disc's inertia spread by the B-spline, I + M h^2/2 (-0.5 % at h = R/8,
// -0.13 % at R/16), with APIC (its affine velocity carries the spin through the grid) and FLIP (the body keeps the
// nodes' angular momentum). Tolerance 2 %. Before this contact, the orbital projection and the nodal motion, a patch
// of held nodes braked it and FLIP lost spin: -26 % (APIC), -32 % (FLIP) at R/8.
TEST(RigidBody, RollsDownAFrictionInclineAsTheClosedForm) {
  for (const auto& [transfer, h] : {std::pair{"apic", 0.025}, std::pair{"apic", 0.0125}, std::pair{"flip", 0.025}}) {
    json j = json::parse(embedded_examples().at("incline_sliding.json"));
    j["grid"]["cell_size"] = h;
    j["mpm"] = {{"transfer", transfer}};
    j["bodies"] = json::array({{{"name", "disc"}, {"material", "rock"}, {"rigid", true}, {"particles_per_cell", 2},
                                {"shape", {{"type", "ball"}, {"center", {0.5, 0.2}}, {"radius", 0.2}}}}});
    j["walls"][0]["friction"] = 0.5;
    j.erase("output");
    Solver<2> s(build_scene<2>(parse_scenario(j, "incline.json")));
    const Body& b = s.scene().bodies[0];
    run_to(s, 0.2);
    const double v0 = mean_velocity(s, b).x();
    run_to(s, 1.0);
    const double a = (mean_velocity(s, b).x() - v0) / 0.8;
    EXPECT_NEAR(a / (9.81 * 0.5 * 2 / 3), 1.0, 0.02) << transfer << " h " << h;
    // rolling: the lowest point is at rest, v = omega R (the spin from the particles' velocities about the centre).
    // APIC only: with FLIP the particles carry the nodes' angular momentum over their own, smaller inertia and spin
    // faster by I_n / I_p (+1.5 % at R/8) while the nodes roll.
    if (std::string(transfer) != "apic") continue;
    const auto& P = s.scene().particles;
    Vec2 xc = Vec2::Zero();
    double m = 0, l = 0, I = 0;
    for (Index i = b.begin; i < b.end; ++i) xc += P.mass[i] * P.x[i], m += P.mass[i];
    xc /= m;
    for (Index i = b.begin; i < b.end; ++i) {
      const Vec2 r = P.x[i] - xc;
      l += P.mass[i] * (r.x() * P.v[i].y() - r.y() * P.v[i].x()), I += P.mass[i] * r.squaredNorm();
    }
    EXPECT_NEAR(-l / I * 0.2 / mean_velocity(s, b).x(), 1.0, 0.02) << transfer << " h " << h;
  }
}

// 3D: a rigid sphere on the 30 degree incline rolls at a = 5/7 g sin 30 = 3.504 m/s^2 with mu = 0.5 and slips at
// g (sin 30 - mu cos 30) = 4.055 m/s^2 with mu = 0.1. At h = R/4 the nodes carry I + M h^2/2 about the spin axis
// (-2.2 % on the rolling a) and the seeded particles sample the sphere at R/8: tolerance 4 % rolling, 1 % slipping.
TEST(RigidBody, SphereRollsAndSlipsOnAnInclineIn3D) {
  for (const double mu : {0.5, 0.1}) {
    json j = json::parse(R"({"schema_version": 1, "name": "sphere",
      "analysis": {"dimension": 3, "end_time": 1.0, "cfl": 0.5, "gravity": [4.905, -8.49571, 0]},
      "mpm": {"transfer": "apic"}, "grid": {"origin": [0, -0.2, -0.3], "size": [4.5, 0.8, 0.6], "cell_size": 0.05},
      "materials": [{"name": "rock", "model": "linear_elastic", "density": 2000, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
      "bodies": [{"name": "ball", "material": "rock", "rigid": true, "shape": {"type": "ball", "center": [0.5, 0.2, 0], "radius": 0.2}}],
      "walls": [{"name": "incline", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "condition": "friction"}]})");
    j["walls"][0]["friction"] = mu;
    Solver<3> s(build_scene<3>(parse_scenario(j, "sphere.json")));
    const Body& b = s.scene().bodies[0];
    const auto vx = [&] {
      const auto& P = s.scene().particles;
      double p = 0, m = 0;
      for (Index i = b.begin; i < b.end; ++i) p += P.mass[i] * P.v[i].x(), m += P.mass[i];
      return p / m;
    };
    run_to(s, 0.2);
    const double v0 = vx();
    run_to(s, 1.0);
    const double a = (vx() - v0) / 0.8;
    if (mu > 0.2) EXPECT_NEAR(a / (5.0 / 7 * 4.905), 1.0, 0.04);
    else EXPECT_NEAR(a / (4.905 - mu * 8.49571), 1.0, 0.01);
  }
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

// A rigid block strikes a rubber pad on a wall (examples/buffer_pad_rigid_wall.json): the body contact sees the
// block's whole mass, so the constraint passes close the contact in a few passes a step (node by node with the
// node's mass they took ~180 on the buffered dam), momentum goes to the wall only, and the block stays rigid.
TEST(RigidBody, ContactWithADeformableBodyClosesInAFewPasses) {
  json j = json::parse(embedded_examples().at("buffer_pad_rigid_wall.json"));
  j["bodies"][1]["rigid"] = true;
  // through the contact (from ~20 ms, ~18 ms long): the example's 0.05 s
  Solver<2> s(build_scene<2>(parse_scenario(j, "pad.json")));
  const Body& b = s.scene().bodies[1];
  run_to(s, 0.05);
  EXPECT_LT(static_cast<double>(s.rigid_passes()) / static_cast<double>(s.steps()), 5.0);
  EXPECT_LT(mean_velocity(s, b).x(), -1.8);  // rebounded (the undamped pad returns ~97 % of 2 m/s)
}


// An elastic disc (rigid_when_free; E 1 GPa, c 1000 m/s, h = r/5) flies 0.2 m at a slip wall at 2 m/s, strikes it and flies
// back. It is rigid while clear of the wall (Clearance: 3 cells) and elastic from before the first node the wall holds to
// after the rebound. At the elastic run's own steps (dt_max below the elastic step) the two runs are equal to round-off
// up to the freeze after the rebound: peak wall force and rebound speed to 1e-9, and the energy balance right after that
// freeze equals the elastic run's at the same step (the ringing given up is counted as dissipated), then stays put in
// rigid flight. At free steps the run takes a fraction of the steps; the strike then starts at another phase of a
// step, which moves the peak by up to about one step's share of the contact (tolerance 2 / steps in contact).
TEST(RigidWhenFree, ElasticDiscOnAWallGivesTheElasticImpact) {
  struct Out {
    double peak = 0, rebound = 0, balance = 0, balance_at_freeze = 0, dissipated = 0;
    long steps = 0, switches = 0, freeze_step = -1, contact_steps = 0;
    bool rigid_loaded = false;
    std::vector<double> balances;
  };
  const double end = 0.2, ke0 = 0.5 * 1000 * 3.14159265358979 * 0.01 * 4;  // rho pi r^2 (thickness 1) v^2 / 2
  auto run = [end](bool when_free, double dt_max) {
    json j = json::parse(embedded_examples().at("wall_impact.json"));
    j["analysis"]["end_time"] = end;
    if (dt_max > 0) j["analysis"]["dt_max"] = dt_max;
    j["grid"] = {{"origin", {-0.1, -0.3}}, {"size", {0.8, 0.6}}, {"cell_size", 0.02}};
    j["materials"][0]["youngs_modulus"] = 1e9;
    j["bodies"] = json::array({{{"name", "disc"}, {"material", "elastic"}, {"particles_per_cell", 2}, {"rigid_when_free", when_free},
                                {"shape", {{"type", "ball"}, {"center", {0.3, 0.0}}, {"radius", 0.1}}}, {"velocity", {-2, 0}}}});
    j.erase("output");
    Solver<2> s(build_scene<2>(parse_scenario(j, "disc.json")));
    const double e0 = s.diagnostics().balance(0.0);
    Out o;
    while (s.time() < end - 1e-12) {
      const bool rigid = s.scene().bodies[0].rigid;
      s.step(s.stable_time_step(end - s.time()));
      const double f = s.scene().walls[0].force.norm();
      o.peak = std::max(o.peak, f);
      o.contact_steps += f > 0;
      o.rigid_loaded = o.rigid_loaded || (rigid && f > 0);
      o.balances.push_back(s.diagnostics().balance(e0));
      if (s.free_switches() == 3 && o.freeze_step < 0) o.freeze_step = s.steps() - 1, o.balance_at_freeze = o.balances.back();
    }
    o.rebound = mean_velocity(s, s.scene().bodies[0]).x();
    o.balance = o.balances.back();
    o.dissipated = s.diagnostics().dissipated;
    o.steps = s.steps(), o.switches = s.free_switches();
    return o;
  };
  const Out el = run(false, 5e-6), same = run(true, 5e-6);
  EXPECT_GT(el.peak, 0);
  EXPECT_NEAR(same.peak, el.peak, 1e-9 * el.peak);
  EXPECT_NEAR(same.rebound, el.rebound, 1e-9 * 2);
  EXPECT_GT(same.rebound, 1.0);  // it rebounded
  EXPECT_FALSE(same.rigid_loaded);
  ASSERT_EQ(same.switches, 3);  // rigid at the start, elastic before the wall, rigid after the rebound
  ASSERT_EQ(same.steps, el.steps);
  EXPECT_NEAR(same.balance_at_freeze, el.balances[same.freeze_step], 1e-9 * ke0);
  EXPECT_NEAR(same.balance, same.balance_at_freeze, 1e-9 * ke0);  // rigid flight keeps its energy
  EXPECT_GT(same.dissipated, 0);  // the ringing given up
  EXPECT_LT(same.dissipated, 0.05 * ke0);

  const Out el_free = run(false, 0), fr = run(true, 0);
  EXPECT_FALSE(fr.rigid_loaded);
  EXPECT_EQ(fr.switches, 3);
  EXPECT_LT(fr.steps, el_free.steps / 2);
  ASSERT_GT(el_free.contact_steps, 5);
  EXPECT_NEAR(fr.peak, el_free.peak, 2.0 / el_free.contact_steps * el_free.peak);
  EXPECT_NEAR(fr.rebound, el_free.rebound, 2.0 / el_free.contact_steps * 2);
}

// A rock disc (E 50 GPa, r 0.2 m, h 0.04 m) strikes a concrete beam-column member at 5 m/s and rebounds. Released half a
// cell above it, it is elastic from the start; it turns rigid while leaving the member, inside the member's clearance
// (4.5 cells here) and never again elastic, and the member never loads it while rigid (a rigid body on a member stops
// the run). The member is free of loads once the disc has left, so at the elastic run's own steps (dt_max, both runs at
// 0.9 of the elastic step) the two runs agree to round-off: the peak contact force, the disc's rebound and the member's
// whole midspan history. At free steps the run is the elastic one's up to the switch, then takes long steps in which
// the member is advanced in sub-steps of at most its ringing step (Rayleigh damping here: 1.25 us); its midspan
// history follows the elastic run's within Newmark's period error at that step for the fundamental (omega_1 = 1.9e4
// rad/s: (omega dt)^2 / 12 = 5e-5 a period) accumulated over the ~50 periods left, a bound of 1.5e-2 of the amplitude
// at the switch, which the 4.7 % damping has brought far below the peak: 1e-3 of the peak allowed. After the switch
// the run steps at the history interval.
TEST(RigidWhenFree, LeavesAMemberRigidInsideItsClearance) {
  struct Out {
    double peak = 0, rebound = 0;
    long steps = 0, switches = 0, switch_step = -1;
    double switch_time = 0, dt_free = 0;
    bool clear_at_switch = true, rigid_loaded = false;
    std::vector<double> t, w, wv;  // midspan deflection and its rate
  };
  auto run = [](bool when_free, double dt_max) {
    json j = json::parse(embedded_examples().at("cylinder_on_member.json"));
    j["analysis"]["end_time"] = 0.03;
    if (dt_max > 0) j["analysis"]["dt_max"] = dt_max;
    j["grid"]["cell_size"] = 0.04;
    j["bodies"][0]["shape"] = {{"type", "ball"}, {"center", {0.55, 0.22}}, {"radius", 0.2}};
    j["bodies"][0]["rigid_when_free"] = when_free;
    j["structure"]["rayleigh_damping"] = {{"mass", 0.0}, {"stiffness", 5e-6}};  // ringing step 1.25 us, 4.7 % at the fundamental
    j.erase("output");
    Solver<2> s(build_scene<2>(parse_scenario(j, "disc_on_member.json")));
    const Clearance c = Clearance::of(s.scene().grid->h(), member_contact_layer(s.scene().coupling, s.scene().grid->h()));
    Out o;
    while (s.time() < 0.03 - 1e-12) {
      const bool rigid = s.scene().bodies[0].rigid;
      s.step(s.stable_time_step(0.03 - s.time()));
      const double f = s.member_contact()->force().norm();
      o.peak = std::max(o.peak, f);
      o.rigid_loaded = o.rigid_loaded || (rigid && f > 0);
      if (s.free_switches() == 1 && o.switch_step < 0)
        o.switch_step = s.steps(), o.switch_time = s.time(), o.clear_at_switch = body_is_clear(s.scene(), 0, c);
      o.t.push_back(s.time());
      o.w.push_back(s.scene().frame->displacement()(3 * 4 + 1));
      o.wv.push_back(s.scene().frame->velocity()(3 * 4 + 1));
    }
    o.rebound = mean_velocity(s, s.scene().bodies[0]).y();
    o.steps = s.steps(), o.switches = s.free_switches(), o.dt_free = s.scene().options.free_dt_max;
    return o;
  };
  const Out el = run(false, 0);
  ASSERT_GT(el.peak, 0);
  ASSERT_GT(el.rebound, 1.0);  // it rebounded
  double wmax = 0;
  for (double w : el.w) wmax = std::max(wmax, std::abs(w));
  ASSERT_GT(wmax, 0);
  const double dt_el = 0.9 * (el.t[1] - el.t[0]);  // below every elastic step

  const Out el_fixed = run(false, dt_el), same = run(true, dt_el);
  EXPECT_EQ(same.switches, 1);
  EXPECT_FALSE(same.clear_at_switch);  // rigid by leaving, not by clearance
  EXPECT_FALSE(same.rigid_loaded);
  ASSERT_EQ(same.steps, el_fixed.steps);
  EXPECT_NEAR(same.peak, el_fixed.peak, 1e-9 * el.peak);
  EXPECT_NEAR(same.rebound, el_fixed.rebound, 1e-9 * 5);
  for (std::size_t i = 0; i < el_fixed.w.size(); ++i) ASSERT_NEAR(same.w[i], el_fixed.w[i], 1e-9 * wmax) << "step " << i;

  const Out fr = run(true, 0);
  EXPECT_EQ(fr.switches, 1);
  EXPECT_FALSE(fr.rigid_loaded);
  // after the switch, steps of the history interval (the last one shortened to the end)
  EXPECT_LE(fr.steps - fr.switch_step, static_cast<long>(std::ceil((0.03 - fr.switch_time) / fr.dt_free)) + 1);
  EXPECT_LT(fr.steps, el.steps * 3 / 5);
  EXPECT_NEAR(fr.peak, el.peak, 1e-9 * el.peak);  // the same steps up to the switch
  EXPECT_NEAR(fr.rebound, el.rebound, 1e-9 * 5);
  double err = 0;  // the elastic run's history at the free run's times (cubic Hermite on deflection and rate)
  for (std::size_t i = 0; i < fr.w.size(); ++i) {
    const auto k = static_cast<std::size_t>(std::upper_bound(el.t.begin(), el.t.end(), fr.t[i]) - el.t.begin());
    if (k == 0 || k >= el.t.size()) continue;
    const double dt = el.t[k] - el.t[k - 1], u = (fr.t[i] - el.t[k - 1]) / dt;
    const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
    const double w = h00 * el.w[k - 1] + h10 * dt * el.wv[k - 1] + h01 * el.w[k] + h11 * dt * el.wv[k];
    err = std::max(err, std::abs(fr.w[i] - w));
  }
  EXPECT_LT(err, 1e-3 * wmax);
}

}  // namespace
}  // namespace dmi
