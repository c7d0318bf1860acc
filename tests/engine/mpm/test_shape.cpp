// Shape functions: partition of unity, linear completeness (sum N_i x_i = x_p) and gradient
// consistency (sum grad N_i = 0, sum grad N_i (x) x_i = I), and the derivative matches a finite difference.
#include <gtest/gtest.h>

#include "engine/mpm/shape.hpp"

namespace dmi {
namespace {

template <class Shape> void check_shape(double lp) {
  const double h = 0.37, inv_h = 1 / h;
  for (double a : {0.51, 0.73, 1.0, 1.26, 1.49, 2.5, 3.999}) {
    for (double b : {0.6, 1.5, 2.01}) {
      Stencil<2, Shape> st;
      const Vec<2> xr(a + 1, b + 1);
      st.compute(xr, Vec<2>::Constant(lp), inv_h);
      double sum = 0;
      Vec<2> first = Vec<2>::Zero(), grad = Vec<2>::Zero();
      Mat<2> gx = Mat<2>::Zero();
      for (int n = 0; n < st.NN; ++n) {
        const Vec<2> xi = (st.base + st.offset[n]).template cast<double>() * h;
        sum += st.N[n];
        first += st.N[n] * xi;
        grad += st.dN[n];
        gx += xi * st.dN[n].transpose();
      }
      EXPECT_NEAR(sum, 1.0, 1e-13);
      EXPECT_NEAR((first - xr * h).norm(), 0.0, 1e-12);
      EXPECT_NEAR(grad.norm(), 0.0, 1e-12);
      EXPECT_NEAR((gx - Mat<2>::Identity()).norm(), 0.0, 1e-12);
      // Finite-difference check of dN/dx of each node (nodes fixed, particle moved).
      const double e = 1e-7;
      Stencil<2, Shape> sp;
      sp.compute(xr + Vec<2>(e, 0), Vec<2>::Constant(lp), inv_h);
      if (sp.base == st.base) {
        for (int n = 0; n < st.NN; ++n) EXPECT_NEAR((sp.N[n] - st.N[n]) / (e * h), st.dN[n][0], 1e-5);
      }
    }
  }
}

TEST(Shape, LinearPartitionOfUnityAndConsistency) { check_shape<LinearShape>(0.25); }
TEST(Shape, BSpline2PartitionOfUnityAndConsistency) { check_shape<BSpline2Shape>(0.25); }
TEST(Shape, GimpPartitionOfUnityAndConsistency) {
  check_shape<GimpShape>(0.25);
  check_shape<GimpShape>(0.125);
  check_shape<GimpShape>(0.5);
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
