// Uniaxial steel law of a fibre, two curves (core/options.hpp SteelCurve).
//
// Bilinear with linear kinematic hardening (Simo & Hughes 1998, Computational Inelasticity, sec. 1.3, Box 1.5 with the
// kinematic hardening of sec. 1.3.2):
//   sigma = E (eps - eps_p), yield function f = |sigma - alpha| - f_y, back stress alpha = H eps_p,
//   H = b E / (1 - b) for a post-yield modulus b E (b the hardening ratio, 0 <= b < 1; b = 0 is perfectly plastic).
// Return mapping (closed form): with the trial sigma_tr = E (eps - eps_p,n), xi = sigma_tr - alpha_n,
//   f_tr = |xi| - f_y > 0:  dgamma = f_tr / (E + H),  sigma = sigma_tr - E dgamma sign(xi),
//   eps_p = eps_p,n + dgamma sign(xi),  alpha = alpha_n + H dgamma sign(xi),  algorithmic tangent E H / (E + H) = b E.
// Reversed yielding starts at a stress change of 2 f_y.
//
// Menegotto & Pinto (1973), with Filippou, Popov & Bertero (1983, eqs. 3-5): between the last reversal (eps_r,
// sigma_r) and the intersection (eps_0, sigma_0) of the elastic line from it with the hardening asymptote of the
// current direction,
//   sigma* = b eps* + (1 - b) eps* / (1 + |eps*|^R)^(1/R),   eps* = (eps - eps_r) / (eps_0 - eps_r),
//   sigma* = (sigma - sigma_r) / (sigma_0 - sigma_r),   R = R0 - a1 xi / (a2 + xi),
// xi = |eps_m - eps_0| / eps_y the plastic excursion of the previous branch (eps_m the largest strain reached in the
// direction the branch heads for). The asymptotes of tension and compression are sigma = +-f_y + b E (eps -+ eps_y);
// the first branch starts at the origin with (eps_0, sigma_0) = +-(eps_y, f_y). Its plastic strain is taken as
// eps - sigma / E (what unloading along E would leave), for the plastic work and the elastic energy. The elastic line
// and the asymptote of a branch meet at eps_0 = eps_r + s_e with s_e = (d f_y (1 - b) + b E eps_r - sigma_r) / (E (1 - b))
// and sigma_0 = sigma_r + E s_e: s_e is kept as such (eps_0 - eps_r would cancel to nothing far out on an asymptote).
#pragma once
#include <cmath>

#include "core/options.hpp"

namespace dmi {

struct SteelLaw {
  double E = 0, fy = 0, hardening = 0;  // Pa, Pa, - (post-yield modulus over E)
  SteelCurve curve = SteelCurve::bilinear;
  double r0 = 20, a1 = 18.5, a2 = 0.15;  // menegotto_pinto: R0, a1, a2 (Filippou, Popov & Bertero 1983)
  double H() const { return hardening * E / (1 - hardening); }
  double yield_strain() const { return fy / E; }
};

// The law with the element's modulus (a member's steel takes the E of its element).
inline SteelLaw with_modulus(SteelLaw law, double E) {
  law.E = E;
  return law;
}

struct FibreHistory {
  double eps_p = 0, alpha = 0;  // plastic strain, back stress (Pa; bilinear)
};

// A Menegotto-Pinto fibre's state: the committed strain and stress, the branch's reversal point, its strain span to
// the asymptote intersection, the largest strains reached each way, and the direction (0 virgin, +1 loading in
// tension, -1 in compression); the branch's curvature R and the normalised strains |eps*| below and above which its
// curve is the elastic line or the asymptote to machine precision (|eps*|^R below 1e-17 or above 1e17).
struct CurveState {
  double eps = 0, sigma = 0, eps_r = 0, sigma_r = 0, span = 0, eps_max = 0, eps_min = 0;
  double R = 0, linear_below = 0, asymptote_above = 0;
  int direction = 0;
};

struct FibreResponse {
  double sigma = 0, tangent = 0;  // Pa, Pa
  FibreHistory history;           // the history at the end of the increment
};

inline FibreResponse bilinear_response(const SteelLaw& law, const FibreHistory& h, double eps) {
  FibreResponse r{law.E * (eps - h.eps_p), law.E, h};
  const double xi = r.sigma - h.alpha, f = std::abs(xi) - law.fy;
  if (f <= 0) return r;
  const double H = law.H(), dgamma = f / (law.E + H), n = xi > 0 ? 1.0 : -1.0;
  r.sigma -= law.E * dgamma * n;
  r.history.eps_p += dgamma * n;
  r.history.alpha += H * dgamma * n;
  r.tangent = law.E * H / (law.E + H);
  return r;
}

// Menegotto-Pinto from the committed state c to strain eps (a reversal starts a new branch at the committed point):
// the stress, its tangent, and the state after it written whole into `next`.
double menegotto_pinto_stress(const SteelLaw& law, const CurveState& c, double eps, double& tangent, CurveState& next);

struct CurveResponse {
  double sigma = 0, tangent = 0;
  CurveState state;
};
inline CurveResponse menegotto_pinto_response(const SteelLaw& law, const CurveState& c, double eps) {
  CurveResponse r;
  r.sigma = menegotto_pinto_stress(law, c, eps, r.tangent, r.state);
  return r;
}

}  // namespace dmi
