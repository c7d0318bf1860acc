#include "engine/structure/frame_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dmi {

FrameDynamics::FrameDynamics(AssembledSystem& sys, FrameIntegrator kind, double hht_alpha)
    : integrator(make_integrator(sys, kind, hht_alpha)) {
  const int n = sys.ndof();
  for (Eigen::VectorXd* x : {&state.d, &state.v, &state.a, &nodal, &f, &d_prev, &v_prev, &cv}) x->setZero(n);
}

void FrameDynamics::advance(AssembledSystem& sys, double dt) {
  if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("Frame::advance: dt must be positive");
  d_prev = state.d;
  v_prev = state.v;
  if (added.empty()) {
    integrator->step(state, f, dt, nullptr);
  } else {
    const SpMat Ma = from_triplets(sys.ndof(), added);
    integrator->step(state, f, dt, &Ma);
  }
  sys.commit(state.d);
  d_prev = state.d - d_prev;
  work_ext += f.dot(d_prev);  // loads constant over the step
  work_applied += nodal.dot(d_prev);
  if (sys.damped()) {
    v_prev = 0.5 * (v_prev + state.v);  // midpoint velocity
    sys.damping_force(v_prev, cv);
    work_damp += dt * v_prev.dot(cv);
  }
  if (!state.d.allFinite() || !state.v.allFinite())
    throw std::runtime_error("Frame: non-finite state at t = " + std::to_string(state.t) + " s (time step above the stable limit " +
                             std::to_string(integrator->stable_time_step()) + " s?)");
}

void FrameDynamics::solve_static(AssembledSystem& sys, int increments) {
  Eigen::SimplicialLDLT<SpMat> ldlt(sys.constrained(sys.stiffness()));
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("Frame: static stiffness factorisation failed");
  const Eigen::VectorXd fm = f.cwiseProduct(sys.free());
  state.d = ldlt.solve(fm);
  if (!sys.linear()) {  // Newton-Raphson on f_int(d) = (k / n) f, k = 1..n, from the linear solution scaled to 1 / n
    constexpr int kMaxIterations = 50;
    state.d /= increments;
    Eigen::VectorXd fint(sys.ndof()), r;
    for (int k = 1; k <= increments; ++k) {
      const Eigen::VectorXd fk = (double(k) / increments) * fm;
      const double ref = std::max(fk.norm(), std::numeric_limits<double>::min());
      for (int it = 0;; ++it) {
        sys.internal_force(state.d, fint);
        r = fk - fint.cwiseProduct(sys.free());
        if (r.norm() <= 1e-10 * ref) break;
        if (it == kMaxIterations)
          throw std::runtime_error("Frame: static Newton iterations did not converge at load step " + std::to_string(k) + " of " +
                                   std::to_string(increments) + " (residual " + std::to_string(r.norm() / ref) + " of the load)");
        ldlt.compute(sys.constrained(sys.tangent(state.d)));
        if (ldlt.info() != Eigen::Success) throw std::runtime_error("Frame: static tangent factorisation failed (a limit point?)");
        state.d += ldlt.solve(r);
      }
      sys.commit(state.d);
    }
  }
  state.v.setZero();
  state.a.setZero();
  state.a_current = false;
}

Eigen::VectorXd FrameDynamics::residual(const AssembledSystem& sys, const Eigen::VectorXd& f_total) const {
  Eigen::VectorXd fint(sys.ndof()), c(sys.ndof());
  sys.internal_force(state.d, fint);
  sys.damping_force(state.v, c);
  return fint + sys.mass() * state.a + c - f_total;
}

}  // namespace dmi
