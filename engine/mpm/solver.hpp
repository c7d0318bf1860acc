// Explicit MPM solver: advances a Scene by one step at a time (Lin & Yang 2024, USL or MUSL).
// Output, checkpoints and progress stay outside; the driver calls step() and reads diagnostics.
#pragma once
#include <array>
#include <chrono>
#include <memory>
#include <string>

#include "engine/mpm/member_contact.hpp"
#include "engine/mpm/clearance.hpp"
#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"
#include "engine/mpm/rigid.hpp"
#include "engine/mpm/fluid_volume.hpp"
#include "engine/mpm/viscous.hpp"

namespace dmi {

template <int D> struct Diagnostics {
  double kinetic = 0, strain = 0;  // J
  double dissipated = 0;           // J, by material viscosity and plasticity since t = 0
  double gravity_work = 0;         // J, work of gravity since t = 0: sum m g.(x - x0)
  double boundary_work = 0;        // J, work of walls and prescribed velocities since t = 0
  Vec<D> momentum = Vec<D>::Zero();  // kg m/s (continua only)
  double frame_kinetic = 0, frame_strain = 0;  // J, beam-column members
  double frame_gravity_work = 0;   // J, work of the members' self-weight
  double contact_work = 0;         // J, work of the material on the members (contact reactions)
  // What inflows brought in since t = 0: mass (kg), momentum (kg m/s) and kinetic energy (J) of the debris as created.
  double inflow_mass = 0, inflow_energy = 0;
  Vec<D> inflow_momentum = Vec<D>::Zero();
  double frame_damping = 0;        // J, dissipated by the frame's Rayleigh damping
  double frame_plastic = 0;        // J, plastic work in the frame's elasto-plastic members
  // Energy balance error (J) of the whole system, continua and frame: stored energy minus the work of
  // gravity and walls (and inflow zones) and the energy inflows brought in, minus E_0. Member contact is internal to the system, so its losses (and any
  // numerical loss or gain) show here: negative = dissipated.
  double balance(double e0) const {
    return kinetic + strain + dissipated + frame_kinetic + frame_strain + frame_damping + frame_plastic - gravity_work - boundary_work -
           frame_gravity_work - inflow_energy - e0;
  }
};

template <int D> class Solver {
 public:
  explicit Solver(Scene<D> scene);

  // Stable step from the CFL condition over all bodies: dt = cfl h / max_b (c_b + |v|_max,b),
  // bounded by the user dt_max and by `limit` (e.g. the time left to the end).
  double stable_time_step(double limit) const;
  // One explicit step of length dt; throws RunError on NaN/Inf or a particle leaving the grid.
  void step(double dt);

  Diagnostics<D> diagnostics() const;
  double time() const { return time_; }
  long steps() const { return steps_; }
  // Courant number of the step last returned by stable_time_step: max over bodies of dt (c + |v|_max) / h (the
  // dt_max or end-of-run limits can make it smaller than the cfl factor; never larger).
  double courant() const { return courant_; }
  // Smallest J = V / V0 over the particles now (a collapse of particles shows as J -> 0).
  double min_jacobian() const;
  const Scene<D>& scene() const { return scene_; }
  const MemberContact<D>* member_contact() const { return members_.get(); }
  const ImplicitViscosity<D>* viscosity() const { return viscosity_.get(); }
  Scene<D>& scene() { return scene_; }
  // The whole dynamic state (time, step count, particles, material history, members, the last binning's order),
  // for checkpoints: a solver built from the same scenario and given load_state() steps on bit for bit.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

  // Wall time of each phase of step() since profile(true) (the small-scene bench, verify/bench.cpp). Off: one
  // untaken branch per phase.
  enum Phase { kBinning, kP2G, kWallTouch, kViscosity, kMembers, kGridUpdate, kBodyContact, kRigid, kG2P, kFrame, kPhases };
  static const char* phase_name(int p);
  void profile(bool on) { profile_ = on; }
  // Binnings other than the particle sorts' (a particle left its tile's margin, particles were added, the first one),
  // for benchmarks.
  long rebins() const { return rebins_; }
  const std::array<double, kPhases>& phase_seconds() const { return phase_seconds_; }
  // Constraint passes on the rigid bodies' nodes beyond the first projection, summed over the steps (rigid_constraints).
  long rigid_passes() const { return rigid_passes_; }
  // rigid_when_free bodies: how often one turned rigid or elastic, and the steps taken with one rigid.
  long free_switches() const { return free_switches_; }
  long free_rigid_steps() const { return free_rigid_steps_; }

 private:
  static constexpr long kSortInterval = 16;  // steps between particle reorderings (sort_particles)
  static constexpr double kImplicitGain = 3.0;  // implicit viscosity only where it lengthens the step more than this
  static constexpr int kRigidPasses = 200;      // constraint passes on the rigid bodies' nodes per step, at most
  void sort_particles();
  void particles_to_grid();
  void implicit_viscosity(double dt);
  void rigid_constraints(double dt);
  void member_boundary_forces(double dt);
  void advance_members(double dt);
  void grid_update(double dt);
  bool grid_to_particles(double dt);
  void update_stress(double dt);
  void switch_free_bodies();
  [[noreturn]] void fail(const std::string& what) const;
  bool profile_ = false;
  long rigid_passes_ = 0;
  long free_switches_ = 0, free_rigid_steps_ = 0;
  double frozen_energy_ = 0;  // J: vibration and strain energy given up by rigid_when_free bodies turning rigid
  std::vector<std::vector<double>> free_gaps_;  // rigid_when_free bodies: the last step's separations (body_gaps), 3 per item
  std::vector<Gap> gaps_;                        // scratch
  long rebins_ = 0;  // binnings not on a sort step: particles moved out of their tiles' margin or added, the first
  std::vector<Index> rigid_nodes_;  // rigid_constraints: the active nodes where a rigid field has mass
  std::array<double, kPhases> phase_seconds_{};
  std::chrono::steady_clock::time_point lap_t_;
  void lap(Phase p) {  // the time since the last lap goes to phase p
    if (!profile_) return;
    const auto t = std::chrono::steady_clock::now();
    phase_seconds_[p] += std::chrono::duration<double>(t - lap_t_).count();
    lap_t_ = t;
  }

  Scene<D> scene_;
  std::unique_ptr<TransferKernels<D>> kernels_;
  std::unique_ptr<MemberContact<D>> members_;  // when the scene has a frame
  std::unique_ptr<ImplicitViscosity<D>> viscosity_;  // when a damped body is integrated implicitly
  std::unique_ptr<RigidBodies<D>> rigid_;            // when the scene has rigid bodies
  std::unique_ptr<FluidVolumes<D>> fluid_;           // when a fluid relaxes its volumes
  double time_ = 0.0;
  long steps_ = 0;
  double boundary_work_ = 0.0;
  double mass_eps_ = 0.0;  // nodal masses below this are treated as empty
  mutable double courant_ = 0.0;
  mutable std::vector<char> implicit_now_;  // per body: its viscosity integrated implicitly this step
  typename ImplicitViscosity<D>::Held held_;  // members' stuck nodes, scratch
};

}  // namespace dmi
