#include "engine/common/parallel.hpp"
#include "engine/mpm/solver.hpp"

#include <limits>
#include <vector>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine/common/error.hpp"
#include "engine/mpm/boundary.hpp"
#include "engine/mpm/clearance.hpp"

namespace dmi {

template <int D> Solver<D>::Solver(Scene<D> scene) : scene_(std::move(scene)) {
  // With linear weights D_p = diag(f(1-f) h^2) vanishes at nodes and APIC's C_p = B_p D_p^-1 is undefined; the
  // parser refuses the pair with a message, this guards programmatic scenes.
  if (scene_.options.shape == ShapeKind::linear && scene_.options.transfer == TransferKind::apic)
    throw std::invalid_argument("APIC transfer needs gimp or bspline2 shape functions, not linear");
  kernels_ = make_transfer_kernels<D>(scene_.options.shape);
  double mmin = std::numeric_limits<double>::infinity();
  for (double m : scene_.particles.mass) mmin = std::min(mmin, m);
  for (const Inflow<D>& in : scene_.inflows) mmin = std::min(mmin, in.min_particle_mass());
  mass_eps_ = std::isfinite(mmin) ? 1e-12 * mmin : 0.0;
  for (const Body& b : scene_.bodies) scene_.materials[b.material]->attach(scene_.particles, b.begin, b.end);
  for (const Body& b : scene_.bodies)  // a rigid body has no stress (its material gives its density)
    if (b.rigid)
      for (Index i = b.begin; i < b.end; ++i) scene_.particles.stress[i].setZero(), scene_.particles.stress_zz[i] = 0;
  if (scene_.frame) members_ = std::make_unique<MemberContact<D>>(*scene_.grid);
  if (scene_.options.implicit_damping && ImplicitViscosity<D>::needed(scene_)) viscosity_ = std::make_unique<ImplicitViscosity<D>>();
  if (FluidVolumes<D>::needed(scene_)) fluid_ = std::make_unique<FluidVolumes<D>>();
  if (std::any_of(scene_.bodies.begin(), scene_.bodies.end(), [](const Body& b) { return b.rigid || b.rigid_when_free; }))
    rigid_ = std::make_unique<RigidBodies<D>>(scene_);
}

// The step as named phases (docs/architecture.md, "The step").
template <int D> void Solver<D>::step(double dt) {
  if (profile_) lap_t_ = std::chrono::steady_clock::now();
  const bool sort = steps_ % kSortInterval == 1;  // locality for the scatter (from the second step on)
  if (sort) sort_particles();
  for (Inflow<D>& in : scene_.inflows) {  // debris entering the driven zone
    if (steps_ % kSortInterval == 0 && backed_up(scene_, in, time_)) {
      std::ostringstream os;
      os << "run stopped at step " << steps_ + 1 << ", t = " << time_ << " s: the debris has backed up to the inflow section of '" << in.name
         << "' (it moves at less than half the hydrograph's velocity just downstream of it, " << in.mass << " kg of "
         << in.hydrograph.mass_per_width(in.density) * in.thickness << " kg entered): the driven zone would push the deposit as a piston. "
         << "Place the section further upstream (debris_surge.section_distance, or the inflow's point)";
      throw RunError(os.str());
    }
    inject(scene_, in, time_, dt);
  }
  if (const bool out = !sort && scene_.grid->outgrown(scene_.particles.x); sort || out) {
    rebins_ += out;
    scene_.grid->bin(scene_.particles.x);    // tiles, active nodes, zeroed fields
  } else {
    scene_.grid->clear_sums();               // the binning holds: zeroed mass (and contact sums)
  }
  lap(kBinning);
  particles_to_grid();                         // m_i, p_i, f_i = f_int + f_ext (eqs. 5-8)
  lap(kP2G);
  wall_touch(scene_);                          // nodes engaged by particles touching unilateral walls
  lap(kWallTouch);
  implicit_viscosity(dt);                      // damped bodies: the viscous nodal force at the end of the step
  lap(kViscosity);
  member_boundary_forces(dt);                  // stage 1: members as velocity boundaries, reactions on the frame
  lap(kMembers);
  grid_update(dt);                             // v^k, v^L = v^k + dt f/m, walls, regions, body contact, rigid bodies
  // v_p, x_p, L_p, F_p (eqs. 13-14; MUSL remaps first), then per body its material law: inside G2P chunk by chunk
  // when every law is pointwise, else as a pass of its own.
  if (!grid_to_particles(dt)) update_stress(dt);
  if (fluid_) fluid_->apply(scene_, *kernels_, dt);  // fluids' J towards the space their particles fill
  lap(kG2P);
  advance_members(dt);                         // stage 2: the frame under the reactions (eqs. 27-29 or Newmark)
  lap(kFrame);
  switch_free_bodies();                        // rigid_when_free bodies: rigid while clear of everything, else elastic
  time_ += dt;
  ++steps_;
}

// A rigid_when_free body turns rigid when nothing is near it (body_is_clear), or when it is leaving whatever is near:
// from each, separated along some axis by a separation that grew over the last step and exceeds both half a cell and
// the farthest any of its particles reaches (so no particle of it touches). It turns elastic again at the end of a
// step in which that failed for something near (a body that was rigid through that step had no particle touching at
// its start, so nothing could load it but walls and bodies, which hold rigid fields); on an approach from clear, before
// any node is shared (each side moves less than a cell a step; the clearances hold a cell and a half beyond the nodes
// a particle and a member reach). A leaving body's nodes may still be contact candidates of a wall or of another body,
// which act on a field approaching them only and hold a rigid field as well as an elastic one; of a member only where
// member contact needs touching particles (sharp decay, surface detection, not stick; else the rigid body would meet
// the member, which a rigid body may not); velocity regions always need the clearance. Its waves set the step only
// while it can touch something. Turning rigid it gives up its vibration (the kinetic energy the rigid projection
// removes) and its strain energy (relaxed to stress-free), counted as dissipated.
template <int D> void Solver<D>::switch_free_bodies() {
  if (!rigid_) return;
  const double h = scene_.grid->h();
  const Clearance c = Clearance::of(h, member_contact_layer(scene_.coupling, h));
  const MemberCoupling& mc = scene_.coupling;
  const Particles<D>& P = scene_.particles;
  free_gaps_.resize(scene_.bodies.size());
  bool any = false;
  for (std::size_t k = 0; k < scene_.bodies.size(); ++k) {
    Body& b = scene_.bodies[k];
    if (!b.rigid_when_free) continue;
    std::vector<double>& last = free_gaps_[k];  // the last step's separations, 3 per item
    const bool some = body_gaps(scene_, static_cast<int>(k), c, gaps_);
    const bool touch_only = member_contact_needs_touch(mc, std::find(mc.bonded_fields.begin(), mc.bonded_fields.end(), b.field) != mc.bonded_fields.end());
    bool clear = some, leaving = some && last.size() == 3 * gaps_.size();
    double apart = -1;  // the separation that leaves no particle touching, once something near asks for it
    for (std::size_t i = 0; i < gaps_.size(); ++i) {
      const Gap& g = gaps_[i];
      if (g.gap() >= g.clear) continue;
      clear = false;
      const bool away = g.kind == Gap::body || g.kind == Gap::wall || (g.kind == Gap::member && touch_only);
      if (away && leaving && apart < 0) {
        // The farthest a particle reaches along a unit direction n (particle_reach: along n and along F^T n, each
        // sum_j |a_j| r_j <= |a| |r|, r the larger reach per axis; |F^T n| <= sigma_max(F) <= sqrt of the largest row
        // sum of |F^T F|), past half a cell, and the touching test's tolerance.
        double reach = 0;
        for (Index p = b.begin; p < b.end; ++p) {
          const Mat<D> C = P.F[p].transpose() * P.F[p];
          const double stretch = std::sqrt(C.cwiseAbs().rowwise().sum().maxCoeff());
          reach = std::max(reach, P.reach_lo[p].cwiseMax(P.reach_hi[p]).norm() * std::max(1.0, stretch));
        }
        apart = std::max(0.5 * h, reach) + 1e-6 * h;
      }
      bool grew = false;
      for (int d = 0; d < 3 && away && leaving; ++d) grew = grew || (g.sep[d] > apart && g.sep[d] > last[3 * i + d]);
      leaving = leaving && away && grew;
    }
    last.resize(3 * gaps_.size());
    for (std::size_t i = 0; i < gaps_.size(); ++i)
      for (int d = 0; d < 3; ++d) last[3 * i + d] = gaps_[i].sep[d];
    const bool free = clear || leaving;
    if (free && !b.rigid) {
      Material<D>& mat = *scene_.materials[b.material];
      const double strain = mat.strain_energy(scene_.particles, b.begin, b.end);
      if (!mat.relax(scene_.particles, b.begin, b.end)) throw std::logic_error("rigid_when_free on a material that cannot relax");
      frozen_energy_ += strain + rigid_->add(scene_, static_cast<int>(k));
      b.rigid = true, ++free_switches_;
    } else if (!free && b.rigid) {
      rigid_->remove(static_cast<int>(k));
      b.rigid = false, ++free_switches_;
    }
    any = any || b.rigid;
  }
  if (any) ++free_rigid_steps_;
}

template <int D> const char* Solver<D>::phase_name(int p) {
  static const char* names[kPhases] = {"binning", "P2G", "wall touch", "implicit viscosity", "member contact", "grid update and walls",
                                       "body contact", "rigid bodies", "G2P and stress", "frame"};
  return names[p];
}

// P2G with gravity: f_i = f_int + m_i g, the body force added per node by the kernels (eq. 8).
template <int D> void Solver<D>::particles_to_grid() { kernels_->p2g(scene_, false); }

// Reorders each body's particles into the tile order of the last binning (a stable counting sort by tile,
// so particles of one tile sit together in memory): the scatter then reads the particle arrays almost
// sequentially instead of jumping across them. Bodies keep
// their index ranges; materials follow the permutation; Particles::slot keeps creation order for outputs.
template <int D> void Solver<D>::sort_particles() {
  Particles<D>& P = scene_.particles;
  const auto& order = scene_.grid->tile_particles();
  if (order.size() != P.size()) return;  // not binned yet
  std::vector<Index> next(scene_.bodies.size()), perm(P.size());
  for (std::size_t b = 0; b < scene_.bodies.size(); ++b) next[b] = scene_.bodies[b].begin;
  bool same = true;
  for (Index q : order) {
    const Index k = next[P.body[q]]++;
    perm[k] = q, same &= k == q;
  }
  if (same) return;  // the binning held since the last sort (no particle left its tile's margin): already in order
  P.permute(perm);
  for (auto& m : scene_.materials) m->permute(perm);
  if (rigid_) rigid_->permute(perm);
}

template <int D> void Solver<D>::implicit_viscosity(double dt) {
  if (!viscosity_) return;
  if (implicit_now_.size() != scene_.bodies.size()) implicit_now_.assign(scene_.bodies.size(), 1);  // a step not from stable_time_step
  try {
    held_.clear();
    if (members_) members_->for_each_stuck([this](Index k, const Vec<D>& v) { held_.emplace_back(k, v); });
    viscosity_->apply(scene_, *kernels_, dt, time_ + dt, mass_eps_, implicit_now_, held_);
  } catch (const RunError& e) {
    throw RunError("run stopped at step " + std::to_string(steps_ + 1) + ", t = " + std::to_string(time_) + " s: " + e.what());
  }
}

template <int D> void Solver<D>::member_boundary_forces(double dt) {
  if (!members_) return;
  members_->apply(scene_, *kernels_, dt);
  // A rigid body on a member would need the member's reaction in the rigid constraint passes (rigid_constraints),
  // which the staggered frame does not take: refused rather than let the body sink into the member.
  if (rigid_)
    for (const Body& b : scene_.bodies)
      if (b.rigid && members_->loaded_field(b.field, scene_.grid->nnodes()))
        throw RunError("run stopped at step " + std::to_string(steps_ + 1) + ", t = " + std::to_string(time_) + " s: the rigid body '" + b.name +
                       "' met a beam-column member; rigid bodies meet walls and other bodies only (make it elastic, or keep a buffer between)");
}

// A frame free of contact loads this step (no reactions, no attached mass: free vibration under its other loads) is
// advanced in equal sub-steps no longer than its ringing step, whatever lengthened the step (a rigid body in flight,
// a light or slow material): it resolves the modes its damping leaves ringing. Under contact loads the frame takes
// the coupling's step.
template <int D> void Solver<D>::advance_members(double dt) {
  if (!scene_.frame) return;
  const double dt_ring = scene_.frame->ringing_step();
  const bool free = !members_ || members_->loads().empty();
  const double pieces = free && dt > dt_ring ? std::ceil(dt / dt_ring) : 1.0;
  if (!(pieces <= 1e6))
    throw RunError("run stopped at step " + std::to_string(steps_ + 1) + ": the frame's ringing step " + std::to_string(dt_ring) +
                   " s would cut a step of " + std::to_string(dt) + " s into more than a million sub-steps");
  const int n = static_cast<int>(pieces);
  try {
    for (int i = 0; i < n; ++i) scene_.frame->advance(dt / n);
  } catch (const std::runtime_error& e) {  // non-finite state, Newton failure
    throw RunError("run stopped at step " + std::to_string(steps_ + 1) + ", t = " + std::to_string(time_) +
                   " s: beam-column frame: " + e.what());
  }
}

template <int D> void Solver<D>::grid_update(double dt) {
  Grid<D>& g = *scene_.grid;
  const Index nn = g.nnodes();
  const auto& active = g.active();
  const Index na = static_cast<Index>(active.size());
  const double eps = mass_eps_;
  parallel_for(0, na, [&](Index a) {
    for (int fld = 0; fld < g.nfields(); ++fld) {
      const Index k = fld * nn + active[a];
      if (g.m[k] > eps) {
        g.v[k] = g.p[k] / g.m[k];
        g.vL[k] = g.v[k] + dt * g.f[k] / g.m[k];  // eqs. (4), (9)
      } else {
        g.m[k] = 0;  // empty node: excluded from boundaries and contact
        g.v[k].setZero(), g.vL[k].setZero();  // (a step that kept the binning did not zero them)
      }
    }
  });
  boundary_work_ += apply_boundaries(scene_, g.vL, dt, time_ + dt, true);
  lap(kGridUpdate);
  body_contact(scene_, g.vL, !(viscosity_ && viscosity_->detected_contact()));  // detection once per step
  lap(kBodyContact);
  if (rigid_ && !rigid_->empty()) rigid_constraints(dt);
  lap(kRigid);
  if (viscosity_) viscosity_->account(g, dt);
  lap(kViscosity);
}

// The walls, regions and body contact act on a rigid body's nodes one by one; its motion follows from all of them at
// once. Alternating projections: the rigid fields' nodal velocities onto their rigid motion, then the constraints
// again (their forces and work added to this step's), until the projection no longer changes them (each constraint
// is a projection onto a convex set of nodal velocities, Coulomb friction with its limit summed over the passes).
// Without it a rigid body on a wall kept sinking: the wall stopped only the few nodes it holds.
template <int D> void Solver<D>::rigid_constraints(double dt) {
  Grid<D>& g = *scene_.grid;
  const double s_min = scene_.gravity.norm() * dt + 1e-12;
  // The passes change velocities only where a rigid field has mass (the projection moves those fields; the walls and
  // body contact act node by node, and elsewhere they already hold from grid_update), so they run over those nodes.
  rigid_nodes_.clear();
  for (Index id : g.active())
    for (const Body& b : scene_.bodies)
      if (b.rigid && g.m[b.field * g.nnodes() + id] > 0) {
        rigid_nodes_.push_back(id);
        break;
      }
  // Body contact between a rigid body and a deformable field sees the body's whole mass (RigidBodies::body_contact);
  // the other pairs at these nodes take boundary.hpp's node-by-node correction.
  const std::vector<char> skip = rigid_->contact_fields(scene_);
  double wall_change = 0, contact_change = 0;
  for (int it = 0; it < kRigidPasses; ++it) {
    const double change = rigid_->project_nodes(scene_, g.vL, s_min, &rigid_nodes_);
    boundary_work_ += rigid_->wall_contact(scene_, g.vL, dt, s_min, wall_change, &rigid_nodes_);  // plane walls on the hulls
    if (std::max({change, wall_change, contact_change}) < 1e-8) return;
    ++rigid_passes_;
    boundary_work_ += apply_boundaries(scene_, g.vL, dt, time_ + dt, true, false, &rigid_nodes_);
    contact_change = rigid_->body_contact(scene_, g.vL, s_min, rigid_nodes_, skip);
    body_contact(scene_, g.vL, false, &rigid_nodes_, &skip);
  }
  rigid_->project_nodes(scene_, g.vL, s_min, &rigid_nodes_);
  boundary_work_ += rigid_->wall_contact(scene_, g.vL, dt, s_min, wall_change, &rigid_nodes_);
}

// Returns true when the stresses were updated too (every body's law pointwise: fused into G2P's chunks).
template <int D> bool Solver<D>::grid_to_particles(double dt) {
  Grid<D>& g = *scene_.grid;
  G2PResult r;
  bool fuse = true;
  for (const Body& b : scene_.bodies) fuse = fuse && (b.rigid || scene_.materials[b.material]->pointwise());
  // After each chunk's gather, on data still in cache: no particle left behind a plane wall, and the stress update when
  // every law is pointwise.
  const typename TransferKernels<D>::ChunkHook after_chunk = [this, dt, fuse](Index i0, Index i1) {
    keep_in_front_of_walls(scene_, i0, i1);
    if (!fuse) return;
    for (const Body& b : scene_.bodies)
      if (const Index a = std::max(b.begin, i0), e = std::min(b.end, i1); a < e && !b.rigid) scene_.materials[b.material]->update(scene_.particles, a, e, dt);
  };
  const auto* after = &after_chunk;
  const bool apic = scene_.options.transfer == TransferKind::apic;  // the particles carry an affine velocity
  if (scene_.options.update == StressUpdate::usl) {
    r = kernels_->g2p(scene_, dt, G2PMode::full, after);
    if (rigid_) rigid_->take_nodal_motion(scene_, g.vL, apic), r.ok = rigid_->move(scene_, dt) && r.ok;
  } else {
    // MUSL (Sulsky et al. 1995): update particle velocities, remap their momentum to the grid,
    // and take the velocity gradient from the remapped nodal velocities.
    r = kernels_->g2p(scene_, dt, G2PMode::velocity_only);
    if (!r.ok) fail("non-finite particle velocity");
    if (rigid_) rigid_->take_nodal_motion(scene_, g.vL, apic);
    for (Index id : g.active())
      for (int fld = 0; fld < g.nfields(); ++fld) g.p[fld * g.nnodes() + id].setZero();
    kernels_->p2g(scene_, true);
    for (Index id : g.active())
      for (int fld = 0; fld < g.nfields(); ++fld) {
        const Index k = fld * g.nnodes() + id;
        g.v[k] = g.m[k] > 0 ? Vec<D>(g.p[k] / g.m[k]) : Vec<D>::Zero();
      }
    // Walls act on the remap as on v^L. Body contact does not: the particles already carry its
    // correction, and re-deciding "approaching" on the remapped field (which can disagree with v^L)
    // feeds strain rates inconsistent with the motion and gained ~12 % energy in the disk test.
    apply_boundaries(scene_, g.v, dt, time_ + dt, false);
    if (members_) members_->constrain_remap(scene_, g.v);  // members are walls too (unlike body contact)
    r = kernels_->g2p(scene_, dt, G2PMode::kinematics, after);
    if (rigid_) r.ok = rigid_->move(scene_, dt) && r.ok;
  }
  if (!r.ok) fail("particle state");
  return fuse;
}

template <int D> void Solver<D>::update_stress(double dt) {
  for (const Body& b : scene_.bodies)
    if (!b.rigid) scene_.materials[b.material]->update(scene_.particles, b.begin, b.end, dt);
}

template <int D> double Solver<D>::stable_time_step(double limit) const {
  const auto& P = scene_.particles;
  double dt = limit;
  if (scene_.options.dt_max > 0) dt = std::min(dt, scene_.options.dt_max);
  std::vector<double> dt_bodies;  // each body's stable step h / (c + |v|) (damping included unless implicit)
  std::vector<double> dt_damped(scene_.bodies.size(), std::numeric_limits<double>::infinity());
  implicit_now_.assign(scene_.bodies.size(), 0);
  for (std::size_t k = 0; k < scene_.bodies.size(); ++k) {
    const Body& b = scene_.bodies[k];
    double vmax = parallel_reduce(b.begin, b.end, 0.0, [&](Index i) { return P.v[i].norm(); }, [](double a, double v) { return std::max(a, v); });
    const Material<D>& mat = *scene_.materials[b.material];
    // A rigid body has no waves: its speed bound is sqrt(|g| h), so that a body at rest falls a fraction of a cell.
    const double h = scene_.grid->h();
    double c = b.rigid ? std::sqrt(scene_.gravity.norm() * h) : mat.wave_speed();
    // An inflow's debris may be lighter than its material (the hydrograph's density): c ~ 1/sqrt(rho); and it enters
    // at up to the hydrograph's fastest velocity.
    for (const Inflow<D>& in : scene_.inflows)
      if (in.body == static_cast<int>(k)) {
        c *= std::sqrt(std::max(1.0, mat.density() / in.min_density()));
        vmax = std::max(vmax, in.hydrograph.max_velocity());
      }
    double dt_b = h / (c + vmax);
    // Kelvin-Voigt: the grid's highest frequency is omega_max ~ 2 sqrt(D) (c + |v|) / h (the checkerboard mode
    // along a diagonal); the 1D value 2 (c + |v|) / h let a damped rubber pad blow up in 2D at cfl 0.5
    // (docs/verification.md, buffer_pad). Strongly damped, the step tends to h^2 / (2 D beta c^2).
    double a, bv;
    const bool implicit = viscosity_ && mat.viscous_coefficients(a, bv);
    if (const double beta = b.rigid ? 0.0 : mat.damping_time(); beta > 0) {
      const double w = 2 * std::sqrt(double(D)) / dt_b, zeta = 0.5 * beta * w;
      dt_damped[k] = (2 / w) * (std::sqrt(1 + zeta * zeta) - zeta);
      if (!implicit) dt_b = dt_damped[k];
    }
    dt_bodies.push_back(dt_b);
  }
  // The elastic step, and the explicit one with every damping limit. The implicit viscosity costs about
  // 2 sqrt(dt / dt_damped) viscous operator passes per step (docs/performance.md): it is used only
  // where it lengthens the step by more than kImplicitGain, for the bodies whose damped limit is below the elastic step.
  const double cfl = scene_.options.cfl;
  double dt_el = dt, dt_ex = dt;
  for (std::size_t k = 0; k < dt_bodies.size(); ++k)
    dt_el = std::min(dt_el, cfl * dt_bodies[k]), dt_ex = std::min(dt_ex, cfl * std::min(dt_bodies[k], dt_damped[k]));
  const bool implicit_step = viscosity_ && dt_el > kImplicitGain * dt_ex;
  dt = implicit_step ? dt_el : dt_ex;
  courant_ = 0;
  for (std::size_t k = 0; k < dt_bodies.size(); ++k) {
    implicit_now_[k] = implicit_step && dt > cfl * dt_damped[k];
    courant_ = std::max(courant_, dt / (implicit_now_[k] ? dt_bodies[k] : std::min(dt_bodies[k], dt_damped[k])));
  }
  // An explicit frame limits the step (2 / omega_max, scaled by the same fraction); Newmark does not.
  if (scene_.frame) dt = std::min(dt, scene_.options.cfl * scene_.frame->stable_time_step());
  // A rigid_when_free body moving rigidly no longer bounds the step by its waves, and perhaps nothing else does.
  if (scene_.options.free_dt_max > 0)
    for (const Body& b : scene_.bodies)
      if (b.rigid_when_free && b.rigid) dt = std::min(dt, scene_.options.free_dt_max);
  return dt;
}

template <int D> void Solver<D>::save_state(StateWriter& w) const {
  w.tag("solver");
  w.put(time_), w.put(steps_), w.put(boundary_work_), w.put(courant_);
  scene_.particles.save_state(w);
  for (const Body& b : scene_.bodies) w.put(b.end), w.put<std::uint8_t>(b.rigid);  // an inflow's body grows; rigid_when_free
  w.put(frozen_energy_), w.put(free_switches_), w.put(free_rigid_steps_);
  w.put<std::uint64_t>(free_gaps_.size());
  for (const auto& g : free_gaps_) w.put(g);
  for (const Inflow<D>& in : scene_.inflows) in.save_state(w);
  w.put(scene_.grid->particle_tiles());
  w.put<std::uint64_t>(scene_.materials.size());
  for (const auto& m : scene_.materials) m->save_state(w);
  for (const auto& wall : scene_.walls) w.put(wall.force);
  for (const auto& reg : scene_.regions) w.put(reg.force);
  w.put<std::uint8_t>(scene_.frame ? 1 : 0);
  if (scene_.frame) scene_.frame->save_state(w);
  if (members_) members_->save_state(w);
  if (viscosity_) viscosity_->save_state(w); else w.put(0.0);  // load_state reads one or the other
  if (fluid_) fluid_->save_state(w);
  if (rigid_) rigid_->save_state(w);
}

template <int D> void Solver<D>::load_state(StateReader& r) {
  r.tag("solver");
  r.get(time_), r.get(steps_), r.get(boundary_work_), r.get(courant_);
  scene_.particles.load_state(r);
  for (Body& b : scene_.bodies) {
    r.get(b.end);
    const auto rigid = r.get<std::uint8_t>();
    if (rigid != b.rigid && !b.rigid_when_free) r.fail("body '" + b.name + "' rigid in the checkpoint, not in the scenario (or the reverse)");
    b.rigid = rigid != 0;
  }
  r.get(frozen_energy_), r.get(free_switches_), r.get(free_rigid_steps_);
  const auto ngaps = r.get<std::uint64_t>();
  if (ngaps != 0 && ngaps != scene_.bodies.size()) r.fail("rigid_when_free gaps for " + std::to_string(ngaps) + " bodies, not " + std::to_string(scene_.bodies.size()));
  free_gaps_.resize(static_cast<std::size_t>(ngaps));
  for (auto& g : free_gaps_) r.get(g);
  r.expect_size("the bodies' particles", scene_.bodies.empty() ? 0 : static_cast<std::size_t>(scene_.bodies.back().end), scene_.particles.size());
  for (Inflow<D>& in : scene_.inflows) in.load_state(r);
  std::vector<Index> tiles;
  r.get(tiles);
  if (!tiles.empty()) {
    r.expect_size("the particles' tiles", tiles.size(), scene_.particles.size());
    for (Index t : tiles)
      if (t < 0 || t >= scene_.grid->ntiles()) r.fail("a particle's tile out of the grid");
    scene_.grid->restore_binning(std::move(tiles));
  }
  r.expect_size("materials", r.get<std::uint64_t>(), scene_.materials.size());
  for (auto& m : scene_.materials) m->load_state(r);
  for (auto& wall : scene_.walls) r.get(wall.force);
  for (auto& reg : scene_.regions) r.get(reg.force);
  r.expect_size("frames", r.get<std::uint8_t>(), scene_.frame ? 1 : 0);
  if (scene_.frame) scene_.frame->load_state(r);
  if (members_) members_->load_state(r);
  if (viscosity_) viscosity_->load_state(r); else r.get<double>();  // save_state writes 0 without one
  if (fluid_) fluid_->load_state(r);
  if (rigid_) rigid_->load_state(r);
}

template <int D> Diagnostics<D> Solver<D>::diagnostics() const {
  const auto& P = scene_.particles;
  Diagnostics<D> d;
  const Index np = static_cast<Index>(P.size());
  // Kinetic energy, gravity's work and momentum in one pass, each in deterministic_sum's chunks and order (the same for
  // any thread count).
  using Sums = std::array<double, 2 + D>;
  const Sums sums = parallel_reduce(
      Index(0), np, Sums{},
      [&](Index i) {
        Sums t;
        t[0] = 0.5 * P.mass[i] * P.v[i].squaredNorm();
        t[1] = P.mass[i] * scene_.gravity.dot(P.x[i] - P.x0[i]);
        for (int c = 0; c < D; ++c) t[2 + c] = P.mass[i] * P.v[i][c];
        return t;
      },
      [](Sums a, const Sums& b) {
        for (std::size_t k = 0; k < a.size(); ++k) a[k] += b[k];
        return a;
      });
  d.kinetic = sums[0], d.gravity_work = sums[1];
  for (int c = 0; c < D; ++c) d.momentum[c] = sums[2 + c];
  for (const Body& b : scene_.bodies) d.strain += scene_.materials[b.material]->strain_energy(P, b.begin, b.end);
  for (const auto& m : scene_.materials) d.dissipated += m->dissipated();
  d.dissipated += frozen_energy_;
  if (viscosity_) d.dissipated += viscosity_->dissipated();
  if (fluid_) d.dissipated -= fluid_->added_energy();  // the volume relaxation's strain energy, as negative dissipation
  d.boundary_work = boundary_work_;
  for (const Inflow<D>& in : scene_.inflows) d.inflow_mass += in.mass, d.inflow_momentum += in.momentum, d.inflow_energy += in.energy;
  if (const auto* f = scene_.frame.get()) {
    d.frame_kinetic = f->kinetic_energy();
    d.frame_strain = f->strain_energy();
    d.frame_gravity_work = f->external_work() - f->applied_work();
    d.contact_work = f->applied_work();
    d.frame_damping = f->damping_work();
    d.frame_plastic = f->plastic_work();
  }
  return d;
}

template <int D> double Solver<D>::min_jacobian() const {
  const auto& P = scene_.particles;
  const Index np = static_cast<Index>(P.size());
  return parallel_reduce(Index(0), np, std::numeric_limits<double>::infinity(), [&](Index i) { return P.vol[i] / P.vol0[i]; },
                         [](double a, double j) { return std::min(a, j); });
}

template <int D> void Solver<D>::fail(const std::string& what) const {
  const auto& P = scene_.particles;
  const Grid<D>& g = *scene_.grid;
  for (const Body& b : scene_.bodies) {
    // The offending particle with the lowest creation index (the solver reorders particles; P.id is stable).
    Index i = -1;
    for (Index k = b.begin; k < b.end; ++k) {
      const bool finite = P.x[k].allFinite() && P.v[k].allFinite();
      if (!(finite && g.interior(P.x[k])) && (i < 0 || P.id[k] < P.id[i])) i = k;
    }
    if (i >= 0) {
      const bool finite = P.x[i].allFinite() && P.v[i].allFinite();
      std::ostringstream os;
      os << "run stopped at step " << steps_ + 1 << ", t = " << time_ << " s: body '" << b.name << "', particle "
         << P.id[i] - b.begin << " (global " << P.id[i] << ") ";
      if (!finite) {
        os << "has a non-finite " << (P.x[i].allFinite() ? "velocity" : "position")
           << " (NaN/Inf): the time step may be too large or a material parameter unphysical";
      } else {
        os << "left the grid at x = (" << P.x[i].transpose() << "); enlarge grid.size/origin or add walls";
      }
      throw RunError(os.str());
    }
  }
  throw RunError("run stopped at step " + std::to_string(steps_ + 1) + ": non-finite " + what);
}

template class Solver<2>;
template class Solver<3>;

}  // namespace dmi
