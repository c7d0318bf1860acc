// Strain-rate effects on the member checks (design/strain_rate_checks) by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "design/strain_rate_checks.hpp"

using namespace dmi::design;

// The demo's buffered dam: flexural tension 1.6166 MPa at 22.968 ms, the contact pulse from 9.700 ms, E 25 GPa:
// eps_dot = 1.6166e6 / (25e9 x 0.013268) = 4.8737e-3 1/s; DIF_t = (4.8737e-3 / 1e-6)^0.018 = exp(0.018 ln 4873.7)
// = exp(0.152850) = 1.16514 (the capacity 1.968 MPa becomes 2.29300 MPa). Before the load, no larger than the static
// demand it started from, another check, or switched off: 1.
TEST(StrainRate, TheDemoDamsFlexuralTensionByHand) {
  const StrainRate sr{true, 0.0097, 25e9};
  double rate = -1;
  const double dif = strain_rate_factor("concrete_flexural_tension", 1.6166e6, 0.0, 0.022968, sr, &rate);
  EXPECT_NEAR(rate, 1.6166e6 / (25e9 * (0.022968 - 0.0097)), 1e-15);
  EXPECT_NEAR(dif, std::exp(0.018 * std::log(rate / 1e-6)), 1e-12);
  EXPECT_NEAR(dif, 1.16514, 1e-5);
  // Compression with a static part: only the rise counts, (1.2 - 0.4) MPa over 10 ms, eps_dot 3.2e-3 1/s,
  // DIF_c = (3.2e-3 / 30e-6)^0.014 = exp(0.014 ln 106.667) = 1.06757.
  EXPECT_NEAR(strain_rate_factor("concrete_compression", 1.2e6, 0.4e6, 0.0197, sr, &rate), std::exp(0.014 * std::log(3.2e-3 / 30e-6)), 1e-9);
  EXPECT_EQ(strain_rate_factor("concrete_flexural_tension", 1.6166e6, 0.0, 0.005, sr, &rate), 1.0);
  EXPECT_EQ(rate, 0.0);
  EXPECT_EQ(strain_rate_factor("concrete_flexural_tension", 1.6166e6, 1.6166e6, 0.02, sr, &rate), 1.0);
  EXPECT_EQ(strain_rate_factor("concrete_shear", 1e6, 0.0, 0.02, sr, &rate), 1.0);
  EXPECT_EQ(strain_rate_factor("concrete_flexural_tension", 1.6166e6, 0.0, 0.02, StrainRate{false, 0.0097, 25e9}, &rate), 1.0);
}
