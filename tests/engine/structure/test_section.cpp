// Section properties against hand formulas (Gere & Goodno App. E) and the thin-wall identities of a pipe.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/structure/section.hpp"

namespace dmi {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Section, RectangleAreaInertiaAndShearFactors) {
  const Section s = Section::rectangle(0.1, 0.2);
  EXPECT_EQ(s.kind(), SectionKind::rectangle);
  for (double x : {0.0, 0.3, 1.0}) {
    EXPECT_DOUBLE_EQ(s.area(x), 0.02);
    EXPECT_NEAR(s.inertia(x), 0.1 * 0.008 / 12, 1e-18);
    EXPECT_DOUBLE_EQ(s.depth(x), 0.2);
    EXPECT_DOUBLE_EQ(s.half_depth(x), 0.1);
    EXPECT_DOUBLE_EQ(s.width(x), 0.1);
  }
  EXPECT_DOUBLE_EQ(s.shear_coefficient(), 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(s.shear_stress_factor(), 1.5);
}

TEST(Section, PipeMatchesExactThinWallIdentities) {
  // A = pi D_m t and I = pi R_m t (R_m^2 + t^2 / 4) hold exactly for a circular hollow section.
  const double D = 0.3, t = 0.01, Rm = 0.5 * (D - t);
  const Section s = Section::pipe(D, t);
  EXPECT_EQ(s.kind(), SectionKind::pipe);
  EXPECT_NEAR(s.area(0.5), kPi * 2 * Rm * t, 1e-15);
  EXPECT_NEAR(s.inertia(0.5), kPi * Rm * t * (Rm * Rm + t * t / 4), 1e-17);
  EXPECT_NEAR(s.area(0), 0.25 * kPi * (D * D - 0.28 * 0.28), 1e-15);
  EXPECT_DOUBLE_EQ(s.depth(1), D);
  EXPECT_DOUBLE_EQ(s.width(1), D);
  EXPECT_DOUBLE_EQ(s.shear_coefficient(), 0.5);
  EXPECT_DOUBLE_EQ(s.shear_stress_factor(), 2.0);
  // t = D/2 is a solid disc: A = pi D^2 / 4, I = pi D^4 / 64.
  const Section disc = Section::pipe(D, D / 2);
  EXPECT_NEAR(disc.area(0), kPi * D * D / 4, 1e-15);
  EXPECT_NEAR(disc.inertia(0), kPi * std::pow(D, 4) / 64, 1e-17);
}

TEST(Section, TaperedDepthVariesLinearlyAndInertiaCubically) {
  const double b = 0.2, h0 = 0.4, h1 = 0.2;
  const Section s = Section::tapered(b, h0, h1);
  EXPECT_EQ(s.kind(), SectionKind::tapered_rectangle);
  for (double x : {0.0, 0.5, 1.0}) {
    const double h = h0 + x * (h1 - h0);
    EXPECT_NEAR(s.depth(x), h, 1e-15);
    EXPECT_NEAR(s.area(x), b * h, 1e-15);
    EXPECT_NEAR(s.inertia(x), b * h * h * h / 12, 1e-17);
    EXPECT_DOUBLE_EQ(s.width(x), b);
  }
  EXPECT_NEAR(s.inertia(0) / s.inertia(1), 8.0, 1e-12);
  EXPECT_NEAR(s.inertia(0.5), b * 0.027 / 12, 1e-17);
}

// Space-frame properties. Rectangle torsion constant J = beta b t^3 against Timoshenko & Goodier's (1970) table of
// beta: 0.141 (b/t = 1), 0.229 (2), 0.263 (3), 0.312 (10), to their three digits, and 1/3 as b/t grows; the square
// by the series to 1e-4 (0.1406). Pipe J = 2 I exactly (polar moment); in-plane I_y of a rectangle h b^3 / 12.
TEST(Section, TorsionConstantsAndOutOfPlaneInertia) {
  const struct { double ratio, beta; } table[] = {{1, 0.141}, {2, 0.229}, {3, 0.263}, {10, 0.312}};
  for (const auto& r : table) {
    const Section wide = Section::rectangle(r.ratio * 0.1, 0.1), deep = Section::rectangle(0.1, r.ratio * 0.1);
    EXPECT_NEAR(wide.torsion_constant(0.5) / (r.ratio * 0.1 * 1e-3), r.beta, 5e-4) << "b/t " << r.ratio;
    EXPECT_DOUBLE_EQ(deep.torsion_constant(0.5), wide.torsion_constant(0.5));
  }
  EXPECT_NEAR(Section::rectangle(1, 1).torsion_constant(0), 0.1406, 1e-4);
  EXPECT_NEAR(Section::rectangle(1000, 1).torsion_constant(0) / 1000, 1.0 / 3, 1e-3);
  const Section p = Section::pipe(0.5, 0.02);
  EXPECT_DOUBLE_EQ(p.torsion_constant(0.3), 2 * p.inertia(0.3));
  EXPECT_DOUBLE_EQ(p.inertia_y(0.3), p.inertia(0.3));
  EXPECT_DOUBLE_EQ(Section::rectangle(0.3, 0.5).inertia_y(0), 0.5 * 0.027 / 12);
  const Section t = Section::tapered(0.4, 0.8, 0.2);  // width 0.4: the thinner side changes along the member
  EXPECT_DOUBLE_EQ(t.torsion_constant(0), Section::rectangle(0.4, 0.8).torsion_constant(0));
  EXPECT_NEAR(t.torsion_constant(1) / Section::rectangle(0.4, 0.2).torsion_constant(0), 1.0, 1e-12);  // h(1) = 0.8 - 0.6
}

TEST(Section, RejectsNonPositiveDimensionsAndThickWalls) {
  EXPECT_THROW(Section::rectangle(0, 0.2), std::invalid_argument);
  EXPECT_THROW(Section::rectangle(0.1, -1), std::invalid_argument);
  EXPECT_THROW(Section::pipe(0.3, 0.16), std::invalid_argument);  // wall thicker than the radius
  EXPECT_THROW(Section::pipe(0.3, 0), std::invalid_argument);
  EXPECT_THROW(Section::tapered(0.1, 0.2, 0), std::invalid_argument);
  EXPECT_THROW(Section::tapered(0.1, 0.2, 0.1).depth(1.5), std::invalid_argument);
  EXPECT_THROW(Section::rectangle(0.1, std::nan("")), std::invalid_argument);
}

// A box 0.2 wide, 0.3 deep, walls 10 mm, by hand: the enclosing rectangle less the hollow 0.18 x 0.28.
TEST(Section, BoxByHand) {
  const Section s = Section::box(0.2, 0.3, 0.01);
  EXPECT_EQ(s.kind(), SectionKind::box);
  EXPECT_TRUE(s.hollow());
  EXPECT_NEAR(s.area(0), 0.06 - 0.18 * 0.28, 1e-15);
  EXPECT_NEAR(s.inertia(0), (0.2 * 0.027 - 0.18 * std::pow(0.28, 3)) / 12, 1e-17);
  EXPECT_NEAR(s.inertia_y(0), (0.3 * 0.008 - 0.28 * std::pow(0.18, 3)) / 12, 1e-17);
  EXPECT_NEAR(s.plastic_modulus(0), 0.2 * 0.09 / 4 - 0.18 * 0.0784 / 4, 1e-15);   // 9.72e-4 m^3
  EXPECT_NEAR(s.plastic_modulus_y(0), 0.3 * 0.04 / 4 - 0.28 * 0.0324 / 4, 1e-15);
  // Bredt: J = 4 A_m^2 t / p_m, A_m = 0.19 x 0.29, p_m = 2 (0.19 + 0.29); W_t = 2 A_m t.
  EXPECT_NEAR(s.torsion_constant(0), 4 * std::pow(0.19 * 0.29, 2) * 0.01 / (2 * 0.48), 1e-15);
  EXPECT_NEAR(s.torsion_modulus(0), 2 * 0.19 * 0.29 * 0.01, 1e-15);
  // Jourawski at the axis: Q = W_pl / 2 over the two walls 2t; A_v = A h / (b + h).
  EXPECT_NEAR(s.shear_stress_factor(), 0.5 * s.plastic_modulus(0) * s.area(0) / (s.inertia(0) * 0.02), 1e-12);
  EXPECT_NEAR(s.shear_coefficient(), 0.3 / 0.5, 1e-15);
  // In a flange the width is b: the stress falls by (2t / b) across the junction.
  const double y = 0.14;
  EXPECT_NEAR(s.shear_flow_stress(0, y - 1e-9) / s.shear_flow_stress(0, y + 1e-9), 0.2 / 0.02, 1e-5);
  EXPECT_THROW(Section::box(0.2, 0.3, 0.1), std::invalid_argument);  // walls meeting in the middle: a solid
}

// An I 0.4 deep, flanges 0.2 x 16 mm, web 10 mm: A 0.01008 m^2, W_pl = 2 b t_f (h - t_f) / 2 + t_w h_w^2 / 4.
TEST(Section, ISectionByHand) {
  const Section s = Section::i_section(0.2, 0.4, 0.016, 0.01);
  EXPECT_EQ(s.kind(), SectionKind::i_section);
  EXPECT_FALSE(s.hollow());
  EXPECT_TRUE(s.thin_walled());
  EXPECT_NEAR(s.area(0), 0.01008, 1e-15);
  EXPECT_NEAR(s.inertia(0), (0.2 * 0.064 - 0.19 * std::pow(0.368, 3)) / 12, 1e-17);
  EXPECT_NEAR(s.inertia_y(0), (2 * 0.016 * 0.008 + 0.368 * 1e-6) / 12, 1e-17);
  EXPECT_NEAR(s.plastic_modulus(0), 0.2 * 0.016 * 0.384 + 0.01 * 0.368 * 0.368 / 4, 1e-15);
  EXPECT_NEAR(s.plastic_modulus_y(0), (2 * 0.016 * 0.04 + 0.368 * 1e-4) / 4, 1e-15);
  EXPECT_NEAR(s.torsion_constant(0), (2 * 0.2 * std::pow(0.016, 3) + 0.368 * 1e-6) / 3, 1e-15);
  EXPECT_NEAR(s.torsion_modulus(0), s.torsion_constant(0) / 0.016, 1e-15);
  EXPECT_NEAR(s.shear_coefficient(), 0.368 * 0.01 / 0.01008, 1e-15);
  // Peak shear at the axis of the web, V Q / (I t_w): 2.85 V / A, above the mean over the web (A / h_w t_w = 2.74).
  EXPECT_NEAR(s.shear_stress_factor(), 0.5 * s.plastic_modulus(0) * 0.01008 / (s.inertia(0) * 0.01), 1e-12);
  EXPECT_GT(s.shear_stress_factor(), 0.01008 / (0.368 * 0.01));
  EXPECT_THROW(Section::i_section(0.2, 0.4, 0.2, 0.01), std::invalid_argument);   // flanges fill the depth
  EXPECT_THROW(Section::i_section(0.2, 0.4, 0.016, 0.2), std::invalid_argument);  // a web as wide as the flanges
}

}  // namespace
}  // namespace dmi
