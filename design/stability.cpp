#include "design/stability.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dmi::design {

double sliding_resistance(const BaseJointLoads& l, double mu, double c, double area) {
  if (!(mu >= 0) || !(c >= 0) || !(area >= 0)) throw std::invalid_argument("sliding_resistance: friction, cohesion and area must be >= 0");
  return l.N > 0 ? mu * l.N + c * area : 0.0;
}

double sliding_factor(const BaseJointLoads& l, double mu, double c, double area) {
  const double resistance = sliding_resistance(l, mu, c, area);
  if (l.N <= 0) return 0.0;
  return l.H == 0 ? std::numeric_limits<double>::infinity() : resistance / std::abs(l.H);
}

double overturning_factor(const BaseJointLoads& l) {
  return l.Mo > 0 ? l.Mr / l.Mo : std::numeric_limits<double>::infinity();
}

ResultantLocation resultant_location(const BaseJointLoads& l, double B, double W) {
  if (!(B > 0) || !(W > 0)) throw std::invalid_argument("resultant_location: base length and width must be > 0");
  ResultantLocation r;
  if (!(l.N > 0)) {  // the joint carries no compression: the dam lifts off
    r.x_r = std::numeric_limits<double>::quiet_NaN();
    r.toe_pressure = std::numeric_limits<double>::infinity();
    return r;
  }
  r.x_r = (l.Mr - l.Mo) / l.N;
  r.eccentricity = 0.5 * B - r.x_r;
  r.within_base = r.x_r >= 0 && r.x_r <= B;
  if (std::abs(r.eccentricity) <= B / 6) {
    r.compressed_fraction = 1;
    r.toe_pressure = l.N / (B * W) * (1 + 6 * r.eccentricity / B);
    r.heel_pressure = l.N / (B * W) * (1 - 6 * r.eccentricity / B);
  } else if (r.eccentricity > 0) {  // towards the toe
    r.compressed_fraction = r.x_r > 0 ? std::min(1.0, 3 * r.x_r / B) : 0.0;
    r.toe_pressure = r.x_r > 0 ? 2 * l.N / (3 * r.x_r * W) : std::numeric_limits<double>::infinity();
  } else {  // towards the heel (a dam leaning upstream)
    const double xh = B - r.x_r;
    r.compressed_fraction = xh > 0 ? std::min(1.0, 3 * xh / B) : 0.0;
    r.heel_pressure = xh > 0 ? 2 * l.N / (3 * xh * W) : std::numeric_limits<double>::infinity();
  }
  return r;
}

double newmark_sliding_displacement(const std::vector<double>& t, const std::vector<double>& H, const std::vector<double>& R,
                                    double m, int substeps) {
  if (t.size() != H.size() || t.size() != R.size()) throw std::invalid_argument("newmark_sliding_displacement: t, H and R differ in length");
  if (!(m > 0) || substeps < 1) throw std::invalid_argument("newmark_sliding_displacement: mass must be > 0 and substeps >= 1");
  double v = 0, d = 0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double dt = (t[k] - t[k - 1]) / substeps;
    if (!(dt >= 0)) throw std::invalid_argument("newmark_sliding_displacement: times must increase");
    for (int s = 0; s < substeps; ++s) {
      // Net force at the sub-step's midpoint (midpoint rule: exact for a constant net force, second order otherwise).
      const double w = (s + 0.5) / substeps;
      const double net = (1 - w) * (H[k - 1] - R[k - 1]) + w * (H[k] - R[k]);
      if (v <= 0 && net <= 0) continue;  // at rest and held by friction
      const double a = net / m;
      if (a < 0 && v + a * dt <= 0) {  // stops inside the sub-step
        d += v * v / (2 * -a);
        v = 0;
        continue;
      }
      d += v * dt + 0.5 * a * dt * dt;
      v += a * dt;
    }
  }
  // Still sliding when the record ends: the impact is over, the loads of before the record act until it stops.
  const double after = H.front() - R.front();
  if (v > 0) {
    if (after >= 0) return std::numeric_limits<double>::infinity();
    d += v * v / (2 * -after / m);
  }
  return d;
}

double RigidSection::critical_angle_rad() const { return std::atan2(centroid_from_toe_m, centroid_height_m); }

// Polygon integrals (Green's theorem) of 1, x, y, x^2 and y^2 over the section, the vertices counter-clockwise, with x
// measured from the toe towards upstream (so the lever of the weight is positive).
RigidSection rigid_section(double heel_x, double toe_x, double crest_up_x, double crest_down_x, double H, double W, double rho) {
  if (!(toe_x > heel_x) || !(crest_down_x >= crest_up_x) || !(H > 0) || !(W > 0) || !(rho > 0))
    throw std::invalid_argument("rigid_section: needs toe > heel, a crest of positive thickness, H, W, rho > 0");
  const double xs[4] = {0.0, toe_x - heel_x, toe_x - crest_up_x, toe_x - crest_down_x};  // toe, heel, crest up, crest down
  const double ys[4] = {0.0, 0.0, H, H};
  double A = 0, Sx = 0, Sy = 0, Ixx = 0, Iyy = 0;  // Sx = int x, Ixx = int x^2
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double c = xs[i] * ys[j] - xs[j] * ys[i];
    A += c / 2;
    Sx += (xs[i] + xs[j]) * c / 6, Sy += (ys[i] + ys[j]) * c / 6;
    Ixx += (xs[i] * xs[i] + xs[i] * xs[j] + xs[j] * xs[j]) * c / 12;
    Iyy += (ys[i] * ys[i] + ys[i] * ys[j] + ys[j] * ys[j]) * c / 12;
  }
  RigidSection r;
  r.area_m2 = A;
  r.mass_kg = rho * W * A;
  r.weight_N = r.mass_kg * 9.81;
  r.base_m = toe_x - heel_x;
  r.centroid_from_toe_m = Sx / A, r.centroid_height_m = Sy / A;
  r.inertia_about_toe_kg_m2 = rho * W * (Ixx + Iyy);
  return r;
}

}  // namespace dmi::design
