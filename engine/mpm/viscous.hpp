// Implicit Kelvin-Voigt viscosity on the grid.
// A damped body's stress is sigma = sigma_e + sigma_v, sigma_v = a tr(D) I + 2 b D (a = beta lambda, b = beta mu,
// beta = zeta / (pi f)). Integrated explicitly, sigma_v cuts the stable step to (2/w)(sqrt(1 + zeta^2) - zeta),
// zeta = beta w / 2, w = 2 sqrt(D) c / h: for strong damping h^2 / (2 D beta c^2), the viscous limit of the grid's
// checkerboard modes, which falls as h^2. Here the nodal velocities of a damped body follow, from the step's
// momentum p = M v, the flow under the elastic nodal force f_e held constant over the step,
//   M du/dt = f_e - K_v u,   K_v u = sum_p V_p sigma_v(D_p(u)) grad N_ip,   D_p(u) = sym(sum_i u_i (x) grad N_ip),
// per damped body over the nodes of its field for the step dt, and the step's viscous nodal force is the momentum it
// removed, f_e - M (u - v) / dt. f_e is P2G's nodal force less the viscous stress of the last update, which P2G scattered
// with the elastic one; the viscous force then joins it, so that members, walls and contact see one nodal force as
// before. The flow is integrated by damped Chebyshev stages (DampedChebyshev: explicit and matrix-free, about
// 2 sqrt(dt lambda_max) passes of the viscous operator, lambda_max bounded per particle), so the step stays the
// elastic CFL step. (A backward Euler solve by a sparse LDL^T factorisation did this until it cost 36 ms a step on
// the buffer at h = 0.01 m: docs/performance.md.)
#pragma once
#include <vector>


#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"

namespace dmi {

// Damped Chebyshev polynomials for the viscous sub-step (the first-order Runge-Kutta-Chebyshev method; van der
// Houwen & Sommeijer 1980; Verwer, Hundsdorfer & Sommeijer 1990): R_s(z) = T_s(w0 - w1 z) / T_s(w0) for the decay
// rate z = dt lambda, w0 = 1 + eps / s^2, w1 = T_s(w0) / T_s'(w0), so that R_s = 1 - z + O(z^2) and |R_s| <= 1 / T_s(w0)
// on [0, beta_s], beta_s = (1 + w0) / w1. eps = 2 damps every mode of that interval at least to 1 / cosh 2 = 0.27
// (the exact flow removes the grid's stiff modes; eps = 0 would keep them) at beta_s ~ 0.96 s^2. With the elastic force
// f = -w^2 x held over the flow, a mode of decay rate z and a = (w dt)^2 steps as v' = R v - (1 - R) a / z (x / dt),
// x' = x + dt v' (symplectic Euler; a fixed point where f balances the viscous force): determinant R, trace
// 1 + R - (1 - R) a / z, stable while (1 - R) a / z <= 2 (1 + R). On [0, z_1] (z_1 the first root of R_s, >= 1)
// R >= 1 - z >= 0 and this is a <= 2 (1 + R); beyond it R >= -1/T_s(w0) >= -1/3, and it holds for a <= 1 at every s
// (tested). So one piece where the body's elastic Courant number keeps a <= 1 (one_piece); elsewhere a step is two
// half-steps (or 4, 8, ... pieces), R_s(z / 2)^2 >= 0, for which it is the explicit elastic limit a <= 4.
struct DampedChebyshev {
  static constexpr double kDamping = 2.0;
  static constexpr int kMaxStages = 200;  // per half-step; beyond, the step is cut in more pieces (pieces_for)
  explicit DampedChebyshev(int s);
  int s;
  double w0 = 1, w1 = 1;
  std::vector<double> T;  // T_j(w0), j = 0..s
  double beta() const { return (1 + w0) / w1; }
  double amplification(double z) const;  // R_s(z)
  // The fewest stages per half-step whose interval holds z / 2 (a step's z), 0 when none up to kMaxStages does or z
  // is not finite.
  static int stages_for(double z);
  // The fewest pieces of the step (2, 4, 8, ...; each by stages_for(2 z / pieces) stages) that keep the stages within
  // kMaxStages; 0 when z is not finite.
  static int pieces_for(double z);
  // Whether the step may be one piece: the fastest elastic mode's w dt (2 sqrt(D) (c + |v|) dt / h) at most 1.
  static bool one_piece(double omega_dt);
};

template <int D> class ImplicitViscosity {
 public:
  // True when the bodies whose material has constant Kelvin-Voigt coefficients (Material::viscous_coefficients) share
  // one velocity field. Damped bodies in several fields (discrete tyres in contact with one another) stay explicit:
  // their contact would need one joint solve over the fields, which is not built.
  static bool needed(const Scene<D>& s);
  // Node-field pairs (field * nnodes + node) the sub-step holds at a given velocity: members' stuck nodes.
  using Held = std::vector<std::pair<Index, Vec<D>>>;
  // Replaces the viscous part of the nodal force of the bodies flagged in `bodies` (a material is integrated
  // implicitly when any of its bodies is; its own dissipation count is then off) by the implicit one. Nodes with mass
  // <= mass_eps are left out. The constraints that act after this force are tried first on the predictor v* of every
  // field (at time t): the components the walls and regions would change are held at the value they would give, and
  // so are the members' stuck nodes in held (their viscous force then reaches the wall or member through the
  // constraint, as an elastic force does); where body contact would change the damped field, the other field's
  // nodal mass joins it along the contact normal n (the direction of the change), m_A + m_B n n^T, so that both leave
  // the sub-step with one normal velocity and the contact force includes the viscous one (momentum is exchanged, not
  // made). Wall touch sets must be current. Throws RunError if the sub-step fails.
  void apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt, double t, double mass_eps, const std::vector<char>& bodies,
            const Held& held);
  // True when the last apply() ran the body contact's surface detection for this step (the grid update may reuse it).
  bool detected_contact() const { return detected_; }
  // After the grid update: the work of this step's viscous nodal forces (the sub-step's mean K_v u) on the final
  // velocities v^L is dissipated, dt sum_i (K_v u)_i . v^L_i.
  void account(const Grid<D>& g, double dt);
  double dissipated() const { return dissipated_; }  // J, since t = 0
  // The dissipated energy and the counts, so that a restart repeats the uninterrupted run exactly.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);
  struct Stats {
    long steps = 0, stages = 0;  // viscous sub-steps (per damped body and step), and their Chebyshev stages
  };
  const Stats& stats() const { return stats_; }

 private:
  struct Stencils {
    int nn = 0;                // entries per particle
    std::vector<Index> node;   // per particle and entry: field-local node
    std::vector<double> weight;  // N
    std::vector<Vec<D>> grad;  // grad N
    std::vector<Mat<D>> H;     // per particle sum grad N grad N^T / N (the rate bound)
    double lambda = 0;         // bound on lambda_max(M^-1 K_v) (1/s); grows as 1/N near a node line of linear hats
  };
  void chebyshev(Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, double dt, int stages, int pieces);
  void solve_body(Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, double dt, double mass_eps, const Held& held);
  void operate(const Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, const std::vector<Vec<D>>& u,
               std::vector<Vec<D>>& out);
  template <int NN>
  void operate_nn(const Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, const std::vector<Vec<D>>& u,
                  std::vector<Vec<D>>& out);
  void incidence(const Stencils& st);

  std::vector<Stencils> stencils_;  // per body (damped ones only)
  std::vector<int> local_;          // field-local node -> unknown (-1: none)
  std::vector<int> entry_;          // per particle and entry: unknown (n, the pad, where none)
  std::vector<Index> nodes_;        // unknown -> field-local node
  std::vector<Vec<D>> rhs_, fe_, u_, q_;  // M' Y_0 (momentum at t), f_e (joined along n at ties), Y, Q
  std::vector<Vec<D>> y0_, q2_, ky_, qsum_;  // Chebyshev: Y_0, Q_j-2, K Y_j-1, the mean force
  std::vector<Mat<D>> minv_;          // per unknown: M'^-1
  std::vector<Mat<D>> sv_;            // operate: per particle V_p sigma_v
  std::vector<double> rate_num_, rate_den_;  // per grid node: sum_p N_ip q_p and sum_p N_ip m_p (the rate bound)
  std::vector<int> inc_start_, inc_particle_, fill_;  // per unknown: its particle entries (CSR), their particle
  std::vector<Vec<D>> inc_grad_;      // ... and grad N
  std::vector<Vec<D>> free_;        // per unknown: 1 for a free component, 0 for a held one
  std::vector<Vec<D>> vstar_, walled_, probe_;  // all node-fields: v*, after the walls and regions, after body contact
  struct Tie {
    Index k;   // the contact partner's node-field
    int l;     // the damped field's unknown
    Vec<D> n;  // contact normal
  };
  std::vector<Tie> ties_;
  struct Slave {
    int l, master, wall;  // an unknown behind a bilateral wall on a grid line, its image in front (u_l = S u_master)
    Mat<D> S;
  };
  std::vector<Slave> slaves_;
  std::vector<char> walled_node_, master_of_;  // per unknown: held by a wall; the image of a mirrored node
  Stats stats_;
  bool probed_ = false, detected_ = false;
  bool serial_ = false;             // this step's operate(): one scatter pass (one thread), else two parallel passes
  std::vector<Index> acc_k_;        // this step's solved node-fields ...
  std::vector<Vec<D>> acc_f_;       // ... and K_v u there
  std::vector<char> material_on_;
  double dissipated_ = 0;
};

}  // namespace dmi
