#include "engine/structure/assembled_system.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace dmi {

SpMat from_triplets(int n, const Triplets& t) {
  SpMat A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

void AssembledSystem::finish(bool lumped, double rayleigh_mass, double rayleigh_stiffness, const ModalDamping& modal) {
  alpha_ = rayleigh_mass;
  beta_ = rayleigh_stiffness;
  check_mechanism();
  factorise_mass(lumped);
  build_modal_damping(modal);
}

std::vector<int> AssembledSystem::free_dofs() const {
  std::vector<int> idx;
  for (int i = 0; i < ndof(); ++i)
    if (free_(i) > 0) idx.push_back(i);
  return idx;
}

// U = M Phi_r (mass-normalised modes up to max_frequency) and rates 2 zeta omega_i.
void AssembledSystem::build_modal_damping(const ModalDamping& modal) {
  if (!(modal.ratio > 0)) return;
  if (!(modal.ratio < 1) || !(modal.max_frequency > 0)) fail("modal damping needs 0 < ratio < 1 and a maximum frequency > 0");
  const std::vector<int> idx = free_dofs();
  const int nf = static_cast<int>(idx.size());
  if (nf > kModalDenseMax)
    fail("modal damping computes every mode and takes at most " + std::to_string(kModalDenseMax) + " free DOFs (the frame has " +
         std::to_string(nf) + "); use Rayleigh damping");
  const Modes m = modes();
  const double wmax = 2 * std::numbers::pi * modal.max_frequency;
  int r = 0;
  while (r < nf && std::sqrt(std::max(m.omega2(r), 0.0)) <= wmax) ++r;
  modal_ratio_ = modal.ratio;
  modal_U_ = free_.asDiagonal() * (M_ * m.shapes.leftCols(r));  // M phi on the free DOFs, zero on restrained ones
  modal_rates_.resize(r);
  for (int i = 0; i < r; ++i) modal_rates_(i) = 2 * modal.ratio * std::sqrt(std::max(m.omega2(i), 0.0));
}

double AssembledSystem::damping_rate_bound(double omega_max) const {
  return alpha_ + beta_ * omega_max * omega_max + 2 * modal_ratio_ * omega_max;
}

double AssembledSystem::max_eigenvalue() const {
  int nf = 0;
  for (int i = 0; i < ndof(); ++i) nf += free_(i) > 0;
  // Exact (dense) for small frames; above ~200 elements the O(n^3) solve costs seconds, so the
  // element bound (conservative: a smaller stable step) is used.
  return nf <= kDenseEigenMax ? eigenvalues().maxCoeff() : element_bound_;
}

double AssembledSystem::ringing_step() const {
  if (ringing_step_ < 0) {
    ringing_step_ = std::numeric_limits<double>::infinity();
    if (beta_ > 0 && alpha_ * beta_ < 1) {
      const double wu = (1 + std::sqrt(1 - alpha_ * beta_)) / beta_, wmax = std::sqrt(max_eigenvalue());
      ringing_step_ = 0.5 / (std::isfinite(wmax) && wmax > 0 ? std::min(wu, wmax) : wu);
    }
  }
  return ringing_step_;
}

void AssembledSystem::factorise_mass(bool lumped) {
  lumped_ = lumped;
  if (!lumped) {
    mass_solver_.compute(constrained(M_));
    if (mass_solver_.info() != Eigen::Success) fail("consistent mass matrix is not positive definite");
    return;
  }
  const int nn = ndof() / node_dofs_;
  inv_diagonal_ = Eigen::VectorXd::Zero(ndof());
  for (int n = 0; n < nn; ++n) {
    std::vector<int> dofs;
    for (int c = 0; c < node_dofs_; ++c)
      if (free_(node_dofs_ * n + c) > 0) dofs.push_back(node_dofs_ * n + c);
    const int k = static_cast<int>(dofs.size());
    Eigen::MatrixXd B(k, k);
    for (int r = 0; r < k; ++r)
      for (int c = 0; c < k; ++c) B(r, c) = M_.coeff(dofs[r], dofs[c]);
    for (int r = 0; r < k; ++r)
      if (!(B(r, r) > 0)) fail("no mass at " + dof_name(dofs[r]));  // HRZ gives every element DOF mass
    const bool diagonal = B.isDiagonal(0.0);
    diagonal_ = diagonal_ && diagonal;
    for (int r = 0; r < k; ++r) inv_diagonal_(dofs[r]) = 1 / B(r, r);
    Eigen::LLT<Eigen::MatrixXd> llt(B);
    if (llt.info() != Eigen::Success) fail("lumped mass block of node " + std::to_string(n) + " is not positive definite");
    inv_blocks_.push_back(diagonal ? Eigen::MatrixXd(inv_diagonal_(dofs).asDiagonal()) : llt.solve(Eigen::MatrixXd::Identity(k, k)));
    block_dofs_.push_back(std::move(dofs));
  }
}

// Singular K0 on the free DOFs: a zero diagonal, a failed LDLT or a pivot below 1e-12 of its diagonal. The
// DOF named is the largest entry of the lowest eigenvector of the diagonally scaled stiffness (the mode).
void AssembledSystem::check_mechanism() const {
  const SpMat K = constrained(K0_);
  const auto mechanism = [this](int dof) {
    fail("the frame is a mechanism: no stiffness against " + dof_name(dof) + " (add supports, or release only one side of a hinge)");
  };
  const Eigen::VectorXd diag = K.diagonal();
  for (int i = 0; i < ndof(); ++i)
    if (!(diag(i) > 0)) mechanism(i);
  Eigen::SimplicialLDLT<SpMat> ldlt(K);
  bool singular = ldlt.info() != Eigen::Success;
  if (!singular) {
    const Eigen::VectorXd D = ldlt.vectorD();
    const auto& perm = ldlt.permutationP().indices();  // original DOF i sits at pivot perm(i)
    for (int i = 0; i < ndof(); ++i) singular = singular || !(D(perm(i)) > 1e-12 * diag(i));
  }
  if (!singular) return;
  if (ndof() > 3 * kDenseEigenMax)
    fail("the frame is a mechanism: its stiffness matrix is singular (add supports, or release only one side of a hinge)");
  const Eigen::VectorXd s = diag.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = s.asDiagonal() * Eigen::MatrixXd(K) * s.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(scaled);
  int worst = 0;
  es.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
  mechanism(worst);
}

SpMat AssembledSystem::constrained(const SpMat& A) const {
  Triplets t;
  t.reserve(A.nonZeros() + ndof());
  for (int c = 0; c < A.outerSize(); ++c)
    for (SpMat::InnerIterator it(A, c); it; ++it)
      if (free_(it.row()) > 0 && free_(it.col()) > 0) t.emplace_back(it.row(), it.col(), it.value());
  for (int i = 0; i < ndof(); ++i)
    if (free_(i) == 0) t.emplace_back(i, i, 1.0);
  return from_triplets(ndof(), t);
}

void AssembledSystem::damping_force(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  out.noalias() = alpha_ * (M_ * v);
  if (beta_ > 0) out.noalias() += beta_ * (K0_ * v);
  if (modal_rates_.size() > 0) out.noalias() += modal_U_ * modal_rates_.cwiseProduct(modal_U_.transpose() * v);
}

void AssembledSystem::solve_mass(Eigen::VectorXd& r, Eigen::VectorXd& a) const {
  r.array() *= free_.array();
  if (!lumped_) {
    a = mass_solver_.solve(r);
  } else if (diagonal_) {
    a = inv_diagonal_.cwiseProduct(r);
  } else {
    a.setZero(ndof());
    for (std::size_t b = 0; b < block_dofs_.size(); ++b) a(block_dofs_[b]) = inv_blocks_[b] * r(block_dofs_[b]);
  }
}

Eigen::VectorXd AssembledSystem::eigenvalues() const { return solve_modes(false).omega2; }

AssembledSystem::Modes AssembledSystem::modes() const { return solve_modes(true); }

AssembledSystem::Modes AssembledSystem::solve_modes(bool shapes) const {
  const std::vector<int> idx = free_dofs();
  const Eigen::MatrixXd K(K0_), M(M_);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K(idx, idx), M(idx, idx),
                                                               shapes ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success) throw std::runtime_error("Frame: generalised eigen solve failed");
  Modes m{es.eigenvalues(), Eigen::MatrixXd()};
  if (shapes) {
    m.shapes = Eigen::MatrixXd::Zero(ndof(), static_cast<Eigen::Index>(idx.size()));
    m.shapes(idx, Eigen::all) = es.eigenvectors();
  }
  return m;
}

std::vector<double> AssembledSystem::natural_frequencies(int n) const {
  const Eigen::VectorXd w2 = eigenvalues();
  if (n < 1 || n > w2.size())
    fail("natural_frequencies(" + std::to_string(n) + "): the frame has " + std::to_string(w2.size()) + " free DOFs");
  std::vector<double> w(n);
  for (int k = 0; k < n; ++k) w[k] = std::sqrt(w2(k));
  return w;
}

}  // namespace dmi
