// The assembled operators a time integrator sees (integrator.hpp), shared by the plane frame (frame_system.hpp,
// 3 DOFs per node) and the space frame (space_frame_system.hpp, 6 DOFs per node): the mass matrix M (lumped or
// consistent, plus nodal masses), the initial (linear) stiffness K0 with support springs, the damping
// C = alpha M + beta K0 + C_modal (Rayleigh and modal terms, ModalDamping), the restrained DOFs, and the internal force and tangent of the coordinate transformation.
// Vectors are full size; restrained DOFs are masked: free() is 1 on free and 0 on restrained DOFs, solves use
// constrained() matrices (identity on restrained rows/columns), so a restrained DOF keeps a zero displacement,
// velocity and acceleration. The unmasked rows of mass() and stiffness() give the support reactions.
// A lumped mass is block diagonal by node (a node's rotational block of a space frame is a full 3 x 3 in global
// axes: torsional and bending rotary inertias differ); each free block is inverted once.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <string>
#include <vector>

#include "engine/structure/damping.hpp"

namespace dmi {

using SpMat = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Adds an element matrix over the 2 N DOFs of nodes i and j (N per node) to the triplets (exact zeros skipped).
template <int N, class Matrix> void scatter_element(Triplets& t, int i, int j, const Matrix& ke) {
  const int base[2] = {N * i, N * j};
  for (int r = 0; r < 2 * N; ++r)
    for (int c = 0; c < 2 * N; ++c)
      if (ke(r, c) != 0) t.emplace_back(base[r / N] + r % N, base[c / N] + c % N, ke(r, c));
}

SpMat from_triplets(int n, const Triplets& t);


class AssembledSystem {
 public:
  virtual ~AssembledSystem() = default;

  int ndof() const { return static_cast<int>(free_.size()); }
  int dofs_per_node() const { return node_dofs_; }
  virtual bool linear() const = 0;
  const Eigen::VectorXd& free() const { return free_; }
  const Eigen::VectorXd& springs() const { return springs_; }  // support springs on free DOFs
  const SpMat& mass() const { return M_; }
  const SpMat& stiffness() const { return K0_; }
  double rayleigh_mass() const { return alpha_; }
  double rayleigh_stiffness() const { return beta_; }
  // A copy of A with restrained rows and columns zeroed and the identity on their diagonal.
  SpMat constrained(const SpMat& A) const;

  // Internal force at d: K0 d (linear) or the transformation's sum_e B^T q + springs, restrained rows included.
  virtual void internal_force(const Eigen::VectorXd& d, Eigen::VectorXd& out) const = 0;
  // Tangent stiffness at d (K0 for the linear transformation), unconstrained.
  virtual SpMat tangent(const Eigen::VectorXd& d) const = 0;
  // Accepts d as the end of a step: plastic elements update their history (internal_force and tangent are functions
  // of the committed history and d). Nothing to do for elastic frames.
  virtual void commit(const Eigen::VectorXd& d) { (void)d; }
  // The committed history kept before a step tries sub-steps (each committed), and put back when they fail.
  virtual void keep_committed() {}
  virtual void restore_committed() {}
  // out = C v = alpha M v + beta K0 v + U diag(rates) U^T v.
  void damping_force(const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  bool damped() const { return alpha_ > 0 || beta_ > 0 || modal_rates_.size() > 0; }
  // The modal term as C_modal = U diag(rates) U^T: U's columns M phi_i (zero on restrained DOFs), rates 2 zeta omega_i;
  // empty without modal damping. The implicit integrator adds it to its sparse matrix as a low-rank update.
  const Eigen::MatrixXd& modal_basis() const { return modal_U_; }
  const Eigen::VectorXd& modal_rates() const { return modal_rates_; }
  // The largest c = v^T C v / v^T M v over the modes: alpha + beta omega_max^2 + 2 zeta omega_max (explicit step).
  double damping_rate_bound(double omega_max) const;
  // The largest step that resolves, with omega dt <= 1/2, every mode the Rayleigh damping leaves underdamped:
  // zeta(omega) = alpha / (2 omega) + beta omega / 2 < 1 below omega_u = (1 + sqrt(1 - alpha beta)) / beta, and that
  // the mesh carries (omega_max, max_eigenvalue): 1 / (2 min(omega_u, omega_max)). Newmark's period error there is
  // (omega dt)^2 / 12 <= 2.1 % (Hughes 2000, ch. 9); the modes above omega_u do not ring. +infinity without
  // stiffness-proportional damping (no mode is overdamped; the HHT dissipation handles the unresolved ones) or when
  // every mode is overdamped (alpha beta >= 1). Computed once (the linear K0 and M; Rayleigh damping is refused with
  // the corotational transformation).
  double ringing_step() const;
  // a = M^-1 r on the free DOFs (0 on restrained ones); lumped: node blocks, consistent: factorised once.
  // r is masked in place (restrained entries zeroed).
  void solve_mass(Eigen::VectorXd& r, Eigen::VectorXd& a) const;

  // Generalised eigenvalues omega^2 of (K0, M) on the free DOFs, ascending (dense: small frames only).
  Eigen::VectorXd eigenvalues() const;
  // The modes on the free DOFs: omega^2 ascending and the mass-normalised shapes (phi^T M phi = I) as full-size
  // columns, zero on restrained DOFs (dense).
  struct Modes {
    Eigen::VectorXd omega2;
    Eigen::MatrixXd shapes;
  };
  Modes modes() const;
  // The n lowest natural circular frequencies (rad/s), ascending; n outside [1, free DOFs] is refused.
  std::vector<double> natural_frequencies(int n) const;
  // omega_max^2: exact up to kDenseEigenMax free DOFs, else the element (Irons) bound plus springs.
  double max_eigenvalue() const;
  static constexpr int kDenseEigenMax = 600;
  static constexpr int kModalDenseMax = 2500;  // free DOFs for modal damping (dense eigenvectors: ~1.4 s at 1 400)

 protected:
  explicit AssembledSystem(int node_dofs) : node_dofs_(node_dofs) {}
  // After the elements' triplets: the supports (restrained DOFs, springs to ground on the free ones, also into K0),
  // the nodal masses (mass on the first `translations` DOFs of a node, rotary inertia on the rest), K0_ and M_, and
  // the springs' share of the element bound: lambda_max(K + S, M) <= lambda_max(K, M) + max s_i / M_ii (S diagonal).
  template <class Support, class NodalMass>
  void assemble_supports_and_masses(int ndof, int translations, const std::vector<Support>& supports, const std::vector<NodalMass>& masses,
                                    Triplets& tk, Triplets& tm) {
    const int nd = node_dofs_;
    free_ = Eigen::VectorXd::Ones(ndof);
    springs_ = Eigen::VectorXd::Zero(ndof);
    for (const Support& s : supports)
      for (int c = 0; c < nd; ++c) {
        if (s.fixed[c]) free_(nd * s.node + c) = 0;
        else springs_(nd * s.node + c) += s.spring[c];
      }
    for (int i = 0; i < ndof; ++i)
      if (springs_(i) > 0) tk.emplace_back(i, i, springs_(i));
    for (const NodalMass& m : masses)
      for (int c = 0; c < nd; ++c) tm.emplace_back(nd * m.node + c, nd * m.node + c, c < translations ? m.mass : m.rotary_inertia);
    K0_ = from_triplets(ndof, tk);
    M_ = from_triplets(ndof, tm);
    double spring_bound = 0;
    for (int i = 0; i < ndof; ++i)
      if (springs_(i) > 0) spring_bound = std::max(spring_bound, springs_(i) / M_.coeff(i, i));
    element_bound_ += spring_bound;
  }
  // After a derived class has filled M_, K0_, free_, springs_ and element_bound_: refuses a mechanism (naming the
  // DOF) and prepares the mass solve.
  void finish(bool lumped, double rayleigh_mass, double rayleigh_stiffness, const ModalDamping& modal);
  virtual std::string dof_name(int dof) const = 0;
  [[noreturn]] virtual void fail(const std::string& what) const = 0;

  Eigen::VectorXd free_, springs_;
  SpMat M_, K0_;
  double element_bound_ = 0;  // max over elements of lambda_max(K_e, M_e), plus the springs' share
  mutable double ringing_step_ = -1;  // ringing_step(), once computed (-1: not yet)

 private:
  void check_mechanism() const;
  void factorise_mass(bool lumped);
  void build_modal_damping(const ModalDamping& modal);
  std::vector<int> free_dofs() const;
  Modes solve_modes(bool shapes) const;

  int node_dofs_ = 3;
  double alpha_ = 0, beta_ = 0, modal_ratio_ = 0;
  Eigen::MatrixXd modal_U_;
  Eigen::VectorXd modal_rates_;
  bool lumped_ = true;
  std::vector<Eigen::MatrixXd> inv_blocks_;   // lumped: each node's free block, inverted
  std::vector<std::vector<int>> block_dofs_;  // and the DOFs it covers
  Eigen::VectorXd inv_diagonal_;              // lumped with every block diagonal: 1 / M_ii (bit for bit 1 / m)
  bool diagonal_ = true;
  Eigen::SimplicialLDLT<SpMat> mass_solver_;  // consistent mass only
};

}  // namespace dmi
