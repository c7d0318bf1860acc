// Envelopes, checks and reactions of a space frame (3D) on small hand-made histories, worked by hand: biaxial bending,
// torsion and resultant shear (docs/design-checks.md, "Space frames").
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "design/checks.hpp"
#include "design/design.hpp"
#include "design/loads.hpp"
#include "design/members.hpp"
#include "engine/io/records_json.hpp"

using namespace dmi::design;
using nlohmann::json;

namespace {

// One horizontal member 'beam' from (0,0,0) to (2,0,0), one element, depth axis e2 = z; supports 'a' (node 0) and 'b'
// (node 1).
json structure(const json& section, const std::string& material) {
  json el{{"member", 0}, {"i", 0}, {"j", 1}, {"s0", 0.0}, {"s1", 1.0}, {"section", section}, {"youngs_modulus_Pa", 210e9},
          {"poisson_ratio", 0.3}, {"density_kg_m3", 7850}, {"e2", {0.0, 0.0, 1.0}}};
  json sup = json::array();
  for (int n = 0; n < 2; ++n)
    sup.push_back({{"node", n ? "b" : "a"}, {"node_index", n}, {"type", "fixed"}, {"fixed", {true, true, true, true, true, true}},
                   {"series", std::string("supports/") + (n ? "b" : "a") + "/reaction"}});
  return json{{"dimension", 3}, {"nodes_m", {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}}}, {"node_names", {"a", "b"}}, {"elements", {el}},
              {"members", {{{"name", "beam"}, {"material", material}, {"first_element", 0}, {"elements", 1}}}}, {"supports", sup}};
}

dmi::Series series(const std::string& path, std::vector<std::string> comps, std::vector<double> data) {
  dmi::Series s;
  s.path = path, s.unit = "N", s.components = std::move(comps), s.data = std::move(data);
  return s;
}

// Two samples, t = 0 (nothing) and 0.1 s: end i carries `fi` (N, Vy, Vz, T, My, Mz), end j nothing.
dmi::Results results(const json& st, const std::array<double, 6>& fi) {
  dmi::Results r;
  r.complete = true;
  r.info.scenario_name = "hand";
  r.info.scenario_json = json{{"name", "hand"}, {"analysis", {{"dimension", 3}}}, {"structure", {{"members", json::array({json::object()})}}}}.dump();
  r.info.structure = dmi::structure_from_json(st, "hand.h5");
  r.time = {0.0, 0.1};
  std::vector<std::string> c;
  for (const char* end : {"_i", "_j"})
    for (const char* q : {"N", "Vy", "Vz", "T", "My", "Mz"}) c.push_back(std::string("e0_") + q + end);
  std::vector<double> d(24, 0.0);
  for (int k = 0; k < 6; ++k) d[12 + k] = fi[k];
  r.series.push_back(series("frame/end_forces", c, d));
  const std::vector<std::string> rc{"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  // t = 0.1: a F = (10, 0, 5) kN; b F = (10, 0, -5) kN, M = (0, 3, 0) kN m.
  r.series.push_back(series("supports/a/reaction", rc, {0, 0, 0, 0, 0, 0, 10e3, 0, 5e3, 0, 0, 0}));
  r.series.push_back(series("supports/b/reaction", rc, {0, 0, 0, 0, 0, 0, 10e3, 0, -5e3, 0, 3e3, 0}));
  r.series.push_back(series("frame/contact_force", {"x", "y", "z"}, {0, 0, 0, 30e3, 0, 40e3}));
  return r;
}

const Check& find(const std::vector<Check>& v, const std::string& id) {
  for (const auto& c : v)
    if (c.id == id) return c;
  throw std::runtime_error("no check " + id);
}

}  // namespace

TEST(SpaceDesign, SteelPipeBiaxialBendingTorsionAndShearByHand) {
  // CHS 500 x 20, S355: A = 0.030159289 m^2, W_el = 3.48038201e-3 m^3, W_pl = 4.6106667e-3 m^3 (class 1), W_t = 2 W_el.
  // End i: N = -200 kN, Vy = 300, Vz = 400 kN (V = 500 kN), T = 50 kN m, My = 180, Mz = 240 kN m (M = 300 kN m).
  Limits L;
  L.steel.yield_strength = 355e6;
  const json pipe{{"kind", "pipe"}, {"diameter_m", 0.5}, {"wall_thickness_m", 0.02}};
  const dmi::Results r = results(structure(pipe, "steel"), {-200e3, 300e3, 400e3, 50e3, 180e3, 240e3});
  const FrameInfo f = frame_info(*r.info.structure, "hand.h5", L);
  ASSERT_EQ(f.dim, 3);
  const auto env = member_envelopes(r, f, L, "hand.h5");
  const auto& ch = env[0].checks;
  const double A = 0.030159289, Wel = 3.48038201e-3, Wpl = 4.6106667e-3, Wt = 2 * Wel;
  // Elastic: |N|/A + |M|/W_el = 6.6314 + 86.1975 = 92.829 MPa, exact (the extreme fibre is sampled where sigma peaks).
  EXPECT_NEAR(find(ch, "steel_elastic_stress").demand, 200e3 / A + 300e3 / Wel, 1.0);
  // Interaction with the resultant moment: 200e3/(A 355e6) + 300e3/(W_pl 355e6) = 0.201966.
  EXPECT_NEAR(find(ch, "steel_interaction").utilisation, 200e3 / (A * 355e6) + 300e3 / (Wpl * 355e6), 1e-6);
  // Torsion: T_Rd = W_t f_y / sqrt 3 = 1.42667e6 N m; 50e3 / T_Rd = 0.035046.
  const double TRd = Wt * 355e6 / std::sqrt(3.0);
  EXPECT_NEAR(find(ch, "steel_torsion").utilisation, 50e3 / TRd, 1e-9);
  // Shear with torsion: V_pl,Rd = 3.9352194e6 N (2D test), reduced by 1 - tau_t/(f_y/sqrt 3) = 1 - 0.035046.
  EXPECT_NEAR(find(ch, "steel_shear").capacity, 3.9352194e6 * (1 - 50e3 / TRd), 10.0);
  EXPECT_NEAR(find(ch, "steel_shear").demand, 500e3, 1e-6);
  // von Mises: the largest of sqrt(sigma^2 + 3 tau^2) around the wall, sigma(phi) = N/A + M/W_el cos(phi - phi_M),
  // tau = T/W_t + 2V/A |sin(phi - phi_V)|; by 36 000 points here, against 74 in the check: the sampling's relative
  // error is below (2.5 deg)^2 / 2 = 1e-3.
  const double phiM = std::atan2(180e3, -240e3), phiV = std::atan2(400e3, 300e3);
  double vm = 0;
  for (int k = 0; k < 36000; ++k) {
    const double phi = 2 * std::numbers::pi * k / 36000;
    const double s = -200e3 / A + 300e3 / Wel * std::cos(phi - phiM), t = 50e3 / Wt + 2 * 500e3 / A * std::abs(std::sin(phi - phiV));
    vm = std::max(vm, std::sqrt(s * s + 3 * t * t));
  }
  EXPECT_NEAR(find(ch, "steel_von_mises").demand / vm, 1.0, 1e-3);
  EXPECT_GE(find(ch, "steel_von_mises").demand, 200e3 / A + 300e3 / Wel);  // never below the extreme fibre's sigma
  // The station envelope: resultants and components.
  const Station& st = env[0].stations[0];
  EXPECT_NEAR(st.V_abs.value, 500e3, 1e-6);
  EXPECT_NEAR(st.M_max.value, 300e3, 1e-6);
  EXPECT_NEAR(st.T_abs.value, 50e3, 1e-9);
  EXPECT_NEAR(st.Mz_max.value, 240e3, 1e-9);
  EXPECT_FALSE(st.M_min.set);  // no sign for a resultant
}

TEST(SpaceDesign, ConcreteRectangleBiaxialCornerStressAndTorsionByHand) {
  // Rectangle b = 2 m (along e3), h = 1 m (along e2): A = 2, I_z = b h^3/12 = 1/6, I_y = h b^3/12 = 2/3 m^4, c = 0.5, w = 1 m.
  // End i: N = -100 kN, Vy = 60, Vz = 80 kN, T = 0, My = 200, Mz = 150 kN m.
  Limits L;
  L.concrete.strain_rate_effects = false;  // the static envelope by hand (the strain-rate factors: test_strain_rate.cpp)
  const json rect{{"kind", "rectangle"}, {"width_m", 2.0}, {"depth_start_m", 1.0}, {"depth_end_m", 1.0}};
  const dmi::Results r = results(structure(rect, "concrete"), {-100e3, 60e3, 80e3, 0.0, 200e3, 150e3});
  const FrameInfo f = frame_info(*r.info.structure, "hand.h5", L);
  const auto ch = member_envelopes(r, f, L, "hand.h5")[0].checks;
  // Corner: -0.05 + 150e3 0.5 / (1/6) + 200e3 1 / (2/3) = -0.05 + 0.45 + 0.30 = 0.70 MPa; compression -0.80 MPa.
  EXPECT_NEAR(find(ch, "concrete_flexural_tension").demand, 0.70e6, 1e-3);
  EXPECT_NEAR(find(ch, "concrete_flexural_tension").utilisation, 0.70e6 / (0.6 * 3.28e6), 1e-9);
  EXPECT_NEAR(find(ch, "concrete_compression").demand, 0.80e6, 1e-3);
  // Without torsion the principal tension peaks at the tension corner, where the shear flow vanishes: 0.70 MPa.
  EXPECT_NEAR(find(ch, "concrete_principal_tension").demand, 0.70e6, 1e-3);
  // One-way shear with the resultant 100 kN against 0.6 x 0.11 sqrt(28) MPa x 2 m x 1 m = 698.478 kN.
  EXPECT_NEAR(find(ch, "concrete_shear").utilisation, 100e3 / 698478.35, 1e-7);
  // Pure torsion T = 100 kN m: tau_max = T / (alpha b t^2), alpha = 0.246 for b/t = 2 (Timoshenko & Goodier 1970,
  // sec. 109 table, three digits): 0.2033 MPa, the principal tension of pure shear.
  const dmi::Results rt = results(structure(rect, "concrete"), {0, 0, 0, 100e3, 0, 0});
  const auto ct = member_envelopes(rt, frame_info(*rt.info.structure, "hand.h5", L), L, "hand.h5")[0].checks;
  EXPECT_NEAR(find(ct, "concrete_principal_tension").demand / (100e3 / (0.246 * 2 * 1)), 1.0, 2.5e-3);
  EXPECT_NEAR(find(ct, "concrete_flexural_tension").demand, 0.0, 1e-9);
}

TEST(SpaceDesign, ReactionTotalsAboutTheSupportCentroidInThreeDimensions) {
  const json pipe{{"kind", "pipe"}, {"diameter_m", 0.5}, {"wall_thickness_m", 0.02}};
  const dmi::Results r = results(structure(pipe, "steel"), {0, 0, 0, 0, 0, 0});
  const FrameInfo f = frame_info(*r.info.structure, "hand.h5", Limits{});
  const Reactions re = reactions(r, f, "hand.h5");
  EXPECT_DOUBLE_EQ(re.about[0], 1.0);
  // F = (20, 0, 0) kN; M about (1, 0, 0): b's own 3 + (-1, 0, 0) x (10, 0, 5) + (1, 0, 0) x (10, 0, -5) = 3 + 5 + 5 = 13 kN m about y.
  EXPECT_NEAR(re.total.at("H_N").abs.value, 20e3, 1e-9);
  EXPECT_NEAR(re.total.at("Fz_N").abs.value, 0.0, 1e-9);
  EXPECT_NEAR(re.total.at("My_Nm").max.value, 13e3, 1e-9);
  EXPECT_NEAR(re.total.at("M_overturning_Nm").abs.value, 13e3, 1e-9);
  EXPECT_NEAR(re.supports[1].at("My_Nm").final, 3e3, 1e-12);
  // Contact in 3D: |(30, 0, 40)| = 50 kN; impulse (3, 0, 4) kN s.
  const Contact c = contact(r);
  EXPECT_NEAR(c.peak_N, 50e3, 1e-9);
  ASSERT_EQ(c.impulse_N_s.size(), 3u);
  EXPECT_NEAR(c.impulse_N_s[2], 4e3, 1e-9);
  // design_run: the base shear key of a space frame and a 3-component location.
  const json run = to_json(design_run(r, Limits{}, "hand.h5"));
  EXPECT_EQ(run["dimension"], 3);
  EXPECT_NEAR(run["base_total"]["H_N"]["abs_max"]["value"].get<double>(), 20e3, 1e-9);
  EXPECT_EQ(run["members"][0]["stations"][0]["location_m"].size(), 3u);
  EXPECT_EQ(run["checks"][0]["location_m"].size(), 3u);
}
