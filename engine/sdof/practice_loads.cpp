// Design-practice impact loads; formulas and sources in practice_loads.hpp.
#include "engine/sdof/practice_loads.hpp"

#include <cmath>
#include <numbers>

#include "engine/sdof/require.hpp"

namespace dmi::sdof {

using namespace detail;

double geo_hertz_impact_force_N(double boulder_speed_m_per_s, double boulder_radius_m,
                                double reduction_factor_Kc) {
  const char* f = "geo_hertz_impact_force_N";
  require_non_negative(f, "boulder_speed_m_per_s", boulder_speed_m_per_s);
  require_positive(f, "boulder_radius_m", boulder_radius_m);
  require_positive(f, "reduction_factor_Kc", reduction_factor_Kc);
  const double force_kN = reduction_factor_Kc * 4000.0 * std::pow(boulder_speed_m_per_s, 1.2) *
                          boulder_radius_m * boulder_radius_m;
  return 1000.0 * force_kN;
}

HardImpact en1991_hard_impact(double impact_speed_m_per_s, double impacting_mass_kg,
                              double equivalent_stiffness_N_per_m) {
  const char* f = "en1991_hard_impact";
  require_non_negative(f, "impact_speed_m_per_s", impact_speed_m_per_s);
  require_positive(f, "impacting_mass_kg", impacting_mass_kg);
  require_positive(f, "equivalent_stiffness_N_per_m", equivalent_stiffness_N_per_m);
  return {impact_speed_m_per_s * std::sqrt(equivalent_stiffness_N_per_m * impacting_mass_kg),
          std::sqrt(impacting_mass_kg / equivalent_stiffness_N_per_m)};
}

double lame_first_parameter(double E, double nu) {
  require_positive("lame_first_parameter", "youngs_modulus_Pa", E);
  require_poisson("lame_first_parameter", "poisson_ratio", nu);
  return E * nu / ((1 + nu) * (1 - 2 * nu));
}

double constrained_modulus(double E, double nu) {
  require_positive("constrained_modulus", "youngs_modulus_Pa", E);
  require_poisson("constrained_modulus", "poisson_ratio", nu);
  return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
}

double japanese_rockfall_force_N(double m, double lame, double H, double g) {
  const char* f = "japanese_rockfall_force_N";
  require_positive(f, "rock_mass_kg", m);
  require_positive(f, "cushion_lame_Pa", lame);
  require_non_negative(f, "fall_height_m", H);
  require_positive(f, "g", g);
  const double W_kN = m * g / 1e3, lame_kN = lame / 1e3;
  return 1e3 * 2.108 * std::pow(W_kN, 2.0 / 3) * std::pow(lame_kN, 0.4) * std::pow(H, 0.6);
}

double astra_gallery_force_N(double e, double r, double ME, double phi_deg, double m, double v) {
  const char* f = "astra_gallery_force_N";
  require_positive(f, "cushion_thickness_m", e);
  require_positive(f, "block_radius_m", r);
  require_positive(f, "cushion_modulus_Pa", ME);
  if (!(std::isfinite(phi_deg) && phi_deg > 0 && phi_deg < 90)) fail(f, "friction_angle_deg", phi_deg, "0 < phi < 90");
  require_positive(f, "block_mass_kg", m);
  require_non_negative(f, "speed_m_per_s", v);
  const double energy_kJ = 0.5 * (m / 1e3) * v * v, ME_kN = ME / 1e3;
  const double F_kN = 2.8 * std::pow(e, -0.5) * std::pow(r, 0.7) * std::pow(ME_kN, 0.4) * std::tan(phi_deg * std::numbers::pi / 180) *
                      std::pow(energy_kJ, 0.6);
  return 1e3 * F_kN;
}

double debris_dynamic_force_N(double alpha, double rho, double v, double h, double w) {
  const char* f = "debris_dynamic_force_N";
  require_positive(f, "alpha", alpha);
  require_positive(f, "density_kg_m3", rho);
  require_non_negative(f, "speed_m_per_s", v);
  require_positive(f, "depth_m", h);
  require_positive(f, "width_m", w);
  return alpha * rho * v * v * h * w;
}

double debris_hydrostatic_dynamic_force_N(double k, double alpha, double rho, double v, double h, double w, double g) {
  require_non_negative("debris_hydrostatic_dynamic_force_N", "k", k);
  require_positive("debris_hydrostatic_dynamic_force_N", "g", g);
  return 0.5 * k * rho * g * h * h * w + debris_dynamic_force_N(alpha, rho, v, h, w);
}

double debris_elastic_wave_force_N(double rho, double E, double nu, double v, double h, double w) {
  const char* f = "debris_elastic_wave_force_N";
  require_positive(f, "density_kg_m3", rho);
  require_positive(f, "youngs_modulus_Pa", E);
  if (!(std::isfinite(nu) && nu > -1 && nu < 0.5)) fail(f, "poisson_ratio", nu, "-1 < nu < 0.5");
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  require_non_negative(f, "speed_m_per_s", v);
  require_positive(f, "depth_m", h);
  require_positive(f, "width_m", w);
  return rho * std::sqrt(M / rho) * v * h * w;
}

}  // namespace dmi::sdof
