// Timoshenko beam-columns in dynamics: the bending frequencies of a deep simply supported beam against the closed form
// of Timoshenko beam theory (shear deformation and rotary inertia), in the plane and space frames, where
// Euler-Bernoulli elements overestimate them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "engine/structure/space_frame.hpp"
#include "tests/engine/structure/beam_models.hpp"

namespace dmi {
namespace {

using test::Beam;
using test::rel;
using test::straight;
using test::support;

constexpr double kPi = std::numbers::pi;

// Simply supported Timoshenko beam, mode n (k = n pi / L): the lower root of
//   (rho I)(rho A) / (kappa G A) w^4 - [rho A + k^2 (rho I + E I rho A / (kappa G A))] w^2 + E I k^4 = 0
// (Timoshenko 1921; Han, Benaroya & Wei 1999).
double timoshenko_ss(const Beam& b, int n) {
  const double A = b.section.area(0), I = b.section.inertia(0), G = b.E / (2 * (1 + b.nu));
  const double kGA = b.section.shear_coefficient() * G * A, k = n * kPi / b.L;
  const double a = b.rho * I * b.rho * A / kGA, bb = b.rho * A + k * k * (b.rho * I + b.E * I * b.rho * A / kGA), c = b.E * I * k * k * k * k;
  return std::sqrt((bb - std::sqrt(bb * bb - 4 * a * c)) / (2 * a));
}

double euler_bernoulli_ss(const Beam& b, int n) {
  const double k = n * kPi / b.L;
  return k * k * std::sqrt(b.EI() / b.rhoA());
}

// The computed frequency nearest to w among the first `count`.
double nearest(const std::vector<double>& w, double target) {
  double best = w.front();
  for (double x : w)
    if (std::abs(x - target) < std::abs(best - target)) best = x;
  return best;
}

Beam deep_beam() {
  Beam b;  // 0.1 x 0.2 m steel rectangle
  b.L = 0.8;  // L / h = 4
  return b;
}

TEST(TimoshenkoDynamics, DeepBeamBendingFrequenciesMatchTimoshenkoTheory) {
  const Beam b = deep_beam();
  for (MassMatrix mass : {MassMatrix::consistent, MassMatrix::lumped}) {
    FrameModel m = straight(b, 32);
    m.mass = mass;
    support(m, 0, true, true, false);
    support(m, 32, false, true, false);
    m.theory = BeamTheory::timoshenko;
    const std::vector<double> wt = Frame(m).natural_frequencies(12);
    m.theory = BeamTheory::euler_bernoulli;
    const std::vector<double> we = Frame(m).natural_frequencies(12);
    for (int n : {1, 2}) {
      const double exact = timoshenko_ss(b, n), t = nearest(wt, exact), e = nearest(we, euler_bernoulli_ss(b, n));
      std::printf("L/h 4, mode %d (%s): Timoshenko theory %.1f Hz, elements %.1f Hz (%+.2f %%); Euler-Bernoulli elements %.1f Hz (%+.1f %%)\n",
                  n, mass == MassMatrix::consistent ? "consistent" : "lumped", exact / (2 * kPi), t / (2 * kPi), 100 * (t / exact - 1),
                  e / (2 * kPi), 100 * (e / exact - 1));
      EXPECT_LT(rel(t, exact), 0.005) << "mode " << n;
      EXPECT_GT(e / exact - 1, 0.05) << "mode " << n;  // Euler-Bernoulli is stiffer
    }
  }
}

TEST(TimoshenkoDynamics, SpaceFrameBendsAboutBothAxesAsTimoshenkoTheory) {
  const Beam b = deep_beam();
  SpaceFrameModel m;
  const int n = 32;
  for (int k = 0; k <= n; ++k) m.nodes.push_back(Vec3(b.L * k / n, 0, 0));
  for (int k = 0; k < n; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = b.section, e.E = b.E, e.nu = b.nu, e.rho = b.rho;
    m.elements.push_back(e);
  }
  m.members.push_back({"beam", 0, n});
  m.mass = MassMatrix::consistent;
  m.theory = BeamTheory::timoshenko;
  SpaceSupportDef left = SpaceSupportDef::pinned(0), right = SpaceSupportDef::pinned(n);
  left.fixed[3] = true;  // no twist
  right.fixed[0] = false;
  m.supports = {left, right};
  const std::vector<double> w = SpaceFrame(m).natural_frequencies(12);
  Beam weak = b;
  weak.section = Section::rectangle(0.2, 0.1);  // bending about the other axis: depth 0.1 m
  for (const Beam& bb : {b, weak}) {
    const double exact = timoshenko_ss(bb, 1), t = nearest(w, exact);
    std::printf("space frame, depth %.1f m: Timoshenko theory %.1f Hz, elements %.1f Hz (%+.2f %%)\n", bb.section.depth(0),
                exact / (2 * kPi), t / (2 * kPi), 100 * (t / exact - 1));
    EXPECT_LT(rel(t, exact), 0.005);
  }
}

}  // namespace
}  // namespace dmi
