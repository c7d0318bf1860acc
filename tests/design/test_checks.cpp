// Capacity formulas of the design checks against hand calculations (docs/design-checks.md).
#include <gtest/gtest.h>

#include <cmath>

#include "design/checks.hpp"
#include "design/limits.hpp"
#include "engine/common/error.hpp"

using namespace dmi::design;
using dmi::Section;

TEST(DesignFormulas, ConcreteTensileAndCompressiveCapacities) {
  ConcreteLimits c;  // defaults: f'c 28 MPa, f_t 3.28 MPa (Lin, Cheng & Tuan), phi 0.60, alpha 0.85
  EXPECT_NEAR(c.tensile_capacity(), 0.60 * 3.28e6, 1e-6);            // 1.968 MPa
  EXPECT_NEAR(c.compressive_capacity(), 0.60 * 0.85 * 28e6, 1e-6);   // 14.28 MPa
  c.tensile_rule = "aci_rupture";                                    // f_r = 0.62 sqrt(28) = 0.62 x 5.29150 = 3.28073 MPa
  EXPECT_NEAR(c.tensile_value(), 3.28073e6, 10.0);
  c.tensile_rule = "aci_plain";                                      // ACI 14.5.2.1: 0.42 sqrt(28) = 2.22243 MPa
  EXPECT_NEAR(c.tensile_value(), 2.22243e6, 10.0);
}

TEST(DesignFormulas, ConcreteOneWayShearByHand) {
  // b = 2 m, h = 1 m, f'c = 28 MPa: 0.11 x sqrt(28) = 0.11 x 5.29150 = 0.582065 MPa; x 2 m^2 = 1.16413 MN; x phi 0.6 = 698.48 kN.
  EXPECT_NEAR(concrete_one_way_shear_capacity(28e6, 1.0, 2.0, 1.0, 0.6), 698478.3, 1.0);
}

TEST(DesignFormulas, ConcretePunchingByHand) {
  // Square patch 0.4 x 0.4 m, h = 1 m: beta = 1 -> min(0.11 x 3, 0.22) = 0.22; b_o = 2 (1.4) + 2 (1.4) = 5.6 m;
  // V_n = 0.22 x 5.29150 MPa x 5.6 m x 1 m = 6.51913 MN; phi 0.6 -> 3.91148 MN.
  EXPECT_NEAR(concrete_punching_capacity(28e6, 1.0, 0.4, 0.4, 1.0, 0.6), 3.911479e6, 5.0);
  // 0.8 x 0.4 m, h = 0.5 m: beta = 2 -> 0.11 (1 + 1) = 0.22 (= the cap); b_o = 2 (1.3) + 2 (0.9) = 4.4 m;
  // V_n = 0.22 x 5.29150 x 4.4 x 0.5 = 2.56109 MN; phi 0.6 -> 1.53665 MN.
  EXPECT_NEAR(concrete_punching_capacity(28e6, 1.0, 0.8, 0.4, 0.5, 0.6), 1.536652e6, 5.0);
  // beta = 1.5: 0.11 (1 + 2/1.5) = 0.25667 > 0.22, the cap governs; beta = 3: 0.11 x 1.6667 = 0.18333 < 0.22.
  EXPECT_NEAR(concrete_punching_capacity(28e6, 1.0, 0.6, 0.4, 0.5, 1.0), 0.22 * 5.2915026e6 * (2 * 1.1 + 2 * 0.9) * 0.5, 5.0);
  EXPECT_NEAR(concrete_punching_capacity(28e6, 1.0, 0.9, 0.3, 0.5, 1.0), 0.11 * (1 + 2.0 / 3) * 5.2915026e6 * (2 * 1.4 + 2 * 0.8) * 0.5, 5.0);
  // A long patch governs by beta: 1.2 x 0.2 m, beta = 6 -> 0.11 (1 + 1/3) = 0.14667 < 0.22.
  const double bo = 2 * (1.2 + 0.5) + 2 * (0.2 + 0.5);
  EXPECT_NEAR(concrete_punching_capacity(28e6, 1.0, 1.2, 0.2, 0.5, 1.0), 0.11 * (4.0 / 3.0) * 5.2915026e6 * bo * 0.5, 5.0);
}

TEST(DesignFormulas, SteelPipeSectionByHand) {
  // CHS 500 x 20: d = 0.46 m; A = pi/4 (0.25 - 0.2116) = 0.0301593 m^2; I = pi/64 (0.0625 - 0.04477456) = 8.700955e-4 m^4;
  // W_el = I / 0.25 = 3.480382e-3 m^3; W_pl = (0.125 - 0.097336) / 6 = 4.610667e-3 m^3; A_v = 2A/pi = 0.0192 m^2.
  EXPECT_NEAR(chs_area(0.5, 0.02), 0.0301593, 1e-7);
  EXPECT_NEAR(chs_elastic_modulus(0.5, 0.02), 3.480382e-3, 1e-9);
  EXPECT_NEAR(chs_plastic_modulus(0.5, 0.02), 4.610667e-3, 1e-9);
  EXPECT_NEAR(chs_shear_area(0.5, 0.02), 0.0192, 1e-12);
  // V_pl,Rd = 0.0192 x 355 MPa / sqrt 3 = 3.93522 MN.
  EXPECT_NEAR(chs_shear_resistance(0.5, 0.02, 355e6, 1.0), 3.935219e6, 2.0);
  // N = 1 MN, M = 0.4 MN m, S355, class 1 (D/t = 25 <= 50 x 235/355 = 33.1):
  // 1 / (0.0301593 x 355) + 0.4 / (4.610667e-3 x 355) = 0.093401 + 0.244381 = 0.337782.
  EXPECT_NEAR(chs_interaction(1e6, 0.4e6, 0.5, 0.02, 355e6, 1.0), 0.337782, 1e-6);
  EXPECT_NEAR(chs_interaction(-1e6, -0.4e6, 0.5, 0.02, 355e6, 1.0), 0.337782, 1e-6);  // signs do not matter
}

TEST(DesignFormulas, SteelPipeClassFromDOverT) {
  // EN 1993-1-1 Table 5.2: eps^2 = 235 / f_y. S355: eps^2 = 0.66197 -> limits 33.10, 46.34, 59.58.
  EXPECT_EQ(chs_class(0.5, 0.02, 355e6), 1);    // D/t 25
  EXPECT_EQ(chs_class(0.4, 0.01, 355e6), 2);    // D/t 40
  EXPECT_EQ(chs_class(0.55, 0.01, 355e6), 3);   // D/t 55
  EXPECT_EQ(chs_class(0.6, 0.01, 355e6), 4);    // D/t 60 > 59.58
  EXPECT_NEAR(chs_class3_limit(355e6), 59.5775, 1e-4);
  EXPECT_EQ(chs_class(0.5, 0.01, 235e6), 1);    // S235: eps = 1, D/t 50 is the class 1 limit itself
  // Class 3: the elastic modulus in the interaction (W_el instead of W_pl).
  const double D = 0.55, t = 0.01, f = 355e6;
  EXPECT_NEAR(chs_interaction(0, 1e5, D, t, f, 1.0), 1e5 / (chs_elastic_modulus(D, t) * f), 1e-12);
}

// EN 1993-1-1 for box and I sections by hand, f_y 355 MPa (eps = sqrt(235/355) = 0.81362).
TEST(DesignFormulas, SteelIAndBoxSectionsByHand) {
  const Section I = Section::i_section(0.2, 0.4, 0.016, 0.01);
  // Outstand c/t = 0.095/0.016 = 5.9375 against 9 eps = 7.3225 (class 1) and 14 eps (class 3); web 36.8 against 72 eps.
  EXPECT_NEAR(flanged_class_ratio(I, 355e6, 1), 5.9375 / (9 * 0.8136157), 1e-6);
  EXPECT_NEAR(flanged_class_ratio(I, 355e6, 3), 5.9375 / (14 * 0.8136157), 1e-6);
  EXPECT_EQ(flanged_class(I, 355e6), 1);
  // N_Rd = 0.01008 x 355e6 = 3.5784 MN, M_Rd = W_pl f_y = 0.00156736 x 355e6 = 556.41 kN m.
  EXPECT_NEAR(flanged_interaction(1e6, 0.4e6, 0, I, 355e6, 1.0), 1e6 / 3.5784e6 + 0.4e6 / 556412.8, 1e-9);
  EXPECT_NEAR(flanged_interaction(-1e6, -0.4e6, 0, I, 355e6, 1.0), flanged_interaction(1e6, 0.4e6, 0, I, 355e6, 1.0), 1e-15);
  // Shear: A_v = h_w t_w = 0.00368 along the web, 2 b t_f = 0.0064 across: A_v f_y / sqrt 3.
  EXPECT_NEAR(flanged_shear_resistance(I, true, 355e6, 1.0), 0.00368 * 355e6 / std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(flanged_shear_resistance(I, false, 355e6, 1.0), 0.0064 * 355e6 / std::sqrt(3.0), 1e-6);
  // Box 0.2 x 0.3 x 0.01: walls (b - 3t)/t = 17 against 33 eps, webs 27 against 72 eps: class 1.
  const Section box = Section::box(0.2, 0.3, 0.01);
  EXPECT_NEAR(flanged_class_ratio(box, 355e6, 1), 17 / (33 * 0.8136157), 1e-6);
  EXPECT_EQ(flanged_class(box, 355e6), 1);
  EXPECT_NEAR(flanged_shear_resistance(box, true, 355e6, 1.1), box.area(0) * 0.3 / 0.5 * 355e6 / std::sqrt(3.0) / 1.1, 1e-6);
  // Class 3 (c/t 31 between 38 eps = 30.92 and 42 eps = 34.17): the elastic moduli about both axes.
  const Section b3 = Section::box(0.34, 0.34, 0.01);
  EXPECT_EQ(flanged_class(b3, 355e6), 3);
  const double Wel = b3.inertia(0) / 0.17;
  EXPECT_NEAR(flanged_interaction(0, 1e5, 2e5, b3, 355e6, 1.0), 3e5 / (Wel * 355e6), 1e-12);
  // Class 4: (0.4 - 0.018)/0.006 = 63.7 > 42 eps = 34.17.
  EXPECT_EQ(flanged_class(Section::box(0.4, 0.4, 0.006), 355e6), 4);
  EXPECT_GT(flanged_class_ratio(Section::box(0.4, 0.4, 0.006), 355e6, 3), 1.0);
}

TEST(DesignLimits, ReadsAFileAndRejectsBadValuesWithThePath) {
  const nlohmann::json ok = nlohmann::json::parse(R"({"concrete": {"compressive_strength_Pa": 35e6, "tensile_rule": "aci_rupture",
      "phi_flexure": 0.65, "punching_patch_m": [0.4, 0.4]}, "steel": {"yield_strength_Pa": 355e6, "gamma_M0": 1.1},
      "members": {"dam": "concrete"}})");
  const Limits L = parse_limits(ok, "limits.json");
  EXPECT_NEAR(L.concrete.tensile_value(), 0.62 * std::sqrt(35.0) * 1e6, 1e-3);
  EXPECT_NEAR(L.concrete.tensile_capacity(), 0.65 * 0.62 * std::sqrt(35.0) * 1e6, 1e-3);
  EXPECT_NEAR(L.steel.design_strength(), 355e6 / 1.1, 1e-6);
  EXPECT_EQ(L.member_material.at("dam"), "concrete");
  auto message = [](const char* text) {
    try {
      parse_limits(nlohmann::json::parse(text), "limits.json");
    } catch (const dmi::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"({"concrete": {"compressive_strength_Pa": -28e6}})"),
            "limits.json: /concrete/compressive_strength_Pa = -28000000.0: expected a number > 0");
  EXPECT_NE(message(R"({"concrete": {"phi_shear": 1.5}})").find("/concrete/phi_shear = 1.5: expected a number in (0, 1]"), std::string::npos);
  EXPECT_NE(message(R"({"steel": {"fy": 355e6}})").find("/steel/fy"), std::string::npos);
  EXPECT_NE(message(R"({"members": {"dam": "timber"}})").find("/members/dam = \"timber\": expected \"concrete\" or \"steel\""), std::string::npos);
  EXPECT_NE(message(R"({"steel": {"gamma_M0": 0.9}})").find("expected a partial factor >= 1"), std::string::npos);
  EXPECT_EQ(L.grid_judge_on, "finest");
  EXPECT_EQ(parse_limits(nlohmann::json::parse(R"({"grid_study": {"judge_on": "conservative_bound"}})"), "l.json").grid_judge_on, "conservative_bound");
  EXPECT_NE(message(R"({"grid_study": {"judge_on": "mean"}})").find("/grid_study/judge_on = \"mean\": expected \"finest\" or \"conservative_bound\""),
            std::string::npos);
}

// A demand at round-off of its capacity (a tension of 4.7e-10 Pa where nothing pulls) is a zero demand, not a number
// the report prints; a small real demand stays.
TEST(Checks, RoundOffDemandIsZero) {
  dmi::design::Check c;
  c.demand = 4.72e-10, c.capacity = 1.97e6;
  c.finish();
  EXPECT_EQ(c.demand, 0.0);
  EXPECT_EQ(c.utilisation, 0.0);
  c.demand = 1.0, c.capacity = 1.97e6;
  c.finish();
  EXPECT_EQ(c.demand, 1.0);
}
