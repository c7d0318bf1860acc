// Uniaxial steel law of a fibre: bilinear elasto-plastic with linear kinematic hardening (Simo & Hughes 1998,
// Computational Inelasticity, sec. 1.3, Box 1.5 with the kinematic hardening of sec. 1.3.2):
//   sigma = E (eps - eps_p), yield function f = |sigma - alpha| - f_y, back stress alpha = H eps_p,
//   H = b E / (1 - b) for a post-yield modulus b E (b the hardening ratio, 0 <= b < 1; b = 0 is perfectly plastic).
// Return mapping (closed form): with the trial sigma_tr = E (eps - eps_p,n), xi = sigma_tr - alpha_n,
//   f_tr = |xi| - f_y > 0:  dgamma = f_tr / (E + H),  sigma = sigma_tr - E dgamma sign(xi),
//   eps_p = eps_p,n + dgamma sign(xi),  alpha = alpha_n + H dgamma sign(xi),  algorithmic tangent E H / (E + H) = b E.
// The cyclic response shows the Bauschinger effect: reversed yielding starts at a stress change of 2 f_y.
#pragma once
#include <cmath>

namespace dmi {

struct SteelLaw {
  double E = 0, fy = 0, hardening = 0;  // Pa, Pa, - (post-yield modulus over E)
  double H() const { return hardening * E / (1 - hardening); }
  double yield_strain() const { return fy / E; }
};

struct FibreHistory {
  double eps_p = 0, alpha = 0;  // plastic strain, back stress (Pa)
};

struct FibreResponse {
  double sigma = 0, tangent = 0;  // Pa, Pa
  FibreHistory history;           // the history at the end of the increment
};

inline FibreResponse steel_response(const SteelLaw& law, const FibreHistory& h, double eps) {
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

}  // namespace dmi
