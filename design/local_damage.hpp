// Local damage of a concrete face struck by a boulder taken as a hard (non-deforming) projectile: penetration
// depth, scabbing and perforation thicknesses by the empirical formulae of missile-impact practice (docs/design-checks.md,
// "Local damage"). Pure functions, SI in and out (kg, m, m/s, Pa); the formulae are empirical in US units and are
// evaluated in those units inside (the conversions are exact: 1 lb = 0.45359237 kg, 1 in = 0.0254 m, 1 ft = 0.3048 m).
#pragma once
#include <string>

namespace dmi::design {

// Nose-shape factor N* of the modified NDRC formula (Kennedy 1976; DOE-STD-3014 App. C).
inline constexpr double kNoseFlat = 0.72;
inline constexpr double kNoseBlunt = 0.84;
inline constexpr double kNoseSpherical = 1.00;  // "average bullet-nosed (spherical end)"; the conservative choice for a boulder
inline constexpr double kNoseVerySharp = 1.14;

// Design margins on thickness, DOE-STD-3014 App. C: t_d > 1.1 t_s against scabbing (after eqs. C-6-5/C-6-6) and
// t_d = 1.2 t_p against perforation (after the Degen eqs. C-6-13/C-6-14).
inline constexpr double kDoeScabbingMargin = 1.1;
inline constexpr double kDoePerforationMargin = 1.2;

// Stated ranges. NDRC thickness formulae: x/d <= 11.75 (scabbing, DOE-STD-3014 eq. C-6-5), x/d <= 13.5 (perforation;
// Kennedy 1976, ACE form). Degen (1980): e/d <= 18. Chang (1981): impact speed 16.7..311.8 m/s (the range of its test data
// as reviewed by Li et al. 2005).
inline constexpr double kNdrcScabbingMaxXd = 11.75;
inline constexpr double kNdrcPerforationMaxXd = 13.5;
inline constexpr double kDegenMaxEd = 18.0;
inline constexpr double kChangMinSpeed = 16.7, kChangMaxSpeed = 311.8;  // m/s
inline constexpr double kChangReferenceSpeed = 200.0 * 0.3048;          // u = 200 ft/s = 60.96 m/s

// Modified NDRC G-function (Kennedy 1976, sec. on the modified NDRC formula; DOE-STD-3014 App. C.6.3.2.1.1), US units:
// G = K N* W / d (V / (1000 d))^1.8, K = 180 / sqrt(f'c) (W lb, d in, V ft/s, f'c psi). Dimensionless.
double ndrc_G(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa, double nose_factor);
// Penetration ratio x/d (Kennedy 1976; DOE-STD-3014 eqs. C-6-3/C-6-4): 2 sqrt(G) for G <= 1, G + 1 for G > 1.
double ndrc_x_over_d(double G);
// Scabbing h_s/d (Kennedy 1976; DOE-STD-3014 eqs. C-6-5/C-6-6): 7.91 (x/d) - 5.06 (x/d)^2 for x/d <= 0.65,
// 2.12 + 1.36 (x/d) above.
double ndrc_scabbing_over_d(double x_over_d);
// Perforation e/d (Kennedy 1976; DOE-STD-3014 App. C.6.3.2.1.2): 3.19 (x/d) - 0.718 (x/d)^2 for x/d <= 1.35,
// 1.32 + 1.24 (x/d) above.
double ndrc_perforation_over_d(double x_over_d);
// Perforation e/d (Degen 1980; DOE-STD-3014 eqs. C-6-13/C-6-14): 2.2 (x/d) - 0.3 (x/d)^2 for x/d <= 1.52 (e/d <= 2.65),
// 0.69 + 1.29 (x/d) above (2.65 <= e/d <= 18).
double degen_perforation_over_d(double x_over_d);
// Perforation (Chang 1981): e/d = (u/V)^0.25 (M V^2 / (d^3 f'c))^0.5, u = 200 ft/s. Dimensionally consistent, so it is
// evaluated in SI directly (u = 60.96 m/s). Returns e (m).
double chang_perforation(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa);
// Scabbing (Chang 1981): h_s/d = 1.84 (u/V)^0.13 (M V^2 / (d^3 f'c))^0.4, u = 200 ft/s. Returns h_s (m).
double chang_scabbing(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa);

// Everything for one impact. *_in_range: the inputs are inside the stated range of that formula (see above; the
// NDRC penetration itself has no separate stated range: penetration_in_range uses the perforation limit x/d <= 13.5).
struct LocalDamage {
  double G = 0, x_over_d = 0;
  double penetration_m = 0;          bool penetration_in_range = false;
  double scabbing_ndrc_m = 0;        bool scabbing_ndrc_in_range = false;
  double scabbing_chang_m = 0;       bool scabbing_chang_in_range = false;
  double perforation_ndrc_m = 0;     bool perforation_ndrc_in_range = false;
  double perforation_degen_m = 0;    bool perforation_degen_in_range = false;
  double perforation_chang_m = 0;    bool perforation_chang_in_range = false;
};
// Throws std::invalid_argument for a non-finite or non-positive input, or a nose factor outside [0.72, 1.14].
LocalDamage local_damage(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa, double nose_factor = kNoseSpherical);

// Governing (largest) scabbing and perforation thickness over the formulae, kept raw and times a margin each
// (>= 1; kDoeScabbingMargin / kDoePerforationMargin for DOE-STD-3014 practice). Throws std::invalid_argument for a
// margin below 1 or not finite.
struct DesignThickness {
  double scabbing_raw_m = 0, perforation_raw_m = 0;
  std::string scabbing_by, perforation_by;  // "ndrc" | "chang" | "degen"
  bool scabbing_in_range = false, perforation_in_range = false;  // of the governing formula
  double scabbing_margin = 1, perforation_margin = 1;
  double scabbing_design_m = 0, perforation_design_m = 0;
};
DesignThickness design_thickness(const LocalDamage& d, double scabbing_margin = 1.0, double perforation_margin = 1.0);

}  // namespace dmi::design
