// The time-stepping shell shared by the plane frame (frame.hpp) and the space frame (space_frame.hpp): the state,
// the integrator, the loads held over a step (given through the owner: nodal loads and the total f, element loads
// included), the mass attached for one step, and the work counters; the static solution and the support residual.
#pragma once
#include <memory>

#include "engine/common/state_io.hpp"

#include "engine/structure/assembled_system.hpp"
#include "engine/structure/integrator.hpp"

namespace dmi {

struct FrameDynamics {
  FrameDynamics(AssembledSystem& sys, FrameIntegrator kind, double hht_alpha);

  // Advances by dt under f (held constant); the work of f, of the nodal part and of the damping is booked.
  void advance(AssembledSystem& sys, double dt);
  // Equilibrium under f on the free DOFs (state set to it, velocity and acceleration zero): K0 d = f, or for a
  // corotational frame Newton-Raphson on f_int(d) = f in equal load increments (residual below 1e-10 of the load).
  void solve_static(AssembledSystem& sys, int increments = 1);
  // r = f_int + M a + C v - f at the current state: on a restrained DOF, the support's reaction.
  Eigen::VectorXd residual(const AssembledSystem& sys, const Eigen::VectorXd& f) const;
  void clear_loads() { nodal.setZero(), added.clear(); }
  double kinetic_energy(const AssembledSystem& sys) const { return 0.5 * state.v.dot(sys.mass() * state.v); }
  // Mass m (a translational block in global axes) attached for the next step at a point whose velocity is G^T times
  // the DOFs of nodes i and j (node_dofs each, node i first): the consistent block G m G^T, G the map of a point force
  // to nodal forces (its columns: unit forces along the global axes), so that the mass moves as the point it sits on.
  template <class GMatrix, class Matrix> void add_point_mass(int node_dofs, int i, int j, const GMatrix& G, const Matrix& m) {
    const Eigen::MatrixXd block = G * m * G.transpose();
    for (int a = 0; a < block.rows(); ++a)
      for (int b = 0; b < block.cols(); ++b)
        if (block(a, b) != 0)
          added.emplace_back(node_dofs * (a < node_dofs ? i : j) + a % node_dofs, node_dofs * (b < node_dofs ? i : j) + b % node_dofs, block(a, b));
  }

  // Force and moment a support exerts on the frame, given the residual r of the total loads: a restrained DOF takes
  // r = f_int + M a + C v - f_ext (the rows of the full matrices couple the free DOFs), a spring on a free DOF
  // -k u; a fixed DOF ignores its spring. After an explicit step a is the acceleration the step used (t_n); it enters
  // only through consistent-mass coupling (lumped: M a = 0 on restrained DOFs).
  template <int N, class Support> Eigen::Matrix<double, N, 1> reaction(const AssembledSystem& sys, const Eigen::VectorXd& r, const Support& s) const {
    Eigen::Matrix<double, N, 1> out;
    for (int c = 0; c < N; ++c) {
      const int i = N * s.node + c;
      out(c) = s.fixed[c] ? r(i) : -sys.springs()(i) * state.d(i);
    }
    return out;
  }
  // Checkpoints: the state, loads, scratch, the owner's element loads w and load flag, the work and the integrator.
  template <class W> void save_state(StateWriter& out, const char* tag, const W& w, bool f_current) const {
    out.tag(tag);
    out.put(state.d), out.put(state.v), out.put(state.a), out.put(state.t), out.put(state.a_current);
    out.put(nodal), out.put(f), out.put(d_prev), out.put(v_prev), out.put(cv), out.put(w);
    out.put(f_current), out.put(work_ext), out.put(work_damp), out.put(work_applied);
    integrator->save_state(out);
  }
  template <class W> void load_state(StateReader& in, const char* tag, W& w, bool& f_current) {
    in.tag(tag);
    const auto n = static_cast<std::size_t>(state.d.size());
    const std::size_t ne = w.size();
    in.get(state.d), in.get(state.v), in.get(state.a), in.get(state.t), in.get(state.a_current);
    in.get(nodal), in.get(f), in.get(d_prev), in.get(v_prev), in.get(cv), in.get(w);
    for (const Eigen::VectorXd* x : {&state.d, &state.v, &state.a, &nodal, &f})
      in.expect_size("frame DOFs", static_cast<std::size_t>(x->size()), n);
    in.expect_size("frame elements", w.size(), ne);
    in.get(f_current), in.get(work_ext), in.get(work_damp), in.get(work_applied);
    added.clear();
    integrator->load_state(in);
  }

  std::unique_ptr<FrameTimeIntegrator> integrator;
  FrameState state;
  Eigen::VectorXd nodal, f, d_prev, v_prev, cv;  // loads (global), step scratch
  Triplets added;                                // attached mass of the next step (kg)
  double work_ext = 0, work_damp = 0, work_applied = 0;
};

}  // namespace dmi
