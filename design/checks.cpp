#include "design/checks.hpp"

#include <algorithm>
#include <array>
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

namespace {
struct Plate {
  double ratio, class1, class2, class3;  // c/t and its limits over eps
};
// The two plates that govern a box or I section's class (flanges in compression, webs in bending).
std::array<Plate, 2> flanged_plates(const Section& s) {
  const double b = s.width(0), h = s.depth(0), tf = s.wall_thickness(), tw = s.web_thickness();
  if (s.kind() == SectionKind::box) return {Plate{(b - 3 * tf) / tf, 33, 38, 42}, Plate{(h - 3 * tw) / tw, 72, 83, 124}};
  return {Plate{0.5 * (b - tw) / tf, 9, 10, 14}, Plate{(h - 2 * tf) / tw, 72, 83, 124}};
}
}  // namespace

double flanged_class_ratio(const Section& s, double fy_Pa, int cls) {
  const double eps = std::sqrt(235e6 / fy_Pa);
  double r = 0;
  for (const Plate& p : flanged_plates(s)) r = std::max(r, p.ratio / ((cls == 1 ? p.class1 : cls == 2 ? p.class2 : p.class3) * eps));
  return r;
}

int flanged_class(const Section& s, double fy_Pa) {
  const double eps = std::sqrt(235e6 / fy_Pa);
  int c = 1;
  for (const Plate& p : flanged_plates(s))
    c = std::max(c, p.ratio <= p.class1 * eps ? 1 : p.ratio <= p.class2 * eps ? 2 : p.ratio <= p.class3 * eps ? 3 : 4);
  return c;
}

double flanged_interaction(double N, double in_plane, double out_of_plane, const Section& s, double fy_Pa, double gamma_M0) {
  const double f = fy_Pa / gamma_M0;
  const bool plastic = flanged_class(s, fy_Pa) <= 2;
  const double Wz = plastic ? s.plastic_modulus(0) : s.inertia(0) / s.half_depth(0);
  const double Wy = plastic ? s.plastic_modulus_y(0) : s.inertia_y(0) / (0.5 * s.width(0));
  return std::abs(N) / (s.area(0) * f) + std::abs(in_plane) / (Wz * f) + std::abs(out_of_plane) / (Wy * f);
}

double flanged_shear_resistance(const Section& s, bool along_web, double fy_Pa, double gamma_M0) {
  const double b = s.width(0), h = s.depth(0), A = s.area(0);
  double Av = 0;
  if (s.kind() == SectionKind::box) Av = A * (along_web ? h : b) / (b + h);
  else Av = along_web ? (h - 2 * s.wall_thickness()) * s.web_thickness() : 2 * b * s.wall_thickness();
  return Av * fy_Pa / std::sqrt(3.0) / gamma_M0;
}

double flanged_torsion_resistance(const Section& s, double fy_Pa, double gamma_M0) {
  return s.torsion_modulus(0) * fy_Pa / std::sqrt(3.0) / gamma_M0;
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
