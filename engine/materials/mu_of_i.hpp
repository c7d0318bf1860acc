// The friction law of the mu(I) rheology and its partial regularisation.
//   mu(I) = mu_s + (mu_2 - mu_s) I / (I0 + I)                                   (Jop, Forterre & Pouliquen 2006)
// With nu = I mu'(I) / mu(I), the incompressible equations are well posed where
//   C(I) = 4 nu^2 - 4 nu + mu^2 (1 - nu / 2)^2 < 0                    (Barker et al. 2015; Barker & Gray 2017, eq. 3.9)
// For Jop's law C -> mu_s^2 > 0 as I -> 0 and C > 0 again at large I: ill posed at both ends. Barker & Gray's partial
// regularisation replaces mu below I_N1, the root of C that ends the low ill-posed range, by
//   mu(I) = sqrt(alpha / ln(A / I)),  A = I_N1 exp(alpha / mu(I_N1)^2)                  (their eq. 6.4 with mu_inf = 0)
// which joins mu continuously at I_N1 and tends to 0 as I -> 0: below the static friction the material creeps at a rate
// that falls as exp(-alpha / mu^2) instead of standing rigid. The high-I range (I above the second root) is left as it
// is. alpha = 0 leaves Jop's law unregularised.
#pragma once
#include <cmath>

namespace dmi {

struct MuOfI {
  double mu_s = 0, mu_2 = 0, I0 = 0, alpha = 0;
  double I_N1 = 0, A = 0;  // set by regularise(); I_N1 = 0: unregularised

  double jop(double I) const { return mu_s + (mu_2 - mu_s) * I / (I0 + I); }
  double jop_slope(double I) const { return (mu_2 - mu_s) * I0 / ((I0 + I) * (I0 + I)); }
  // Barker & Gray's C(I) of Jop's law: well posed where negative.
  double C(double I) const {
    const double m = jop(I), nu = I * jop_slope(I) / m;
    return 4 * nu * nu - 4 * nu + m * m * (1 - nu / 2) * (1 - nu / 2);
  }
  // I_N1 by bisection between 1e-12 (ill posed, C > 0) and the I where mu reaches the tangent of the mean of the
  // two friction angles (well posed for physical constants, C < 0); without that sign change there is nothing to
  // regularise and Jop's law is kept.
  void regularise(double alpha_reg) {
    alpha = alpha_reg, I_N1 = 0, A = 0;
    if (!(alpha > 0)) return;
    const double tz = std::tan(0.5 * (std::atan(mu_s) + std::atan(mu_2)));
    double lo = 1e-12, hi = I0 * (tz - mu_s) / (mu_2 - tz);
    if (!(C(lo) > 0 && C(hi) < 0)) return;
    for (int k = 0; k < 200 && hi - lo > 1e-14 * hi; ++k) (C(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    I_N1 = 0.5 * (lo + hi);
    const double m = jop(I_N1);
    A = I_N1 * std::exp(alpha / (m * m));
  }
  double mu(double I) const {
    if (I_N1 == 0 || I >= I_N1) return jop(I);
    return I > 0 ? std::sqrt(alpha / std::log(A / I)) : 0.0;
  }
  // d mu / d I (for the Newton step; at I = 0 of the regularised branch, 0).
  double slope(double I) const {
    if (I_N1 == 0 || I >= I_N1) return jop_slope(I);
    return I > 0 ? 0.5 * std::sqrt(alpha) * std::pow(std::log(A / I), -1.5) / I : 0.0;
  }
};

}  // namespace dmi
