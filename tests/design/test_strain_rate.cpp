// Strain-rate effects on the member checks (design/strain_rate_checks) by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "design/dynamic_strength.hpp"
#include "design/strain_rate_checks.hpp"

using namespace dmi::design;

// The demo's buffered dam: flexural tension 1.6166 MPa at 22.968 ms, the contact pulse from 9.700 ms, E 25 GPa:
// eps_dot = 1.6166e6 / (25e9 x 0.013268) = 4.8737e-3 1/s; DIF_t = (4.8737e-3 / 1e-6)^0.018 = exp(0.018 ln 4873.7)
// = exp(0.152850) = 1.16514; the capacity 1.968 MPa becomes 2.29300 MPa, utilisation 0.82145 -> 0.70502. A check
// before the load, or no larger than the static demand it started from (self-weight at rest), keeps the static strength.
TEST(StrainRate, TheDemoDamsFlexuralTensionByHand) {
  FrameInfo f;
  FrameInfo::Element e;
  e.E = 25e9;
  f.elements = {e};
  f.members = {FrameInfo::Member{"dam", "concrete", "concrete", 0, 1, 4.0}};
  MemberEnvelope env;
  env.name = "dam", env.cls = "concrete";
  ConcreteLimits C;
  Check t;
  t.id = "concrete_flexural_tension", t.demand = 1.6166e6, t.capacity = C.tensile_capacity(), t.time_s = 0.022968;
  t.finish();
  Check before = t;
  before.time_s = 0.005;
  Check at_rest = t;  // a demand no larger than the static one it started from
  at_rest.static_demand = t.demand;
  env.checks = {t, before, at_rest};
  std::vector<MemberEnvelope> m = {env};
  apply_strain_rate(m, f, 0.0097, C);
  const double rate = 1.6166e6 / (25e9 * (0.022968 - 0.0097));
  EXPECT_NEAR(m[0].checks[0].strain_rate, rate, 1e-15);
  EXPECT_NEAR(m[0].checks[0].dynamic_factor, std::exp(0.018 * std::log(rate / 1e-6)), 1e-12);
  EXPECT_NEAR(m[0].checks[0].dynamic_factor, 1.16514, 1e-5);
  EXPECT_NEAR(m[0].checks[0].utilisation, 1.6166e6 / (1.968e6 * 1.16514), 1e-5);
  EXPECT_EQ(m[0].checks[1].dynamic_factor, 1.0);
  EXPECT_EQ(m[0].checks[2].dynamic_factor, 1.0);
  // Switched off in the limits file: static strengths.
  C.strain_rate_effects = false;
  m = {env};
  apply_strain_rate(m, f, 0.0097, C);
  EXPECT_EQ(m[0].checks[0].capacity, t.capacity);
}
