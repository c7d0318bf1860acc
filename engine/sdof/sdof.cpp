// Lin, Cheng & Tuan and Hertz; equations are stated in sdof.hpp.
#include "engine/sdof/sdof.hpp"

#include "engine/sdof/require.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dmi::sdof {
namespace {

using namespace detail;

void validate(const char* function, const Oscillator& o) {
  require_positive(function, "mass_kg", o.mass_kg);
  require_positive(function, "stiffness_N_per_m", o.stiffness_N_per_m);
  require_non_negative(function, "damping_ratio", o.damping_ratio);
}

constexpr double kCantileverBeta1L = 1.8751040687119611;  // first root of 1 + cos x cosh x = 0

}  // namespace

double natural_frequency(double mass_kg, double stiffness_N_per_m) {
  require_positive("natural_frequency", "mass_kg", mass_kg);
  require_positive("natural_frequency", "stiffness_N_per_m", stiffness_N_per_m);
  return std::sqrt(stiffness_N_per_m / mass_kg);
}

double critical_damping(double mass_kg, double stiffness_N_per_m) {
  require_positive("critical_damping", "mass_kg", mass_kg);
  require_positive("critical_damping", "stiffness_N_per_m", stiffness_N_per_m);
  return 2.0 * std::sqrt(stiffness_N_per_m * mass_kg);
}

double damped_frequency(double natural_frequency_rad_per_s, double damping_ratio) {
  require_positive("damped_frequency", "natural_frequency_rad_per_s", natural_frequency_rad_per_s);
  if (!(std::isfinite(damping_ratio) && damping_ratio >= 0 && damping_ratio < 1))
    fail("damped_frequency", "damping_ratio", damping_ratio, "0 <= zeta < 1 (underdamped)");
  return natural_frequency_rad_per_s * std::sqrt(1.0 - damping_ratio * damping_ratio);
}

double Oscillator::natural_frequency_rad_per_s() const {
  validate("Oscillator::natural_frequency_rad_per_s", *this);
  return std::sqrt(stiffness_N_per_m / mass_kg);
}

double Oscillator::damping_coefficient_N_s_per_m() const {
  validate("Oscillator::damping_coefficient_N_s_per_m", *this);
  return damping_ratio * 2.0 * std::sqrt(stiffness_N_per_m * mass_kg);
}

Oscillator oscillator_from_damping_coefficient(double mass_kg, double stiffness_N_per_m,
                                               double damping_N_s_per_m) {
  const char* f = "oscillator_from_damping_coefficient";
  require_positive(f, "mass_kg", mass_kg);
  require_positive(f, "stiffness_N_per_m", stiffness_N_per_m);
  require_non_negative(f, "damping_N_s_per_m", damping_N_s_per_m);
  return {mass_kg, stiffness_N_per_m, damping_N_s_per_m / critical_damping(mass_kg, stiffness_N_per_m)};
}

double free_vibration(const Oscillator& o, double u0_m, double v0_m_per_s, double t_s) {
  const char* f = "free_vibration";
  validate(f, o);
  require_finite(f, "u0_m", u0_m);
  require_finite(f, "v0_m_per_s", v0_m_per_s);
  require_non_negative(f, "t_s", t_s);
  const double wn = std::sqrt(o.stiffness_N_per_m / o.mass_kg), z = o.damping_ratio;
  if (z == 0) return u0_m * std::cos(wn * t_s) + v0_m_per_s / wn * std::sin(wn * t_s);  // eq. (9)
  const double decay = std::exp(-z * wn * t_s), b = v0_m_per_s + z * wn * u0_m;
  if (z < 1) {  // eq. (14)
    const double wd = wn * std::sqrt(1.0 - z * z);
    return decay * (u0_m * std::cos(wd * t_s) + b / wd * std::sin(wd * t_s));
  }
  if (z == 1) return decay * (u0_m + b * t_s);
  const double ws = wn * std::sqrt(z * z - 1.0);
  return decay * (u0_m * std::cosh(ws * t_s) + b / ws * std::sinh(ws * t_s));
}

double unit_impulse_response(const Oscillator& o, double t_s, double tau_s) {
  const char* f = "unit_impulse_response";
  validate(f, o);
  require_finite(f, "t_s", t_s);
  require_finite(f, "tau_s", tau_s);
  if (t_s < tau_s) return 0.0;
  return free_vibration(o, 0.0, 1.0 / o.mass_kg, t_s - tau_s);  // eqs. (18)-(19)
}

double impulse_response(const Oscillator& o, double impulse_N_s, double t_s, double tau_s) {
  require_finite("impulse_response", "impulse_N_s", impulse_N_s);
  return impulse_N_s * unit_impulse_response(o, t_s, tau_s);
}

ImpulsePeak unit_impulse_peak(const Oscillator& o) {
  validate("unit_impulse_peak", o);
  const double wn = std::sqrt(o.stiffness_N_per_m / o.mass_kg), z = o.damping_ratio;
  const double scale = 1.0 / (o.mass_kg * wn);
  if (z < 1) {  // eq. (20); atan2 gives pi/2 at zeta = 0
    const double s = std::sqrt(1.0 - z * z), phase = std::atan2(s, z);
    return {scale * std::exp(-(z / s) * phase), phase / (wn * s)};
  }
  if (z == 1) return {scale / std::numbers::e, 1.0 / wn};
  const double s = std::sqrt(z * z - 1.0), phase = std::atanh(s / z);
  return {scale * std::exp(-(z / s) * phase), phase / (wn * s)};
}

BoulderImpact boulder_on_dam(double boulder_mass_kg, double boulder_speed_m_per_s,
                             double dam_mass_kg, double dam_stiffness_N_per_m) {
  const char* f = "boulder_on_dam";
  require_positive(f, "boulder_mass_kg", boulder_mass_kg);
  require_positive(f, "boulder_speed_m_per_s", boulder_speed_m_per_s);
  require_positive(f, "dam_mass_kg", dam_mass_kg);
  require_positive(f, "dam_stiffness_N_per_m", dam_stiffness_N_per_m);
  const double impulse = boulder_mass_kg * boulder_speed_m_per_s;              // eq. (21)
  const double wn = std::sqrt(dam_stiffness_N_per_m / dam_mass_kg);
  const double u_max = impulse / (dam_mass_kg * wn);                           // eq. (22)
  return {impulse, wn, u_max, dam_stiffness_N_per_m * u_max};                  // eq. (23)
}

double Section::radius_of_gyration_m() const {
  require_positive("Section::radius_of_gyration_m", "area_m2", area_m2);
  require_positive("Section::radius_of_gyration_m", "second_moment_m4", second_moment_m4);
  return std::sqrt(second_moment_m4 / area_m2);
}

Section rectangular_section(double width_m, double depth_m) {
  require_positive("rectangular_section", "width_m", width_m);
  require_positive("rectangular_section", "depth_m", depth_m);
  return {width_m * depth_m, width_m * depth_m * depth_m * depth_m / 12.0};
}

Section tapered_rectangular_section(double width_m, double crest_depth_m, double base_depth_m) {
  const char* f = "tapered_rectangular_section";
  require_positive(f, "width_m", width_m);
  require_positive(f, "crest_depth_m", crest_depth_m);
  require_positive(f, "base_depth_m", base_depth_m);
  return rectangular_section(width_m, 0.5 * (crest_depth_m + base_depth_m));
}

CantileverSdof cantilever_sdof(double youngs_modulus_Pa, double density_kg_per_m3,
                               const Section& section, double height_m) {
  const char* f = "cantilever_sdof";
  require_positive(f, "youngs_modulus_Pa", youngs_modulus_Pa);
  require_positive(f, "density_kg_per_m3", density_kg_per_m3);
  require_positive(f, "section.area_m2", section.area_m2);
  require_positive(f, "section.second_moment_m4", section.second_moment_m4);
  require_positive(f, "height_m", height_m);
  const double L = height_m, r = section.radius_of_gyration_m();
  const double k = 3.0 * youngs_modulus_Pa * section.second_moment_m4 / (L * L * L);
  const double M = density_kg_per_m3 * section.area_m2 * L / 2.0;
  const double w1 = kCantileverBeta1L * kCantileverBeta1L * std::sqrt(youngs_modulus_Pa / density_kg_per_m3) * r / (L * L);
  return {k, M, std::sqrt(k / M), w1};
}

double series_stiffness(double dam_stiffness_N_per_m, double buffer_stiffness_N_per_m) {
  require_positive("series_stiffness", "dam_stiffness_N_per_m", dam_stiffness_N_per_m);
  require_positive("series_stiffness", "buffer_stiffness_N_per_m", buffer_stiffness_N_per_m);
  return 1.0 / (1.0 / dam_stiffness_N_per_m + 1.0 / buffer_stiffness_N_per_m);
}

double buffer_layer_stiffness(double buffer_modulus_Pa, double contact_area_m2, double thickness_m) {
  const char* f = "buffer_layer_stiffness";
  require_positive(f, "buffer_modulus_Pa", buffer_modulus_Pa);
  require_positive(f, "contact_area_m2", contact_area_m2);
  require_positive(f, "thickness_m", thickness_m);
  return buffer_modulus_Pa * contact_area_m2 / thickness_m;
}

BoulderImpact buffered_boulder_on_dam(double boulder_mass_kg, double boulder_speed_m_per_s,
                                      double dam_mass_kg, double dam_stiffness_N_per_m,
                                      double buffer_stiffness_N_per_m) {
  return boulder_on_dam(boulder_mass_kg, boulder_speed_m_per_s, dam_mass_kg,
                        series_stiffness(dam_stiffness_N_per_m, buffer_stiffness_N_per_m));
}

double hertz_effective_modulus(double youngs_modulus_1_Pa, double poisson_ratio_1,
                               double youngs_modulus_2_Pa, double poisson_ratio_2) {
  const char* f = "hertz_effective_modulus";
  require_positive(f, "youngs_modulus_1_Pa", youngs_modulus_1_Pa);
  require_poisson(f, "poisson_ratio_1", poisson_ratio_1);
  require_positive(f, "youngs_modulus_2_Pa", youngs_modulus_2_Pa);
  require_poisson(f, "poisson_ratio_2", poisson_ratio_2);
  return 1.0 / ((1.0 - poisson_ratio_1 * poisson_ratio_1) / youngs_modulus_1_Pa +
                (1.0 - poisson_ratio_2 * poisson_ratio_2) / youngs_modulus_2_Pa);
}

HertzImpact hertz_sphere_impact(double boulder_mass_kg, double boulder_speed_m_per_s,
                                double boulder_radius_m, double boulder_modulus_Pa,
                                double boulder_poisson_ratio, double barrier_modulus_Pa,
                                double barrier_poisson_ratio) {
  const char* f = "hertz_sphere_impact";
  require_positive(f, "boulder_mass_kg", boulder_mass_kg);
  require_positive(f, "boulder_speed_m_per_s", boulder_speed_m_per_s);
  require_positive(f, "boulder_radius_m", boulder_radius_m);
  const double e_star = hertz_effective_modulus(boulder_modulus_Pa, boulder_poisson_ratio,
                                                barrier_modulus_Pa, barrier_poisson_ratio);
  const double v = boulder_speed_m_per_s, sqrt_r = std::sqrt(boulder_radius_m);
  const double delta = std::pow(15.0 * boulder_mass_kg * v * v / (16.0 * e_star * sqrt_r), 0.4);
  const double force = 4.0 / 3.0 * e_star * sqrt_r * std::pow(delta, 1.5);
  return {e_star, delta, force, 2.94 * delta / v};
}

std::vector<double> cantilever_base_shear(double EI, double m, double L, double a, const std::vector<double>& t,
                                          const std::vector<double>& force, int modes) {
  const char* f = "cantilever_base_shear";
  require_positive(f, "bending_stiffness_N_m2", EI);
  require_positive(f, "mass_per_length_kg_per_m", m);
  require_positive(f, "length_m", L);
  require_positive(f, "load_height_m", a);
  if (a > L) fail(f, "load_height_m", a, "<= length_m");
  if (modes < 1 || modes > 8) fail(f, "modes", modes, "an integer in [1, 8]");
  if (force.size() != t.size()) fail(f, "force.size()", static_cast<double>(force.size()), "t.size()");
  struct Mode { double w, La, Lj, Mj; };  // omega, phi(a), int m phi, int m phi^2
  std::vector<Mode> md;
  double static_part = 1.0;
  for (int j = 1; j <= modes; ++j) {
    // Root of 1 + cos x cosh x by Newton from (2j - 1) pi / 2 (the first from 1.875).
    double x = j == 1 ? kCantileverBeta1L : (2 * j - 1) * std::numbers::pi / 2;
    for (int it = 0; it < 50; ++it) {
      const double g = 1 + std::cos(x) * std::cosh(x), dg = -std::sin(x) * std::cosh(x) + std::cos(x) * std::sinh(x);
      const double dx = g / dg;
      x -= dx;
      if (std::abs(dx) < 1e-15 * x) break;
    }
    const double b = x / L, sj = (std::cosh(x) + std::cos(x)) / (std::sinh(x) + std::sin(x));
    const auto phi = [&](double y) { return std::cosh(b * y) - std::cos(b * y) - sj * (std::sinh(b * y) - std::sin(b * y)); };
    const int n = 4000;  // Simpson's rule on n intervals
    double Lj = 0, Mj = 0;
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2), p = phi(L * i / n);
      Lj += w * p, Mj += w * p * p;
    }
    Lj *= m * L / (3 * n), Mj *= m * L / (3 * n);
    md.push_back({b * b * std::sqrt(EI / m), phi(a), Lj, Mj});
    static_part -= Lj * phi(a) / Mj;
  }
  std::vector<double> V(t.size(), 0.0), q(md.size(), 0.0), qd(md.size(), 0.0);
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double dt = t[k] - t[k - 1];
    if (!(dt > 0)) fail(f, "t (step)", dt, "increasing times");
    double v = static_part * force[k];
    for (std::size_t j = 0; j < md.size(); ++j) {
      const Mode& o = md[j];
      const double qs = force[k] * o.La / (o.Mj * o.w * o.w);  // static modal response to the step's force
      const double c = std::cos(o.w * dt), s = std::sin(o.w * dt), d = q[j] - qs;
      q[j] = qs + d * c + qd[j] / o.w * s;
      qd[j] = -d * o.w * s + qd[j] * c;
      v += o.Lj * o.w * o.w * q[j];
    }
    V[k] = v;
  }
  return V;
}

}  // namespace dmi::sdof
