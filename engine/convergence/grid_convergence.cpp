#include "engine/convergence/grid_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace dmi {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Observed order for unequal ratios and a monotone sequence (e32 / e21 > 0): the root of
//   e32 / e21 = r21^p (r32^p - 1) / (r21^p - 1)
// (Celik et al. 2008, eqs. 3-5, with the sign kept: p <= 0 means the change does not shrink with the cell). The
// right side increases with p, so bisection on [-20, 30] finds it.
double observed_order(double r21, double r32, double e21, double e32) {
  const double target = e32 / e21;
  auto g = [&](double p) {
    if (std::abs(p) < 1e-12) return std::log(r32) / std::log(r21);
    return std::pow(r21, p) * (std::pow(r32, p) - 1) / (std::pow(r21, p) - 1);
  };
  double lo = -20, hi = 30;
  if (target <= g(lo)) return lo;
  if (target >= g(hi)) return hi;
  for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

GridConvergence grid_convergence(const std::array<double, 3>& h, const std::array<double, 3>& f) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(h[i]) || !std::isfinite(f[i]) || !(h[i] > 0))
      throw std::invalid_argument("grid_convergence: non-finite value or cell size at grid " + std::to_string(i + 1));
  if (!(h[0] < h[1] && h[1] < h[2])) throw std::invalid_argument("grid_convergence: cell sizes must increase from fine to coarse");
  GridConvergence c;
  c.h = h, c.f = f;
  const double r21 = h[1] / h[0], r32 = h[2] / h[1];
  const double e21 = f[1] - f[0], e32 = f[2] - f[1];
  const double scale = std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2])});
  const double f1 = std::abs(f[0]) > 0 ? std::abs(f[0]) : scale;
  c.order = c.asymptotic_ratio = kNaN;
  c.extrapolated = f[0];
  if (scale == 0 || (std::abs(e21) <= 1e-9 * scale && std::abs(e32) <= 1e-9 * scale)) {
    c.behaviour = GridBehaviour::converged;
    c.gci = 0;
    return c;
  }
  if (e21 == 0 || e32 / e21 < 0) {  // oscillatory (or the fine pair equal): the largest change from the finest value bounds the error
    c.behaviour = GridBehaviour::oscillatory;
    c.gci = c.safety_factor * std::max(std::abs(e21), std::abs(f[2] - f[0])) / f1;
    return c;
  }
  const double p = observed_order(r21, r32, e21, e32);
  const bool diverging = !(p > 0);  // the change does not shrink as the cell does
  double p_used = p;
  if (diverging) {
    c.behaviour = GridBehaviour::diverging;
  } else if (p < 0.5 || p > 1.1 * kFormalOrder) {
    c.behaviour = GridBehaviour::out_of_range;
  } else {
    c.behaviour = GridBehaviour::monotone;
    p_used = std::min(p, kFormalOrder);
  }
  if (c.behaviour != GridBehaviour::monotone) {
    p_used = std::clamp(diverging ? 0.5 : p, 0.5, kFormalOrder);
    c.safety_factor = 3.0;
  }
  c.order = diverging ? kNaN : p;
  const double rp = std::pow(r21, p_used);
  c.extrapolated = diverging ? f[0] : (rp * f[0] - f[1]) / (rp - 1);
  c.gci = c.safety_factor * std::abs(e21) / f1 / (rp - 1);
  if (!diverging) {
    const double gci32 = c.safety_factor * std::abs(e32) / std::max(std::abs(f[1]), 1e-300) / (std::pow(r32, p_used) - 1);
    c.asymptotic_ratio = gci32 / (rp * c.gci);
  }
  return c;
}

const char* behaviour_name(GridBehaviour b) {
  switch (b) {
    case GridBehaviour::converged: return "converged";
    case GridBehaviour::monotone: return "monotone";
    case GridBehaviour::out_of_range: return "outside_asymptotic_range";
    case GridBehaviour::oscillatory: return "oscillatory";
    case GridBehaviour::diverging: return "diverging";
  }
  return "";
}

std::string describe(const GridConvergence& c) {
  char b[256];
  switch (c.behaviour) {
    case GridBehaviour::converged: return "the same on all three grids";
    case GridBehaviour::monotone:
      if (c.order > kFormalOrder)
        std::snprintf(b, sizeof b, "converging monotonically, observed order %.2f (index with the method's order %.0f)", c.order, kFormalOrder);
      else
        std::snprintf(b, sizeof b, "converging monotonically, observed order %.2f", c.order);
      return b;
    case GridBehaviour::out_of_range:
      if (c.order > kFormalOrder)
        std::snprintf(b, sizeof b, "converging faster than the method's order %.0f (observed %.2f): not yet asymptotic; index with Fs = 3 and order %.0f",
                      kFormalOrder, c.order, kFormalOrder);
      else
        std::snprintf(b, sizeof b, "converging but outside the asymptotic range (observed order %.2f); index with Fs = 3 and order %.1f",
                      c.order, std::clamp(c.order, 0.5, kFormalOrder));
      return b;
    case GridBehaviour::oscillatory:
      return "NOT CONVERGED: oscillates under refinement; the uncertainty is 1.25 times the largest difference from the finest grid's value";
    case GridBehaviour::diverging:
      return "NOT CONVERGED: the change grows as the cell shrinks; index with Fs = 3 and order 0.5, a rough bound only";
  }
  return "";
}

}  // namespace dmi
