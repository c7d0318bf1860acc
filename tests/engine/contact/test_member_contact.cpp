// Members as velocity boundaries (Lin & Yang two-stage contact, Lin & Yang 2024), end to end on
// small scenes with closed forms: a block resting on a stiff beam loads it with its weight; a block
// sliding on it decelerates at mu g; separable contact never pulls; orientation by x-bar (eq. 24)
// holds for material below a member.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

using J = nlohmann::json;

// A stiff fixed-fixed steel beam, x in [0, 4], centre-line y = 0.1 (surfaces 0 and 0.2), Newmark
// (so the step is the block's), and a soft 0.5 x 0.25 m block of 125 kg whose bottom sits on
// the top surface (below: its top on the bottom surface).
J scene(const J& contact, const J& velocity, bool below, double end_time) {
  const double y0 = below ? -0.25 : 0.2;
  return J{{"schema_version", 1},
           {"name", "block on a stiff beam"},
           {"analysis", {{"dimension", 2}, {"plane", "strain"}, {"end_time", end_time}, {"gravity", below ? J::array({0, 0}) : J::array({0, -9.81})}}},
           {"grid", {{"origin", {-0.5, -1.0}}, {"size", {5.0, 2.5}}, {"cell_size", 0.1}}},
           {"materials", {{{"name", "soft"}, {"density", 1000}, {"youngs_modulus", 1e6}, {"poisson_ratio", 0.3}},
                          {{"name", "steel"}, {"density", 7850}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}}}},
           {"bodies", {{{"name", "block"}, {"material", "soft"}, {"shape", {{"type", "box"}, {"min", {1.0, y0}}, {"max", {1.5, y0 + 0.25}}}},
                        {"velocity", velocity}}}},
           {"structure", {{"integrator", "newmark"}, {"self_weight", false},
                          {"nodes", {{{"name", "A"}, {"position", {0, 0.1}}}, {{"name", "B"}, {"position", {4, 0.1}}}}},
                          {"members", {{{"name", "beam"}, {"start", "A"}, {"end", "B"}, {"material", "steel"}, {"elements", 8},
                                        {"section", {{"type", "rectangle"}, {"width", 1.0}, {"depth", 0.2}}}}}},
                          {"supports", {{{"node", "A"}, {"type", "fixed"}}, {{"node", "B"}, {"type", "fixed"}}}}}},
           {"member_contact", contact},
           {"output", {{"probes", {{{"name", "block"}, {"type", "body"}, {"body", "block"}, {"quantities", {"velocity", "displacement"}}}}}}}};
}

RunOutput run(const J& j) { return run_quiet(parse_scenario(j.dump(), "test")); }

TEST(MemberContact, BlockRestingOnABeamLoadsItWithItsWeight) {
  const RunOutput out = run(scene({{"mode", "separable"}}, {0, 0}, false, 0.6));
  const auto& t = out.results.time;
  const double weight = 125 * 9.81;
  const double contact = -time_mean(t, series(out.results, "frame/contact_force"), 1, 0.2, 0.6);
  const double reactions = time_mean(t, series(out.results, "supports/A/reaction"), 1, 0.2, 0.6) +
                           time_mean(t, series(out.results, "supports/B/reaction"), 1, 0.2, 0.6);
  EXPECT_NEAR(contact / weight, 1.0, 0.02);
  EXPECT_NEAR(reactions / weight, 1.0, 0.02);
  // The material distance lets the block sink until the mass centre its bottom nodes see reaches
  // the surface (q = 1): measured 17 mm, i.e. 0.17 of a cell. The paper's node distance holds a
  // block whose bottom lies on a grid line exactly where it is.
  EXPECT_LT(column_max(series(out.results, "probes/block/displacement"), 1, true), 0.25 * 0.1);
  const RunOutput node = run(scene({{"mode", "separable"}, {"distance", "node"}}, {0, 0}, false, 0.6));
  EXPECT_LT(column_max(series(node.results, "probes/block/displacement"), 1, true), 1e-3);
}

TEST(MemberContact, FrictionDeceleratesASlidingBlockAtMuG) {
  const RunOutput fr = run(scene({{"mode", "friction"}, {"friction", 0.3}}, {2, 0}, false, 0.35));
  const double a = slope(fr.results.time, series(fr.results, "probes/block/velocity"), 0, 0.05, 0.3);
  EXPECT_NEAR(a / (-0.3 * 9.81), 1.0, 0.05);
  const RunOutput smooth = run(scene({{"mode", "separable"}}, {2, 0}, false, 0.35));
  EXPECT_NEAR(slope(smooth.results.time, series(smooth.results, "probes/block/velocity"), 0, 0.05, 0.3), 0.0, 0.05);
}

// A block moving up into the beam from below: x-bar orients the normal downwards, the beam is
// pushed up (never pulled down), and the block is sent back. (It keeps only 0.16 of its speed: the
// decay layer stops a cell-thick slab of a 2.5-cell block at once; docs/verification.md.)
TEST(MemberContact, MaterialBelowAMemberIsPushedBackAndNeverPulled) {
  const RunOutput out = run(scene({{"mode", "separable"}}, {0, 1}, true, 0.3));
  const Series& f = series(out.results, "frame/contact_force");
  double up = 0, down = 0;
  for (std::size_t k = 0; k < f.samples(); ++k) {
    up = std::max(up, f.data[2 * k + 1]);
    down = std::min(down, f.data[2 * k + 1]);
  }
  EXPECT_GT(up, 100.0);
  EXPECT_EQ(down, 0.0);
  EXPECT_LT(series(out.results, "probes/block/velocity").data.back(), -0.1);
}

// A 1000 kg debris block at 5 m/s stuck to a 222 kg steel pipe (the project's core case, reviewer's
// repro): with the staggered coupling the material is held at v*_n and the frame takes the reaction.
// The attached-mass treatment and HHT damping of the unresolved frame modes keep the coupled system
// from gaining energy (it gained 4e6 J of 12.7 kJ with average acceleration); so does the explicit frame.
TEST(MemberContact, HeavyDebrisStuckToALightPipeGainsNoEnergy) {
  const J base = J::parse(R"({"schema_version": 1, "name": "pipe",
    "analysis": {"dimension": 2, "plane": "strain", "end_time": 0.3, "dt_max": 1e-4, "gravity": [0, -10]},
    "mpm": {"shape_function": "linear"}, "grid": {"origin": [-0.5, -1.0], "size": [4.0, 3.0], "cell_size": 0.1},
    "materials": [{"name": "debris", "density": 2000, "youngs_modulus": 1e7, "poisson_ratio": 0.3},
                  {"name": "steel", "density": 7850, "youngs_modulus": 2e11, "poisson_ratio": 0.3}],
    "bodies": [{"name": "block", "material": "debris", "particles_per_cell": 4,
                "shape": {"type": "box", "min": [1.0, 0.35], "max": [2.0, 0.85]}, "velocity": [0, -5]}],
    "structure": {"integrator": "newmark", "self_weight": false,
      "nodes": [{"name": "A", "position": [0, 0]}, {"name": "B", "position": [3, 0]}],
      "members": [{"name": "pipe", "start": "A", "end": "B", "material": "steel", "elements": 6,
                   "section": {"type": "pipe", "diameter": 0.3, "wall_thickness": 0.01}}],
      "supports": [{"node": "A", "type": "fixed"}, {"node": "B", "type": "fixed"}]},
    "member_contact": {"mode": "stick"}, "output": {"history_interval": 0.005}})");
  for (const char* integrator : {"newmark", "explicit"}) {
    J j = base;
    j["structure"]["integrator"] = integrator;
    const RunOutput out = run(j);
    const Series& bal = series(out.results, "energy/balance_error");
    const double input = 12500 + series(out.results, "energy/gravity_work").data.back();
    double worst = -1e300;
    for (double b : bal.data) worst = std::max(worst, b);
    EXPECT_LT(worst, 0.01 * input) << integrator;
    EXPECT_LT(bal.data.back(), 0.0) << integrator;  // the sticking impact dissipates
  }
}

// A structure stands in equilibrium under its own weight at t = 0 (initial_state static, the default):
// the fixed-fixed beam's mid-span sits at w L^4 / (384 EI) and stays there; unloaded it swings to ~2x.
TEST(MemberContact, SelfWeightStartsInStaticEquilibrium) {
  J j = scene({{"mode", "separable"}}, {0, 0}, false, 0.05);
  j["structure"]["self_weight"] = true;
  j["structure"]["integrator"] = "explicit";
  j["bodies"][0]["shape"] = {{"type", "box"}, {"min", {4.2, 0.5}}, {"max", {4.4, 0.7}}};  // out of reach
  j["output"]["probes"] = {{{"name", "mid"}, {"type", "member"}, {"member", "beam"}, {"position", 0.5}, {"quantities", {"displacement"}}}};
  const double w = 7850 * 0.2 * 9.81, EI = 2e11 * 0.2 * 0.2 * 0.2 / 12, sag = w * 256 / (384 * EI);
  const RunOutput st = run(j);
  const Series& u = series(st.results, "probes/mid/displacement");
  EXPECT_NEAR(-u.data[1], sag, 1e-3 * sag);
  EXPECT_NEAR(column_max(u, 1, true), sag, 0.01 * sag);
  j["structure"]["initial_state"] = "unloaded";
  const RunOutput un = run(j);
  EXPECT_GT(column_max(series(un.results, "probes/mid/displacement"), 1, true), 1.5 * sag);
}

// A body bonded to a member (a tyre buffer fixed on a dam face) hangs from it whatever the contact mode:
// a block under the beam stays put and the supports carry its weight; not bonded, it falls away.
TEST(MemberContact, BondedBodyHangsFromTheMember) {
  J j = scene({{"mode", "separable"}, {"bonded", {"block"}}}, {0, 0}, true, 0.6);
  j["analysis"]["gravity"] = {0, -9.81};
  const RunOutput bonded = run(j);
  const auto& t = bonded.results.time;
  EXPECT_LT(column_max(series(bonded.results, "probes/block/displacement"), 1, true), 0.025);
  const double reactions = time_mean(t, series(bonded.results, "supports/A/reaction"), 1, 0.2, 0.6) +
                           time_mean(t, series(bonded.results, "supports/B/reaction"), 1, 0.2, 0.6);
  EXPECT_NEAR(reactions / (125 * 9.81), 1.0, 0.03);
  j["member_contact"].erase("bonded");
  j["analysis"]["end_time"] = 0.3;
  const RunOutput loose = run(j);
  EXPECT_GT(column_max(series(loose.results, "probes/block/displacement"), 1, true), 0.3);
}

// An explicit frame's stability limit enters the global step (scaled by the CFL fraction); an
// implicit (Newmark) frame does not limit it. The stiff steel beam (c = 5 km/s) governs here.
TEST(MemberContact, ExplicitFrameLimitsTheTimeStepNewmarkDoesNot) {
  J j = scene({{"mode", "separable"}}, {0, 0}, false, 0.1);
  const Solver<2> implicit(build_scene<2>(parse_scenario(j.dump(), "test")));
  j["structure"]["integrator"] = "explicit";
  const Solver<2> expl(build_scene<2>(parse_scenario(j.dump(), "test")));
  const double mpm = implicit.stable_time_step(1.0), frame = expl.scene().frame->stable_time_step();
  EXPECT_TRUE(std::isinf(implicit.scene().frame->stable_time_step()));
  EXPECT_LT(0.5 * frame, mpm);
  EXPECT_DOUBLE_EQ(expl.stable_time_step(1.0), 0.5 * frame);
}

}  // namespace
}  // namespace dmi
