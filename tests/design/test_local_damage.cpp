// Local damage of a concrete face by a hard projectile (modified NDRC, Degen, Chang) against hand calculations in US
// units (docs/design-checks.md, "Local damage").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "design/local_damage.hpp"
#include "design/local_damage_checks.hpp"

using namespace dmi::design;

TEST(LocalDamage, BoulderAt5MetresPerSecondByHandInUsUnits) {
  // 1000 kg granite boulder, d = 0.9 m, V = 5 m/s, f'c = 28 MPa, N* = 1.0 (spherical end).
  // W = 1000 / 0.45359237 = 2204.623 lb; d = 0.9 / 0.0254 = 35.43307 in; V = 5 / 0.3048 = 16.40420 ft/s;
  // f'c = 28e6 / 6894.757 = 4061.057 psi, sqrt = 63.72642, K = 180 / 63.72642 = 2.824574.
  // W/d = 62.21935 lb/in; V / (1000 d) = 16.40420 / 35433.07 = 4.629630e-4, ^1.8 = 9.953670e-7;
  // G = 2.824574 x 1.0 x 62.21935 x 9.953670e-7 = 1.749290e-4 (<= 1) -> x/d = 2 sqrt(G) = 0.026452; x = 0.023807 m (0.937 in).
  const LocalDamage r = local_damage(1000, 0.9, 5, 28e6, kNoseSpherical);
  EXPECT_NEAR(r.G, 1.749290e-4, 1e-9);
  EXPECT_NEAR(r.x_over_d, 0.026452, 1e-6);
  EXPECT_NEAR(r.penetration_m, 0.023807, 1e-6);
  // Scabbing, x/d <= 0.65: 7.91 x 0.026452 - 5.06 x 0.026452^2 = 0.209238 - 0.003541 = 0.205696 -> 0.185126 m.
  EXPECT_NEAR(r.scabbing_ndrc_m, 0.185126, 2e-6);
  // Perforation, x/d <= 1.35: 3.19 x 0.026452 - 0.718 x 0.026452^2 = 0.084382 - 0.000502 = 0.083880 -> 0.075492 m.
  EXPECT_NEAR(r.perforation_ndrc_m, 0.075492, 2e-6);
  // Degen, x/d <= 1.52: 2.2 x 0.026452 - 0.3 x 0.026452^2 = 0.058195 - 0.000210 = 0.057985 -> 0.052186 m.
  EXPECT_NEAR(r.perforation_degen_m, 0.052186, 2e-6);
  // Chang in consistent US units (slug, ft, lb/ft^2): M = 2204.623 / 32.17405 = 68.52177 slug, d = 2.952756 ft,
  // f'c = 4061.057 x 144 = 584792.2 psf; M V^2 / (d^3 f'c) = 68.52177 x 16.40420^2 / (25.74450 x 584792.2) = 1.224770e-3.
  // u/V = 200 / 16.40420 = 12.19200: ^0.25 = 1.868610, ^0.13 = 1.384171.
  // e/d = 1.868610 x sqrt(1.224770e-3) = 1.868610 x 0.034997 = 0.065395 -> 0.058856 m;
  // h_s/d = 1.84 x 1.384171 x (1.224770e-3)^0.4 = 1.84 x 1.384171 x 0.068426 = 0.174273 -> 0.156845 m.
  EXPECT_NEAR(r.perforation_chang_m, 0.058856, 2e-6);
  EXPECT_NEAR(r.scabbing_chang_m, 0.156845, 2e-6);
  // Ranges: x/d far inside the NDRC/Degen ranges; 5 m/s is below Chang's 16.7 m/s.
  EXPECT_TRUE(r.penetration_in_range && r.scabbing_ndrc_in_range && r.perforation_ndrc_in_range && r.perforation_degen_in_range);
  EXPECT_FALSE(r.scabbing_chang_in_range);
  EXPECT_FALSE(r.perforation_chang_in_range);
}

TEST(LocalDamage, BoulderAt25MetresPerSecondByHandInUsUnits) {
  // Same boulder at V = 25 m/s = 82.02100 ft/s: V / (1000 d) = 2.314815e-3, ^1.8 = 1.803554e-5;
  // G = 2.824574 x 62.21935 x 1.803554e-5 = 3.169624e-3 -> x/d = 2 sqrt(G) = 0.112599; x = 0.101339 m (3.99 in).
  const LocalDamage r = local_damage(1000, 0.9, 25, 28e6, kNoseSpherical);
  EXPECT_NEAR(r.G, 3.169624e-3, 2e-9);
  EXPECT_NEAR(r.penetration_m, 0.101339, 2e-6);
  // NDRC scabbing 7.91 x 0.112599 - 5.06 x 0.012678 = 0.890657 - 0.064153 = 0.826503 -> 0.743853 m.
  EXPECT_NEAR(r.scabbing_ndrc_m, 0.743853, 2e-6);
  // NDRC perforation 3.19 x 0.112599 - 0.718 x 0.012678 = 0.359190 - 0.009103 = 0.350087 -> 0.315078 m.
  EXPECT_NEAR(r.perforation_ndrc_m, 0.315078, 2e-6);
  // Degen 2.2 x 0.112599 - 0.3 x 0.012678 = 0.247717 - 0.003803 = 0.243914 -> 0.219522 m.
  EXPECT_NEAR(r.perforation_degen_m, 0.219522, 2e-6);
  // Chang: M V^2 / (d^3 f'c) = 68.52177 x 82.02100^2 / (25.74450 x 584792.2) = 3.061924e-2 (25 x the 5 m/s value);
  // u/V = 2.438400: ^0.25 = 1.249615, ^0.13 = 1.122855. e/d = 1.249615 x 0.174984 = 0.218662 -> 0.196796 m;
  // h_s/d = 1.84 x 1.122855 x 0.247969 = 0.512318 -> 0.461086 m.
  EXPECT_NEAR(r.perforation_chang_m, 0.196796, 2e-6);
  EXPECT_NEAR(r.scabbing_chang_m, 0.461086, 2e-6);
  EXPECT_TRUE(r.scabbing_chang_in_range && r.perforation_chang_in_range);
  // A blunt nose (0.84) scales G: 3.169624e-3 x 0.84 = 2.662484e-3, x/d = 0.103199.
  EXPECT_NEAR(local_damage(1000, 0.9, 25, 28e6, kNoseBlunt).x_over_d, 0.103199, 1e-6);
}

TEST(LocalDamage, AgreesWithTheSiFormOfTheGFunction) {
  // Li et al. (2005) write G in SI as 3.8e-5 N* M / (d sqrt(f'c)) (V/d)^1.8 (kg, m, Pa, m/s); 3.8e-5 is a rounded
  // conversion constant, so the two agree to about 0.1 %: 3.8e-5 x 1000 / (0.9 x 5291.503) x (5/0.9)^1.8 = 1.747719e-4.
  const double si = 3.8e-5 * 1000 / (0.9 * std::sqrt(28e6)) * std::pow(5 / 0.9, 1.8);
  EXPECT_NEAR(si, 1.747719e-4, 1e-9);
  EXPECT_NEAR(ndrc_G(1000, 0.9, 5, 28e6, 1.0) / si, 1.0, 2e-3);
  EXPECT_GT(std::abs(ndrc_G(1000, 0.9, 5, 28e6, 1.0) / si - 1.0), 1e-4);  // not identical: the imperial form is used
}

TEST(LocalDamage, SteelMissileWithGAboveOneByHand) {
  // 100 kg, d = 0.1 m, V = 150 m/s, N* = 1.0: W = 220.4623 lb, d = 3.937008 in, V = 492.1260 ft/s;
  // W/d = 55.99741; V / (1000 d) = 0.125, ^1.8 = 2.368307e-2; G = 2.824574 x 55.99741 x 2.368307e-2 = 3.745924 (> 1)
  // -> x/d = G + 1 = 4.745924; x = 0.474592 m.
  const LocalDamage r = local_damage(100, 0.1, 150, 28e6, kNoseSpherical);
  EXPECT_NEAR(r.G, 3.745924, 2e-6);
  EXPECT_NEAR(r.penetration_m, 0.474592, 1e-6);
  // Linear branches: scabbing 2.12 + 1.36 x 4.745924 = 8.574457; perforation 1.32 + 1.24 x 4.745924 = 7.204946;
  // Degen 0.69 + 1.29 x 4.745924 = 6.812242 (inside 2.65..18).
  EXPECT_NEAR(r.scabbing_ndrc_m, 0.857446, 1e-6);
  EXPECT_NEAR(r.perforation_ndrc_m, 0.720495, 1e-6);
  EXPECT_NEAR(r.perforation_degen_m, 0.681224, 1e-6);
  // Chang: M V^2 / (d^3 f'c) = 100 x 22500 / (1e-3 x 28e6) = 80.35714; u/V = 0.4064:
  // e/d = 0.798433 x 8.964215 = 7.157324; h_s/d = 1.84 x 0.889537 x 5.781091 = 9.462189.
  EXPECT_NEAR(r.perforation_chang_m, 0.715732, 1e-6);
  EXPECT_NEAR(r.scabbing_chang_m, 0.946219, 1e-6);
  EXPECT_TRUE(r.penetration_in_range && r.scabbing_ndrc_in_range && r.perforation_ndrc_in_range);
  // At 300 m/s with a very sharp nose x/d = 15.87 > 13.5: outside every NDRC range, Degen e/d = 21.2 > 18.
  const LocalDamage far = local_damage(100, 0.1, 300, 28e6, kNoseVerySharp);
  EXPECT_NEAR(far.x_over_d, 15.870235, 1e-5);
  EXPECT_FALSE(far.penetration_in_range || far.scabbing_ndrc_in_range || far.perforation_ndrc_in_range || far.perforation_degen_in_range);
}

TEST(LocalDamage, BranchPointsAreNearlyContinuous) {
  // x/d = 0.65: 7.91 x 0.65 - 5.06 x 0.4225 = 3.003650 vs 2.12 + 1.36 x 0.65 = 3.004000.
  EXPECT_NEAR(ndrc_scabbing_over_d(0.65), 3.003650, 1e-9);
  EXPECT_NEAR(ndrc_scabbing_over_d(std::nextafter(0.65, 1.0)), 3.004000, 1e-9);
  // x/d = 1.35: 3.19 x 1.35 - 0.718 x 1.8225 = 2.997945 vs 1.32 + 1.24 x 1.35 = 2.994000.
  EXPECT_NEAR(ndrc_perforation_over_d(1.35), 2.997945, 1e-9);
  EXPECT_NEAR(ndrc_perforation_over_d(std::nextafter(1.35, 2.0)), 2.994000, 1e-9);
  // x/d = 1.52: 2.2 x 1.52 - 0.3 x 2.3104 = 2.650880 vs 0.69 + 1.29 x 1.52 = 2.650800 (Degen's e/d = 2.65).
  EXPECT_NEAR(degen_perforation_over_d(1.52), 2.650880, 1e-9);
  EXPECT_NEAR(degen_perforation_over_d(std::nextafter(1.52, 2.0)), 2.650800, 1e-9);
  // G = 1: 2 sqrt(1) = 2 = 1 + 1 (continuous).
  EXPECT_DOUBLE_EQ(ndrc_x_over_d(1.0), 2.0);
  EXPECT_NEAR(ndrc_x_over_d(1.0 + 1e-12), 2.0, 1e-11);
}

TEST(LocalDamage, DesignThicknessTakesTheLargestAndAppliesMargins) {
  // 25 m/s case: scabbing NDRC 0.743853 > Chang 0.461086; perforation NDRC 0.315078 > Degen 0.219522, Chang 0.196796.
  const LocalDamage r = local_damage(1000, 0.9, 25, 28e6);
  const DesignThickness raw = design_thickness(r);
  EXPECT_EQ(raw.scabbing_by, "ndrc");
  EXPECT_EQ(raw.perforation_by, "ndrc");
  EXPECT_DOUBLE_EQ(raw.scabbing_design_m, raw.scabbing_raw_m);
  EXPECT_NEAR(raw.perforation_raw_m, 0.315078, 2e-6);
  // DOE-STD-3014 margins: 1.1 x 0.743853 = 0.818238 m; 1.2 x 0.315078 = 0.378094 m.
  const DesignThickness doe = design_thickness(r, kDoeScabbingMargin, kDoePerforationMargin);
  EXPECT_NEAR(doe.scabbing_design_m, 0.818238, 3e-6);
  EXPECT_NEAR(doe.perforation_design_m, 0.378094, 3e-6);
  EXPECT_NEAR(doe.scabbing_raw_m, 0.743853, 2e-6);  // the raw values are kept
  // 150 m/s steel missile: Chang scabbing 0.946219 > NDRC 0.857446 governs; perforation NDRC 0.720495 > Chang 0.715732.
  const DesignThickness s = design_thickness(local_damage(100, 0.1, 150, 28e6), 1.2, 1.2);
  EXPECT_EQ(s.scabbing_by, "chang");
  EXPECT_TRUE(s.scabbing_in_range);
  EXPECT_NEAR(s.scabbing_design_m, 1.2 * 0.946219, 2e-6);
  EXPECT_EQ(s.perforation_by, "ndrc");
  EXPECT_THROW(design_thickness(r, 0.9, 1.0), std::invalid_argument);
  EXPECT_THROW(design_thickness(r, 1.0, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST(LocalDamage, RejectsBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(local_damage(0, 0.9, 5, 28e6), std::invalid_argument);
  EXPECT_THROW(local_damage(1000, -0.9, 5, 28e6), std::invalid_argument);
  EXPECT_THROW(local_damage(1000, 0.9, nan, 28e6), std::invalid_argument);
  EXPECT_THROW(local_damage(1000, 0.9, 5, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(local_damage(1000, 0.9, 5, 28e6, 1.5), std::invalid_argument);
  EXPECT_NO_THROW(local_damage(1000, 0.9, 5, 28e6, kNoseFlat));
}

// The checks on a dam: the demo's section (heel 0, toe 1.6, crest from 0 to 1, 4 m high) is 1.6 - 0.6 y / 4 thick:
// 1.06 m at 3.6 m. A 1 t, 0.894 m boulder at 5 m/s on 28 MPa: perforation and scabbing against that, times 1.2 and 1.1;
// none with a buffer.
TEST(LocalDamage, ChecksAgainstTheSectionThicknessAtTheImpactHeight) {
  dmi::DesignBasis b;
  b.dam.height_m = 4, b.dam.heel_x_m = 0, b.dam.toe_x_m = 1.6, b.dam.crest_upstream_x_m = 0, b.dam.crest_downstream_x_m = 1.0;
  EXPECT_NEAR(section_thickness_at(b.dam, 3.6), 1.06, 1e-12);
  EXPECT_NEAR(section_thickness_at(b.dam, 0.0), 1.6, 1e-12);
  dmi::BoulderBasis k;
  k.mass_kg = 1000, k.diameter_m = 0.894, k.speed_m_s = 5, k.impact_height_m = 3.6;
  b.boulder = k;
  ConcreteLimits C;
  std::vector<Check> checks;
  const std::optional<LocalDamageRecord> j = local_damage_checks(b, C, checks);
  ASSERT_TRUE(j.has_value());
  ASSERT_EQ(checks.size(), 2u);
  const DesignThickness t = design_thickness(local_damage(1000, 0.894, 5, 28e6, kNoseSpherical), 1.1, 1.2);
  EXPECT_EQ(checks[0].id, "local_perforation");
  EXPECT_EQ(checks[0].level, "ultimate");
  EXPECT_NEAR(checks[0].utilisation, t.perforation_design_m / 1.06, 1e-12);
  EXPECT_EQ(checks[1].level, "serviceability");
  EXPECT_NEAR(checks[1].demand, t.scabbing_design_m, 1e-12);
  EXPECT_NEAR(j->thickness_m, 1.06, 1e-12);
  const std::optional<LocalDamageRecord> back = local_damage_from_json(to_json(*j), "design.json local_damage");  // the record survives its file
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(to_json(*back), to_json(*j));
  b.buffer = dmi::BufferBasis{};
  checks.clear();
  EXPECT_FALSE(local_damage_checks(b, C, checks).has_value());
  EXPECT_TRUE(checks.empty());
}
