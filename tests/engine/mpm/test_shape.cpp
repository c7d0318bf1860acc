// Shape functions in 2D and 3D (the separable stencil the transfers walk): partition of unity, linear completeness
// (sum N_i x_i = x_p) and gradient consistency (sum grad N_i = 0, sum grad N_i (x) x_i = I), and the derivative matches a finite difference;
// sum grad N_i grad N_i^T / N_i from the 1D factors equals the sum over the entries; each axis's weights are the 1D
// definition's.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/mpm/shape.hpp"

namespace dmi {
namespace {

template <int D, class Shape> void check_shape(double lp) {
  const double h = 0.37, inv_h = 1 / h;
  const Vec<D> origin = Vec<D>::Constant(-0.2);
  for (double a : {0.51, 0.73, 1.0, 1.26, 1.49, 2.5, 3.999}) {
    for (double b : {0.6, 1.5, 2.01}) {
      Vec<D> xr = Vec<D>::Constant(b + 1);
      xr[0] = a + 1;
      if constexpr (D == 3) xr[2] = 0.5 * (a + b) + 1;
      const Vec<D> x = origin + xr * h, half = Vec<D>::Constant(lp * h);
      Stencil<D, Shape> st;
      st.compute(x, half, origin, inv_h);
      // Each axis as the 1D definition gives it (the 2D B-spline stencil evaluates both axes in one vector).
      for (int d = 0; d < D; ++d) {
        int base;
        double w[Shape::K], dw[Shape::K];
        Shape::eval((x[d] - origin[d]) * inv_h, lp, base, w, dw);
        EXPECT_EQ(st.base[d], base);
        for (int k = 0; k < Shape::K; ++k) {
          EXPECT_NEAR(st.w[d][k], w[k], 1e-15);
          EXPECT_NEAR(st.dw[d][k], dw[k], 1e-14);
        }
      }
      double sum = 0;
      Vec<D> first = Vec<D>::Zero(), grad = Vec<D>::Zero();
      Mat<D> gx = Mat<D>::Zero();
      for (int r = 0; r < st.R; ++r)
        for (int k = 0; k < st.K; ++k) {
          const Vec<D> xi = origin + st.node(r, k).template cast<double>() * h;
          sum += st.N(r, k);
          first += st.N(r, k) * xi;
          grad += st.grad(r, k);
          gx += xi * st.grad(r, k).transpose();
        }
      EXPECT_NEAR(sum, 1.0, 1e-13);
      EXPECT_NEAR((first - x).norm(), 0.0, 1e-12);
      EXPECT_NEAR(grad.norm(), 0.0, 1e-12);
      EXPECT_NEAR((gx - Mat<D>::Identity()).norm(), 0.0, 1e-12);
      // sum grad N grad N^T / N (the implicit viscosity's rate bound) from the 1D factors equals the sum over the
      // entries; infinite in both where a node's weight vanishes but not its slope (linear hats on a node line).
      Mat<D> H = Mat<D>::Zero();
      bool finite = true;
      for (int r = 0; r < st.R; ++r)
        for (int k = 0; k < st.K; ++k)
          if (const Vec<D> g = st.grad(r, k); g.squaredNorm() > 0) {
            if (st.N(r, k) > 0) H += g * g.transpose() / st.N(r, k); else finite = false;
          }
      const Mat<D> Hs = st.inverse_weighted_slopes(inv_h);
      EXPECT_EQ(Hs.allFinite(), finite) << "a " << a << " b " << b;
      if (finite && Hs.allFinite()) EXPECT_LE((Hs - H).norm(), 1e-12 * H.norm()) << "a " << a << " b " << b;
      // Finite-difference check of grad N of each node along every axis (nodes fixed, particle moved).
      const double e = 1e-7;
      for (int d = 0; d < D; ++d) {
        Stencil<D, Shape> sp;
        sp.compute(x + e * h * Vec<D>::Unit(d), half, origin, inv_h);
        if (std::equal(sp.base, sp.base + D, st.base)) {
          for (int r = 0; r < st.R; ++r)
            for (int k = 0; k < st.K; ++k) EXPECT_NEAR((sp.N(r, k) - st.N(r, k)) / (e * h), st.grad(r, k)[d], 1e-5);
        }
      }
    }
  }
}

template <class Shape> void check_shape(double lp) {
  check_shape<2, Shape>(lp);
  check_shape<3, Shape>(lp);
}

TEST(Shape, LinearPartitionOfUnityAndConsistency) { check_shape<LinearShape>(0.25); }
TEST(Shape, BSpline2PartitionOfUnityAndConsistency) { check_shape<BSpline2Shape>(0.25); }
TEST(Shape, GimpPartitionOfUnityAndConsistency) {
  check_shape<GimpShape>(0.25);
  check_shape<GimpShape>(0.125);
  check_shape<GimpShape>(0.5);
}

TEST(Shape, BSpline2StencilAxesMatchTheDefinitionOnCellLinesAndBelowTheOrigin) {
  // Positions on cell lines and half-cell lines (exact in binary: h = 1/4) and left of the origin (negative bases): the
  // 2D stencil's weights (both axes in one vector with AVX2) are the 1D definition's, bit for bit.
  const double h = 0.25;
  for (double x : {-1.0, -0.375, -0.125, 0.0, 0.125, 0.25, 0.375, 1.0, 2.625, 2.9375})
    for (double y : {-0.5, 0.0625, 0.125, 1.75}) {
      Stencil<2, BSpline2Shape> st;
      st.compute(Vec<2>(x, y), Vec<2>::Zero(), Vec<2>::Zero(), 1 / h);
      const double xr[2] = {x / h, y / h};
      for (int d = 0; d < 2; ++d) {
        int base;
        double w[3], dw[3];
        BSpline2Shape::eval(xr[d], 0, base, w, dw);
        EXPECT_EQ(st.base[d], base) << x << " " << y;
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(st.w[d][k], w[k]) << x << " " << y;
          EXPECT_EQ(st.dw[d][k], dw[k]) << x << " " << y;
        }
      }
    }
}

TEST(Shape, GimpReducesToLinearAwayFromCellEdges) {
  // With |r| in [lp, 1 - lp] the uGIMP weight is the linear hat.
  double s, ds;
  GimpShape::weight(0.5, 0.25, s, ds);
  EXPECT_DOUBLE_EQ(s, 0.5);
  EXPECT_DOUBLE_EQ(ds, -1.0);
}

}  // namespace
}  // namespace dmi
