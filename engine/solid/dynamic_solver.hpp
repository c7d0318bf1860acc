// Linear transient dynamics M a + C v + K u = f(t) with fixed DOFs (held at zero, as in StaticSolver).
//   Newmark family (Hughes, The Finite Element Method (2000) section 9.1; Chopra, Dynamics of Structures,
//   section 5.4), "a-form" with predictors
//     u~ = u_n + dt v_n + dt^2 (1 - 2 beta) a_n / 2,   v~ = v_n + dt (1 - gamma) a_n,
//     u_n+1 = u~ + beta dt^2 a_n+1,                      v_n+1 = v~ + gamma dt a_n+1.
//   beta = 1/4, gamma = 1/2 (average acceleration, trapezoidal rule) is unconditionally stable,
//   second-order accurate and conserves kinetic + strain energy in undamped free vibration.
//   HHT-alpha (Hilber, Hughes & Taylor 1977; Hughes 2000 section 9.3.2), alpha in [-1/3, 0]:
//     M a_n+1 + (1 + alpha) (C v_n+1 + K u_n+1) - alpha (C v_n + K u_n) = (1 + alpha) f_n+1 - alpha f_n,
//   with gamma = (1 - 2 alpha) / 2, beta = (1 - alpha)^2 / 4 unless given: second order, unconditionally
//   stable, dissipating high frequencies (alpha = 0 is the average-acceleration rule).
//   Solved for a_n+1 with the effective matrix M* = M + (1 + alpha) (gamma dt C + beta dt^2 K) restricted
//   to the free DOFs, factorised once (Eigen SimplicialLDLT; constant dt).
//   Rayleigh damping C = a_M M + b_K K (M lumped or consistent as used); modal damping ratio
//   zeta(w) = a_M / (2 w) + b_K w / 2 (Chopra section 11.4).
//   Lumped mass: diagonal row sums of the given (consistent) M.
//   Reaction at t_n+1 (same sign as StaticSolver: the force the supports exert on the structure):
//     r = K u + C v + M a - f on the fixed DOFs, zero elsewhere (for HHT the free-DOF balance holds at the
//     alpha-point, the reaction is still taken from the state at t_n+1).
//   Energy: kinetic v^T M v / 2 + strain u^T K u / 2 (J).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <functional>
#include <vector>

namespace dmi::solid {

struct DynamicOptions {
  double dt_s = NAN;             // constant time step, > 0
  double hht_alpha = 0;          // in [-1/3, 0]
  double beta = NAN, gamma = NAN;  // NaN: from hht_alpha (1/4, 1/2 when alpha = 0)
  double rayleigh_mass = 0;      // a_M, 1/s
  double rayleigh_stiffness = 0; // b_K, s
  bool lumped_mass = false;      // row-sum lumping of M
  void validate() const;         // throws
  double newmark_beta() const;
  double newmark_gamma() const;
};

class DynamicSolver {
 public:
  // K, M full (n x n); fixed DOFs held at zero. Throws on bad sizes/options or a singular M* / M_ff.
  DynamicSolver(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                std::vector<int> fixed_dofs, const DynamicOptions& opt);
  // Sets u, v (full length, fixed entries ignored -> 0) and the load at time t0, and the consistent
  // initial acceleration a = M_ff^-1 (f - C v - K u)_f. The default state is at rest at t = 0 with f = 0.
  void initialize(const Eigen::VectorXd& u0, const Eigen::VectorXd& v0, const Eigen::VectorXd& f0, double t0 = 0);
  // Advances one dt with f_next = f(t + dt).
  void step(const Eigen::VectorXd& f_next);

  const Eigen::VectorXd& u() const { return u_; }
  const Eigen::VectorXd& v() const { return v_; }
  const Eigen::VectorXd& a() const { return a_; }
  const Eigen::VectorXd& f() const { return f_; }
  double time() const { return t0_ + steps_ * opt_.dt_s; }  // t_0 + n dt
  double dt() const { return opt_.dt_s; }
  double kinetic_energy() const;
  double strain_energy() const;
  double energy() const { return kinetic_energy() + strain_energy(); }
  Eigen::VectorXd reaction() const;  // full length, non-zero on fixed DOFs only
  const std::vector<int>& fixed_dofs() const { return fixed_; }
  const Eigen::SparseMatrix<double>& mass() const { return M_; }  // as used (lumped if requested)

 private:
  Eigen::VectorXd damping_times(const Eigen::VectorXd& x) const;  // C x
  Eigen::VectorXd solve_free(Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& s, const Eigen::VectorXd& rhs) const;
  DynamicOptions opt_;
  double beta_, gamma_;
  Eigen::SparseMatrix<double> K_, M_;
  std::vector<int> fixed_, free_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> eff_, mass_;
  Eigen::VectorXd u_, v_, a_, f_;
  double t0_ = 0;
  long steps_ = 0;
};

// Load history: f(t) (full length) sampled at t_0 + n dt.
using LoadHistory = std::function<Eigen::VectorXd(double t_s)>;

struct DynamicRecord {
  std::vector<double> time_s;         // t_0 ... t_N
  Eigen::MatrixXd u;                  // (N + 1) x record_dofs: displacement, m
  Eigen::MatrixXd reaction;           // (N + 1) x groups: summed reaction of each DOF group, N
  Eigen::VectorXd energy_J;           // kinetic + strain
  Eigen::VectorXd peak_u, peak_u_time_s;                // max |u| per recorded DOF (signed value at the peak)
  Eigen::VectorXd peak_reaction, peak_reaction_time_s;  // max |group reaction| (signed)
  double peak_nodal_reaction_N = 0;   // max over steps and fixed DOFs of |r_i|
};

// Re-initialises the solver at its current (u, v, time) with f(time) (consistent a), then takes n_steps.
DynamicRecord run_history(DynamicSolver& s, const LoadHistory& f, int n_steps, const std::vector<int>& record_dofs,
                          const std::vector<std::vector<int>>& reaction_groups = {});

}  // namespace dmi::solid
