// Modal damping (ModalDamping): each mode of a cantilever keeps the one ratio it is given, measured by the logarithmic
// decrement of its modal coordinate under the Newmark integrator (whose Woodbury solve carries the low-rank damping),
// where Rayleigh damping fitted at the first two modes over-damps the higher ones; the modal damping matrix is
// diagonal in the modes with 2 zeta omega_i on its diagonal, in 2D and 3D; energy is conserved with the dissipation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "engine/structure/frame_system.hpp"
#include "engine/structure/integrator.hpp"
#include "engine/structure/space_frame.hpp"
#include "engine/structure/space_frame_system.hpp"
#include "tests/engine/structure/beam_models.hpp"

namespace dmi {
namespace {

using test::Beam;
using test::rel;
using test::straight;
using test::support;

constexpr double kPi = std::numbers::pi;

FrameModel cantilever(int n) {
  FrameModel m = straight(Beam{}, n);
  m.integrator = FrameIntegrator::newmark;
  support(m, 0, true, true, true);
  return m;
}

// The free-DOF modes of (K0, M), mass-normalised, scattered to full-size vectors.
struct Modes {
  Eigen::VectorXd omega;
  Eigen::MatrixXd phi;
};
Modes modes_of(const AssembledSystem& s) {
  const AssembledSystem::Modes m = s.modes();
  return {m.omega2.cwiseSqrt(), m.shapes};
}

// Phi^T C Phi for the assembled damping (through damping_force).
Eigen::MatrixXd modal_damping_matrix(const AssembledSystem& s, const Eigen::MatrixXd& phi) {
  Eigen::MatrixXd cphi(s.ndof(), phi.cols());
  Eigen::VectorXd out;
  for (int k = 0; k < phi.cols(); ++k) {
    s.damping_force(phi.col(k), out);
    cphi.col(k) = out;
  }
  return phi.transpose() * cphi;
}

TEST(ModalDamping, DampingMatrixIsDiagonalInTheModesWithTwoZetaOmega) {
  FrameModel m = cantilever(8);
  m.modal_damping.ratio = 0.05;
  const FrameSystem sys(m);
  const Modes md = modes_of(sys);
  const Eigen::MatrixXd c = modal_damping_matrix(sys, md.phi);
  const double scale = c.diagonal().maxCoeff();
  for (int i = 0; i < c.rows(); ++i)
    for (int j = 0; j < c.cols(); ++j)
      EXPECT_NEAR(c(i, j), i == j ? 2 * 0.05 * md.omega(i) : 0.0, 1e-9 * scale) << i << ", " << j;
  // A band: modes above max_frequency carry no damping.
  m.modal_damping.max_frequency = md.omega(3) / (2 * kPi) * 1.01;
  const Eigen::MatrixXd cb = modal_damping_matrix(FrameSystem(m), md.phi);
  for (int i = 0; i < cb.rows(); ++i) EXPECT_NEAR(cb(i, i), i <= 3 ? 2 * 0.05 * md.omega(i) : 0.0, 1e-9 * scale) << i;
}

TEST(ModalDamping, SpaceFrameDampingMatrixIsDiagonalInTheModes) {
  SpaceFrameModel m;
  const int n = 6;
  for (int k = 0; k <= n; ++k) m.nodes.push_back(Vec3(0, 0, 3.0 * k / n));
  for (int k = 0; k < n; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = Section::rectangle(0.3, 0.5), e.E = 30e9, e.nu = 0.2, e.rho = 2400;
    m.elements.push_back(e);
  }
  m.members.push_back({"column", 0, n});
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  m.modal_damping.ratio = 0.03;
  const SpaceFrameSystem sys(m);
  const Modes md = modes_of(sys);
  const Eigen::MatrixXd c = modal_damping_matrix(sys, md.phi);
  const double scale = c.diagonal().maxCoeff();
  for (int i = 0; i < c.rows(); ++i)
    for (int j = 0; j < c.cols(); ++j) EXPECT_NEAR(c(i, j), i == j ? 2 * 0.03 * md.omega(i) : 0.0, 1e-9 * scale);
}

// zeta of mode k from the decay of its modal coordinate q = phi_k^T M d after release from d = phi_k (Newmark,
// average acceleration, dt = T_k / 200: the period error (pi/200)^2 / 12 = 2e-5 does not reach the ratio).
double measured_ratio(const FrameModel& m, int k) {
  FrameSystem sys(m);
  const Modes md = modes_of(sys);
  const Eigen::VectorXd mphi = sys.mass() * md.phi.col(k);
  Newmark nm(sys, 0.0);
  FrameState st{md.phi.col(k), Eigen::VectorXd::Zero(sys.ndof()), Eigen::VectorXd::Zero(sys.ndof())};
  const Eigen::VectorXd f = Eigen::VectorXd::Zero(sys.ndof());
  const double T = 2 * kPi / md.omega(k), dt = T / 200;
  std::vector<double> peaks{1.0};
  double q0 = 1.0, q1 = 1.0;
  for (int s = 0; s < 200 * 6; ++s) {
    nm.step(st, f, dt, nullptr);
    const double q2 = mphi.dot(st.d);
    if (q1 > q0 && q1 >= q2) peaks.push_back(q1 + 0.125 * (q2 - q0) * (q2 - q0) / (2 * q1 - q2 - q0));  // maxima
    q0 = q1;
    q1 = q2;
  }
  const double delta = std::log(peaks.front() / peaks.back()) / (peaks.size() - 1);
  return delta / std::sqrt(4 * kPi * kPi + delta * delta);
}

TEST(ModalDamping, EveryModeDecaysAtItsRatioWhereRayleighOverdampsTheHighOnes) {
  const double zeta = 0.05;
  FrameModel modal = cantilever(12);
  modal.modal_damping.ratio = zeta;
  FrameModel rayleigh = cantilever(12);
  const Eigen::VectorXd w = modes_of(FrameSystem(rayleigh)).omega;
  rayleigh.rayleigh_mass = 2 * zeta * w(0) * w(1) / (w(0) + w(1));  // Chopra 2012, eq. 11.4.9
  rayleigh.rayleigh_stiffness = 2 * zeta / (w(0) + w(1));
  for (int k : {0, 2, 5}) {
    const double zm = measured_ratio(modal, k), zr = measured_ratio(rayleigh, k);
    std::printf("mode %d (%.0f Hz): modal zeta %.4f, Rayleigh (modes 1-2) zeta %.4f\n", k + 1, w(k) / (2 * kPi), zm, zr);
    EXPECT_LT(rel(zm, zeta), 0.01) << "mode " << k + 1;
    if (k >= 2) EXPECT_GT(zr, 2 * zeta) << "mode " << k + 1;
  }
}

TEST(ModalDamping, EnergyIsConservedWithTheDissipatedWork) {
  FrameModel m = cantilever(8);
  m.modal_damping.ratio = 0.05;
  Frame f(m);
  f.add_nodal_load(8, Vec3(0, -1e4, 0));
  f.solve_static();
  f.clear_loads();
  const double e0 = f.strain_energy(), T = 2 * kPi / f.natural_frequencies(1)[0];
  for (int k = 0; k < 600; ++k) f.advance(T / 100);
  std::printf("modal damping: dissipated %.4f of the initial energy in 6 periods\n", f.damping_work() / e0);
  EXPECT_GT(f.damping_work(), 0.5 * e0);
  EXPECT_LT(std::abs(f.kinetic_energy() + f.strain_energy() + f.damping_work() - e0), 1e-9 * e0);
}

TEST(ModalDamping, RefusedWithCorotationalMembers) {
  FrameModel m = cantilever(4);
  m.modal_damping.ratio = 0.05;
  m.transform = FrameTransform::corotational;
  EXPECT_THROW(Frame{m}, std::invalid_argument);
}

}  // namespace
}  // namespace dmi
