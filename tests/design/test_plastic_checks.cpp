// The ultimate level of members that yield: the closed forms by hand (EN 1993-1-1 flexural buckling, DNV-RP-C204
// denting, the residual of a ringing history) and the checks of a small plastic frame's results assembled by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "design/checks.hpp"
#include "design/plastic_checks.hpp"

namespace dmi::design {
namespace {

TEST(PlasticChecks, FlexuralBucklingByHand) {
  // A 0.01 m^2, I 1e-4 m^4, L 5 m, E 210 GPa, f_y 355 MPa, curve a (alpha 0.21):
  // N_cr = pi^2 E I / L^2 = 8 290.47 kN; lambda = sqrt(3 550 / 8 290.47) = 0.654372; Phi = 0.5 (1 + 0.21 x 0.454372
  // + 0.428202) = 0.761810; chi = 1 / (0.761810 + sqrt(0.580355 - 0.428202)) = 0.868148; N_b,Rd = 3 081.92 kN.
  EXPECT_NEAR(flexural_buckling_resistance(0.01, 1e-4, 5, 210e9, 355e6, buckling_imperfection("a"), 1.0), 3081.92e3, 0.01e3);
  // A stocky member (lambda < 0.2): chi = 1 (Phi - sqrt(Phi^2 - lambda^2) would exceed it).
  EXPECT_NEAR(flexural_buckling_resistance(0.01, 1e-4, 0.5, 210e9, 355e6, 0.21, 1.0), 3.55e6, 1);
  EXPECT_DOUBLE_EQ(buckling_imperfection("c"), 0.49);
  EXPECT_THROW(buckling_imperfection("e"), std::invalid_argument);
}

TEST(PlasticChecks, DentDepthByHand) {
  // CHS 0.5 x 0.016, f_y 355 MPa, knife edge: R_c = f_y t^2/4 sqrt(D/t) = 127.009 kN; at 1 MN,
  // w/D = (1e6 / (22 R_c))^(1/0.55) = 0.154392, w = 77.196 mm; the energy to that dent 22 R_c D (w/D)^1.55 / 1.55 = 49.804 kJ.
  EXPECT_NEAR(dent_depth_at_force(1e6, 0.5, 0.016, 355e6, 0), 0.077196, 1e-6);
  EXPECT_NEAR(dent_depth_for_energy(49803.94, 0.5, 0.016, 355e6, 0), 0.077196, 1e-6);
  // A wider contact resists more: a shallower dent under the same force.
  EXPECT_LT(dent_depth_at_force(1e6, 0.5, 0.016, 355e6, 0.5), dent_depth_at_force(1e6, 0.5, 0.016, 355e6, 0));
}

TEST(PlasticChecks, ResidualOfARingingHistory) {
  std::vector<double> t, u;
  for (int k = 0; k <= 2000; ++k) {
    t.push_back(k * 1e-3);
    u.push_back(t.back() < 1 ? 0.01 : 0.11 + 0.02 * std::sin(2 * std::numbers::pi * (t.back() - 1) / 0.1));
  }
  const Residual r = residual_of(t, u, 0.5);  // five whole periods
  EXPECT_NEAR(r.value, 0.1, 1e-4);
  EXPECT_NEAR(r.amplitude, 0.02, 1e-4);
  EXPECT_EQ(member_group("column_0_2"), "column");
  EXPECT_EQ(member_group("dam"), "dam");
}

// One plastic pipe column of two elements, 4 m, fixed at its foot; histories assembled by hand.
TEST(PlasticChecks, ChecksOfAPlasticColumn) {
  FrameInfo f;
  f.dim = 2;
  f.nodes = {{0, 0, 0}, {0, 2, 0}, {0, 4, 0}};
  for (int e = 0; e < 2; ++e) {
    FrameInfo::Element el;
    el.i = e, el.j = e + 1, el.s0 = 0.5 * e, el.s1 = 0.5 * (e + 1), el.E = 205e9, el.yield_strength = 355e6;
    el.section = Section::pipe(0.5, 0.016);
    f.elements.push_back(el);
  }
  f.members.push_back({"column_0_1", "steel", "steel", 0, 2, 4.0, true});
  Results r;
  r.complete = true;
  r.time = {0.0, 0.01, 0.02, 0.03};
  r.info.stats.frame_periods = {0.015};
  // frame/plastic: [work, peak strain, plastic strain] per element; the foot element peaks at 0.02 s.
  r.series.push_back({"frame/plastic", "J, -, -", {"e0_work", "e0_peak_strain", "e0_plastic_strain", "e1_work", "e1_peak_strain", "e1_plastic_strain"},
                      {0, 0, 0, 0, 0, 0, 100, 0.004, 0.002, 0, 0.001, 0, 900, 0.012, 0.010, 50, 0.001, 0, 1000, 0.012, 0.011, 60, 0.001, 0}});
  // The crest (node 2) ends at 30 mm, ringing +-5 mm; its start (the state at rest) at 0.
  std::vector<double> disp(4 * 9, 0.0);
  const double crest[4] = {0, 0.02, 0.035, 0.025};
  for (int k = 0; k < 4; ++k) disp[9 * k + 6] = crest[k];
  r.series.push_back({"frame/displacement", "m, m, rad", std::vector<std::string>(9, "u"), disp});
  r.series.push_back({"energy/frame_plastic", "J", {"value"}, {0, 100, 950, 1060}});
  MemberEnvelope env;
  env.name = "column_0_1", env.cls = "steel", env.length = 4, env.plastic = true;
  Station st;
  st.N_min.min(-1e6, 0.02);
  env.stations.push_back(st);
  std::vector<Check> checks;
  SteelLimits S;
  S.yield_strength = 355e6;
  const std::optional<PlasticRecord> p = plastic_part(r, f, {env}, std::nullopt, Contact{}, S, checks, "test");
  ASSERT_TRUE(p.has_value());
  EXPECT_DOUBLE_EQ(p->energy.by_group_J.at("column"), 1060.0);
  EXPECT_DOUBLE_EQ(p->energy.plastic_work_J, 1060.0);
  EXPECT_EQ(to_json(*plastic_from_json(to_json(*p), "test")), to_json(*p));  // the record reads back the same
  const auto find = [&](const char* id) {
    for (const Check& c : checks)
      if (c.id == id) return c;
    ADD_FAILURE() << id;
    return Check{};
  };
  const Check strain = find("steel_strain");
  EXPECT_DOUBLE_EQ(strain.demand, 0.012);
  EXPECT_DOUBLE_EQ(strain.time_s, 0.02);
  EXPECT_DOUBLE_EQ(strain.position, 0.25);  // the foot element's middle
  EXPECT_NEAR(find("steel_hinge_class").capacity, 50 * 235.0 / 355.0, 1e-12);
  EXPECT_DOUBLE_EQ(find("steel_flexural_buckling").demand, 1e6);
  // Residual over the last period (0.015 s: the samples at 0.02 and 0.03 s): mean 0.030 m, drift 0.030 / 4.
  const Check drift = find("steel_residual_drift");
  EXPECT_NEAR(drift.demand, 0.030 / 4, 1e-12);
  ASSERT_TRUE(p->residual_drift.has_value());
  EXPECT_NEAR(p->residual_drift->amplitude_m, 0.005, 1e-12);
}

}  // namespace
}  // namespace dmi::design
