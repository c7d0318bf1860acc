// Time integrators of the frame's equation of motion M a + C v + f_int(d) = f (SEEDS.md A.3 eq. (26)),
// kept apart from the physics (STYLE.md rule 3): they see the frame only through FrameSystem. The loads f
// are held constant over a step.
#pragma once
#include <Eigen/Dense>
#include <memory>

#include "engine/structure/frame_system.hpp"

namespace dmi {

struct FrameState {
  Eigen::VectorXd d, v, a;  // full size; zero on restrained DOFs
  double t = 0;
  bool a_current = false;   // a satisfies the equation of motion at t (Newmark recomputes it otherwise)
};

class FrameTimeIntegrator {
 public:
  virtual ~FrameTimeIntegrator() = default;
  virtual double stable_time_step() const = 0;
  virtual void step(FrameState& s, const Eigen::VectorXd& f, double dt) = 0;
};

// SEEDS.md A.3 eqs. (27)-(29) (symplectic Euler): a_n = M^-1 (f - f_int(d_n) - C v_n),
// v_{n+1} = v_n + dt a_n, d_{n+1} = d_n + dt v_{n+1}. Per mode with damping ratio zeta the amplification
// matrix has det = 1 - 2 zeta omega dt and trace 2 - (omega dt)^2 - 2 zeta omega dt, stable for
// omega dt <= 2 (sqrt(1 + zeta^2) - zeta), i.e. dt <= 4 / (sqrt(4 omega^2 + c^2) + c), c = alpha + beta omega^2;
// it decreases with omega, so the highest mode of (K0, M) governs (2 / omega_max without damping).
// With d and v both at t_n the scheme is first-order accurate (d_1 = d_0 + dt^2 a_0 instead of dt^2 a_0 / 2);
// read as central differences with v_{n+1/2}, second order.
class ExplicitEuler final : public FrameTimeIntegrator {
 public:
  explicit ExplicitEuler(const FrameSystem& sys);
  double stable_time_step() const override { return dt_stable_; }
  void step(FrameState& s, const Eigen::VectorXd& f, double dt) override;

 private:
  const FrameSystem& sys_;
  double dt_stable_ = 0;
  Eigen::VectorXd fint_, cv_, r_;
};

// Newmark (1959) average acceleration, gamma = 1/2, beta = 1/4: unconditionally stable, and it conserves
// 0.5 v^T M v + 0.5 d^T K d exactly for a linear undamped system. d_{n+1} = d_n + dt v_n + dt^2/4 (a_n + a_{n+1}),
// v_{n+1} = v_n + dt/2 (a_n + a_{n+1}), equilibrium at t_{n+1}. In the increment D = d_{n+1} - d_n:
// a_{n+1} = 4/dt^2 D - 4/dt v_n - a_n, v_{n+1} = 2/dt D - v_n.
// Linear: (K0 + 2/dt C + 4/dt^2 M) D = f - K0 d_n + M (4/dt v_n + a_n) + C v_n, the matrix factorised when dt
// changes. Corotational: Newton-Raphson on R(D) = f - f_int - M a_{n+1} - C v_{n+1} with K_t + 2/dt C + 4/dt^2 M.
class Newmark final : public FrameTimeIntegrator {
 public:
  explicit Newmark(const FrameSystem& sys);
  double stable_time_step() const override;
  void step(FrameState& s, const Eigen::VectorXd& f, double dt) override;

 private:
  void initial_acceleration(FrameState& s, const Eigen::VectorXd& f);
  void step_linear(FrameState& s, const Eigen::VectorXd& f, double dt);
  void step_newton(FrameState& s, const Eigen::VectorXd& f, double dt);

  const FrameSystem& sys_;
  double dt_factored_ = 0;
  Eigen::SimplicialLDLT<SpMat> solver_;
  Eigen::VectorXd fint_, tmp_, rhs_, dd_;
};

std::unique_ptr<FrameTimeIntegrator> make_integrator(const FrameSystem& sys, FrameIntegrator kind);

}  // namespace dmi
