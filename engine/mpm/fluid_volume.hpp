// Volumes of weakly compressible fluids kept consistent with the space their particles fill.
// A fluid's only state is its volume ratio J (engine/materials/viscous_fluid.hpp), integrated per particle from the
// velocity gradient, while the particles move with the interpolated velocity. The two drift apart where the flow
// splashes and thins to single particles (the empty-node rule, the tension cut-off, walls whose interpolated velocity
// on the plane still points into them): a stopped stream then packs 1.3-2.8 times the mass into the space it fills
// with J near 1, and its pressure never sees it (docs/verification.md, "alpha against the Froude number"). Here each
// step J relaxes towards the ratio the grid measures, the particles' reference volumes present at their nodes against
// the space those nodes hold,
//   J_grid,p = sum_i N_ip V_i / sum_i N_ip (sum_q N_iq V0_q),   V_i = integral of N_i over the space in front of the walls,
// (the density-summation form of the equation of state, rho_p = rho0 / J_grid, as SPH takes rho = sum_q m_q W_pq,
// Monaghan 1992; V_i = h^D away from walls), by J <- J (J_grid / J)^kappa, kappa = min(1, dt c0 / (n h)): over n
// acoustic cell transits, so the pressure noise of a density read from particle positions is filtered while a drift
// that builds up over the flow's time is undone. The strain energy the relaxation changes, sum V0 (W(J') - W(J)), is
// counted (added energy as negative dissipation) so that the energy balance stays closed and shows it.
// V_i counts walls only: next to another body or a member a fluid reads the nodes it shares as partly empty (its
// pressure there is relaxed towards zero, and it packs closer before it pushes). Fields holding several fluids share
// one J_grid per particle stencil.
#pragma once
#include <vector>

#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"

namespace dmi {

template <int D> class FluidVolumes {
 public:
  // True when a deformable body's material keeps its volume with a relaxation (Material::volume_relaxation() > 0).
  static bool needed(const Scene<D>& s);
  // After the stress update: J, F = J^(1/D) I and V = V0 J of those bodies' particles relaxed as above.
  void apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt);
  double added_energy() const { return added_; }  // J: strain energy the relaxation added since t = 0 (negative: removed)
  void save_state(StateWriter& w) const { w.put(added_); }
  void load_state(StateReader& r) { r.get(added_); }
  // V_i (m^D) of every node: the integral of its shape function over the space in front of every wall (quadrature
  // on 8 (2D) or 4 (3D) points per cell and axis where a wall cuts the support, h^D elsewhere).
  static std::vector<double> node_volumes(const Scene<D>& s);

 private:
  std::vector<double> vol_, ref_;  // per node: V_i, and sum_q N_iq V0_q of one field
  std::vector<Index> node_;
  std::vector<double> w_;
  std::vector<Vec<D>> grad_;
  double added_ = 0;
};

}  // namespace dmi
