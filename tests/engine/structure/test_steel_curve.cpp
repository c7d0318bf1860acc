// Menegotto-Pinto steel (engine/structure/steel_law): the first branch and a reversal against the curve's equations
// worked by hand, the tangent against the stress's derivative, the Bauschinger effect and the dissipation of a
// cycle against the bilinear law, and the bilinear law as its sharp limit.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/structure/steel_law.hpp"

namespace dmi {
namespace {

constexpr double kE = 200e9, kFy = 355e6, kB = 0.01;

SteelLaw mp(double r0 = 20, double a1 = 18.5, double a2 = 0.15) {
  return SteelLaw{kE, kFy, kB, SteelCurve::menegotto_pinto, r0, a1, a2};
}

// One fibre of either law: its committed state, the stress at a strain, committed or not.
struct OneFibre {
  SteelLaw law;
  FibreHistory h;
  CurveState c;
  double stress(double eps, double* tangent = nullptr, bool commit = true) {
    double t = 0, sigma = 0;
    if (law.curve == SteelCurve::menegotto_pinto) {
      const CurveResponse r = menegotto_pinto_response(law, c, eps);
      sigma = r.sigma, t = r.tangent;
      if (commit) c = r.state;
    } else {
      const FibreResponse r = bilinear_response(law, h, eps);
      sigma = r.sigma, t = r.tangent;
      if (commit) h = r.history;
    }
    if (tangent) *tangent = t;
    return sigma;
  }
};

// Strain path through its points in steps of ey / 50; each step committed. Returns (eps, sigma) at every step.
struct Path {
  std::vector<double> eps, sigma;
};
Path walk(const SteelLaw& law, const std::vector<double>& points_in_ey) {
  Path p;
  OneFibre fibre{law, {}, {}};
  double e = 0;
  const double ey = law.yield_strain(), de = ey / 50;
  for (double target : points_in_ey) {
    const double t = target * ey, dir = t > e ? 1 : -1;
    while (dir * (t - e) > 1e-12 * ey) {
      e = dir > 0 ? std::min(e + de, t) : std::max(e - de, t);
      p.eps.push_back(e), p.sigma.push_back(fibre.stress(e));
    }
  }
  return p;
}

// The first branch from the origin: sigma* = b eps* + (1 - b) eps* / (1 + eps*^R0)^(1/R0), eps* = eps / ey,
// sigma* = sigma / fy. At eps = ey: b + (1 - b) 2^(-1/20) = 0.01 + 0.99 x 0.9659363 = 0.9662769.
TEST(SteelCurve, FirstBranchIsTheClosedFormFromTheOrigin) {
  const SteelLaw law = mp();
  const double ey = law.yield_strain();
  const auto first = [&](double eps) { return menegotto_pinto_response(law, CurveState{}, eps).sigma / kFy; };
  EXPECT_NEAR(first(ey), 0.9662769, 1e-7);
  for (double k : {0.25, 0.5, 0.9, 1.0, 1.5, 3.0, 10.0}) {
    const double es = k, expect = kB * es + (1 - kB) * es / std::pow(1 + std::pow(es, 20.0), 1 / 20.0);
    EXPECT_NEAR(first(k * ey), expect, 1e-12) << k;
    EXPECT_NEAR(first(-k * ey), -expect, 1e-12) << k;
  }
  // Far out it runs along the hardening asymptote f_y + b E (eps - ey): 1 + 0.01 x 9 at 10 ey.
  EXPECT_NEAR(first(10 * ey), 1.09, 1e-9);
}

// Loaded to 5 ey (sigma_r = f_y (1 + 0.04) on the asymptote) and reversed: the elastic line from there meets the
// compression asymptote -f_y + b E (eps + ey) at eps_0 = 3 ey, sigma_0 = -0.96 f_y; the excursion xi = |-ey - 3 ey| / ey
// = 4 gives R = 20 - 18.5 x 4 / 4.15 = 2.16867. At eps = 3 ey (a stress change the bilinear law would take
// elastically to -0.96 f_y): eps* = 1, sigma* = b + (1 - b) 2^(-1/R), sigma = 1.04 f_y - 2 f_y sigma*.
TEST(SteelCurve, AReversalYieldsGraduallyAsFilippouEtAlWrite) {
  const SteelLaw law = mp();
  const double ey = law.yield_strain();
  CurveState h;
  for (int k = 1; k <= 250; ++k) h = menegotto_pinto_response(law, h, k * 0.02 * ey).state;  // to 5 ey
  const double sr = h.sigma / kFy;
  EXPECT_NEAR(sr, 1.04, 1e-9);
  const CurveResponse start = menegotto_pinto_response(law, h, 5 * ey - 1e-9 * ey);
  EXPECT_NEAR(start.tangent / kE, 1.0, 1e-6);  // it unloads along E
  const double R = 20 - 18.5 * 4 / 4.15, ss = kB + (1 - kB) / std::pow(2.0, 1 / R);
  const CurveResponse at3 = menegotto_pinto_response(law, h, 3 * ey);
  EXPECT_NEAR(at3.sigma / kFy, sr - 2 * ss, 1e-9);
  EXPECT_NEAR((at3.state.eps_r + at3.state.span) / ey, 3.0, 1e-12);  // eps_0
  EXPECT_NEAR((at3.state.sigma_r + kE * at3.state.span) / kFy, -0.96, 1e-12);  // sigma_0
  EXPECT_NEAR(at3.state.R, R, 1e-12);
  // The Bauschinger effect: far less compression than the bilinear law's -0.96 f_y at the same strain.
  FibreHistory hb;
  const SteelLaw bl{kE, kFy, kB};
  for (int k = 1; k <= 250; ++k) hb = bilinear_response(bl, hb, k * 0.02 * ey).history;
  EXPECT_NEAR(bilinear_response(bl, hb, 3 * ey).sigma / kFy, -0.96, 1e-9);
  EXPECT_GT(at3.sigma / kFy, -0.5);
}

// The tangent is the derivative of the stress along a cyclic path (central differences of the same branch).
TEST(SteelCurve, TangentIsTheDerivative) {
  const SteelLaw law = mp();
  const double ey = law.yield_strain();
  CurveState h;
  for (double target : {4.0, -3.0, 2.0}) {
    const double t = target * ey;
    while (std::abs(h.eps - t) > 1e-9 * ey) {
      const double e = h.eps + std::copysign(std::min(0.1 * ey, std::abs(t - h.eps)), t - h.eps);
      const CurveResponse r = menegotto_pinto_response(law, h, e), lo = menegotto_pinto_response(law, h, e - 1e-6 * ey),
                          hi = menegotto_pinto_response(law, h, e + 1e-6 * ey);
      // Away from the branch's start (where the direction, and so the branch, changes with the sign of the step).
      if (std::abs(e - h.eps) > 2e-6 * ey) EXPECT_NEAR(r.tangent / ((hi.sigma - lo.sigma) / (2e-6 * ey)), 1.0, 1e-5) << e / ey;
      h = r.state;
    }
  }
}

// A cycle between +-5 ey dissipates: the loop encloses positive work, less than the bilinear law's sharp loop.
TEST(SteelCurve, ACycleDissipatesLessThanTheBilinearLoop) {
  const std::vector<double> cycle = {5, -5, 5};
  auto work = [&](const SteelLaw& law) {
    const Path p = walk(law, cycle);
    double w = 0;
    for (std::size_t k = 1; k < p.eps.size(); ++k) w += 0.5 * (p.sigma[k] + p.sigma[k - 1]) * (p.eps[k] - p.eps[k - 1]);
    return w;
  };
  const double ey = kFy / kE;
  const double w_mp = work(mp()), w_bl = work(SteelLaw{kE, kFy, kB});
  // From 5 ey to 5 ey through -5 ey (the first loading's work, up to 5 ey, is in both; its elastic part is recovered).
  EXPECT_GT(w_mp, 0);
  EXPECT_LT(w_mp, w_bl);
  EXPECT_GT(w_mp, 0.5 * w_bl);  // the loop rounds its corners, it does not collapse
  EXPECT_GT(w_bl, 10 * kFy * ey);
}

// With R held very large (a1 = 0), the curve is the bilinear kinematic law: the difference is largest at a knee,
// (1 - b)(1 - 2^(-1/R)) |sigma_0 - sigma_r| <= 0.99 x 3.5e-4 x 2.08 f_y = 7.2e-4 f_y for R = 2000.
TEST(SteelCurve, SharpLimitIsTheBilinearLaw) {
  const std::vector<double> cycle = {5, -5, 3};
  const Path a = walk(mp(2000, 0, 0.15), cycle), b = walk(SteelLaw{kE, kFy, kB}, cycle);
  ASSERT_EQ(a.sigma.size(), b.sigma.size());
  double worst = 0;
  for (std::size_t k = 0; k < a.sigma.size(); ++k) worst = std::max(worst, std::abs(a.sigma[k] - b.sigma[k]) / kFy);
  EXPECT_LT(worst, 1e-3);
}

// Far out on an asymptote, a step of a few ulps and back (a reversal of a reversal) keeps finite stresses and the
// asymptote's stress: the branch's span is computed from the point, not as the difference of two large strains.
TEST(SteelCurve, ReversalsByRoundOffStayFinite) {
  for (double b : {0.0, kB}) {
    const SteelLaw law{kE, kFy, b, SteelCurve::menegotto_pinto, 20, 18.5, 0.15};
    const double ey = law.yield_strain();
    CurveState h;
    for (int k = 1; k <= 500; ++k) h = menegotto_pinto_response(law, h, -k * 0.02 * ey).state;  // to -10 ey
    const double e = h.eps, asymptote = -kFy + b * kE * (e + ey);
    for (double ulps : {1.0, 3.0, 100.0}) {
      const double up = e + ulps * 4e-18;
      CurveState h1 = menegotto_pinto_response(law, h, up).state;
      const CurveResponse back = menegotto_pinto_response(law, h1, e);
      EXPECT_TRUE(std::isfinite(back.sigma) && std::isfinite(back.tangent)) << b << " " << ulps;
      EXPECT_NEAR(back.sigma / kFy, asymptote / kFy, 1e-6) << b << " " << ulps;
    }
  }
}

}  // namespace
}  // namespace dmi
