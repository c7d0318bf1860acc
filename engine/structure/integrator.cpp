#include "engine/structure/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dmi {

ExplicitEuler::ExplicitEuler(const FrameSystem& sys) : sys_(sys) {
  const Eigen::VectorXd w2 = sys.eigenvalues();
  if (w2.size() == 0 || !w2.allFinite() || !(w2.minCoeff() > 0))
    throw std::invalid_argument("Frame: (K, M) eigenvalues are not finite and positive; no stable time step");
  const double w = std::sqrt(w2.maxCoeff());
  const double c = sys.model().rayleigh_mass + sys.model().rayleigh_stiffness * w * w;
  dt_stable_ = 4 / (std::sqrt(4 * w * w + c * c) + c);
  const int n = sys.ndof();
  fint_.setZero(n);
  cv_.setZero(n);
  r_.setZero(n);
}

void ExplicitEuler::step(FrameState& s, const Eigen::VectorXd& f, double dt) {
  sys_.internal_force(s.d, fint_);                     // f_int(d_n)
  r_ = f - fint_;
  if (sys_.damped()) {
    sys_.damping_force(s.v, cv_);
    r_ -= cv_;
  }
  sys_.solve_mass(r_, s.a);                            // eq. (27)
  s.v += dt * s.a;                                     // eq. (28)
  s.d += dt * s.v;                                     // eq. (29)
  s.t += dt;
  s.a_current = false;                                 // a is a_n, not a_{n+1}
}

Newmark::Newmark(const FrameSystem& sys) : sys_(sys) {
  const int n = sys.ndof();
  fint_.setZero(n);
  tmp_.setZero(n);
  rhs_.setZero(n);
  dd_.setZero(n);
}

double Newmark::stable_time_step() const { return std::numeric_limits<double>::infinity(); }

void Newmark::step(FrameState& s, const Eigen::VectorXd& f, double dt) {
  if (!s.a_current) initial_acceleration(s, f);
  if (sys_.linear()) step_linear(s, f, dt);
  else step_newton(s, f, dt);
  s.t += dt;
  s.a_current = true;
}

void Newmark::initial_acceleration(FrameState& s, const Eigen::VectorXd& f) {
  sys_.internal_force(s.d, fint_);
  sys_.damping_force(s.v, tmp_);
  rhs_ = f - fint_ - tmp_;
  sys_.solve_mass(rhs_, s.a);
}

void Newmark::step_linear(FrameState& s, const Eigen::VectorXd& f, double dt) {
  const double alpha = sys_.model().rayleigh_mass, beta = sys_.model().rayleigh_stiffness;
  if (dt != dt_factored_) {
    const SpMat K = (1 + 2 * beta / dt) * sys_.stiffness() + (2 * alpha / dt + 4 / (dt * dt)) * sys_.mass();
    solver_.compute(sys_.constrained(K));
    if (solver_.info() != Eigen::Success)
      throw std::runtime_error("Frame: Newmark effective matrix factorisation failed");
    dt_factored_ = dt;
  }
  // rhs = f - K0 (d - beta v) + M ((4/dt + alpha) v + a), C = alpha M + beta K0.
  tmp_ = s.d - beta * s.v;
  rhs_.noalias() = f - sys_.stiffness() * tmp_;
  tmp_ = (4 / dt + alpha) * s.v + s.a;
  rhs_.noalias() += sys_.mass() * tmp_;
  rhs_.array() *= sys_.free().array();
  dd_ = solver_.solve(rhs_);
  s.a = 4 / (dt * dt) * dd_ - 4 / dt * s.v - s.a;
  s.v = 2 / dt * dd_ - s.v;
  s.d += dd_;
}

void Newmark::step_newton(FrameState& s, const Eigen::VectorXd& f, double dt) {
  constexpr int kMaxIterations = 20;
  constexpr double kResidualTol = 1e-8, kIncrementTol = 1e-8;
  const double alpha = sys_.model().rayleigh_mass, beta = sys_.model().rayleigh_stiffness;
  const Eigen::VectorXd d0 = s.d, v0 = s.v, a0 = s.a, fm = f.cwiseProduct(sys_.free());
  Eigen::VectorXd D = dt * v0, delta = Eigen::VectorXd::Zero(sys_.ndof());
  double ref = 0, res = 0;
  for (int it = 0; it <= kMaxIterations; ++it) {
    s.d = d0 + D;
    s.v = 2 / dt * D - v0;
    s.a = 4 / (dt * dt) * D - 4 / dt * v0 - a0;
    sys_.internal_force(s.d, fint_);
    sys_.damping_force(s.v, tmp_);
    const Eigen::VectorXd inertia = sys_.mass() * s.a;
    rhs_ = (f - fint_ - inertia - tmp_).cwiseProduct(sys_.free());
    if (it == 0)
      ref = std::max({fm.norm(), fint_.cwiseProduct(sys_.free()).norm(), inertia.cwiseProduct(sys_.free()).norm(),
                      std::numeric_limits<double>::min()});
    res = rhs_.norm();
    if (it > 0 && res <= kResidualTol * ref && delta.norm() <= kIncrementTol * std::max(D.norm(), s.d.norm())) return;
    if (it == kMaxIterations) break;
    const SpMat J = sys_.tangent(s.d) + (2 * beta / dt) * sys_.stiffness() +
                    (2 * alpha / dt + 4 / (dt * dt)) * sys_.mass();
    solver_.compute(sys_.constrained(J));
    if (solver_.info() != Eigen::Success) break;
    delta = solver_.solve(rhs_);
    D += delta;
  }
  s.d = d0;  // leave the state at t_n
  s.v = v0;
  s.a = a0;
  throw std::runtime_error("Frame: Newmark Newton iterations did not converge at t = " + std::to_string(s.t + dt) +
                           " s, residual " + std::to_string(res) + " N (relative " + std::to_string(res / ref) + ")");
}

std::unique_ptr<FrameTimeIntegrator> make_integrator(const FrameSystem& sys, FrameIntegrator kind) {
  if (kind == FrameIntegrator::newmark) return std::make_unique<Newmark>(sys);
  return std::make_unique<ExplicitEuler>(sys);
}

}  // namespace dmi
