// Design-practice impact loads: the formulas guidelines give for a boulder or a debris surge striking a protection
// structure, beside the simulation (design/estimates.cpp). SI in and out (N); each formula is stated in the units of
// its source and converted inside. Full references: docs/references.md; formulas and assumptions: docs/design-checks.md.
#pragma once

namespace dmi::sdof {

// Empirical Hertz form with the GEO parameters (Kwan 2012, GEO Report 270, "Supplementary technical
// guidance on design of rigid debris-resisting barriers", Hong Kong):
//   F [kN] = K_c 4000 v^1.2 r^2,  v in m/s, r = boulder radius in m,
// the moduli of boulder and barrier are implicit in the 4000; K_c = 0.1 (the GEO default) is a
// reduction factor for the non-elastic response. Returns Newtons.
double geo_hertz_impact_force_N(double boulder_speed_m_per_s, double boulder_radius_m,
                                double reduction_factor_Kc = 0.1);

struct HardImpact {
  double peak_force_N;  // F = v_r sqrt(k m)
  double duration_s;    // delta_t = sqrt(m/k), so F delta_t = m v_r
};

// EN 1991-1-7 Annex C.2.1 "hard impact", eq. (C.1): object of mass m (kg) at velocity v_r (m/s) on a struck
// object of equivalent elastic stiffness k (N/m); rectangular pulse. Note F = m v_r sqrt(k/m) is
// Lin, Cheng & Tuan's eq. (23) with the impacting mass in place of the dam's.
HardImpact en1991_hard_impact(double impact_speed_m_per_s, double impacting_mass_kg,
                              double equivalent_stiffness_N_per_m);

// Lame's first parameter lambda = E nu / ((1 + nu)(1 - 2 nu)) (Pa).
double lame_first_parameter(double youngs_modulus_Pa, double poisson_ratio);

// Constrained (oedometric) modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) (Pa).
double constrained_modulus(double youngs_modulus_Pa, double poisson_ratio);

// Japan Road Association (2000), Rockfall Countermeasure Handbook: a rock of weight W = m g falling from height H
// onto a cushion with Lame constant lambda,
//   P [kN] = 2.108 W^(2/3) lambda^(2/5) H^(3/5),   W in kN, lambda in kN/m^2, H in m.
// It is Hertz's rigid sphere on an elastic half-space (Johnson 1985, ch. 11) with the cushion's Poisson ratio 0.25 and
// the rock's unit weight near 26 kN/m^3 folded into the constant (tests/engine/sdof: 0.2 % from Hertz). The
// handbook's factor for a cushion thinner than the rock is not applied (the half-space form). Returns Newtons.
double japanese_rockfall_force_N(double rock_mass_kg, double cushion_lame_Pa, double fall_height_m, double g = 9.81);

// ASTRA 12006 (2008), rock-fall protection galleries with a granular cushion, the characteristic impact force
//   F_k [kN] = 2.8 e^-0.5 r^0.7 M_E^0.4 tan(phi) (m v^2 / 2)^0.6,
// e the cushion thickness (m), r the block radius (m), M_E the cushion's modulus from plate-load tests (kN/m^2),
// phi its friction angle, m v^2/2 the kinetic energy in kJ (m in t). Calibrated on gravel cushions (Labiouse et al.
// 1996). Returns Newtons.
double astra_gallery_force_N(double cushion_thickness_m, double block_radius_m, double cushion_modulus_Pa,
                             double friction_angle_deg, double block_mass_kg, double speed_m_per_s);

// Debris surge of density rho, front speed v and flow depth h on a barrier of width w, dynamic (momentum-flux) form
// F = alpha rho v^2 h w (Kwan 2012, GEO Report 270: alpha = 2.5 for rigid barriers; alpha = 1 is the momentum flux
// of a surge stopped by a wall). Returns Newtons.
double debris_dynamic_force_N(double alpha, double density_kg_m3, double speed_m_per_s, double depth_m, double width_m);

// The same plus the hydrostatic thrust of the arrested flow: F = (k rho g h / 2 + alpha rho v^2) h w, the sum of the
// hydrostatic (k) and hydrodynamic (alpha) forms reviewed by Hubl et al. (2009). Returns Newtons.
double debris_hydrostatic_dynamic_force_N(double k, double alpha, double density_kg_m3, double speed_m_per_s, double depth_m,
                                          double width_m, double g = 9.81);

// A blunt, full-depth surge front stopped by a rigid wall as a coherent elastic continuum: the compression wave that
// brings it to rest carries the pressure rho c v (the water-hammer pressure of Joukowsky 1900) with c = sqrt(M / rho),
// M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) the constrained modulus: F = rho c v h w over the wave's return time through
// the depth. Not a design load: the bound a continuum model reaches with a vertical front, set by the debris modulus.
double debris_elastic_wave_force_N(double density_kg_m3, double youngs_modulus_Pa, double poisson_ratio, double speed_m_per_s,
                                   double depth_m, double width_m);

}  // namespace dmi::sdof
