// Implicit Kelvin-Voigt viscosity on the grid.
// A damped body's stress is sigma = sigma_e + sigma_v, sigma_v = a tr(D) I + 2 b D (a = beta lambda, b = beta mu,
// beta = zeta / (pi f)). Integrated explicitly, sigma_v cuts the stable step to (2/w)(sqrt(1 + zeta^2) - zeta),
// zeta = beta w / 2, w = 2 sqrt(D) c / h: for strong damping h^2 / (2 D beta c^2), the viscous limit of the grid's
// checkerboard modes, which falls as h^2. Here the viscous nodal force is taken at the end of the step (backward
// Euler on the viscous part, forward on the elastic one):
//   (M + dt K_v) u = M v*,   v* = (p + dt f_e) / m,   f_v = -K_v u,
//   K_v u = sum_p V_p sigma_v(D_p(u)) grad N_ip,   D_p(u) = sym(sum_i u_i (x) grad N_ip),
// per damped body over the nodes of its field, by a sparse LDL^T factorisation (K_v is symmetric positive
// semi-definite and the lumped M positive, so the system is SPD). f_e is P2G's nodal force less the viscous
// stress of the last update, which P2G scattered with the elastic one; f_v then joins it, so that members, walls and
// contact see one nodal force as before. The viscous part is unconditionally stable and the step is the elastic
// CFL step.
#pragma once
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"

namespace dmi {

template <int D> class ImplicitViscosity {
 public:
  // True when the bodies whose material has constant Kelvin-Voigt coefficients (Material::viscous_coefficients) share
  // one velocity field. Damped bodies in several fields (discrete tyres in contact with one another) stay explicit:
  // their contact would need one joint solve over the fields, which is not built.
  static bool needed(const Scene<D>& s);
  // Node-field pairs (field * nnodes + node) the solve holds at a given velocity: members' stuck nodes.
  using Held = std::vector<std::pair<Index, Vec<D>>>;
  // Replaces the viscous part of the nodal force of the bodies flagged in `bodies` (a material is integrated
  // implicitly when any of its bodies is; its own dissipation count is then off) by the implicit one. Nodes with mass
  // <= mass_eps are left out. The constraints that act after this force are tried first on the predictor v* of every
  // field (at time t): the components the walls and regions would change are held at the value they would give, and
  // so are the members' stuck nodes in held (their viscous force then reaches the wall or member through the
  // constraint, as an elastic force does); where body contact would change the damped field, the other field's
  // nodal mass joins it along the contact normal n (the direction of the change), m_A + m_B n n^T, so that both leave
  // the solve with one normal velocity and the contact force includes the viscous one (momentum is exchanged, not
  // made). Wall touch sets must be current. Throws RunError if the solve fails.
  void apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt, double t, double mass_eps, const std::vector<char>& bodies,
            const Held& held);
  // True when the last apply() ran the body contact's surface detection for this step (the grid update may reuse it).
  bool detected_contact() const { return detected_; }
  // After the grid update: the work of this step's viscous nodal forces on the final velocities v^L is dissipated,
  // dt sum_i (K_v u)_i . v^L_i.
  void account(const Grid<D>& g, double dt);
  double dissipated() const { return dissipated_; }  // J, since t = 0
  // The dissipated energy and the factor CG reuses (as the matrix it factorised, refactorised on load), so that a
  // restart repeats the uninterrupted run exactly.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);
  struct Stats {
    long factorisations = 0, reused = 0, iterations = 0;  // solves by a fresh factor; by the last one (CG), CG iterations
  };
  const Stats& stats() const { return stats_; }

 private:
  struct Stencils {
    int nn = 0;                // entries per particle
    std::vector<Index> node;   // per particle and entry: field-local node
    std::vector<Vec<D>> grad;  // grad N
  };
  void solve_body(Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, double dt, double mass_eps, const Held& held);
  void operate(const Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, const std::vector<Vec<D>>& u,
               std::vector<Vec<D>>& out) const;
  bool preconditioned_solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  bool map_onto_factor(Index off, int nf);
  void index_factor_keys(std::size_t keys);
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z);

  std::vector<Stencils> stencils_;  // per body (damped ones only)
  std::vector<int> local_;          // field-local node -> unknown (-1: none)
  std::vector<int> entry_;          // per particle and entry: unknown (-1: none)
  std::vector<Index> nodes_;        // unknown -> field-local node
  std::vector<Vec<D>> rhs_, u_, q_;
  std::vector<Vec<D>> free_;        // per unknown: 1 for a free component, 0 for a held one
  std::vector<Vec<D>> vstar_, walled_, probe_;  // all node-fields: v*, after the walls and regions, after body contact
  struct Tie {
    Index k;   // the contact partner's node-field
    int l;     // the damped field's unknown
    Vec<D> n;  // contact normal
  };
  std::vector<Tie> ties_;
  std::vector<Mat<D>> blocks_;      // per unknown and neighbour offset: the block of A
  std::vector<char> used_;
  std::vector<int> dof_;            // per unknown component: free index, -1 held
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  Eigen::SparseMatrix<double> A_;
  std::vector<int> outer_, inner_;  // the pattern ldlt_ was analysed for
  bool factored_ = false;           // ldlt_ holds a numeric factor (of an earlier step's matrix of that pattern)
  std::vector<double> factored_values_;  // that matrix's values (pattern outer_, inner_)
  std::vector<Index> factor_key_;   // per unknown of the factor: node-field x D + component
  std::vector<int> factor_slot_;    // key -> the factor's unknown (-1: none), over all node-fields
  std::vector<Index> slot_keys_;    // the keys set in factor_slot_
  std::vector<int> map_;            // this step's unknown -> the factor's (-1: Jacobi)
  bool identity_ = false;           // map_ is the identity
  Eigen::VectorXd jacobi_, work_;
  bool stale_ = false;              // the last reuse came close to the budget: factorise at the next step
  int budget_ = 1;                  // solves a preconditioned CG may take: the factorisation's cost in solves
  Stats stats_;
  std::vector<int> pair_slot_;      // per pair of stencil entries: the offset slot
  bool probed_ = false, detected_ = false;
  std::vector<Index> acc_k_;        // this step's solved node-fields ...
  std::vector<Vec<D>> acc_f_;       // ... and K_v u there
  std::vector<char> material_on_;
  double dissipated_ = 0;
};

}  // namespace dmi
