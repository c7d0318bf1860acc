// Time integrators of the frame's equation of motion M a + C v + f_int(d) = f (Lin & Yang 2024 eq. (26)),
// kept apart from the physics: they see the frame only through AssembledSystem. The loads f
// are held constant over a step.
#pragma once
#include <Eigen/Dense>
#include <memory>

#include "engine/structure/assembled_system.hpp"
#include "engine/structure/frame.hpp"

namespace dmi {

struct FrameState {
  Eigen::VectorXd d, v, a;  // full size; zero on restrained DOFs
  double t = 0;
  bool a_current = false;   // a satisfies the equation of motion at t (Newmark recomputes it otherwise)
};

// Ma: mass attached to the frame for this step only (material held by member contact, lumped to the
// nodes' translational DOFs), or nullptr. It enters the inertia of the step, M -> M + Ma: the
// implicit added-mass treatment that keeps the staggered MPM-frame coupling stable when the material
// is heavy against the member (a partitioned coupling with the reaction from v*_n alone rang up).
class FrameTimeIntegrator {
 public:
  virtual ~FrameTimeIntegrator() = default;
  virtual double stable_time_step() const = 0;
  virtual void step(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) = 0;
  // History vectors carried from one step to the next (checkpoints). Factorisations are rebuilt: they are a
  // deterministic function of the matrices, so a restarted run refactorises to the same bits.
  virtual void save_state(StateWriter& w) const = 0;
  virtual void load_state(StateReader& r) = 0;
};

// Lin & Yang 2024 eqs. (27)-(29) (symplectic Euler): a_n = M^-1 (f - f_int(d_n) - C v_n),
// v_{n+1} = v_n + dt a_n, d_{n+1} = d_n + dt v_{n+1}. Per mode with damping ratio zeta the amplification
// matrix has det = 1 - 2 zeta omega dt and trace 2 - (omega dt)^2 - 2 zeta omega dt, stable for
// omega dt <= 2 (sqrt(1 + zeta^2) - zeta), i.e. dt <= 4 / (sqrt(4 omega^2 + c^2) + c), c = alpha + beta omega^2;
// it decreases with omega, so the highest mode of (K0, M) governs (2 / omega_max without damping).
// With d and v both at t_n the scheme is first-order accurate (d_1 = d_0 + dt^2 a_0 instead of dt^2 a_0 / 2);
// read as central differences with v_{n+1/2}, second order.
class ExplicitEuler final : public FrameTimeIntegrator {
 public:
  explicit ExplicitEuler(const AssembledSystem& sys);
  double stable_time_step() const override { return dt_stable_; }
  void step(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) override;
  void save_state(StateWriter& w) const override { w.put(fint_), w.put(cv_), w.put(r_); }
  void load_state(StateReader& r) override { r.get(fint_), r.get(cv_), r.get(r_); }

 private:
  const AssembledSystem& sys_;
  double dt_stable_ = 0;
  Eigen::VectorXd fint_, cv_, r_;
  Eigen::SimplicialLDLT<SpMat> added_solver_;  // M + Ma, refactorised in steps with attached mass
};

// Newmark family in the HHT-alpha form (Hilber, Hughes & Taylor 1977): equilibrium
//   (M + Ma) a_{n+1} + (1 + alpha)(C v_{n+1} + f_int(d_{n+1})) - alpha (C v_n + f_int(d_n)) = f,
//   d_{n+1} = d_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_{n+1}), v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}),
//   gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4, alpha in [-1/3, 0] (FrameModel::hht_alpha).
// alpha = 0 is the average-acceleration rule (Newmark 1959): second order, no numerical damping, it
// conserves 0.5 v^T M v + 0.5 d^T K d for a linear undamped frame. alpha < 0 damps modes with
// omega dt >> 1 and stays second order and unconditionally stable: members coupled to the grid
// need it, since stick contact feeds the undamped high modes that ring at omega dt >> 1 back into
// the material (a debris block on a steel pipe gained 4e6 J with alpha = 0 at dt = 1e-4 s).
// Linear: the effective matrix c0 (M + Ma) + (1 + alpha)(K0 + c1 C) is factorised when dt changes
// (and in steps with attached mass); corotational or plastic: Newton-Raphson with K_t in place of K0, with a
// backtracking line search on the residual; a step whose Newton iterations fail is retried in 2, 4, ... 64 sub-steps,
// each committed (a plastic hinge forming within a step can leave the tangent too soft for the full step). The modal damping term
// U diag(rates) U^T joins the sparse factorisation as a low-rank update (Woodbury identity, Golub & Van Loan
// 2013, sec. 2.1.4): (A + U D U^T)^-1 b = A^-1 b - Y (D^-1 + U^T Y)^-1 U^T A^-1 b, Y = A^-1 U.
class Newmark final : public FrameTimeIntegrator {
 public:
  Newmark(AssembledSystem& sys, double hht_alpha);
  double stable_time_step() const override;
  void step(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma) override;
  void save_state(StateWriter& w) const override { w.put(fint_), w.put(fint0_), w.put(tmp_), w.put(rhs_), w.put(dd_); }
  void load_state(StateReader& r) override {
    r.get(fint_), r.get(fint0_), r.get(tmp_), r.get(rhs_), r.get(dd_);
    dt_factored_ = 0;  // refactorise on the next step
    pattern_outer_.clear();
  }

 private:
  void initial_acceleration(FrameState& s, const Eigen::VectorXd& f);
  void kinematics(const FrameState& n, const Eigen::VectorXd& D, double dt, FrameState& s);
  void step_linear(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma);
  void step_newton(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma);
  // One Newton solve of the step; false (s left at t_n) when it does not converge.
  bool newton(FrameState& s, const Eigen::VectorXd& f, double dt, const SpMat* Ma, double& residual, double& reference);
  // Factorises A (the sparse part of the effective matrix) and, with modal damping weighted by c_modal in the
  // effective matrix, the Woodbury capacitance matrix.
  bool factorize(const SpMat& A, double c_modal, bool throw_on_failure = true);
  // x = (A + c_modal U diag(rates) U^T)^-1 b for the last factorisation.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

  AssembledSystem& sys_;  // non-const: sub-steps commit plastic elements
  double alpha_ = 0, beta_ = 0.25, gamma_ = 0.5;
  double dt_factored_ = 0;   // 0: keff_ is stale (new dt, or restarted)
  bool factored_with_mass_ = false;  // solver_ holds keff_ + c0 Ma, not keff_
  SpMat kc_, mc_;            // constrained K0 and M on one pattern
  SpMat keff_, keff_ma_;     // constrained effective matrix for dt_factored_, and with the attached mass
  std::vector<int> pattern_outer_, pattern_inner_;  // the sparsity pattern solver_ last analysed
  Eigen::SimplicialLDLT<SpMat> solver_;
  Eigen::MatrixXd modal_Y_;                 // A^-1 U
  Eigen::LLT<Eigen::MatrixXd> capacitance_; // (c_modal diag(rates))^-1 + U^T A^-1 U
  Eigen::VectorXd fint_, fint0_, tmp_, rhs_, dd_;
};

std::unique_ptr<FrameTimeIntegrator> make_integrator(AssembledSystem& sys, FrameIntegrator kind, double hht_alpha);

}  // namespace dmi
