// Stage 1 of Lin & Yang's (2024) two-stage contact: beam-column members act on the MPM grid as velocity
// boundaries through Yang's (2016) equivalent specific-force field, and the reactions load the frame. Per step,
// after P2G and before the grid update:
//   r   = (y - x^M) . n - c(xi)                      signed distance to the member surface (Lin & Yang 2024, eq. 23),
//         y = x_i (distance "node", the default and the paper's) or y = xbar_i (distance "material": from the
//         mass-weighted particle position the node sees)
//   n   oriented towards the material a node sees:   (xbar_i - x^M) . n > 0, eqs. (24)-(25)
//   q   weight of eq. (16) over the layer l_n = decay_scale |(h n_x, h n_y)| = decay_scale h (eq. 18):
//         sharp (default): 1 for nodes on or inside the surface (a band >= l_n wide for thin members), kept while
//         the node presses and r <= r_on + l_n / 2 (hysteresis), else 0 -- the node set a rigid wall holds;
//         linear / cosine (the paper's decay layer): 0 < q < 1 across l_n, which brakes a partly held node by q of
//         its approach velocity every step -- a dashpot that absorbs a hard elastic impact (docs/verification.md)
//   surface detection (default, sharp decay): a node is taken only when engaged by a particle whose domain
//         touches the member surface (engine/mpm/touch.hpp), as for a rigid wall; unilateral contact holds it while
//         touched, stick keeps it (the material stays stuck) while it lies within l_n of the surface
//   f_v = -f_tot + (m v* - p) / dt                    stick / prescribed velocity, eq. (20)
//         normal part only, and only while it pushes the material away (f_v . n > 0): separable, eq. (21)
//         plus a tangential part limited by mu f_v . n: friction (Coulomb)
//   f_bc = q f_v added to the node (eq. 19); -f_bc acts on the member at the surface point x^M + c n, i.e. a
//   force at x^M plus the moment of the offset, turned into consistent end forces by Frame::add_point_load.
//   The held nodal mass q m (q m n n^T when sliding) is attached to the frame for the step at the surface point,
//   moving as the section there (Frame::add_point_mass, consistent with the reaction's force and moment): the
//   staggered scheme computes the reaction from v*_n, and a heavy mass on a light member needs its inertia, the
//   rotary inertia of its offset included, in the frame's implicit step to stay stable.
// v* is the velocity of the member's surface point: centre-line velocity plus omega x (c n) (frame
// state at t_n).
// In 3D the surface is the section's swept boundary: r is the signed distance to a round section (|x - x^M| - R)
// or a rectangle (the box distance in the section's axes, its edges rounded along the centre-line at element ends),
// n its gradient; the reaction acts at the section point supporting n (the face point nearest the node, a corner
// for an oblique n), and v* = v(x^M) + omega x arm.
// Each node is held by one member: the one whose surface is nearest. Material on both sides of a member
// thinner than a cell shares nodes, and x-bar then averages both sides (one normal per node and field):
// keep bodies on opposite sides in separate fields (multi-field contact), or members thicker than a cell.
// Deviation from the paper: separable contact tests the sign of the normal force (equivalently the
// trial velocity v^k + dt f_tot/m approaching the member) rather than v^k alone, so the field never
// pulls material towards a member in the step it starts to separate.
#pragma once
#include <array>
#include <vector>

#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"

namespace dmi {

struct MemberContactStats {
  long candidates = 0;       // node-element pairs tested (all steps)
  long loaded = 0;           // node-field pairs that received a force (all steps)
  long projection_iterations = 0;
  int max_projection_iterations = 0;
};

// One reaction of this step: force of the material on the member at a surface point.
template <int D> struct ContactLoadOf {
  int element = 0;
  double xi = 0;        // local coordinate on the element, 0 at its start node, 1 at its end
  Vec<D> point, force;  // surface point (m) and force (N)
};
using ContactLoad = ContactLoadOf<2>;
template <int D> void save_loads(StateWriter& w, const std::vector<ContactLoadOf<D>>& v) {
  w.put<std::uint64_t>(v.size());
  for (const auto& c : v) w.put(c.element), w.put(c.xi), w.put(c.point), w.put(c.force);
}
template <int D> void load_loads(StateReader& r, std::vector<ContactLoadOf<D>>& v) {
  const auto n = r.get<std::uint64_t>();
  if (n > (std::uint64_t{1} << 32)) r.fail("contact load count " + std::to_string(n) + " out of range");
  v.resize(static_cast<std::size_t>(n));
  for (auto& c : v) r.get(c.element), r.get(c.xi), r.get(c.point), r.get(c.force);
}

// The deformed centre-line type of a D-dimensional scene's members.
template <int D> using CurveOf = std::conditional_t<D == 2, ElementCurve, SpaceElementCurve>;

// A space member's section at the two ends of an element (tapered: linear between): round (radius) or rectangular
// (half depth along e2, half width along e3). Plane members use the half depth only.
struct MemberSectionShape {
  bool round = false;
  double a0 = 0, a1 = 0;  // radius or half depth at xi = 0 and 1 (m)
  double b0 = 0, b1 = 0;  // half width at xi = 0 and 1 (m), rectangles
};

// The layer l_n beyond a member's surface whose nodes are contact candidates: decay_scale h, and with the material
// distance x-bar may lie up to a stencil half-width (1.5 h) nearer the member.
inline double member_contact_layer(const MemberCoupling& c, double h) {
  return c.decay_scale * h + (c.distance == DistanceKind::material ? 1.5 * h : 0.0);
}

// Whether member contact takes a node of a field only where its particles touch the member (the sharp held zone
// with surface detection; bonded fields are held from the start, as stuck).
inline bool member_contact_detects_touch(const MemberCoupling& c, bool bonded) {
  return !bonded && c.decay == DecayKind::sharp && c.detection == DetectionKind::surface;
}
// Whether it holds such a node only while its particles touch (unilateral contact); stuck material stays held.
inline bool member_contact_needs_touch(const MemberCoupling& c, bool bonded) {
  return member_contact_detects_touch(c, bonded) && c.mode != MemberContactMode::stick;
}

// Each element's bounding box in its present shape (the deformed centre-line's Bezier hull grown by the section's reach).
template <int D> std::vector<std::array<Vec<D>, 2>> member_bounds(const FrameOf<D>& fr);

// Lower bounds on a node's distance to an element's surface, without projecting (member_contact.cpp).
template <int D> struct SurfaceBound;
// A candidate node's geometry this step (member_contact.cpp).
template <int D> struct NodeGeometry;

template <int D> class MemberContact {
 public:
  explicit MemberContact(const Grid<D>& g);
  // Adds f_bc to grid.f of the member-contact fields, loads the frame with the reactions (after
  // clearing its loads). Frame state at t_n, grid after P2G. Returns false if nothing was touched.
  void apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt);
  // MUSL: the same boundary on the remapped nodal velocities (field layout), with the normals,
  // weights q and member velocities of this step's apply(): stick v += q (v* - v); separable removes
  // q times an approaching normal relative velocity; friction also limits the tangential one.
  void constrain_remap(const Scene<D>& s, std::vector<Vec<D>>& vel) const;
  const MemberContactStats& stats() const { return stats_; }
  // The node-field pairs (field * nnodes + node) held by stick at full weight in the last step, with the velocity
  // v* they were given (the implicit viscosity holds them there in its solve, engine/mpm/viscous.hpp).
  // True when a node of the given field received a force in the last step.
  bool loaded_field(int field, Index nnodes) const {
    for (const Loaded& l : loaded_)
      if (l.pressed && l.k / nnodes == field) return true;
    return false;
  }
  template <class Fn> void for_each_stuck(Fn&& f) const {
    for (const Loaded& l : loaded_)
      if (l.pressed && l.mode == MemberContactMode::stick && l.q == 1) f(l.k, l.vstar);
  }
  // Total force the material exerts on the members in the last step (N): sum of -f_bc.
  const Vec<D>& force() const { return force_; }
  // The individual reactions of the last step (they sum to force()).
  const std::vector<ContactLoadOf<D>>& loads() const { return loads_; }
  // Counters and the last step's reactions, for checkpoints (the rest is rebuilt every step).
  void save_state(StateWriter& w) const {
    w.tag("member_contact");
    w.put(stats_), w.put(force_);
    save_loads(w, loads_);
    w.put(held_);
    // The next step's implicit damping holds the stuck nodes of this one.
    w.put<std::uint64_t>(loaded_.size());
    for (const Loaded& l : loaded_) w.put(l.k), w.put(l.n), w.put(l.vstar), w.put(l.q), w.put(l.mode), w.put(l.pressed);
  }
  void load_state(StateReader& r) {
    r.tag("member_contact");
    r.get(stats_), r.get(force_);
    load_loads(r, loads_);
    r.get(held_);
    loaded_.resize(r.get<std::uint64_t>());
    for (Loaded& l : loaded_) r.get(l.k), r.get(l.n), r.get(l.vstar), r.get(l.q), r.get(l.mode), r.get(l.pressed);
  }

 private:
  struct Candidate {
    Index node;
    int element;
    double xi, dist2;
    double surface;  // distance to the member surface, |x - x^M| - c (m)
    Vec<D> xm;       // projection point on the centre-line
  };
  void find_candidates(const Scene<D>& s);
  void consider_node(const Scene<D>& s, int e, const SurfaceBound<D>& bound, Index id, double ln);
  void mass_positions(const Scene<D>& s, const TransferKernels<D>& kernels);
  void touching(const Scene<D>& s);
  void boundary_forces(Scene<D>& s, double dt);
  NodeGeometry<D> geometry(const Scene<D>& s, const Candidate& c) const;
  void load_field(Scene<D>& s, const Candidate& c, const NodeGeometry<D>& geo, int f, double dt);
  struct Loaded {  // a node-field pair that received a boundary force this step
    Index k;        // field * nnodes + node
    Vec<D> n, vstar;
    double q;
    MemberContactMode mode;
    bool pressed;  // received a force (a separating node is listed for MUSL's remap but gets none)
  };
  std::vector<CurveOf<D>> curves_;  // deformed centre-lines at t_n, by element (this step)
  std::vector<MemberSectionShape> shapes_;  // their sections (3D: round or rectangular, this step's axes)
  std::vector<Candidate> cand_;
  std::vector<Loaded> loaded_;
  std::vector<int> slot_;          // per node: index into cand_, -1 if none
  std::vector<Vec<D>> mx_;         // sum m_p N_ip x_p, field layout; nonzero only at candidate nodes
  std::vector<Index> tiles_;               // occupied-tile indices whose particles reach a candidate
  std::vector<unsigned char> tile_flag_;   // per tile id, scratch
  std::vector<Index> marked_;
  TouchSet touch_;                         // surface detection: node-fields engaged by particles touching a member
  std::vector<Index> held_;                // node-field pairs that received a force in the last step
  std::vector<unsigned char> held_flag_;   // per node-field, scratch: set from held_ during apply()
  Vec<D> force_ = Vec<D>::Zero();
  std::vector<ContactLoadOf<D>> loads_;
  MemberContactStats stats_;
};

}  // namespace dmi
