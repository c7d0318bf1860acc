// Frame dynamics: natural frequencies against Euler-Bernoulli closed forms with their convergence orders,
// the explicit scheme's stability limit, Newmark's energy conservation and second order in dt, Rayleigh
// damping by logarithmic decrement, the corotational curl of a cantilever into a circle, and the power
// identity between add_point_load and velocity_at.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/engine/structure/beam_models.hpp"

namespace dmi {
namespace {

using test::Beam;
using test::rel;
using test::straight;
using test::support;

constexpr double kPi = std::numbers::pi;

struct Bc {
  const char* name;
  double beta_l;  // (beta L) of the first mode
  bool left[3], right[3];
};

TEST(FrameDynamics, NaturalFrequenciesConvergeAtTheExpectedOrder) {
  const Beam b;
  const Bc cases[] = {{"simply supported", kPi, {true, true, false}, {false, true, false}},
                      {"fixed-fixed", 4.730040744862704, {true, true, true}, {true, true, true}},
                      {"cantilever", 1.875104068711961, {true, true, true}, {false, false, false}}};
  for (MassMatrix mass : {MassMatrix::lumped, MassMatrix::consistent}) {
    for (const Bc& bc : cases) {
      const double exact = bc.beta_l * bc.beta_l * std::sqrt(b.EI() / (b.rhoA() * std::pow(b.L, 4)));
      std::vector<double> err;
      for (int n : {2, 4, 8, 16}) {
        FrameModel m = straight(b, n);
        m.mass = mass;
        support(m, 0, bc.left[0], bc.left[1], bc.left[2]);
        if (bc.right[1]) support(m, n, bc.right[0], bc.right[1], bc.right[2]);
        err.push_back(rel(Frame(m).natural_frequencies(1)[0], exact));
      }
      const double order = std::log2(err[2] / err[3]);
      std::printf("omega_1 %-16s %-10s errors n=2,4,8,16: %.3e %.3e %.3e %.3e  order(8->16) %.2f\n", bc.name,
                  mass == MassMatrix::lumped ? "lumped" : "consistent", err[0], err[1], err[2], err[3], order);
      for (int k = 0; k < 3; ++k) EXPECT_LT(err[k + 1], err[k]) << bc.name;
      if (mass == MassMatrix::consistent) EXPECT_NEAR(order, 4.0, 0.3) << bc.name;
      else EXPECT_NEAR(order, 2.0, 0.3) << bc.name;
    }
  }
}

// A cantilever released from its static tip-load deflection (zero velocity); a heavy tip mass makes the
// response nearly single-mode, so zero crossings measure the first period cleanly.
Frame released_cantilever(const Beam& b, int n, FrameIntegrator integ, MassMatrix mass = MassMatrix::lumped,
                          FrameTransform tr = FrameTransform::linear, double tip_mass = 0) {
  FrameModel m = straight(b, n);
  m.integrator = integ;
  m.mass = mass;
  m.transform = tr;
  support(m, 0, true, true, true);
  if (tip_mass > 0) m.masses.push_back({n, tip_mass, 0.0});
  Frame f(m);
  f.add_nodal_load(n, Vec3(0, -1e4, 0));
  f.solve_static();
  f.clear_loads();
  return f;
}

double tip_uy(const Frame& f) { return f.displacement()(3 * (f.nnodes() - 1) + 1); }

// Mean period from upward zero crossings of the tip deflection, and the largest relative energy change.
struct Vibration { double period = 0, drift = 0; };
Vibration free_vibration(Frame& f, double dt, int steps) {
  const double e0 = f.kinetic_energy() + f.strain_energy();
  std::vector<double> up;
  Vibration r;
  double prev = tip_uy(f);
  for (int k = 0; k < steps; ++k) {
    f.advance(dt);
    const double u = tip_uy(f);
    if (prev < 0 && u >= 0) up.push_back(f.time() - dt * u / (u - prev));
    prev = u;
    r.drift = std::max(r.drift, std::abs(f.kinetic_energy() + f.strain_energy() - e0) / e0);
  }
  r.period = (up.back() - up.front()) / (up.size() - 1);
  return r;
}

TEST(FrameDynamics, NewmarkFreeVibrationConservesEnergyAndPeriod) {
  const Beam b;
  Frame f = released_cantilever(b, 8, FrameIntegrator::newmark, MassMatrix::lumped, FrameTransform::linear,
                                10 * b.rhoA() * b.L);
  EXPECT_TRUE(std::isinf(f.stable_time_step()));
  const double T = 2 * kPi / f.natural_frequencies(1)[0];
  const double dt = T / 100, elongation = dt * kPi / std::atan(kPi / 100) / T - 1;  // T_h = 2 pi dt / (2 atan(w dt/2))
  const Vibration r = free_vibration(f, dt, 600);
  std::printf("Newmark dt = T1/100: period error %.2e (theory %.2e), energy drift %.2e\n", rel(r.period, T), elongation,
              r.drift);
  EXPECT_NEAR(r.period / T - 1, elongation, 0.1 * elongation);
  EXPECT_LT(r.drift, 1e-10);
  EXPECT_NEAR(f.external_work(), 0, 1e-14);
}

TEST(FrameDynamics, ExplicitStabilityLimitIsTwoOverOmegaMax) {
  for (MassMatrix mass : {MassMatrix::lumped, MassMatrix::consistent}) {
    const Beam b;
    const double tip = 10 * b.rhoA() * b.L;
    Frame probe = released_cantilever(b, 8, FrameIntegrator::explicit_euler, mass, FrameTransform::linear, tip);
    const double wmax = probe.natural_frequencies(3 * 8).back(), dt = probe.stable_time_step();
    EXPECT_NEAR(dt, 2 / wmax, 1e-12 * dt);
    const double T = 2 * kPi / probe.natural_frequencies(1)[0];
    Frame below = released_cantilever(b, 8, FrameIntegrator::explicit_euler, mass, FrameTransform::linear, tip);
    const Vibration r = free_vibration(below, 0.9 * dt, static_cast<int>(3 * T / (0.9 * dt)));
    std::printf("explicit %s 0.9 dt_stable: period error %.2e, max energy change %.2e\n",
                mass == MassMatrix::lumped ? "lumped" : "consistent", rel(r.period, T), r.drift);
    EXPECT_LT(rel(r.period, T), 1e-3);
    EXPECT_LT(r.drift, 0.01);
    Frame above = released_cantilever(b, 8, FrameIntegrator::explicit_euler, mass, FrameTransform::linear, tip);
    const double e0 = above.strain_energy();
    bool blew_up = false;
    try {
      for (int k = 0; k < 3000 && !blew_up; ++k) {
        above.advance(1.05 * dt);
        blew_up = above.kinetic_energy() + above.strain_energy() > 1e6 * e0;
      }
    } catch (const std::runtime_error&) {
      blew_up = true;  // non-finite state detected
    }
    EXPECT_TRUE(blew_up);
  }
}

// Above 600 free DOFs the explicit step comes from the element bound (Irons), not a dense eigen
// solve: it must be safe (not above 2/omega_max) and not needlessly small; a 5 000-element frame (15 003 DOFs, far
// beyond a dense eigen solve) gets a finite positive step from the same bound.
TEST(FrameDynamics, LargeFramesUseASafeElementBoundForTheStableStep) {
  for (MassMatrix mass : {MassMatrix::lumped, MassMatrix::consistent}) {
    const Beam b;
    Frame f = released_cantilever(b, 250, FrameIntegrator::explicit_euler, mass);
    const double exact = 2 / f.natural_frequencies(3 * 250).back(), dt = f.stable_time_step();
    EXPECT_LE(dt, exact * (1 + 1e-12));
    EXPECT_GT(dt, 0.5 * exact);
    std::printf("250 elements, %s: element-bound step / exact = %.3f\n", mass == MassMatrix::lumped ? "lumped" : "consistent",
                dt / exact);
  }
  const Frame big = released_cantilever(Beam{}, 5000, FrameIntegrator::explicit_euler);
  const double dt_big = big.stable_time_step(), dt_250 = released_cantilever(Beam{}, 250, FrameIntegrator::explicit_euler).stable_time_step();
  EXPECT_TRUE(std::isfinite(dt_big));
  // The element bound scales with the element length (Irons: dt ~ L_e / c for the axial mode, ~ L_e^2 for bending):
  // 20x shorter elements give a step between 20^-2 and 20^-1 of the 250-element one.
  EXPECT_LE(dt_big, dt_250 / 20 * (1 + 1e-9));
  EXPECT_GE(dt_big, dt_250 / 400 * (1 - 1e-9));
}

// Orders in dt on a single-DOF oscillator with an exact solution: one lumped-mass bar element, fixed at node 0,
// released from a static axial tip load; the tip moves as u0 cos(omega t), omega^2 = (EA/L) / (m/2).
double bar_error(FrameIntegrator integ, int steps, double t_over_T, double hht_alpha = 0.0) {
  const Beam b;
  FrameModel m = straight(b, 1);
  m.integrator = integ;
  m.hht_alpha = hht_alpha;
  support(m, 0, true, true, true);
  Frame f(m);
  f.add_nodal_load(1, Vec3(1e5, 0, 0));
  f.solve_static();
  f.clear_loads();
  const double u0 = f.displacement()(3), w = std::sqrt(2 * b.EA() / (b.rhoA() * b.L * b.L));
  const double t = t_over_T * 2 * kPi / w;
  for (int k = 0; k < steps; ++k) f.advance(t / steps);
  return std::abs(f.displacement()(3) - u0 * std::cos(w * t)) / u0;
}

TEST(FrameDynamics, NewmarkIsSecondOrderAndTheExplicitSchemeFirstOrder) {
  for (FrameIntegrator integ : {FrameIntegrator::newmark, FrameIntegrator::explicit_euler}) {
    const bool newmark = integ == FrameIntegrator::newmark;
    std::vector<double> err;
    for (int n : {40, 80, 160, 320}) err.push_back(bar_error(integ, n, 1.3));
    for (int k = 0; k + 1 < 4; ++k) {
      const double order = std::log2(err[k] / err[k + 1]);
      std::printf("%s bar error n=%d: %.3e, order %.2f\n", newmark ? "Newmark" : "explicit", 40 << k, err[k], order);
      // Eqs. (27)-(29) start the staggered velocity with v_0 instead of v_{1/2}: first order (see integrator.hpp).
      EXPECT_NEAR(order, newmark ? 2.0 : 1.0, 0.1);
    }
  }
}

// HHT-alpha (alpha = -0.1) keeps second order, and damps a mode resolved by far too few steps
// (omega dt = 10: spectral radius -> (1 + alpha)/(1 - alpha) = 0.82 per step), which average
// acceleration (alpha = 0) keeps at full amplitude.
TEST(FrameDynamics, HhtIsSecondOrderAndDampsUnresolvedModes) {
  std::vector<double> err;
  for (int n : {40, 80, 160}) err.push_back(bar_error(FrameIntegrator::newmark, n, 1.3, -0.1));
  for (int k = 0; k + 1 < 3; ++k) EXPECT_NEAR(std::log2(err[k] / err[k + 1]), 2.0, 0.15);
  const Beam b;
  const double w = std::sqrt(2 * b.EA() / (b.rhoA() * b.L * b.L)), T = 2 * kPi / w;
  const int steps = 60;
  const double t_over_T = steps * 10 / w / T;  // omega dt = 10
  const double exact = std::abs(std::cos(w * t_over_T * T));  // error = |u - u0 cos(w t)| / u0 = |cos| when u -> 0
  EXPECT_NEAR(bar_error(FrameIntegrator::newmark, steps, t_over_T, -0.1), exact, 1e-3);
  // alpha = 0: no decay (energy conserved), the computed motion keeps amplitude u0 with a wrong phase.
  EXPECT_GT(std::abs(bar_error(FrameIntegrator::newmark, steps, t_over_T, 0.0) - exact), 0.05);
}

TEST(FrameDynamics, RayleighDampingMatchesLogarithmicDecrement) {
  const Beam b;
  const double zeta = 0.02;
  for (bool stiffness : {false, true}) {
    FrameModel m = straight(b, 4);
    m.integrator = FrameIntegrator::newmark;
    support(m, 0, true, true, true);
    m.masses.push_back({4, 10 * b.rhoA() * b.L, 0.0});  // heavy tip: one dominant mode
    const double w1 = Frame(m).natural_frequencies(1)[0];
    (stiffness ? m.rayleigh_stiffness : m.rayleigh_mass) = stiffness ? 2 * zeta / w1 : 2 * zeta * w1;
    Frame f(m);
    f.add_nodal_load(4, Vec3(0, -1e4, 0));
    f.solve_static();
    f.clear_loads();
    const double e0 = f.strain_energy(), dt = 2 * kPi / w1 / 400;
    std::vector<double> peaks;
    double u0 = tip_uy(f), u1 = u0;
    for (int k = 0; k < 400 * 6; ++k) {
      f.advance(dt);
      const double u2 = tip_uy(f);
      if (u1 < u0 && u1 <= u2) peaks.push_back(u1 - 0.125 * (u2 - u0) * (u2 - u0) / (u2 - 2 * u1 + u0));  // minima
      u0 = u1;
      u1 = u2;
    }
    ASSERT_GE(peaks.size(), 5u);
    const double delta = std::log(peaks.front() / peaks.back()) / (peaks.size() - 1);
    const double measured = delta / std::sqrt(4 * kPi * kPi + delta * delta);
    std::printf("Rayleigh %s damping: zeta target %.4f, measured %.5f\n", stiffness ? "stiffness" : "mass", zeta,
                measured);
    EXPECT_LT(rel(measured, zeta), 0.01);
    // Newmark's discrete energy balance: kinetic + strain + dissipated = initial.
    EXPECT_LT(std::abs(f.kinetic_energy() + f.strain_energy() + f.damping_work() - e0), 1e-9 * e0);
  }
}

// The ringing step: the modes Rayleigh damping leaves underdamped, zeta(omega) = alpha / (2 omega) + beta omega / 2 < 1,
// lie below omega_u = 1 / (2 dt_ring), where zeta = 1; each natural frequency with zeta < 1 has omega dt_ring <= 1/2.
// Without stiffness-proportional damping no mode is overdamped: no such step; with very light damping the mesh's
// highest mode sets it.
TEST(FrameDynamics, RingingStepResolvesEveryUnderdampedMode) {
  const Beam b;
  FrameModel m = straight(b, 12);
  support(m, 0, true, true, true);
  const std::vector<double> w = Frame(m).natural_frequencies(3 * 12);
  EXPECT_TRUE(std::isinf(Frame(m).ringing_step()));
  m.rayleigh_mass = 2 * 0.05 * w[0];
  m.rayleigh_stiffness = 2 * 0.05 / w[4];  // 5 % at the fifth mode: the highest modes are overdamped
  const double dt = Frame(m).ringing_step(), wu = 0.5 / dt;
  auto zeta = [&](double om) { return m.rayleigh_mass / (2 * om) + m.rayleigh_stiffness * om / 2; };
  EXPECT_NEAR(zeta(wu), 1.0, 1e-12);
  int ringing = 0, overdamped = 0;
  for (double om : w) {
    if (zeta(om) < 1) {
      ++ringing;
      EXPECT_LE(om * dt, 0.5);
    } else {
      ++overdamped;
    }
  }
  EXPECT_GT(ringing, 4);
  EXPECT_GT(overdamped, 0);
  // Damping so light that every mode rings: the mesh's highest mode bounds it (1 / (2 omega_max)).
  m.rayleigh_mass = 0, m.rayleigh_stiffness = 1e-12;
  EXPECT_NEAR(Frame(m).ringing_step(), 0.5 / w.back(), 1e-9 * 0.5 / w.back());
}

TEST(FrameDynamics, CorotationalCantileverCurlsIntoACircle) {
  Beam b;
  b.L = 1;
  b.section = Section::rectangle(0.05, 0.05);
  const int n = 16;
  FrameModel m = straight(b, n);
  m.integrator = FrameIntegrator::newmark;
  m.transform = FrameTransform::corotational;
  support(m, 0, true, true, true);
  const double w1 = Frame(m).natural_frequencies(1)[0], T = 2 * kPi / w1;
  m.rayleigh_mass = 2 * w1;  // critical for the first mode: a quasi-static load path
  Frame f(m);
  const double Mfull = 2 * kPi * b.EI() / b.L, dt = T / 20;
  for (int k = 1; k <= 400; ++k) {
    const double ramp = k >= 200 ? 1.0 : 0.5 * (1 - std::cos(kPi * k / 200));
    f.clear_loads();
    f.add_nodal_load(n, Vec3(0, 0, ramp * Mfull));
    f.advance(dt);
  }
  // Each element bends uniformly and keeps its chord length L/n; 16 chords turned by 2 pi / 16 close a polygon.
  const double phi = 2 * kPi / n, R = b.L / n / (2 * std::sin(phi / 2));
  std::printf("corotational circle: tip at (%.2e, %.2e) m, tip rotation / 2 pi = %.6f, mid-node error %.2e m\n",
              f.node_position(n).x(), f.node_position(n).y(), f.displacement()(3 * n + 2) / (2 * kPi),
              (f.node_position(n / 2) - Vec2(0, 2 * R)).norm());
  EXPECT_LT(f.node_position(n).norm(), 1e-3 * b.L);
  EXPECT_NEAR(f.displacement()(3 * n + 2), 2 * kPi, 1e-3);
  EXPECT_LT((f.node_position(n / 2) - Vec2(0, 2 * R)).norm(), 1e-3 * b.L);
  EXPECT_NEAR(f.forces_at(5, 0.5).M, Mfull, 1e-3 * Mfull);
  EXPECT_NEAR(f.forces_at(5, 0.5).N, 0, 1e-3 * Mfull / b.L);
}

TEST(FrameDynamics, CorotationalMatchesLinearForSmallMotion) {
  const Beam b;
  Frame lin = released_cantilever(b, 4, FrameIntegrator::explicit_euler);
  Frame cor = released_cantilever(b, 4, FrameIntegrator::explicit_euler, MassMatrix::lumped,
                                  FrameTransform::corotational);
  const double amp = std::abs(tip_uy(lin)), dt = 0.5 * lin.stable_time_step();
  EXPECT_DOUBLE_EQ(cor.stable_time_step(), lin.stable_time_step());
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    lin.advance(dt);
    cor.advance(dt);
    worst = std::max(worst, std::abs(tip_uy(lin) - tip_uy(cor)));
  }
  EXPECT_LT(worst, 1e-3 * amp);
}

// d/dxi at x of the cubic through g(0), g(1/3), g(2/3), g(1) (exact when g is a cubic), by Lagrange.
template <class G> double cubic_slope(const G& g, double x) {
  const double p[4] = {0, 1.0 / 3, 2.0 / 3, 1};
  double slope = 0;
  for (int k = 0; k < 4; ++k) {
    double dl = 0, den = 1;
    for (int j = 0; j < 4; ++j) {
      if (j == k) continue;
      den *= p[k] - p[j];
      double prod = 1;
      for (int i = 0; i < 4; ++i)
        if (i != k && i != j) prod *= x - p[i];
      dl += prod;
    }
    slope += g(p[k]) * dl / den;
  }
  return slope;
}

TEST(FrameDynamics, PointLoadPowerEqualsNodalPower) {
  Beam b;
  FrameModel m = straight(b, 3, 0.6);
  support(m, 0, true, true, true);
  Frame f(m);
  f.add_nodal_load(3, Vec3(2e4, -3e4, 5e3));
  f.add_distributed_load(1, Vec2(1e3, -4e3));
  const double dt = 0.5 * f.stable_time_step();
  for (int k = 0; k < 37; ++k) f.advance(dt);  // a state with general nodal and angular velocities
  const Vec2 F(3e3, 7e3);
  const double moment = 2e3;
  for (double xi : {0.0, 0.37, 0.8, 1.0}) {
    f.clear_loads();
    f.add_point_load(1, xi, F, moment);
    const double w0 = f.external_work();
    f.advance(dt);  // explicit: work = f . (d_{n+1} - d_n) = dt f . v_{n+1}
    const ElementCurve c = f.curve(1);
    const double rate = cubic_slope([&](double s) { return f.velocity_at(1, s).dot(c.e2); }, xi) / c.L;
    const double power = F.dot(f.velocity_at(1, xi)) + moment * rate;
    EXPECT_NEAR((f.external_work() - w0) / dt, power, 1e-9 * std::abs(power)) << xi;
    EXPECT_NEAR(f.angular_velocity_at(1, xi), rate, 1e-9 * std::abs(rate) + 1e-12) << xi;  // the moment's dual
  }
}

// The mass attached at a point offset from the centre-line moves as that point: G^T v is the centre-line velocity plus
// the section's rotation times the arm, for any state, so q^T (G m G^T) q = m |v_point|^2 (the added kinetic energy).
TEST(FrameDynamics, AttachedMassMovesWithTheSectionPoint) {
  Beam b;
  FrameModel m = straight(b, 3, 0.6);
  support(m, 0, true, true, true);
  Frame f(m);
  f.add_nodal_load(3, Vec3(2e4, -3e4, 5e3));
  const double dt = 0.5 * f.stable_time_step();
  for (int k = 0; k < 37; ++k) f.advance(dt);  // general nodal and angular velocities
  const Vec2 arm(-0.04, 0.11);
  const int i = m.elements[1].i, j = m.elements[1].j;
  Eigen::Matrix<double, 6, 1> q;
  q << f.velocity().segment<3>(3 * i), f.velocity().segment<3>(3 * j);
  for (double xi : {0.0, 0.37, 1.0}) {
    Eigen::Matrix<double, 6, 2> G;
    for (int a = 0; a < 2; ++a) G.col(a) = f.point_load_vector(1, xi, Vec2::Unit(a), arm.x() * Vec2::Unit(a).y() - arm.y() * Vec2::Unit(a).x());
    const Vec2 point = f.velocity_at(1, xi) + f.angular_velocity_at(1, xi) * Vec2(-arm.y(), arm.x());
    const Vec2 dual = G.transpose() * q;
    EXPECT_NEAR((dual - point).norm(), 0.0, 1e-9 * point.norm()) << xi;
    EXPECT_GT(std::abs(f.angular_velocity_at(1, xi)) * arm.norm(), 1e-3 * point.norm()) << xi;  // the arm matters here
  }
}

}  // namespace
}  // namespace dmi
