#include "engine/structure/steel_law.hpp"

#include <algorithm>

namespace dmi {

namespace {

// A new branch from the reversal point (eps_r, sigma_r) towards the asymptote of direction d: its strain span to the
// intersection, s_e = (d f_y (1 - b) + b E eps_r - sigma_r) / (E (1 - b)).
double span_to_asymptote(const SteelLaw& law, double d, double eps_r, double sigma_r) {
  const double b = law.hardening, E = law.E;
  return (d * law.fy * (1 - b) + b * E * eps_r - sigma_r) / (E * (1 - b));
}

// The branch's R = R0 - a1 xi / (a2 + xi), xi the plastic excursion |eps_m - eps_0| / eps_y of the extreme strain it
// heads for.
void curvature(const SteelLaw& law, CurveState& h) {
  const double eps_m = h.direction > 0 ? h.eps_max : h.eps_min;
  const double xi = std::abs(eps_m - (h.eps_r + h.span)) / law.yield_strain();
  h.R = law.r0 - law.a1 * xi / (law.a2 + xi);
  h.linear_below = std::pow(1e-17, 1 / h.R), h.asymptote_above = std::pow(1e17, 1 / h.R);
}

}  // namespace

double menegotto_pinto_stress(const SteelLaw& law, const CurveState& c, double eps, double& tangent, CurveState& h) {
  h = c;
  const double ey = law.yield_strain(), deps = eps - h.eps;
  if (h.direction == 0) {  // virgin: the first branch from the origin towards the asymptote it heads for
    if (deps == 0) return tangent = law.E, h.sigma;
    h.direction = deps > 0 ? 1 : -1;
    h.eps_max = ey, h.eps_min = -ey;
    h.eps_r = h.sigma_r = 0;
    h.span = h.direction * ey;
    curvature(law, h);
  } else if (deps * h.direction < 0) {  // a reversal at the committed point: a new branch
    const double span = span_to_asymptote(law, -h.direction, h.eps, h.sigma);
    // A point already on the asymptote it would head for (a reversal of a reversal by round-off) stays on its branch.
    if (-h.direction * span > 1e-9 * ey) {
      h.eps_r = h.eps, h.sigma_r = h.sigma;
      if (h.direction > 0) h.eps_max = std::max(h.eps_max, h.eps);
      else h.eps_min = std::min(h.eps_min, h.eps);
      h.direction = -h.direction;
      h.span = span;
      curvature(law, h);
    }
  }
  const double R = h.R, b = law.hardening;
  const double es = (eps - h.eps_r) / h.span, a = std::abs(es), scale_s = law.E * h.span;
  // g = (1 + a^R)^(1/R) and t = (1 + a^R)^-(1 + 1/R), past the knee through q = a^-R (a^R overflows for a sharp knee).
  double g = 1, t = 1;
  if (a < h.linear_below) {
    // on the elastic line: g = 1, t = 1 to machine precision
  } else if (a > h.asymptote_above) {
    g = a, t = 0;  // on the asymptote
  } else if (a <= 1) {
    const double d1 = 1 + std::pow(a, R);
    g = std::pow(d1, 1 / R), t = 1 / (d1 * g);
  } else {
    const double q = std::pow(a, -R), u = std::pow(1 + q, 1 / R);
    g = a * u, t = q / a / ((1 + q) * u);
  }
  const double sigma = h.sigma_r + scale_s * (b * es + (1 - b) * es / g);
  tangent = law.E * (b + (1 - b) * t);
  h.eps = eps, h.sigma = sigma;
  return sigma;
}

}  // namespace dmi
