// Shape functions as compile-time strategies. Each gives, per axis, the first node index of the
// stencil and K one-dimensional weights w and derivatives dw/d(x/h) for a particle at grid
// coordinate xr = (x - origin)/h. The D-dimensional N_i and grad N_i are tensor products.
//   linear:   S(r) = 1 - |r|                                  (Sulsky et al. 1994)
//   GIMP:     uGIMP with particle half-length lp (grid units) (Bardenhagen & Kober 2004)
//   bspline2: quadratic B-spline, S = 3/4 - r^2 (|r|<1/2), (3/2 - |r|)^2/2 (1/2<=|r|<3/2)
#pragma once
#include <cmath>

#include "engine/common/types.hpp"

namespace dmi {

struct LinearShape {
  static constexpr int K = 2;
  [[gnu::always_inline]] static inline void eval(double xr, double /*lp*/, int& base, double* w, double* dw) {
    base = static_cast<int>(std::floor(xr));
    const double f = xr - base;
    w[0] = 1 - f;
    w[1] = f;
    dw[0] = -1;
    dw[1] = 1;
  }
};

struct BSpline2Shape {
  static constexpr int K = 3;
  [[gnu::always_inline]] static inline void eval(double xr, double /*lp*/, int& base, double* w, double* dw) {
    base = static_cast<int>(std::floor(xr - 0.5));
    const double f = xr - base;  // in [0.5, 1.5)
    w[0] = 0.5 * (1.5 - f) * (1.5 - f);
    w[1] = 0.75 - (f - 1) * (f - 1);
    w[2] = 0.5 * (f - 0.5) * (f - 0.5);
    dw[0] = f - 1.5;
    dw[1] = -2 * (f - 1);
    dw[2] = f - 0.5;
  }
};

struct GimpShape {
  static constexpr int K = 3;
  // 1D uGIMP weight S(r) and slope S'(r) for r = x_p - x_i (grid units), 0 < lp <= 1/2.
  [[gnu::always_inline]] static inline void weight(double r, double lp, double& s, double& ds) {
    const double a = std::abs(r), sg = r < 0 ? -1.0 : 1.0;
    if (a < lp) {
      s = 1 - (r * r + lp * lp) / (2 * lp);
      ds = -r / lp;
    } else if (a < 1 - lp) {
      s = 1 - a;
      ds = -sg;
    } else if (a < 1 + lp) {
      const double t = 1 + lp - a;
      s = t * t / (4 * lp);
      ds = -sg * t / (2 * lp);
    } else {
      s = 0;
      ds = 0;
    }
  }
  [[gnu::always_inline]] static inline void eval(double xr, double lp, int& base, double* w, double* dw) {
    base = static_cast<int>(std::floor(xr - 0.5));
    for (int k = 0; k < K; ++k) weight(xr - (base + k), lp, w[k], dw[k]);
  }
};

// Stencil of one particle: K^D nodes with N_i and grad N_i (1/m).
template <int D, class Shape> struct Stencil {
  static constexpr int K = Shape::K;
  static constexpr int NN = D == 2 ? K * K : K * K * K;
  IVec<D> base;
  double N[NN];
  Vec<D> dN[NN];
  IVec<D> offset[NN];

  // xr: grid coordinates of the particle; lp: half-size in grid units; inv_h = 1/h.
  void compute(const Vec<D>& xr, const Vec<D>& lp, double inv_h) {
    double w[D][K], dw[D][K];
    for (int d = 0; d < D; ++d) Shape::eval(xr[d], lp[d], base[d], w[d], dw[d]);
    int n = 0;
    if constexpr (D == 2) {
      for (int a = 0; a < K; ++a)
        for (int b = 0; b < K; ++b, ++n) {
          N[n] = w[0][a] * w[1][b];
          dN[n] = Vec<2>(dw[0][a] * w[1][b], w[0][a] * dw[1][b]) * inv_h;
          offset[n] = IVec<2>(a, b);
        }
    } else {
      for (int a = 0; a < K; ++a)
        for (int b = 0; b < K; ++b)
          for (int c = 0; c < K; ++c, ++n) {
            N[n] = w[0][a] * w[1][b] * w[2][c];
            dN[n] = Vec<3>(dw[0][a] * w[1][b] * w[2][c], w[0][a] * dw[1][b] * w[2][c], w[0][a] * w[1][b] * dw[2][c]) * inv_h;
            offset[n] = IVec<3>(a, b, c);
          }
    }
  }
};

}  // namespace dmi
