// Stability of the dam on its foundation joint against hand calculations (docs/design-checks.md, "Stability").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "design/stability.hpp"
#include "design/stability_checks.hpp"
#include "design/damping_share.hpp"

using namespace dmi;
using namespace dmi::design;

namespace {

// The record as design.json holds it; it reads back the same.
nlohmann::json stability_json(const Results& r, const FrameInfo& f, const DesignBasis& b, const FoundationLimits& L, std::vector<Check>& checks,
                              const std::string& where) {
  const std::optional<StabilityRecord> s = stability(r, f, b, L, checks, where);
  if (!s) return nullptr;
  const nlohmann::json j = to_json(*s);
  EXPECT_EQ(nlohmann::json::parse(to_json(*stability_from_json(nlohmann::json::parse(j.dump()), "test")).dump()), nlohmann::json::parse(j.dump()));
  return j;
}

// A 6 m dam, crest 1.5 m, base 3.5 m, 3 m wide, rho 2400, vertical upstream face (heel at x = 3.5 m from the toe),
// battered downstream face. Weight: rectangle 1.5 x 6 and triangle 2.0 x 6 / 2, times 3 m x 2400 kg/m3 x 9.81:
// W_rect = 9 m2 x 3 x 23544 = 635 688 N at x = 3.5 - 0.75 = 2.75 m; W_tri = 6 m2 x 3 x 23544 = 423 792 N at
// x = 2/3 x 2.0 = 1.3333 m from the toe. N = 1 059 480 N; Mr = 635 688 x 2.75 + 423 792 x 1.33333 = 1 748 142 + 565 056
// = 2 313 198 N m about the toe.
BaseJointLoads trial_dam(double H, double Mo) {
  BaseJointLoads l;
  l.N = 635688.0 + 423792.0;
  l.Mr = 635688.0 * 2.75 + 423792.0 * 2.0 * 2.0 / 3.0;
  l.H = H;
  l.Mo = Mo;
  return l;
}

}  // namespace

TEST(Stability, SlidingFactorByHand) {
  // H = 1 421 kN (the trial dam's buffered peak base shear), mu 0.6, no cohesion: 0.6 x 1 059 480 / 1 421 000 = 0.44735.
  EXPECT_NEAR(sliding_factor(trial_dam(1.421e6, 0), 0.6, 0.0, 10.5), 0.447352, 1e-6);
  // With 100 kPa cohesion over 3.5 x 3 m: (635 688 + 1 050 000) / 1 421 000 = 1.186269.
  EXPECT_NEAR(sliding_factor(trial_dam(1.421e6, 0), 0.6, 1e5, 10.5), (0.6 * 1059480.0 + 1.05e6) / 1.421e6, 1e-9);
  EXPECT_TRUE(std::isinf(sliding_factor(trial_dam(0, 0), 0.6, 0, 10.5)));
  BaseJointLoads lifted = trial_dam(1e5, 0);
  lifted.N = -1;
  EXPECT_EQ(sliding_factor(lifted, 0.6, 1e5, 10.5), 0.0);
}

TEST(Stability, OverturningAndResultantByHand) {
  // Mo = 5 385 kN m: Mr / Mo = 2 313 198 / 5 385 000 = 0.429563; x_r = (2 313 198 - 5 385 000) / 1 059 480 = -2.89936 m:
  // the resultant leaves the base downstream of the toe, e = 1.75 + 2.89936 = 4.64936 m.
  const BaseJointLoads l = trial_dam(1.421e6, 5.385e6);
  EXPECT_NEAR(overturning_factor(l), 0.429563, 1e-6);
  const ResultantLocation r = resultant_location(l, 3.5, 3.0);
  EXPECT_NEAR(r.x_r, -2.899344, 1e-5);
  EXPECT_FALSE(r.within_base);
  EXPECT_EQ(r.compressed_fraction, 0.0);
  EXPECT_TRUE(std::isinf(r.toe_pressure));
}

TEST(Stability, BearingPressuresInsideAndOutsideTheMiddleThird) {
  // Self-weight alone: x_r = 2 313 198 / 1 059 480 = 2.183333 m, e = 1.75 - 2.183333 = -0.433333 m (towards the heel),
  // |e| < B/6 = 0.583333: q = N / (B W) (1 -+ 6e/B) = 100 902.9 Pa x (1 -+ 0.742857): toe 25 946, heel 175 859 Pa.
  const ResultantLocation r0 = resultant_location(trial_dam(0, 0), 3.5, 3.0);
  EXPECT_NEAR(r0.x_r, 2.183333, 1e-6);
  EXPECT_EQ(r0.compressed_fraction, 1.0);
  EXPECT_NEAR(r0.toe_pressure, 1059480.0 / 10.5 * (1 - 6 * 0.4333333 / 3.5), 0.5);
  EXPECT_NEAR(r0.heel_pressure, 1059480.0 / 10.5 * (1 + 6 * 0.4333333 / 3.5), 0.5);
  // Mo = 1 500 kN m: x_r = (2 313 198 - 1 500 000) / 1 059 480 = 0.767545 m, e = 0.982455 m > B/6: compressed length
  // 3 x_r = 2.302635 m (fraction 0.657896), toe pressure 2 N / (3 x_r W) = 2 119 960 / 6.907905 = 306 717 Pa.
  const ResultantLocation r1 = resultant_location(trial_dam(5e5, 1.5e6), 3.5, 3.0);
  EXPECT_NEAR(r1.x_r, 0.767545, 1e-6);
  EXPECT_NEAR(r1.compressed_fraction, 3 * 0.767545 / 3.5, 1e-6);
  EXPECT_NEAR(r1.toe_pressure, 2 * 1059480.0 / (3 * 0.7675452 * 3.0), 1.0);
  EXPECT_TRUE(r1.within_base);
}

// A rectangular pulse H0 over T against a constant resistance R < H0: the block accelerates at (H0 - R)/m for T, then
// decelerates at R/m: d = a1 T^2 / 2 + (a1 T)^2 / (2 R / m). m = 1e5 kg, H0 = 1.5e6 N, R = 6e5 N, T = 0.01 s:
// a1 = 9 m/s2, v1 = 0.09 m/s, d = 4.5e-4 + 0.0081 / 12 = 4.5e-4 + 6.75e-4 = 1.125e-3 m.
TEST(Stability, NewmarkSlidingBlockUnderARectangularPulse) {
  const double m = 1e5, H0 = 1.5e6, R = 6e5, T = 0.01;
  const std::vector<double> t = {0.0, T, T + 1e-12, 0.1};
  const std::vector<double> H = {H0, H0, 0.0, 0.0}, Rv = {R, R, R, R};
  EXPECT_NEAR(newmark_sliding_displacement(t, H, Rv, m), 1.125e-3, 1e-9);
  // Below the resistance nothing moves; it never slides back upstream.
  EXPECT_EQ(newmark_sliding_displacement(t, {5e5, 5e5, 0, 0}, Rv, m), 0.0);
  EXPECT_EQ(newmark_sliding_displacement(t, {-2e6, -2e6, 0, 0}, Rv, m), 0.0);
  // A record that ends while the block slides: the loads of before the record (none) let friction stop it, the same
  // 1.125e-3 m; a block whose loads before the record already exceed friction never stops.
  EXPECT_NEAR(newmark_sliding_displacement({0.0, 1e-12, T}, {0.0, H0, H0}, {R, R, R}, m), 1.125e-3, 1e-9);
  EXPECT_TRUE(std::isinf(newmark_sliding_displacement({0.0, T}, {H0, H0}, {R, R}, m)));
}

// A triangular pulse (linear decay from H0 to 0 over T) against R: net force H0 (1 - t/T) - R exceeds 0 until
// t1 = T (1 - R/H0); the velocity peaks there. m = 1e5, H0 = 2e6, R = 5e5, T = 0.02: t1 = 0.015 s;
// v(t) = [(H0 - R) t - H0 t^2 / (2T)] / m, v(t1) = (1.5e6 x 0.015 - 2e6 x 2.25e-4 / 0.04) / 1e5 = (22 500 - 11 250) / 1e5
// = 0.1125 m/s; the block stops when v = 0 again. Exact by integrating: d(T) = [(H0 - R) T^2/2 - H0 T^2/6] / m
// = (300 - 133.333) / 1e5 = 1.666667e-3 m with v(T) = (30 000 - 20 000) / 1e5 = 0.1 m/s; then it decelerates at R/m = 5:
// 0.01 / 10 = 1e-3 m. Total 2.666667e-3 m.
TEST(Stability, NewmarkSlidingBlockUnderATriangularPulse) {
  const std::vector<double> t = {0.0, 0.02, 0.2}, H = {2e6, 0.0, 0.0}, R = {5e5, 5e5, 5e5};
  EXPECT_NEAR(newmark_sliding_displacement(t, H, R, 1e5, 256), 2.666667e-3, 2e-8);
}

// The trial dam's section (heel 0, toe 3.5, crest from 0 to 1.5, H 6 m, W 3 m, rho 2400): A = (1.5 + 3.5) / 2 x 6 = 15 m2,
// m = 108 000 kg; the weight's lever about the toe (from the rectangle 9 m2 at 2.75 m and the triangle 6 m2 at 4/3 m):
// (9 x 2.75 + 6 x 1.33333) / 15 = 2.183333 m; centroid height (9 x 3 + 6 x 2) / 15 = 2.6 m. Inertia about the toe:
// rectangle 1.5 x 6 centred at (2.75, 3): 1.5 x 6 x (1.5^2 + 6^2) / 12 + 9 (2.75^2 + 3^2) = 28.6875 + 149.0625 = 177.75 m4;
// triangle (0, 0), (2, 0), (2, 6): centroid (4/3, 2), I_c = A (a^2 + b^2 + c^2) / 36 with sides 2, 6, sqrt(40):
// 6 x 80 / 36 = 13.3333; + 6 (16/9 + 4) = 34.6667 -> 48.0; total 225.75 m4 x 2400 x 3 = 1 625 400 kg m2.
TEST(Stability, RigidSectionOfTheTrialDamByHand) {
  const RigidSection s = rigid_section(0.0, 3.5, 0.0, 1.5, 6.0, 3.0, 2400.0);
  EXPECT_NEAR(s.area_m2, 15.0, 1e-12);
  EXPECT_NEAR(s.mass_kg, 108000.0, 1e-8);
  EXPECT_NEAR(s.weight_N, 1059480.0, 1e-6);
  EXPECT_NEAR(s.centroid_from_toe_m, 2.1833333, 1e-6);
  EXPECT_NEAR(s.centroid_height_m, 2.6, 1e-12);
  EXPECT_NEAR(s.inertia_about_toe_kg_m2, 1625400.0, 1.0);
  EXPECT_NEAR(s.critical_angle_rad(), std::atan2(2.1833333, 2.6), 1e-6);
}

// The dam through the design layer: the trial dam (base at x = 0 .. 3.5, toe downstream at 3.5, support at the base
// centre x0 = 1.75) at rest, then a 20 ms rectangular pulse of 1 421 kN downstream acting 5 m above the base. Reactions
// of a rigid dam (the supports exert them on the dam): Fx = -H, Fy = W, and about x0 the moment that balances the
// weight's (W (x_G - x0), x_G = 3.5 - 2.183333 = 1.316667 m from the heel) and the pulse's (H 5 m):
// M = W (1.316667 - 1.75) + H 5 = -459 108 + 7 105 000 N m during the pulse.
TEST(Stability, TrialDamThroughTheDesignLayer) {
  const double W = 1059480.0, H = 1.421e6, x0 = 1.75, xg = 3.5 - 2.1833333333;
  Results r;
  Series s{"supports/base/reaction", "N", {"Fx", "Fy", "M"}, {}};
  // Samples at the pulse's edges (the histories are linear between samples): 0, 10 ms, 30 ms, 200 ms.
  const double ts[6] = {0.0, 0.01, 0.01 + 1e-12, 0.03, 0.03 + 1e-12, 0.2}, hs[6] = {0, 0, H, H, 0, 0};
  for (int k = 0; k < 6; ++k) {
    r.time.push_back(ts[k]);
    s.data.insert(s.data.end(), {-hs[k], W, W * (xg - x0) + hs[k] * 5.0});
  }
  r.series.push_back(s);
  FrameInfo f;
  f.dim = 2;
  f.nodes = {{x0, 0, 0}};
  f.supports = {FrameInfo::Support{"base", "supports/base/reaction", 0}};
  DesignBasis b;
  b.dam.height_m = 6, b.dam.width_m = 3, b.dam.density_kg_m3 = 2400;
  b.dam.heel_x_m = 0, b.dam.toe_x_m = 3.5, b.dam.crest_upstream_x_m = 0, b.dam.crest_downstream_x_m = 1.5;
  ASSERT_TRUE(stability_applies(f, b));
  FoundationLimits L;  // mu 0.6, c 0
  std::vector<Check> checks;
  const nlohmann::json j = stability_json(r, f, b, L, checks, "r.h5");
  // At rest: e = 1.75 - 2.183333 = -0.433333 m (|e| / (B/6) = 0.742857), heel pressure 175 859 Pa, no shear.
  EXPECT_NEAR(j["persistent"]["eccentricity_m"].get<double>(), -0.4333333, 1e-6);
  EXPECT_NEAR(j["persistent"]["heel_pressure_Pa"].get<double>(), W / 10.5 * (1 + 6 * 0.4333333 / 3.5), 1.0);
  EXPECT_TRUE(j["persistent"]["sliding_factor"].is_null());  // H = 0: infinite
  // The pulse: sliding factor 0.6 W / H = 0.447352; over the pulse a = (H - 0.6 W) / m = (1 421 000 - 635 688) / 108 000
  // = 7.271407 m/s2 for 20 ms: v = 0.1454281 m/s, d = 1.454281e-3 m; then friction 0.6 g = 5.886 m/s2 stops it in
  // v^2 / (2 x 5.886) = 1.796575e-3 m: 3.250856e-3 m.
  EXPECT_NEAR(j["impact"]["least_sliding_factor"]["sliding_factor"].get<double>(), 0.6 * W / H, 1e-9);
  EXPECT_NEAR(j["impact"]["sliding_displacement_m"].get<double>(), 3.250856e-3, 1e-8);
  // Rocking: Mo = H 5 = 7 105 000 N m against Mr = W 2.183333 = 2 313 198 N m, I_toe = 1 625 400 kg m2:
  // theta'' = 2.948075 rad/s2 for 20 ms, omega = 0.0589615 rad/s, theta = 5.89615e-4 rad; then Mr / I = 1.423157 rad/s2
  // stops it in omega^2 / (2 x 1.423157) = 1.221396e-3 rad: 1.811011e-3 rad.
  EXPECT_NEAR(j["impact"]["peak_rocking_rotation_rad"].get<double>(), 1.811011e-3, 1e-8);
  // The checks: persistent sliding, resultant, bearing; the impact's sliding displacement and rocking.
  ASSERT_EQ(checks.size(), 5u);
  EXPECT_EQ(checks[1].id, "stability_resultant_persistent");
  EXPECT_NEAR(checks[1].utilisation, 0.742857, 1e-5);
  EXPECT_NEAR(checks[3].utilisation, 3.250856e-3 / 0.05, 1e-6);
  EXPECT_NEAR(checks[4].demand, 1.5 * 1.811011e-3, 1e-8);
}

// The same dam and pulse as a space frame (x along the flow, y across, z up): the reaction series carries
// Fx, Fy, Fz, Mx, My, Mz, and the elevation's moment is -My (a moment about +y turns z towards x). The same numbers.
TEST(Stability, TrialDamInThreeDimensions) {
  const double W = 1059480.0, H = 1.421e6, x0 = 1.75, xg = 3.5 - 2.1833333333;
  Results r;
  Series s{"supports/base/reaction", "N", {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}, {}};
  const double ts[6] = {0.0, 0.01, 0.01 + 1e-12, 0.03, 0.03 + 1e-12, 0.2}, hs[6] = {0, 0, H, H, 0, 0};
  for (int k = 0; k < 6; ++k) {
    r.time.push_back(ts[k]);
    s.data.insert(s.data.end(), {-hs[k], 0.0, W, 0.0, -(W * (xg - x0) + hs[k] * 5.0), 0.0});
  }
  r.series.push_back(s);
  FrameInfo f;
  f.dim = 3, f.nodes = {{x0, 0, 0}}, f.supports = {FrameInfo::Support{"base", "supports/base/reaction", 0}};
  DesignBasis b;
  b.dam.height_m = 6, b.dam.width_m = 3, b.dam.density_kg_m3 = 2400;
  b.dam.heel_x_m = 0, b.dam.toe_x_m = 3.5, b.dam.crest_upstream_x_m = 0, b.dam.crest_downstream_x_m = 1.5;
  FoundationLimits L;
  std::vector<Check> checks;
  const nlohmann::json j = stability_json(r, f, b, L, checks, "r.h5");
  EXPECT_NEAR(j["persistent"]["eccentricity_m"].get<double>(), -0.4333333, 1e-6);
  EXPECT_NEAR(j["impact"]["least_sliding_factor"]["sliding_factor"].get<double>(), 0.6 * W / H, 1e-9);
  EXPECT_NEAR(j["impact"]["sliding_displacement_m"].get<double>(), 3.250856e-3, 1e-8);
  EXPECT_NEAR(j["impact"]["peak_rocking_rotation_rad"].get<double>(), 1.811011e-3, 1e-8);
}

// Water 3 m behind the trial dam, full uplift: U = 9 810 x 3 x 3.5 x 3 / 2 = 154 507.5 N at 2B/3 = 2.333333 m from the
// toe: at rest N = 1 059 480 - 154 507.5 = 904 972.5 N and x_r = (2 313 198 - 154 507.5 x 2.333333) / 904 972.5
// = 2.157730 m; half the uplift with drains (uplift_factor 0.5).
TEST(Stability, UpliftUnderTheWaterBehindTheDam) {
  const double W = 1059480.0, x0 = 1.75, xg = 3.5 - 2.1833333333;
  Results r;
  Series s{"supports/base/reaction", "N", {"Fx", "Fy", "M"}, {}};
  for (double t : {0.0, 0.1}) r.time.push_back(t), s.data.insert(s.data.end(), {0.0, W, W * (xg - x0)});
  r.series.push_back(s);
  FrameInfo f;
  f.dim = 2, f.nodes = {{x0, 0, 0}}, f.supports = {FrameInfo::Support{"base", "supports/base/reaction", 0}};
  DesignBasis b;
  b.dam.height_m = 6, b.dam.width_m = 3, b.dam.density_kg_m3 = 2400;
  b.dam.heel_x_m = 0, b.dam.toe_x_m = 3.5, b.dam.crest_upstream_x_m = 0, b.dam.crest_downstream_x_m = 1.5;
  b.dam.water_height_m = 3, b.dam.water_unit_weight_N_m3 = 9810;
  FoundationLimits L;
  std::vector<Check> checks;
  nlohmann::json j = stability_json(r, f, b, L, checks, "r.h5");
  EXPECT_NEAR(j["foundation"]["uplift_N"].get<double>(), 154507.5, 1e-6);
  EXPECT_NEAR(j["persistent"]["N_N"].get<double>(), 904972.5, 1e-3);
  EXPECT_NEAR(j["persistent"]["resultant_from_toe_m"].get<double>(), 2.157730, 1e-5);
  L.uplift_factor = 0.5;
  checks.clear();
  j = stability_json(r, f, b, L, checks, "r.h5");
  EXPECT_NEAR(j["persistent"]["N_N"].get<double>(), W - 77253.75, 1e-3);
}

// The damping's share of the impact energy by hand: a 1 t boulder at 5 m/s brings 12.5 kJ; 1.25 kJ of damping work by
// the governing instant is 10 % (not above: not flagged), 2.5 kJ at the end 20 %.
TEST(Stability, DampingShareOfTheImpactEnergy) {
  Results r;
  r.time = {0.0, 0.01, 0.02, 0.05};
  r.series.push_back(Series{"energy/frame_damping", "J", {"value"}, {0.0, 500.0, 1250.0, 2500.0}});
  DesignBasis b;
  BoulderBasis k;
  k.mass_kg = 1000, k.speed_m_s = 5;
  b.boulder = k;
  nlohmann::json j = to_json(*damping_share(r, b, 0.02));
  EXPECT_EQ(to_json(*damping_from_json(j, "test")), j);  // the record reads back the same
  EXPECT_NEAR(j["impact_energy_J"].get<double>(), 12500.0, 1e-9);
  EXPECT_NEAR(j["share_at_governing"].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(j["share"].get<double>(), 0.2, 1e-12);
  EXPECT_FALSE(j["flagged"].get<bool>());
  EXPECT_TRUE(damping_share(r, b, 0.05)->flagged);
  // Against the energy the members received (the contact's work on them): 1.25 kJ of 10 kJ by 0.02 s is 12.5 %, flagged
  // though the impact-energy share is 10 %; by a base shear peak at 0.01 s 500 J of 8 kJ, 6.25 %.
  r.series.push_back(Series{"energy/contact_work", "J", {"value"}, {0.0, 8000.0, 10000.0, 10000.0}});
  j = to_json(*damping_share(r, b, 0.02, 0.01));
  EXPECT_EQ(to_json(*damping_from_json(j, "test")), j);
  EXPECT_NEAR(j["share_of_received_at_governing"].get<double>(), 0.125, 1e-12);
  EXPECT_NEAR(j["base_shear_peak"]["share_of_received"].get<double>(), 0.0625, 1e-12);
  EXPECT_TRUE(j["flagged"].get<bool>());
  j = to_json(*damping_share(r, b, 0.01, 0.01));
  EXPECT_FALSE(j["flagged"].get<bool>());
}

// Cohesion over the compressed base area w B (3 m x 3.5 m at rest, base fully compressed): 100 kPa adds 1 050 kN to
// the persistent resistance. A static shear the friction cannot hold (H 700 kN against 0.6 x 1 059 kN = 636 kN): the
// dam slides without end under the loads at rest; the displacement is held as 1e300 (finite in design.json), failing.
TEST(Stability, CohesionAndAnUnboundedSlide) {
  const double W = 1059480.0, x0 = 1.75, xg = 3.5 - 2.1833333333;
  auto results = [&](double H) {
    Results r;
    Series s{"supports/base/reaction", "N", {"Fx", "Fy", "M"}, {}};
    for (double t : {0.0, 0.1}) r.time.push_back(t), s.data.insert(s.data.end(), {-H, W, W * (xg - x0) + H * 2.0});
    r.series.push_back(s);
    return r;
  };
  FrameInfo f;
  f.dim = 2, f.nodes = {{x0, 0, 0}}, f.supports = {FrameInfo::Support{"base", "supports/base/reaction", 0}};
  DesignBasis b;
  b.dam.height_m = 6, b.dam.width_m = 3, b.dam.density_kg_m3 = 2400;
  b.dam.heel_x_m = 0, b.dam.toe_x_m = 3.5, b.dam.crest_upstream_x_m = 0, b.dam.crest_downstream_x_m = 1.5;
  FoundationLimits L;
  L.cohesion = 1e5;
  std::vector<Check> checks;
  stability_json(results(2e5), f, b, L, checks, "r.h5");
  ASSERT_EQ(checks[0].id, "stability_sliding_persistent");
  EXPECT_NEAR(checks[0].capacity, 0.6 * W + 1e5 * 3.5 * 3.0, 1e-6);
  L.cohesion = 0;
  checks.clear();
  const nlohmann::json j = stability_json(results(7e5), f, b, L, checks, "r.h5");
  EXPECT_EQ(checks[3].id, "stability_sliding_displacement");
  EXPECT_EQ(checks[3].demand, 1e300);
  EXPECT_FALSE(checks[3].passed);
  EXPECT_TRUE(std::isfinite(checks[3].utilisation));
  // A frame whose vertical reaction at rest is not the section's weight (self-weight off) is not assessed.
  checks.clear();
  Results off = results(0);
  off.series[0].data[1] = off.series[0].data[4] = 0.0;
  EXPECT_TRUE(stability_json(off, f, b, L, checks, "r.h5").contains("not_assessed"));
  EXPECT_TRUE(checks.empty());
}
