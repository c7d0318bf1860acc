// Projection of grid nodes on deformed member centre-lines (engine/contact/projection.hpp):
// compared with a brute-force minimum over a dense sampling of the cubic.
#include <gtest/gtest.h>

#include <random>

#include "engine/contact/projection.hpp"
#include "engine/structure/frame.hpp"

namespace dmi {
namespace {

double brute_force(const ElementCurve& c, const Vec2& x, double& xi) {
  double best = 1e300;
  for (int k = 0; k <= 200000; ++k) {
    const double s = k / 200000.0, d = (c.point(s) - x).squaredNorm();
    if (d < best) { best = d; xi = s; }
  }
  return best;
}

ElementCurve curve(double t1, double t2, double w2 = 0) {
  ElementCurve c;
  c.o = Vec2(1.0, 2.0);
  c.e1 = Vec2(std::cos(0.3), std::sin(0.3));
  c.e2 = Vec2(-c.e1.y(), c.e1.x());
  c.L = 2.0;
  c.t1 = t1;
  c.t2 = t2;
  c.w2 = w2;
  return c;
}

TEST(Projection, StraightChordIsTheClosedForm) {
  const ElementCurve c = curve(0, 0);
  const Vec2 x = c.o + 0.7 * c.e1 + 0.4 * c.e2;
  const Projection p = project_on_curve(c, x);
  EXPECT_NEAR(p.xi, 0.35, 1e-12);
  EXPECT_NEAR(p.dist2, 0.16, 1e-12);
}

TEST(Projection, EndsAreClamped) {
  const ElementCurve c = curve(0.2, -0.1);
  EXPECT_DOUBLE_EQ(project_on_curve(c, c.o - 0.5 * c.e1).xi, 0.0);
  EXPECT_DOUBLE_EQ(project_on_curve(c, c.point(1) + 0.5 * c.e1).xi, 1.0);
}

// Strongly bent elements (end rotations up to 1.5 rad, as in a beam wrapping round a boulder) and
// random points up to one element length away: the safeguarded Newton search finds the global
// minimum of the sampled distance, in a handful of iterations.
TEST(Projection, MatchesBruteForceOnBentElements) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> rot(-1.5, 1.5), pos(-1.0, 3.0), off(-2.0, 2.0);
  int worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const ElementCurve c = curve(rot(rng), rot(rng), 0.3 * off(rng));
    const Vec2 x = c.o + pos(rng) * c.e1 + off(rng) * c.e2;
    double xi_bf;
    const double d_bf = brute_force(c, x, xi_bf);
    const Projection p = project_on_curve(c, x);
    EXPECT_LE(p.dist2, d_bf + 1e-9) << "trial " << trial << " xi " << p.xi << " vs " << xi_bf;
    worst = std::max(worst, p.iterations);
  }
  EXPECT_LE(worst, 12);
}

}  // namespace
}  // namespace dmi
