// Rigid bodies in the MPM grid. A rigid body's particles scatter mass and momentum as any body's (no stress, so no
// internal force), and meet walls, members and other bodies through the same nodal constraints. After G2P their
// velocities are projected on the rigid motions: with M = sum m_p, r_p = x_p - x_c,
//   V = sum m_p v_p / M,   omega = I^-1 sum m_p r_p x v_p,   v_p <- V + omega x r_p,
// which keeps the body's linear and angular momentum (I = sum m_p (|r_p|^2 1 - r_p r_p^T), the particles as points,
// the inertia their velocities carry: with the particles' own inertia added, a rigid motion would not be a fixed point
// of the projection and every step would take a fraction of the spin away), then the body moves rigidly:
// x_c += dt V, R <- exp(dt [omega]x) R, x_p = x_c + R (x0_p - x_c0); F_p = R, L_p = [omega]x. No wave speed limits
// its step, only |v| dt < h. A body may also join while the run goes (Body::rigid_when_free): x0_p and x_c0 are then
// its configuration at that moment, and F_p = R F_p(then).
#pragma once
#include <type_traits>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/mpm/scene.hpp"

namespace dmi {

template <int D> class RigidBodies {
 public:
  // The rigid bodies of the scene (Body::rigid): initial centre, inertia and motion (the projection of the seeded
  // velocities).
  explicit RigidBodies(Scene<D>& s);
  bool empty() const { return bodies_.empty(); }
  // A rigid_when_free body turning rigid: it joins in its present configuration (centre, inertia and the particles'
  // offsets from the centre now, their F kept as F_0), its velocities projected on the rigid motion. Returns the
  // kinetic energy the projection removed (its vibration, J).
  double add(Scene<D>& s, int body);
  // The body leaves: its particles keep the rigid motion's last positions, velocities, F = R F_0 and L.
  void remove(int body);
  // The solver reordered the particles (new[i] = old[perm[i]]).
  void permute(const std::vector<Index>& perm);
  // Particle velocities of every rigid body projected on its rigid motion (momentum and angular momentum kept).
  void project(Scene<D>& s);
  // After G2P: each rigid body takes the motion its nodes ended the step with (vel, rigid after the constraint
  // passes), its particles V + omega x r. The nodes carry the body's momentum and, after P2G, its angular momentum
  // L about the same centre (B-splines, GIMP and linear shapes keep first moments), but with the inertia I_n of the
  // nodes, I_p + M h^2/2 per axis for quadratic B-splines. APIC's affine velocity carries the difference, so the body
  // spins at the nodes' omega; without it (FLIP, PIC) the body keeps the nodes' angular momentum, omega =
  // I_p^-1 I_n omega_n. Either way the step keeps both momenta exactly; the FLIP increment, projected, had lost spin
  // every step (a rolling disc 6 % slow at h = R/8).
  void take_nodal_motion(Scene<D>& s, const std::vector<Vec<D>>& vel, bool affine);
  // The rigid bodies' nodal velocities (each in its own field) projected on the rigid motion with the nodes' masses
  // and positions (momentum and angular momentum of the field kept). Returns the largest change of a nodal
  // velocity relative to the body's speed scale |V| + |omega| r_max + s (s > 0, e.g. |g| dt).
  // only: the nodes where a rigid field has mass (a subset of the active nodes, in their order), else all active.
  double project_nodes(Scene<D>& s, std::vector<Vec<D>>& vel, double s_min, const std::vector<Index>* only = nullptr) const;
  // Plane walls (slip, friction) on the rigid bodies' hulls (Body::hull_points): the hull points that would pass the
  // wall within dt are contacts; sequential impulses on the body's nodal motion (V, omega about the nodes' mass
  // centre, with their mass and inertia) make each contact's normal velocity at least -gap/dt (0 once touching) and,
  // with friction, keep its tangential impulse within mu times the normal one (Catto 2005: accumulated impulses,
  // clamped); the nodes then take the new rigid motion. Adds the impulses / dt to the walls' forces; returns the
  // work of the walls on the body (J): friction's tangential impulse times the point's final slip velocity (a fixed
  // wall's normal impulse does none; an impact's loss is the contact's, in the energy balance as for the node-level
  // walls), and in change the largest change of a nodal velocity relative to the body's speed scale (as
  // project_nodes). The contact is at the shape's surface, so a disc rolls on its lowest point, not on a patch of
  // held nodes a cell wide.
  double wall_contact(Scene<D>& s, std::vector<Vec<D>>& vel, double dt, double s_min, double& change,
                      const std::vector<Index>* only = nullptr) const;
  // Per field: 1 where the field holds exactly one body and it is rigid; body_contact takes its contacts with
  // unflagged fields.
  std::vector<char> contact_fields(const Scene<D>& s) const;
  // Body contact of each rigid body (its own field) with deformable fields at the given nodes, by surface detection
  // (this step's fronts): the correction of boundary.hpp's body_contact (a field moving towards the other loses that
  // normal relative velocity; stick, or Coulomb with mu = contact_friction), with the rigid side's whole mass and
  // inertia behind each node, 1/m_a -> K(r) = 1/M + [r]x^T I^-1 [r]x, instead of the node's mass, by sequential
  // impulses on the body's nodal motion (the nodes then take it). Node by node with the node's mass, each constraint
  // pass closed only about m_rigid node / m_deformable node of the gap (180 passes a step on the buffered dam at
  // h 0.04 m, docs/performance.md). Returns the largest change of a rigid nodal velocity relative to the body's speed
  // scale (as project_nodes). rigid: contact_fields(s).
  double body_contact(Scene<D>& s, std::vector<Vec<D>>& vel, double s_min, const std::vector<Index>& nodes,
                      const std::vector<char>& rigid) const;
  // Rigid motion over dt from the projected velocities: centre, rotation, particle positions, F and L. False when
  // a particle left the grid's interior or became non-finite.
  bool move(Scene<D>& s, double dt);
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  using Spin = std::conditional_t<D == 2, double, Vec<3>>;
  struct State {
    int body = 0;
    double mass = 0;
    Vec<D> xc0 = Vec<D>::Zero(), xc = Vec<D>::Zero(), V = Vec<D>::Zero();
    Mat<D> R = Mat<D>::Identity();
    Mat<3> I0 = Mat<3>::Zero();  // inertia about the centre in the initial orientation (2D: I0(2,2))
    Spin omega{};
  };
  State make_state(const Scene<D>& s, int body, const std::vector<Vec<D>>& x);
  void project_one(Scene<D>& s, State& st);
  bool move_one(Scene<D>& s, State& st, double dt);
  std::vector<State> bodies_;
  // Per particle (indexed like the particles; meaningful on the rigid bodies' ranges): the offset from the body's
  // centre when it became rigid (x_p = x_c + R ref_p) and F then (F_p = R F0_p).
  std::vector<Vec<D>> ref_;
  std::vector<Mat<D>> F0_;
};

// Per velocity field: 1 when plane walls act on it through wall_contact rather than node by node (the field holds
// one body, rigid, with a hull).
template <int D> std::vector<char> hull_fields(const Scene<D>& s);

}  // namespace dmi
