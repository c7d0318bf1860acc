#include "design/checks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dmi::design {

nlohmann::json Check::to_json() const {
  nlohmann::json j{{"id", id}, {"title", title}, {"member", member}, {"material", material}, {"demand", demand}, {"capacity", capacity},
                   {"unit", unit}, {"utilisation", utilisation}, {"passed", passed}, {"formula", formula}, {"source", source},
                   {"level", level}, {"situation", situation}, {"dynamic_increase_factor", dynamic_factor}, {"strain_rate_per_s", strain_rate}};
  j["position"] = position >= 0 ? nlohmann::json(position) : nlohmann::json(nullptr);
  j["s_m"] = s_m >= 0 ? nlohmann::json(s_m) : nlohmann::json(nullptr);
  j["location_m"] = space ? nlohmann::json{x_m, y_m, z_m} : nlohmann::json{x_m, y_m};
  j["time_s"] = time_s >= 0 ? nlohmann::json(time_s) : nlohmann::json(nullptr);
  return j;
}

double sqrt_fc_Pa(double fc_Pa, double lambda) { return lambda * std::sqrt(fc_Pa / 1e6) * 1e6; }

double concrete_one_way_shear_capacity(double fc_Pa, double lambda, double width_m, double depth_m, double phi) {
  return phi * 0.11 * sqrt_fc_Pa(fc_Pa, lambda) * width_m * depth_m;
}

double concrete_punching_capacity(double fc_Pa, double lambda, double patch_w_m, double patch_h_m, double depth_m, double phi) {
  const double beta = std::max(patch_w_m, patch_h_m) / std::min(patch_w_m, patch_h_m);
  const double bo = 2 * (patch_w_m + depth_m) + 2 * (patch_h_m + depth_m);
  return phi * std::min(0.11 * (1 + 2 / beta), 0.22) * sqrt_fc_Pa(fc_Pa, lambda) * bo * depth_m;
}

double chs_area(double D, double t) {
  const double d = D - 2 * t;
  return 0.25 * std::numbers::pi * (D * D - d * d);
}
double chs_elastic_modulus(double D, double t) {
  const double d = D - 2 * t;
  return std::numbers::pi / 64 * (std::pow(D, 4) - std::pow(d, 4)) / (0.5 * D);
}
double chs_plastic_modulus(double D, double t) {
  const double d = D - 2 * t;
  return (D * D * D - d * d * d) / 6;
}
double chs_shear_area(double D, double t) { return 2 * chs_area(D, t) / std::numbers::pi; }

int chs_class(double D, double t, double fy_Pa) {
  const double eps2 = 235e6 / fy_Pa, r = D / t;
  return r <= 50 * eps2 ? 1 : r <= 70 * eps2 ? 2 : r <= 90 * eps2 ? 3 : 4;
}
double chs_class3_limit(double fy_Pa) { return 90 * 235e6 / fy_Pa; }

double chs_shear_resistance(double D, double t, double fy_Pa, double gamma_M0) {
  return chs_shear_area(D, t) * fy_Pa / std::sqrt(3.0) / gamma_M0;
}

double chs_interaction(double N, double M, double D, double t, double fy_Pa, double gamma_M0) {
  const double f = fy_Pa / gamma_M0;
  const double W = chs_class(D, t, fy_Pa) <= 2 ? chs_plastic_modulus(D, t) : chs_elastic_modulus(D, t);
  return std::abs(N) / (chs_area(D, t) * f) + std::abs(M) / (W * f);
}

double chs_torsion_resistance(double D, double t, double fy_Pa, double gamma_M0) {
  return 2 * chs_elastic_modulus(D, t) * fy_Pa / std::sqrt(3.0) / gamma_M0;
}

double chs_shear_resistance_with_torsion(double T, double D, double t, double fy_Pa, double gamma_M0) {
  // tau_t,Ed / (f_y / (sqrt 3 gamma_M0)) = (|T| / W_t) / (T_Rd / W_t) = |T| / T_Rd
  return std::max(0.0, 1 - std::abs(T) / chs_torsion_resistance(D, t, fy_Pa, gamma_M0)) * chs_shear_resistance(D, t, fy_Pa, gamma_M0);
}

double buckling_imperfection(const std::string& curve) {
  if (curve == "a0") return 0.13;
  if (curve == "a") return 0.21;
  if (curve == "b") return 0.34;
  if (curve == "c") return 0.49;
  if (curve == "d") return 0.76;
  throw std::invalid_argument("buckling curve '" + curve + "' (a0, a, b, c or d)");
}

double flexural_buckling_resistance(double A, double I, double L_cr, double E, double fy, double alpha, double gamma_M1) {
  const double N_cr = std::numbers::pi * std::numbers::pi * E * I / (L_cr * L_cr), lambda = std::sqrt(A * fy / N_cr);
  const double phi = 0.5 * (1 + alpha * (lambda - 0.2) + lambda * lambda);
  const double chi = std::min(1.0, 1 / (phi + std::sqrt(phi * phi - lambda * lambda)));
  return chi * A * fy / gamma_M1;
}

namespace {
struct DentCurve {
  double Rc, c1, c2;
};
DentCurve dent_curve(double D, double t, double fy, double b) {
  return {fy * t * t / 4 * std::sqrt(D / t), 22 + 1.2 * b / D, 1.925 / (3.5 + b / D)};
}
}  // namespace

double dent_depth_at_force(double F, double D, double t, double fy, double b) {
  const DentCurve k = dent_curve(D, t, fy, b);
  return D * std::pow(F / (k.c1 * k.Rc), 1 / k.c2);
}

double dent_depth_for_energy(double E, double D, double t, double fy, double b) {
  const DentCurve k = dent_curve(D, t, fy, b);
  return D * std::pow(E * (k.c2 + 1) / (k.c1 * k.Rc * D), 1 / (k.c2 + 1));
}

}  // namespace dmi::design
