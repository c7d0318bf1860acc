// Shape functions as compile-time strategies. Each gives, per axis, the first node index of the
// stencil and K one-dimensional weights w and derivatives dw/d(x/h) for a particle at grid
// coordinate xr = (x - origin)/h. The D-dimensional N_i and grad N_i are tensor products.
//   linear:   S(r) = 1 - |r|                                  (Sulsky et al. 1994)
//   GIMP:     uGIMP with particle half-length lp (grid units) (Bardenhagen & Kober 2004)
//   bspline2: quadratic B-spline, S = 3/4 - r^2 (|r|<1/2), (3/2 - |r|)^2/2 (1/2<=|r|<3/2)
#pragma once
#include <cmath>
#include <limits>
#include <type_traits>
#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

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

constexpr int ipow(int k, int n) { return n == 0 ? 1 : k * ipow(k, n - 1); }

// Stencil of one particle in separable form: its K^D nodes walked as R = K^(D-1) rows along x, the fastest axis of the
// node ids, so a row's K nodes are adjacent in memory. Row r holds the nodes base + (a, b_1(r), ..., b_{D-1}(r)),
// a = 0..K-1, with b_d(r) the d-th base-K digit of r (axis 1 fastest). The D-dimensional functions are products:
//   N = w_0(a) W_r,  grad N = (dw_0(a)/h W_r, w_0(a) dW_r[0], ..., w_0(a) dW_r[D-2]),
//   W_r = prod_{d>0} w_d(b_d),  dW_r[d-1] = dw_d(b_d)/h prod_{e>0, e!=d} w_e(b_e).
template <int D, class Shape> struct Stencil {
  static constexpr int K = Shape::K, R = ipow(K, D - 1), NN = K * R;
  // Offset of row r from the base node along axis d (1 <= d < D).
  static constexpr int digit(int r, int d) { return r / ipow(K, d - 1) % K; }

  int base[D];
  double xr[D];              // the particle in grid coordinates, (x - origin) / h
  double w[D][K], dw[D][K];  // 1D weights and slopes per cell along each axis
  double dwx[K];             // dw[0] / h (1/m)
  double W[R], dW[D - 1][R];

  // x, half: the particle's position and half-size (m); ih = 1/h.
  [[gnu::always_inline]] inline void compute(const Vec<D>& x, const Vec<D>& half, const Vec<D>& origin, double ih) {
#if defined(__AVX2__) && defined(__FMA__)
    if constexpr (D == 2 && std::is_same_v<Shape, BSpline2Shape>) {
      eval_bspline2_2d(x, origin, ih);  // both axes at once, the same formulas as BSpline2Shape::eval
    } else
#endif
    {
      for (int d = 0; d < D; ++d) {
        xr[d] = (x[d] - origin[d]) * ih;
        Shape::eval(xr[d], half[d] * ih, base[d], w[d], dw[d]);
      }
    }
    for (int a = 0; a < K; ++a) dwx[a] = dw[0][a] * ih;
    for (int r = 0; r < R; ++r) {
      W[r] = 1;
      for (int d = 1; d < D; ++d) W[r] *= w[d][digit(r, d)];
      for (int d = 1; d < D; ++d) {
        double s = dw[d][digit(r, d)] * ih;
        for (int e = 1; e < D; ++e)
          if (e != d) s *= w[e][digit(r, e)];
        dW[d - 1][r] = s;
      }
    }
  }
#if defined(__AVX2__) && defined(__FMA__)
  // BSpline2Shape::eval along x and y in the two lanes of one vector (the transfers are bound by instruction count:
  // perf put the scalar weights of both axes among the hottest lines of P2G and G2P).
  [[gnu::always_inline]] inline void eval_bspline2_2d(const Vec<D>& x, const Vec<D>& origin, double ih) {
    const __m128d XR = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(x.data()), _mm_loadu_pd(origin.data())), _mm_set1_pd(ih));
    const __m128d B = _mm_floor_pd(_mm_sub_pd(XR, _mm_set1_pd(0.5)));
    const __m128d f = _mm_sub_pd(XR, B);  // in [0.5, 1.5)
    const __m128d a = _mm_sub_pd(_mm_set1_pd(1.5), f), b = _mm_sub_pd(f, _mm_set1_pd(1.0)), c = _mm_sub_pd(f, _mm_set1_pd(0.5));
    const __m128d half = _mm_set1_pd(0.5);
    const __m128d w0 = _mm_mul_pd(half, _mm_mul_pd(a, a)), w1 = _mm_fnmadd_pd(b, b, _mm_set1_pd(0.75)), w2 = _mm_mul_pd(half, _mm_mul_pd(c, c));
    const __m128d d0 = _mm_sub_pd(f, _mm_set1_pd(1.5)), d1 = _mm_mul_pd(_mm_set1_pd(-2.0), b);
    _mm_storeu_pd(xr, XR);
    const __m128i bi = _mm_cvttpd_epi32(B);
    base[0] = _mm_cvtsi128_si32(bi), base[1] = _mm_extract_epi32(bi, 1);
    _mm_storel_pd(&w[0][0], w0), _mm_storeh_pd(&w[1][0], w0);
    _mm_storel_pd(&w[0][1], w1), _mm_storeh_pd(&w[1][1], w1);
    _mm_storel_pd(&w[0][2], w2), _mm_storeh_pd(&w[1][2], w2);
    _mm_storel_pd(&dw[0][0], d0), _mm_storeh_pd(&dw[1][0], d0);
    _mm_storel_pd(&dw[0][1], d1), _mm_storeh_pd(&dw[1][1], d1);
    _mm_storel_pd(&dw[0][2], c), _mm_storeh_pd(&dw[1][2], c);
  }
#endif
  double N(int r, int a) const { return w[0][a] * W[r]; }
  Vec<D> grad(int r, int a) const {
    Vec<D> g;
    g[0] = dwx[a] * W[r];
    for (int d = 1; d < D; ++d) g[d] = w[0][a] * dW[d - 1][r];
    return g;
  }
  // H = sum_i grad N_i grad N_i^T / N_i over the stencil (1/m^2), from the 1D factors: with A_d = sum_a w_d(a),
  // B_d = sum_a w_d'(a) and C_d = sum_a w_d'(a)^2 / w_d(a), H_dd = C_d prod_(e != d) A_e and H_de = B_d B_e prod_(f != d, e)
  // A_f (a node whose weight vanishes with its slope adds nothing; one whose slope does not makes H infinite).
  Mat<D> inverse_weighted_slopes(double ih) const {
    double A[D], B[D], C[D];
    for (int d = 0; d < D; ++d) {
      A[d] = B[d] = C[d] = 0;
      for (int a = 0; a < K; ++a) {
        const double s = dw[d][a] * ih;
        A[d] += w[d][a], B[d] += s;
        if (s != 0) C[d] += w[d][a] > 0 ? s * s / w[d][a] : std::numeric_limits<double>::infinity();
      }
    }
    Mat<D> H;
    for (int d = 0; d < D; ++d)
      for (int e = 0; e < D; ++e) {
        double v = d == e ? C[d] : B[d] * B[e];
        for (int f = 0; f < D; ++f)
          if (f != d && f != e) v *= A[f];
        H(d, e) = v;
      }
    return H;
  }
  IVec<D> node(int r, int a) const {
    IVec<D> ijk;
    ijk[0] = base[0] + a;
    for (int d = 1; d < D; ++d) ijk[d] = base[d] + digit(r, d);
    return ijk;
  }
};

}  // namespace dmi
