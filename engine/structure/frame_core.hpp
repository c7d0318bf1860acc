// What the plane frame (frame.cpp) and the space frame (space_frame.cpp) hold and do alike: the assembled system
// (FrameSystem, SpaceFrameSystem), the time-stepping shell (FrameDynamics), the uniform element loads per element in
// local axes, their turning into nodal loads at the start of a step, the index checks, the static solution, the
// support reactions, the strain energy and the checkpoints. Each frame adds its own kinematics (point loads, the
// deformed centre line, section forces) around it. NodeDofs: 3 (plane) or 6 (space).
#pragma once
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/structure/frame_dynamics.hpp"

namespace dmi {

template <class System, class Load, int NodeDofs> struct FrameCore {
  using NodeVector = Eigen::Matrix<double, NodeDofs, 1>;
  using ElementVector = Eigen::Matrix<double, 2 * NodeDofs, 1>;

  template <class Model>
  FrameCore(Model m, const char* name) : sys(std::move(m)), dyn(sys, sys.model().integrator, sys.model().hht_alpha), name(name) {
    w.assign(sys.nelements(), Load::Zero());
  }

  void update_loads() {  // f = nodal + element loads at the current state
    if (f_current && sys.linear()) return;
    dyn.f = dyn.nodal;
    sys.add_element_loads(w, dyn.state.d, dyn.f);
    f_current = true;
  }
  void check_element(int e, double xi) const {
    if (e < 0 || e >= sys.nelements())
      throw std::invalid_argument(name + ": element index " + std::to_string(e) + " outside [0, " + std::to_string(sys.nelements()) + ")");
    if (!(xi >= 0 && xi <= 1))
      throw std::invalid_argument(name + ": element " + std::to_string(e) + ": xi = " + std::to_string(xi) + " outside [0, 1]");
  }
  void check_node(int n) const {
    if (n < 0 || NodeDofs * n >= sys.ndof())
      throw std::invalid_argument(name + ": node index " + std::to_string(n) + " outside [0, " + std::to_string(nnodes()) + ")");
  }
  int nnodes() const { return sys.ndof() / NodeDofs; }

  void clear_loads() {
    dyn.clear_loads();
    for (Load& x : w) x.setZero();
    f_current = false;
  }
  void add_nodal_load(int node, const NodeVector& f) {
    check_node(node);
    if (!f.allFinite()) throw std::invalid_argument(name + ": non-finite load at node " + std::to_string(node));
    dyn.nodal.template segment<NodeDofs>(NodeDofs * node) += f;
    f_current = false;
  }
  // The nodal forces g of a load on element e (its end nodes' DOFs, node i first).
  void add_element_end_loads(int e, const ElementVector& g) {
    const auto& el = sys.model().elements[e];
    dyn.nodal.template segment<NodeDofs>(NodeDofs * el.i) += g.template head<NodeDofs>();
    dyn.nodal.template segment<NodeDofs>(NodeDofs * el.j) += g.template tail<NodeDofs>();
    f_current = false;
  }
  void add_distributed_load(int e, const Load& w_local) {
    check_element(e, 0);
    if (!w_local.allFinite()) throw std::invalid_argument(name + ": non-finite load on element " + std::to_string(e));
    w[e] += w_local;
    f_current = false;
  }

  void advance(double dt) {
    update_loads();
    dyn.advance(sys, dt);
  }
  void solve_static(int increments) {
    dyn.state.d.setZero();
    f_current = false;
    update_loads();
    dyn.solve_static(sys, increments);
    f_current = false;
  }

  template <class Support> NodeVector reaction(int support, const std::vector<Support>& supports) const {
    if (support < 0 || support >= static_cast<int>(supports.size()))
      throw std::invalid_argument(name + ": support index " + std::to_string(support) + " out of range");
    Eigen::VectorXd f = dyn.nodal;
    sys.add_element_loads(w, dyn.state.d, f);
    return dyn.template reaction<NodeDofs>(sys, dyn.residual(sys, f), supports[support]);
  }

  // 0.5 d^T K_springs d plus each element's: the elastic energy of a plastic element's fibres, else 0.5 q^T f q.
  double strain_energy() const {
    const Eigen::VectorXd& d = dyn.state.d;
    double u = 0.5 * d.dot(sys.springs().cwiseProduct(d));
    for (int e = 0; e < sys.nelements(); ++e)
      u += sys.fibre_beam(e) ? sys.fibre_beam(e)->elastic_energy() : sys.element(e).strain_energy(sys.element_state(e, d).v);
    return u;
  }

  void save_state(StateWriter& out, const char* tag) const {
    dyn.save_state(out, tag, w, f_current);
    sys.fibres().save_state(out);
  }
  void load_state(StateReader& in, const char* tag) {
    dyn.load_state(in, tag, w, f_current);
    sys.fibres().load_state(in);
  }

  System sys;
  FrameDynamics dyn;
  std::vector<Load> w;  // uniform element loads, local axes (N/m)
  bool f_current = false;
  std::string name;     // "Frame", "SpaceFrame": the class errors name
};

}  // namespace dmi
