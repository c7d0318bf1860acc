#include "engine/structure/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dmi {

ExplicitEuler::ExplicitEuler(const AssembledSystem& sys) : sys_(sys) {
  const double w2 = sys.max_eigenvalue();  // the constructor already refused mechanisms
  if (!std::isfinite(w2) || !(w2 > 0))
    throw std::invalid_argument("Frame: (K, M) eigenvalues are not finite and positive; no stable time step");
  const double w = std::sqrt(w2);
  const double c = sys.damping_rate_bound(w);
  dt_stable_ = 4 / (std::sqrt(4 * w * w + c * c) + c);
  const int n = sys.ndof();
  fint_.setZero(n);
  cv_.setZero(n);
  r_.setZero(n);
}

void ExplicitEuler::step(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) {
  sys_.internal_force(s.d, fint_);                     // f_int(d_n)
  r_ = f - fint_;
  if (sys_.damped()) {
    sys_.damping_force(s.v, cv_);
    r_ -= cv_;
  }
  if (Ma) {                                             // eq. (27) with the attached mass
    added_solver_.compute(sys_.constrained(sys_.mass() + *Ma));
    if (added_solver_.info() != Eigen::Success) throw std::runtime_error("Frame: mass with attached material is singular");
    r_.array() *= sys_.free().array();
    s.a = added_solver_.solve(r_);
  } else {
    sys_.solve_mass(r_, s.a);                          // eq. (27)
  }
  s.v += dt * s.a;                                     // eq. (28)
  s.d += dt * s.v;                                     // eq. (29)
  s.t += dt;
  s.a_current = false;                                 // a is a_n, not a_{n+1}
}

Newmark::Newmark(AssembledSystem& sys, double hht_alpha) : sys_(sys) {
  const double a = hht_alpha;
  if (!(a >= -1.0 / 3 && a <= 0)) throw std::invalid_argument("Frame: HHT alpha must lie in [-1/3, 0]");
  alpha_ = a;
  gamma_ = 0.5 - a;
  beta_ = 0.25 * (1 - a) * (1 - a);
  const int n = sys.ndof();
  fint_.setZero(n);
  fint0_.setZero(n);
  tmp_.setZero(n);
  rhs_.setZero(n);
  dd_.setZero(n);
}

double Newmark::stable_time_step() const { return std::numeric_limits<double>::infinity(); }

void Newmark::step(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) {
  if (!s.a_current) initial_acceleration(s, f);
  if (sys_.linear()) step_linear(s, f, dt, Ma);
  else step_newton(s, f, dt, Ma);
  s.t += dt;
  s.a_current = true;
}

void Newmark::initial_acceleration(FrameState& s, const Eigen::VectorXd& f) {
  sys_.internal_force(s.d, fint_);
  sys_.damping_force(s.v, tmp_);
  rhs_ = f - fint_ - tmp_;
  sys_.solve_mass(rhs_, s.a);
}

// Increment D = d_{n+1} - d_n gives a_{n+1} = c0 (D - dt v_n) - (1/(2 beta) - 1) a_n and
// v_{n+1} = c1 D + (1 - gamma/beta) v_n + dt (1 - gamma/(2 beta)) a_n, c0 = 1/(beta dt^2), c1 = gamma/(beta dt).
// s may be n itself (the linear step updates in place, without copying the state): a_{n+1} goes through tmp_ first.
void Newmark::kinematics(const FrameState& n, const Eigen::VectorXd& D, double dt, FrameState& s) {
  const double c0 = 1 / (beta_ * dt * dt), c1 = gamma_ / (beta_ * dt);
  tmp_ = c0 * (D - dt * n.v) - (0.5 / beta_ - 1) * n.a;
  s.v = c1 * D + (1 - gamma_ / beta_) * n.v + dt * (1 - 0.5 * gamma_ / beta_) * n.a;
  s.a.swap(tmp_);
  s.d = n.d + D;
}

// Numeric LDLT of A; the symbolic analysis (AMD ordering, elimination tree) is redone only when A's sparsity pattern
// differs from the last one analysed. Under stick contact the matrix changes every step but its pattern does not,
// and the ordering was the largest single cost of a small frame's step (perf, Lin & Yang verification 1: 16 elements, Newmark).
bool Newmark::factorize(const SpMat& A, double c_modal, bool throw_on_failure) {
  const auto n = static_cast<std::size_t>(A.outerSize()) + 1;
  const bool same = pattern_outer_.size() == n && std::equal(pattern_outer_.begin(), pattern_outer_.end(), A.outerIndexPtr()) &&
                    pattern_inner_.size() == static_cast<std::size_t>(A.nonZeros()) &&
                    std::equal(pattern_inner_.begin(), pattern_inner_.end(), A.innerIndexPtr());
  if (!same) {
    solver_.analyzePattern(A);
    pattern_outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n);
    pattern_inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  }
  solver_.factorize(A);
  if (solver_.info() == Eigen::Success && sys_.modal_rates().size() > 0) {
    const Eigen::MatrixXd& U = sys_.modal_basis();
    modal_Y_ = solver_.solve(U);
    Eigen::MatrixXd S = U.transpose() * modal_Y_;
    S.diagonal() += (c_modal * sys_.modal_rates()).cwiseInverse();
    capacitance_.compute(S);
    if (capacitance_.info() == Eigen::Success) return true;
  } else if (solver_.info() == Eigen::Success) {
    return true;
  }
  if (throw_on_failure) throw std::runtime_error("Frame: Newmark effective matrix factorisation failed");
  return false;
}

void Newmark::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  x = solver_.solve(b);
  if (sys_.modal_rates().size() > 0) x.noalias() -= modal_Y_ * capacitance_.solve(sys_.modal_basis().transpose() * x);
}

void Newmark::step_linear(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) {
  const double c0 = 1 / (beta_ * dt * dt), c1 = gamma_ / (beta_ * dt);
  const double ar = sys_.rayleigh_mass(), br = sys_.rayleigh_stiffness(), cmodal = (1 + alpha_) * c1;
  if (dt != dt_factored_) {  // c0 M + (1 + alpha)(K0 + c1 C), C = ar M + br K0: rebuilt when dt changes (CFL steps)
    const double ck = (1 + alpha_) * (1 + c1 * br), cm = c0 + (1 + alpha_) * c1 * ar;
    if (kc_.nonZeros() == 0) {  // K0 and M constrained on one common pattern, so keff_ is a sum of value arrays
      kc_ = sys_.constrained(sys_.stiffness() + 0.0 * sys_.mass());
      mc_ = sys_.constrained(sys_.mass() + 0.0 * sys_.stiffness());
      if (kc_.nonZeros() != mc_.nonZeros() || !std::equal(kc_.innerIndexPtr(), kc_.innerIndexPtr() + kc_.nonZeros(), mc_.innerIndexPtr()))
        throw std::logic_error("Newmark: K0 and M patterns differ");
    }
    keff_ = kc_;  // constrained DOFs get ck + cm on the diagonal: decoupled, with zero right-hand side, so still 0
    const double* k = kc_.valuePtr();
    const double* m = mc_.valuePtr();
    double* v = keff_.valuePtr();
    for (Eigen::Index q = 0; q < keff_.nonZeros(); ++q) v[q] = ck * k[q] + cm * m[q];
    dt_factored_ = dt;
    if (!Ma) factorize(keff_, cmodal);
    factored_with_mass_ = false;
  }
  if (Ma) {  // + c0 Ma on the free DOFs, written into a copy of the cached matrix (same pattern: node blocks)
    keff_ma_ = keff_;
    const Eigen::VectorXd& free = sys_.free();
    for (int c = 0; c < Ma->outerSize(); ++c)
      for (SpMat::InnerIterator it(*Ma, c); it; ++it)
        if (free(it.row()) > 0 && free(it.col()) > 0) keff_ma_.coeffRef(it.row(), it.col()) += c0 * it.value();
    keff_ma_.makeCompressed();
    factorize(keff_ma_, cmodal);
    factored_with_mass_ = true;
  } else if (factored_with_mass_) {
    factorize(keff_, cmodal);
    factored_with_mass_ = false;
  }
  // rhs = f - K0 d_n + (M + Ma)(c0 dt v_n + (1/(2 beta) - 1) a_n)
  //       - (1 + alpha) C ((1 - gamma/beta) v_n + dt (1 - gamma/(2 beta)) a_n) + alpha C v_n
  tmp_ = c0 * dt * s.v + (0.5 / beta_ - 1) * s.a;
  rhs_.noalias() = f - sys_.stiffness() * s.d;
  rhs_.noalias() += sys_.mass() * tmp_;
  if (Ma) rhs_.noalias() += *Ma * tmp_;
  if (sys_.damped()) {
    tmp_ = (1 + alpha_) * ((1 - gamma_ / beta_) * s.v + dt * (1 - 0.5 * gamma_ / beta_) * s.a) - alpha_ * s.v;
    sys_.damping_force(tmp_, fint_);
    rhs_ -= fint_;
  }
  rhs_.array() *= sys_.free().array();
  solve(rhs_, dd_);
  kinematics(s, dd_, dt, s);
}

// Corotational or plastic: Newton-Raphson on R(D) = f - (M + Ma) a_{n+1} - (1 + alpha)(f_int(d_{n+1}) + C v_{n+1})
// + alpha (f_int(d_n) + C v_n), Jacobian c0 (M + Ma) + (1 + alpha)(K_t + c1 C).
void Newmark::step_newton(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) {
  double res = 0, ref = 0;
  if (newton(s, f, dt, Ma, res, ref)) return;
  const FrameState n = s;
  sys_.keep_committed();
  for (int k = 2; k <= 64; k *= 2) {
    bool ok = true;
    for (int j = 0; j < k && ok; ++j) {
      ok = newton(s, f, dt / k, Ma, res, ref);
      if (ok && j + 1 < k) sys_.commit(s.d), s.t += dt / k;
    }
    if (ok) {
      s.t = n.t;  // step() advances the time by dt
      return;
    }
    s = n;
    sys_.restore_committed();  // the sub-steps committed so far are undone with the state
  }
  throw std::runtime_error("Frame: Newmark Newton iterations did not converge at t = " + std::to_string(n.t + dt) +
                           " s, residual " + std::to_string(res) + " N (relative " + std::to_string(res / ref) + "), in up to 64 sub-steps");
}

bool Newmark::newton(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma, double& res, double& ref) {
  constexpr int kMaxIterations = 20, kMaxHalvings = 8;
  constexpr double kResidualTol = 1e-8, kIncrementTol = 1e-8;
  const double c0 = 1 / (beta_ * dt * dt), c1 = gamma_ / (beta_ * dt);
  const double ar = sys_.rayleigh_mass(), br = sys_.rayleigh_stiffness();
  const FrameState n = s;
  sys_.internal_force(n.d, fint0_);
  sys_.damping_force(n.v, tmp_);
  fint0_ += tmp_;  // f_int(d_n) + C v_n
  const Eigen::VectorXd fm = f.cwiseProduct(sys_.free());
  Eigen::VectorXd D = dt * n.v, delta = Eigen::VectorXd::Zero(sys_.ndof());
  const auto residual = [&](const Eigen::VectorXd& Dk, Eigen::VectorXd& inertia) {
    kinematics(n, Dk, dt, s);
    sys_.internal_force(s.d, fint_);
    sys_.damping_force(s.v, tmp_);
    inertia = sys_.mass() * s.a;
    if (Ma) inertia += *Ma * s.a;
    rhs_ = (f - inertia - (1 + alpha_) * (fint_ + tmp_) + alpha_ * fint0_).cwiseProduct(sys_.free());
    return rhs_.norm();
  };
  Eigen::VectorXd inertia;
  res = residual(D, inertia);
  ref = std::max({fm.norm(), fint_.cwiseProduct(sys_.free()).norm(), inertia.cwiseProduct(sys_.free()).norm(), std::numeric_limits<double>::min()});
  for (int it = 0; it <= kMaxIterations; ++it) {
    if (it > 0 && res <= kResidualTol * ref && delta.norm() <= kIncrementTol * std::max(D.norm(), s.d.norm())) return true;
    if (it == kMaxIterations) break;
    SpMat J = (1 + alpha_) * (sys_.tangent(s.d) + c1 * br * sys_.stiffness()) + (c0 + (1 + alpha_) * c1 * ar) * sys_.mass();
    if (Ma) J += c0 * *Ma;
    if (!factorize(sys_.constrained(J), (1 + alpha_) * c1, false)) break;
    solve(rhs_, delta);
    // Backtracking: the full step unless it raises the residual (a hinge yielding through the step).
    const Eigen::VectorXd D0 = D;
    double step = 1;
    for (int h = 0;; ++h, step *= 0.5) {
      D = D0 + step * delta;
      const double trial = residual(D, inertia);
      if (trial < res || h == kMaxHalvings) {
        res = trial;
        break;
      }
    }
    delta *= step;
  }
  s = n;  // leave the state at t_n
  return false;
}

std::unique_ptr<FrameTimeIntegrator> make_integrator(AssembledSystem& sys, FrameIntegrator kind, double hht_alpha) {
  if (kind == FrameIntegrator::newmark) return std::make_unique<Newmark>(sys, hht_alpha);
  return std::make_unique<ExplicitEuler>(sys);
}

}  // namespace dmi
