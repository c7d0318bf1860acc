#include "design/local_damage.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dmi::design {

namespace {
constexpr double kLb = 0.45359237;              // kg per lb (mass; W in the NDRC formula is the weight in lbf, numerically equal)
constexpr double kIn = 0.0254;                  // m per in
constexpr double kFt = 0.3048;                  // m per ft
constexpr double kPsi = 4.4482216152605 / (kIn * kIn);  // Pa per psi = 1 lbf / in^2 = 6894.757...

void require_positive(double v, const char* what) {
  if (!std::isfinite(v) || v <= 0) throw std::invalid_argument(std::string("local damage: ") + what + " must be finite and > 0");
}
void require_margin(double v, const char* what) {
  if (!std::isfinite(v) || v < 1) throw std::invalid_argument(std::string("design thickness: ") + what + " must be finite and >= 1");
}
// M V^2 / (d^3 f'c), the dimensionless energy ratio of Chang's formulae (any consistent units).
double chang_energy_ratio(double m, double d, double v, double fc) { return m * v * v / (d * d * d * fc); }
}  // namespace

double ndrc_G(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa, double nose_factor) {
  const double W = mass_kg / kLb, d = diameter_m / kIn, V = speed_m_s / kFt, fc = fc_Pa / kPsi;
  const double K = 180.0 / std::sqrt(fc);
  return K * nose_factor * (W / d) * std::pow(V / (1000.0 * d), 1.8);
}

double ndrc_x_over_d(double G) { return G <= 1.0 ? 2.0 * std::sqrt(G) : G + 1.0; }

double ndrc_scabbing_over_d(double xd) { return xd <= 0.65 ? 7.91 * xd - 5.06 * xd * xd : 2.12 + 1.36 * xd; }

double ndrc_perforation_over_d(double xd) { return xd <= 1.35 ? 3.19 * xd - 0.718 * xd * xd : 1.32 + 1.24 * xd; }

double degen_perforation_over_d(double xd) { return xd <= 1.52 ? 2.2 * xd - 0.3 * xd * xd : 0.69 + 1.29 * xd; }

double chang_perforation(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa) {
  const double r = chang_energy_ratio(mass_kg, diameter_m, speed_m_s, fc_Pa);
  return std::pow(kChangReferenceSpeed / speed_m_s, 0.25) * std::sqrt(r) * diameter_m;
}

double chang_scabbing(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa) {
  const double r = chang_energy_ratio(mass_kg, diameter_m, speed_m_s, fc_Pa);
  return 1.84 * std::pow(kChangReferenceSpeed / speed_m_s, 0.13) * std::pow(r, 0.4) * diameter_m;
}

LocalDamage local_damage(double mass_kg, double diameter_m, double speed_m_s, double fc_Pa, double nose_factor) {
  require_positive(mass_kg, "mass");
  require_positive(diameter_m, "diameter");
  require_positive(speed_m_s, "speed");
  require_positive(fc_Pa, "f'c");
  if (!std::isfinite(nose_factor) || nose_factor < kNoseFlat || nose_factor > kNoseVerySharp)
    throw std::invalid_argument("local damage: nose factor must be in [0.72, 1.14]");
  LocalDamage r;
  r.G = ndrc_G(mass_kg, diameter_m, speed_m_s, fc_Pa, nose_factor);
  r.x_over_d = ndrc_x_over_d(r.G);
  const double d = diameter_m, xd = r.x_over_d;
  r.penetration_m = xd * d;
  r.penetration_in_range = xd <= kNdrcPerforationMaxXd;
  r.scabbing_ndrc_m = ndrc_scabbing_over_d(xd) * d;
  r.scabbing_ndrc_in_range = xd <= kNdrcScabbingMaxXd;
  r.perforation_ndrc_m = ndrc_perforation_over_d(xd) * d;
  r.perforation_ndrc_in_range = xd <= kNdrcPerforationMaxXd;
  r.perforation_degen_m = degen_perforation_over_d(xd) * d;
  r.perforation_degen_in_range = degen_perforation_over_d(xd) <= kDegenMaxEd;
  const bool chang_speed_ok = speed_m_s >= kChangMinSpeed && speed_m_s <= kChangMaxSpeed;
  r.scabbing_chang_m = chang_scabbing(mass_kg, d, speed_m_s, fc_Pa);
  r.scabbing_chang_in_range = chang_speed_ok;
  r.perforation_chang_m = chang_perforation(mass_kg, d, speed_m_s, fc_Pa);
  r.perforation_chang_in_range = chang_speed_ok;
  return r;
}

DesignThickness design_thickness(const LocalDamage& d, double scabbing_margin, double perforation_margin) {
  require_margin(scabbing_margin, "scabbing margin");
  require_margin(perforation_margin, "perforation margin");
  DesignThickness t;
  // Scabbing: NDRC or Chang, the larger (ties go to NDRC, the first listed).
  const bool scab_chang = d.scabbing_chang_m > d.scabbing_ndrc_m;
  t.scabbing_raw_m = scab_chang ? d.scabbing_chang_m : d.scabbing_ndrc_m;
  t.scabbing_by = scab_chang ? "chang" : "ndrc";
  t.scabbing_in_range = scab_chang ? d.scabbing_chang_in_range : d.scabbing_ndrc_in_range;
  // Perforation: the largest of NDRC, Degen and Chang (ties: the first listed).
  t.perforation_raw_m = d.perforation_ndrc_m;
  t.perforation_by = "ndrc";
  t.perforation_in_range = d.perforation_ndrc_in_range;
  if (d.perforation_degen_m > t.perforation_raw_m) {
    t.perforation_raw_m = d.perforation_degen_m;
    t.perforation_by = "degen";
    t.perforation_in_range = d.perforation_degen_in_range;
  }
  if (d.perforation_chang_m > t.perforation_raw_m) {
    t.perforation_raw_m = d.perforation_chang_m;
    t.perforation_by = "chang";
    t.perforation_in_range = d.perforation_chang_in_range;
  }
  t.scabbing_margin = scabbing_margin;
  t.perforation_margin = perforation_margin;
  t.scabbing_design_m = scabbing_margin * t.scabbing_raw_m;
  t.perforation_design_m = perforation_margin * t.perforation_raw_m;
  return t;
}

}  // namespace dmi::design
