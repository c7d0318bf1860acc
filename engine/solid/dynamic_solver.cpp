#include "engine/solid/dynamic_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dmi::solid {

void DynamicOptions::validate() const {
  if (!(dt_s > 0) || !std::isfinite(dt_s)) throw std::invalid_argument("DynamicOptions: dt_s must be finite and > 0");
  if (!(hht_alpha >= -1.0 / 3 - 1e-15 && hht_alpha <= 0)) throw std::invalid_argument("DynamicOptions: hht_alpha must be in [-1/3, 0]");
  if (!(newmark_beta() >= 0) || !(newmark_gamma() >= 0) || !std::isfinite(newmark_beta()) || !std::isfinite(newmark_gamma()))
    throw std::invalid_argument("DynamicOptions: beta and gamma must be finite and >= 0");
  if (!(rayleigh_mass >= 0) || !(rayleigh_stiffness >= 0) || !std::isfinite(rayleigh_mass + rayleigh_stiffness))
    throw std::invalid_argument("DynamicOptions: Rayleigh coefficients must be finite and >= 0");
}
double DynamicOptions::newmark_beta() const {
  return std::isnan(beta) ? 0.25 * (1 - hht_alpha) * (1 - hht_alpha) : beta;
}
double DynamicOptions::newmark_gamma() const { return std::isnan(gamma) ? 0.5 - hht_alpha : gamma; }

namespace {
using Sparse = Eigen::SparseMatrix<double>;

Sparse restrict_free(const Sparse& A, const std::vector<int>& map, int n_free) {
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Sparse::InnerIterator it(A, c); it; ++it)
      if (map[it.row()] >= 0 && map[it.col()] >= 0) t.emplace_back(map[it.row()], map[it.col()], it.value());
  Sparse B(n_free, n_free);
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

void factorise(Eigen::SimplicialLDLT<Sparse>& s, const Sparse& A, const char* what) {
  s.compute(A);
  if (s.info() != Eigen::Success || (s.vectorD().array() <= 0).any())
    throw std::invalid_argument(std::string("DynamicSolver: ") + what + " is singular or not positive definite");
}
}  // namespace

DynamicSolver::DynamicSolver(const Sparse& K, const Sparse& M, std::vector<int> fixed_dofs, const DynamicOptions& opt)
    : opt_(opt), K_(K), M_(M) {
  opt_.validate();
  beta_ = opt_.newmark_beta(), gamma_ = opt_.newmark_gamma();
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n || M.rows() != n || M.cols() != n) throw std::invalid_argument("DynamicSolver: K and M must be n x n");
  std::sort(fixed_dofs.begin(), fixed_dofs.end());
  fixed_dofs.erase(std::unique(fixed_dofs.begin(), fixed_dofs.end()), fixed_dofs.end());
  if (!fixed_dofs.empty() && (fixed_dofs.front() < 0 || fixed_dofs.back() >= n))
    throw std::invalid_argument("DynamicSolver: fixed DOF out of range");
  fixed_ = std::move(fixed_dofs);
  std::vector<int> map(n, -1);
  for (int i = 0; i < n; ++i)
    if (!std::binary_search(fixed_.begin(), fixed_.end(), i)) map[i] = static_cast<int>(free_.size()), free_.push_back(i);
  if (opt_.lumped_mass) {
    const Eigen::VectorXd rows = M * Eigen::VectorXd::Ones(n);
    M_ = Sparse(n, n);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) t.emplace_back(i, i, rows(i));
    M_.setFromTriplets(t.begin(), t.end());
  }
  const int nf = static_cast<int>(free_.size());
  const double s = 1 + opt_.hht_alpha, dt = opt_.dt_s;
  // M* = M + (1 + alpha) (gamma dt C + beta dt^2 K), C = a_M M + b_K K.
  const Sparse eff = (1 + s * gamma_ * dt * opt_.rayleigh_mass) * M_ +
                     (s * gamma_ * dt * opt_.rayleigh_stiffness + s * beta_ * dt * dt) * K_;
  factorise(eff_, restrict_free(eff, map, nf), "the effective matrix M*");
  factorise(mass_, restrict_free(M_, map, nf), "M_ff");
  u_ = v_ = a_ = f_ = Eigen::VectorXd::Zero(n);
}

Eigen::VectorXd DynamicSolver::damping_times(const Eigen::VectorXd& x) const {
  Eigen::VectorXd c = Eigen::VectorXd::Zero(x.size());
  if (opt_.rayleigh_mass != 0) c += opt_.rayleigh_mass * (M_ * x);
  if (opt_.rayleigh_stiffness != 0) c += opt_.rayleigh_stiffness * (K_ * x);
  return c;
}

Eigen::VectorXd DynamicSolver::solve_free(Eigen::SimplicialLDLT<Sparse>& s, const Eigen::VectorXd& rhs) const {
  Eigen::VectorXd r(free_.size());
  for (std::size_t i = 0; i < free_.size(); ++i) r(i) = rhs(free_[i]);
  const Eigen::VectorXd x = s.solve(r);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(rhs.size());
  for (std::size_t i = 0; i < free_.size(); ++i) out(free_[i]) = x(i);
  return out;
}

void DynamicSolver::initialize(const Eigen::VectorXd& u0, const Eigen::VectorXd& v0, const Eigen::VectorXd& f0, double t0) {
  const int n = static_cast<int>(K_.rows());
  if (u0.size() != n || v0.size() != n || f0.size() != n) throw std::invalid_argument("DynamicSolver::initialize: wrong length");
  if (!u0.allFinite() || !v0.allFinite() || !f0.allFinite() || !std::isfinite(t0))
    throw std::invalid_argument("DynamicSolver::initialize: non-finite input");
  u_ = u0, v_ = v0, f_ = f0, t0_ = t0, steps_ = 0;
  for (int i : fixed_) u_(i) = v_(i) = 0;
  a_ = solve_free(mass_, f_ - damping_times(v_) - K_ * u_);  // M a_0 = f_0 - C v_0 - K u_0
}

void DynamicSolver::step(const Eigen::VectorXd& f_next) {
  if (f_next.size() != K_.rows() || !f_next.allFinite()) throw std::invalid_argument("DynamicSolver::step: bad load vector");
  const double dt = opt_.dt_s, al = opt_.hht_alpha;
  const Eigen::VectorXd ut = u_ + dt * v_ + 0.5 * dt * dt * (1 - 2 * beta_) * a_;
  const Eigen::VectorXd vt = v_ + dt * (1 - gamma_) * a_;
  // M* a_n+1 = (1 + alpha) (f_n+1 - C v~ - K u~) - alpha (f_n - C v_n - K u_n)
  const Eigen::VectorXd rhs =
      (1 + al) * (f_next - damping_times(vt) - K_ * ut) - al * (f_ - damping_times(v_) - K_ * u_);
  a_ = solve_free(eff_, rhs);
  u_ = ut + beta_ * dt * dt * a_;
  v_ = vt + gamma_ * dt * a_;
  f_ = f_next;
  ++steps_;
  if (!u_.allFinite()) throw std::runtime_error("DynamicSolver::step: solution is not finite");
}

double DynamicSolver::kinetic_energy() const { return 0.5 * v_.dot(M_ * v_); }
double DynamicSolver::strain_energy() const { return 0.5 * u_.dot(K_ * u_); }

Eigen::VectorXd DynamicSolver::reaction() const {
  const Eigen::VectorXd r = K_ * u_ + damping_times(v_) + M_ * a_ - f_;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(r.size());
  for (int i : fixed_) out(i) = r(i);
  return out;
}

DynamicRecord run_history(DynamicSolver& s, const LoadHistory& f, int n_steps, const std::vector<int>& record_dofs,
                          const std::vector<std::vector<int>>& reaction_groups) {
  if (n_steps < 0) throw std::invalid_argument("run_history: n_steps must be >= 0");
  const int n = static_cast<int>(s.u().size()), nr = static_cast<int>(record_dofs.size());
  const int ng = static_cast<int>(reaction_groups.size());
  for (int d : record_dofs)
    if (d < 0 || d >= n) throw std::invalid_argument("run_history: record DOF out of range");
  for (const auto& g : reaction_groups)
    for (int d : g)
      if (d < 0 || d >= n) throw std::invalid_argument("run_history: reaction DOF out of range");
  const double t0 = s.time();
  s.initialize(s.u(), s.v(), f(t0), t0);
  DynamicRecord rec;
  rec.u.resize(n_steps + 1, nr), rec.reaction.resize(n_steps + 1, ng), rec.energy_J.resize(n_steps + 1);
  rec.peak_u = rec.peak_u_time_s = Eigen::VectorXd::Zero(nr);
  rec.peak_reaction = rec.peak_reaction_time_s = Eigen::VectorXd::Zero(ng);
  for (int k = 0; k <= n_steps; ++k) {
    if (k > 0) s.step(f(t0 + k * s.dt()));
    const double t = s.time();
    rec.time_s.push_back(t);
    for (int i = 0; i < nr; ++i) {
      rec.u(k, i) = s.u()(record_dofs[i]);
      if (std::abs(rec.u(k, i)) > std::abs(rec.peak_u(i))) rec.peak_u(i) = rec.u(k, i), rec.peak_u_time_s(i) = t;
    }
    const Eigen::VectorXd r = s.reaction();
    rec.peak_nodal_reaction_N = std::max(rec.peak_nodal_reaction_N, r.cwiseAbs().maxCoeff());
    for (int g = 0; g < ng; ++g) {
      double sum = 0;
      for (int d : reaction_groups[g]) sum += r(d);
      rec.reaction(k, g) = sum;
      if (std::abs(sum) > std::abs(rec.peak_reaction(g))) rec.peak_reaction(g) = sum, rec.peak_reaction_time_s(g) = t;
    }
    rec.energy_J(k) = s.energy();
  }
  return rec;
}

}  // namespace dmi::solid
