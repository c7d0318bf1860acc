// Grid convergence index (Roache 1994; Celik et al. 2008): manufactured solutions f(h) = f0 + C h^p recover p and f0 exactly, with unequal ratios;
// the index equals Roache's formula; oscillating and diverging sequences are flagged, never passed as converged.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/convergence/grid_convergence.hpp"

using namespace dmi;

namespace {
std::array<double, 3> manufactured(const std::array<double, 3>& h, double f0, double C, double p) {
  return {f0 + C * std::pow(h[0], p), f0 + C * std::pow(h[1], p), f0 + C * std::pow(h[2], p)};
}
}  // namespace

TEST(GridConvergence, ManufacturedSolutionGivesOrderAndLimitWithUnequalRatios) {
  for (double p : {0.8, 1.0, 1.5, 2.0}) {
    const std::array<double, 3> h{0.01, 0.015, 0.0195};  // ratios 1.5 and 1.3
    const GridConvergence c = grid_convergence(h, manufactured(h, 500.0, -4000.0, p));
    EXPECT_EQ(c.behaviour, GridBehaviour::monotone) << p;
    EXPECT_NEAR(c.order, p, 1e-8) << p;
    EXPECT_NEAR(c.extrapolated, 500.0, 1e-8) << p;
    // Roache: GCI_fine = 1.25 |(f2 - f1) / f1| / (r21^p - 1); and in the asymptotic range the two indices agree.
    const auto f = manufactured(h, 500.0, -4000.0, p);
    EXPECT_NEAR(c.gci, 1.25 * std::abs((f[1] - f[0]) / f[0]) / (std::pow(1.5, p) - 1), 1e-12);
    EXPECT_NEAR(c.asymptotic_ratio, f[0] / f[1], 1e-9) << p;  // GCI_32 / (r^p GCI_21) = f1 / f2 exactly here
  }
}

// An order above the method's (kFormalOrder = 2) is not trusted: the study is outside the asymptotic range (beyond
// 1.1 p_f), and the index and the extrapolation take p_f with Fs = 3 (Oberkampf & Roy 2010); within the band, p_f
// with Fs = 1.25. The order reported is still the observed one.
TEST(GridConvergence, AnOrderAboveTheMethodsIsTakenAsTheMethods) {
  const std::array<double, 3> h{0.01, 0.015, 0.0195};
  const auto f = manufactured(h, 500.0, -4000.0, 3.0);
  const GridConvergence c = grid_convergence(h, f);
  EXPECT_EQ(c.behaviour, GridBehaviour::out_of_range);
  EXPECT_NEAR(c.order, 3.0, 1e-8);
  EXPECT_EQ(c.safety_factor, 3.0);
  const double r2 = 1.5 * 1.5;
  EXPECT_NEAR(c.gci, 3.0 * std::abs((f[1] - f[0]) / f[0]) / (r2 - 1), 1e-12);
  EXPECT_NEAR(c.extrapolated, (r2 * f[0] - f[1]) / (r2 - 1), 1e-9);
  EXPECT_NE(describe(c).find("faster than the method's order 2"), std::string::npos);
  const auto g = manufactured(h, 500.0, -4000.0, 2.1);  // within 10 % of 2: monotone, indexed with order 2
  const GridConvergence d = grid_convergence(h, g);
  EXPECT_EQ(d.behaviour, GridBehaviour::monotone);
  EXPECT_NEAR(d.order, 2.1, 1e-8);
  EXPECT_EQ(d.safety_factor, 1.25);
  EXPECT_NEAR(d.gci, 1.25 * std::abs((g[1] - g[0]) / g[0]) / (r2 - 1), 1e-12);
}

// The main job's buffered base shear at commit 0148f7d (cfl 0.125) on the demo's grids, 0.02 / 0.0283 / 0.04 m:
// 433.7 / 417.1 / 367.6 kN (observed order 3.15), against the limit of the same build's finer study, 0.02 / 0.0141 /
// 0.01 m at order 2.0: 454.9 kN (docs/verification.md, "The buffered demo dam converges under refinement"). The index
// must cover the fine value's distance to it (4.9 %); taken at the observed order it read 2.4 %.
TEST(GridConvergence, TheDemosBaseShearIndexCoversTheFinerStudysLimit) {
  const GridConvergence c = grid_convergence({0.02, 0.02 * std::sqrt(2.0), 0.04}, {433.7, 417.1, 367.6});
  EXPECT_GT(c.order, 3.0);
  EXPECT_GE(c.gci, (454.9 - 433.7) / 433.7);
}

TEST(GridConvergence, TheIndexBoundsTheTrueErrorOfTheFineValue) {
  const std::array<double, 3> h{0.02, 0.02 * std::sqrt(2.0), 0.04};
  const auto f = manufactured(h, 1.0, 3.0, 1.0);
  const GridConvergence c = grid_convergence(h, f);
  EXPECT_GT(c.gci, std::abs(f[0] - 1.0) / f[0]);       // Fs = 1.25 > 1: the index exceeds the exact error
  EXPECT_LT(c.gci, 1.3 * std::abs(f[0] - 1.0) / f[0]);
}

TEST(GridConvergence, OscillationIsFlaggedAndBoundedByTheSpread) {
  const GridConvergence c = grid_convergence({0.01, 0.02, 0.04}, {100.0, 130.0, 90.0});
  EXPECT_EQ(c.behaviour, GridBehaviour::oscillatory);
  EXPECT_TRUE(std::isnan(c.order));
  EXPECT_NEAR(c.gci, 1.25 * 30.0 / 100.0, 1e-12);
  EXPECT_NE(describe(c).find("NOT CONVERGED"), std::string::npos);
}

TEST(GridConvergence, GrowingChangesAreDivergingNotConverged) {
  // f ~ h^-0.8 (a peak that grows as the cell shrinks): the fine change exceeds the coarse one.
  const std::array<double, 3> h{0.01, 0.02, 0.04};
  const GridConvergence c = grid_convergence(h, {std::pow(0.01, -0.8), std::pow(0.02, -0.8), std::pow(0.04, -0.8)});
  EXPECT_EQ(c.behaviour, GridBehaviour::diverging);
  EXPECT_EQ(c.safety_factor, 3.0);
  EXPECT_NE(describe(c).find("NOT CONVERGED"), std::string::npos);
}

TEST(GridConvergence, SlowOrderIsOutsideTheAsymptoticRange) {
  const std::array<double, 3> h{0.01, 0.02, 0.04};
  const GridConvergence c = grid_convergence(h, manufactured(h, 10.0, 1.0, 0.3));
  EXPECT_EQ(c.behaviour, GridBehaviour::out_of_range);
  EXPECT_NEAR(c.order, 0.3, 1e-8);
  EXPECT_EQ(c.safety_factor, 3.0);
}

TEST(GridConvergence, EqualValuesAreConvergedAndBadInputThrows) {
  const GridConvergence c = grid_convergence({1, 2, 3}, {5.0, 5.0, 5.0});
  EXPECT_EQ(c.behaviour, GridBehaviour::converged);
  EXPECT_EQ(c.gci, 0.0);
  EXPECT_THROW(grid_convergence({1, 1, 3}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(grid_convergence({1, 2, 3}, {1, NAN, 3}), std::invalid_argument);
}
