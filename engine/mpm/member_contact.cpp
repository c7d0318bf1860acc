#include "engine/mpm/member_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/common/coulomb.hpp"
#include "engine/contact/projection.hpp"
#include "engine/structure/space_frame.hpp"

namespace dmi {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Weight q of the boundary force at signed distance r from a member surface of half depth hm (eq. 16).
// Sharp: a node is held fully (q = 1) once r <= r_on and, if it was held in the previous step, while
// r <= r_on + release; else it is free. r_on = max(0, (l_n - 2 hm) / 2): nodes on or inside the member surface, as a
// rigid wall holds the nodes on or behind its plane, widened for members thinner than l_n so that the held band
// (2 hm + 2 r_on >= l_n) always contains a grid node. The release band keeps a member that vibrates across the
// threshold from switching a loaded node on and off every step: each switch is a plastic impact of the node, and
// a hard impact lost most of its energy without it. Unilateral contact releases at l_n / 2. Stuck material
// (stick mode, bonded bodies) releases at l_n, one node spacing along a grid axis: a member surface moving
// through the grid then holds the next node row (on or behind the surface) before it lets the last one go, and
// the material stays on it however far the member moves. Linear 1 - r / l_n and cosine (1 + cos(pi r / l_n)) / 2 hold
// nodes partly; a partly held node is braked by q of its approach velocity every step, a dashpot of impedance
// ~ q (1 - q) rho c per unit area that absorbs a hard elastic impact (docs/verification.md, member contact).
double weight(DecayKind k, double r, double ln, double hm, bool held_before, bool stuck) {
  if (k == DecayKind::sharp) {
    const double on = std::max(0.0, 0.5 * ln - hm) + 1e-9 * ln;  // a node on the surface is held (round-off)
    const double release = stuck ? ln : 0.5 * ln;
    return r <= on || (held_before && r <= on + release) ? 1.0 : 0.0;
  }
  if (r <= 0) return 1.0;
  if (r >= ln) return 0.0;
  const double s = r / ln;
  return k == DecayKind::linear ? 1 - s : 0.5 * (1 + std::cos(kPi * s));
}

// Unit normal of the centre-line c at xi pointing from its point xm there to x, at distance d (eq. A.9); for x on the
// curve the tangent turned by +90 degrees (A.7).
Vec2 outward_normal(const ElementCurve& c, double xi, const Vec2& x, const Vec2& xm, double d, double h) {
  if (d > 1e-12 * h) return (x - xm) / d;
  const Vec2 t = c.d1(xi).normalized();
  return Vec2(-t.y(), t.x());
}

// Axis-aligned box of an element's deformed centre-line: the cubic lies in the convex hull of its
// Bezier control points x(0), x(0) + x'(0)/3, x(1) - x'(1)/3, x(1).
template <class Curve, class V> void curve_box(const Curve& c, V& lo, V& hi) {
  const V p0 = c.point(0), p3 = c.point(1);
  const V p1 = p0 + c.d1(0) / 3, p2 = p3 - c.d1(1) / 3;
  lo = p0.cwiseMin(p1).cwiseMin(p2).cwiseMin(p3);
  hi = p0.cwiseMax(p1).cwiseMax(p2).cwiseMax(p3);
}

MemberSectionShape shape_of(const Frame& f, int e) { return {false, f.half_depth(e, 0), f.half_depth(e, 1), 0, 0}; }
MemberSectionShape shape_of(const SpaceFrame& f, int e) {
  const SpaceElementDef& el = f.model().elements[e];
  const Section& s = el.section;
  if (s.kind() == SectionKind::pipe) return {true, s.half_depth(el.s0), s.half_depth(el.s1), 0, 0};
  return {false, s.half_depth(el.s0), s.half_depth(el.s1), 0.5 * s.width(el.s0), 0.5 * s.width(el.s1)};
}

// Farthest section point from the centre-line (m): the radius, half depth, or a rectangle's half diagonal.
template <int D> double section_reach(const MemberSectionShape& s) {
  if (D == 2 || s.round) return std::max(s.a0, s.a1);
  return std::max(std::hypot(s.a0, s.b0), std::hypot(s.a1, s.b1));
}

// The surface of a space member's section at xi, seen from x (projection xm): the section's axes orthogonalised
// against the tangent, x's coordinates in them, and the half sizes.
struct SpaceSurface {
  Vec3 t, e2, e3;
  double tc = 0, y = 0, z = 0, a = 0, b = 0;
  bool round = false;
};
SpaceSurface space_surface(const SpaceElementCurve& c, const MemberSectionShape& sh, double xi, const Vec3& x, const Vec3& xm) {
  SpaceSurface s;
  s.t = c.d1(xi).normalized();
  s.e2 = (c.e2 - c.e2.dot(s.t) * s.t).normalized();
  s.e3 = s.t.cross(s.e2);
  const Vec3 d = x - xm;
  s.y = d.dot(s.e2), s.z = d.dot(s.e3);
  s.a = sh.a0 + xi * (sh.a1 - sh.a0), s.b = sh.b0 + xi * (sh.b1 - sh.b0);
  // Inside an element the projection is perpendicular to the tangent; at a clamped end the offset along it counts
  // (the end cap) unless it is round-off (a node on the joint of two elements).
  s.tc = xi > 0 && xi < 1 ? 0.0 : d.dot(s.t);
  if (std::abs(s.tc) <= 1e-9 * (s.a + s.b + d.norm())) s.tc = 0;
  s.round = sh.round;
  return s;
}

// Signed distance from x to the section's swept surface and its outward unit normal n0 (the distance's gradient):
// round |x - xm| - R; rectangle the box distance with (|t|, |y| - a, |z| - b), nearest face inside.
double space_distance(const SpaceSurface& s, double h, Vec3& n0) {
  if (s.round) {
    const Vec3 d = s.tc * s.t + s.y * s.e2 + s.z * s.e3;
    const double r = d.norm();
    n0 = r > 1e-12 * h ? Vec3(d / r) : s.e2;
    return r - s.a;
  }
  const double qt = std::abs(s.tc), qy = std::abs(s.y) - s.a, qz = std::abs(s.z) - s.b;
  const auto sgn = [](double v) { return v < 0 ? -1.0 : 1.0; };
  if (qt > 0 || qy > 0 || qz > 0) {
    const Vec3 g(sgn(s.tc) * std::max(qt, 0.0), sgn(s.y) * std::max(qy, 0.0), sgn(s.z) * std::max(qz, 0.0));
    const double r = g.norm();
    n0 = (g(0) * s.t + g(1) * s.e2 + g(2) * s.e3) / r;
    return r;
  }
  n0 = qy >= qz ? Vec3(sgn(s.y) * s.e2) : Vec3(sgn(s.z) * s.e3);
  return std::max(qy, qz);
}

// The rectangle's face nearest the material at xbar (the one it lies furthest beyond, or nearest to inside): the
// normal for a node inside the section, whose own nearest face is ambiguous (a node on the centre-line is equidistant
// from two faces of a square) and says nothing about where the material is (the plane member takes the side of
// x-bar, eqs. (24)-(25)).
Vec3 face_towards(const SpaceSurface& s, const Vec3& xbar, const Vec3& xm) {
  const double yb = (xbar - xm).dot(s.e2), zb = (xbar - xm).dot(s.e3);
  if (std::abs(yb) - s.a >= std::abs(zb) - s.b) return yb < 0 ? Vec3(-s.e2) : s.e2;
  return zb < 0 ? Vec3(-s.e3) : s.e3;
}

// The section point supporting the direction n (from the centre-line): a round section's R n; a rectangle's face
// point nearest x for a face normal, a corner for an oblique one.
Vec3 space_arm(const SpaceSurface& s, const Vec3& n) {
  if (s.round) return s.a * n;
  const double ny = n.dot(s.e2), nz = n.dot(s.e3);
  const double ys = std::abs(ny) > 1e-9 ? std::copysign(s.a, ny) : std::clamp(s.y, -s.a, s.a);
  const double zs = std::abs(nz) > 1e-9 ? std::copysign(s.b, nz) : std::clamp(s.z, -s.b, s.b);
  return ys * s.e2 + zs * s.e3;
}

}  // namespace

template <int D> MemberContact<D>::MemberContact(const Grid<D>& g) {
  slot_.assign(static_cast<std::size_t>(g.nnodes()), -1);
  mx_.assign(static_cast<std::size_t>(g.nnodes() * g.nfields()), Vec<D>::Zero());
}

// Lower bounds on a node's distance to an element's surface without projecting. The curve lies in the hull of its
// Bezier points P0..P3, and every hull point is within dev = max(dist(P1, chord), dist(P2, chord)) of the chord
// segment P0P3 (distance to a convex set is convex), so |x - curve| >= |x - chord| - dev. A rectangle's depth axis
// gives a sharper bound: the surface's e2(xi) lies in the plane of the curve's e2 and the tangent, so e3(xi) = t x e2(xi)
// is normal to the curve's e2, and along u = e2 every section point lies within a of the centre-line, which lies
// within the Bezier points' extent [u_lo, u_hi]: |x - surface| >= dist(u.x, [u_lo, u_hi]) - a. What it culls (the
// nodes in front of a wide member's face) is exactly what the projection would have rejected.
template <int D> struct SurfaceBound {
  Vec<D> q0, ch;
  double ch2 = 0, dev = 0, hd_max = 0;
  bool by_depth = false;
  Vec<D> u = Vec<D>::Zero();
  double u_lo = 0, u_hi = 0, a_max = 0;

  SurfaceBound(const CurveOf<D>& c, const MemberSectionShape& shape, double section_reach) : hd_max(section_reach) {
    q0 = c.point(0);
    const Vec<D> q3 = c.point(1), q1 = q0 + c.d1(0) / 3, q2 = q3 - c.d1(1) / 3;
    ch = q3 - q0;
    ch2 = ch.squaredNorm();
    dev = std::max(chord_distance(q1), chord_distance(q2));
    if constexpr (D == 3) {
      by_depth = !shape.round;
      a_max = std::max(shape.a0, shape.a1);
      u = c.e2.normalized();
      u_lo = std::min({u.dot(q0), u.dot(q1), u.dot(q2), u.dot(q3)});
      u_hi = std::max({u.dot(q0), u.dot(q1), u.dot(q2), u.dot(q3)});
    }
  }
  double chord_distance(const Vec<D>& x) const {
    const double t = ch2 > 0 ? std::clamp((x - q0).dot(ch) / ch2, 0.0, 1.0) : 0.0;
    return (x - q0 - t * ch).norm();
  }
  double lower(const Vec<D>& x) const {
    double r_low = chord_distance(x) - dev - hd_max;
    if constexpr (D == 3)
      if (by_depth) {
        const double ux = u.dot(x);
        r_low = std::max(r_low, std::max({0.0, ux - u_hi, u_lo - ux}) - a_max);
      }
    return r_low;
  }
};

namespace {

// The box of nodes that can hold mass: the occupied tiles' reach.
template <int D> void occupied_box(const Grid<D>& g, IVec<D>& lo_out, IVec<D>& hi_out) {
  lo_out = g.nodes(), hi_out = IVec<D>::Constant(-1);
  for (Index t : g.occupied()) {
    IVec<D> lo, hi;
    g.tile_nodes(t, lo, hi);
    lo_out = lo_out.cwiseMin(lo), hi_out = hi_out.cwiseMax(hi);
  }
}

}  // namespace

// A node near element e: projected on its curve unless a bound shows it no nearer than the free zone's edge ln or the
// surface it already has; kept as a candidate when its surface distance is below ln and the nearest so far (surface,
// not centre-line: joints of unequal depth).
template <int D> void MemberContact<D>::consider_node(const Scene<D>& s, int e, const SurfaceBound<D>& bound, Index id, double ln) {
  const Grid<D>& g = *s.grid;
  bool has_mass = false;
  for (int f : s.coupling.fields) has_mass = has_mass || g.m[f * g.nnodes() + id] > 0;
  if (!has_mass) return;
  const Vec<D> x = g.node_pos(id);
  int& k = slot_[id];
  const double r_low = bound.lower(x);
  if (r_low >= ln || (k >= 0 && r_low >= cand_[k].surface)) return;
  const CurveOf<D>& c = curves_[e];
  const Projection pr = project_on_curve(c, x);
  ++stats_.candidates;
  stats_.projection_iterations += pr.iterations;
  stats_.max_projection_iterations = std::max(stats_.max_projection_iterations, pr.iterations);
  double r = 0;
  if constexpr (D == 2) {
    r = std::sqrt(pr.dist2) - s.frame->half_depth(e, pr.xi);
  } else {
    Vec3 n0;
    r = space_distance(space_surface(c, shapes_[e], pr.xi, x, c.point(pr.xi)), g.h(), n0);
  }
  if (r >= ln) return;  // free zone whichever side the material is on (node distance)
  if (k < 0) {
    k = static_cast<int>(cand_.size());
    cand_.push_back(Candidate{id, e, pr.xi, pr.dist2, r, c.point(pr.xi)});
  } else if (r < cand_[k].surface) {
    cand_[k] = Candidate{id, e, pr.xi, pr.dist2, r, c.point(pr.xi)};
  }
}

// Every active node within reach (section reach + decay layer) of an element, with its nearest element.
template <int D> void MemberContact<D>::find_candidates(const Scene<D>& s) {
  const Grid<D>& g = *s.grid;
  const FrameOf<D>& fr = *s.frame;
  // With the material distance, x-bar may lie up to a stencil half-width (1.5 h) nearer the member.
  const double ln = member_contact_layer(s.coupling, g.h());
  for (const Candidate& c : cand_) slot_[c.node] = -1;
  cand_.clear();
  IVec<D> occ_lo, occ_hi;
  occupied_box(g, occ_lo, occ_hi);
  curves_.resize(static_cast<std::size_t>(fr.nelements()));
  shapes_.resize(static_cast<std::size_t>(fr.nelements()));
  for (int e = 0; e < fr.nelements(); ++e) {
    curves_[e] = fr.curve(e);
    shapes_[e] = shape_of(fr, e);
    Vec<D> lo, hi;
    curve_box(curves_[e], lo, hi);
    const double hd_max = section_reach<D>(shapes_[e]);  // sections taper linearly
    const double reach = hd_max + ln + 1e-9 * g.h();
    const SurfaceBound<D> bound(curves_[e], shapes_[e], hd_max);
    IVec<D> a, b;
    bool empty = false;
    for (int d = 0; d < D; ++d) {
      a[d] = std::max({0, occ_lo[d], static_cast<int>(std::ceil((lo[d] - reach - g.origin()[d]) * g.inv_h()))});
      b[d] = std::min({g.nodes()[d] - 1, occ_hi[d], static_cast<int>(std::floor((hi[d] + reach - g.origin()[d]) * g.inv_h()))});
      empty = empty || a[d] > b[d];
    }
    if (empty) continue;
    any_node_in_box<D>(a, b, [&](const IVec<D>& ijk) {
      consider_node(s, e, bound, g.node_id(ijk), ln);
      return false;
    });
  }
}

// mx_i = sum_p m_p N_ip x_p at the candidate nodes, from the particles of the occupied tiles that
// reach them (Grid::tiles_reaching, the inverse of Grid::tile_nodes).
template <int D> void MemberContact<D>::mass_positions(const Scene<D>& s, const TransferKernels<D>& kernels) {
  const Grid<D>& g = *s.grid;
  if (tile_flag_.size() != static_cast<std::size_t>(g.ntiles())) tile_flag_.assign(static_cast<std::size_t>(g.ntiles()), 0);
  marked_.clear();
  for (const Candidate& c : cand_) {
    IVec<D> lo, hi;
    g.tiles_reaching(g.node_ijk(c.node), lo, hi);
    IVec<D> t = lo;
    while (true) {
      Index id = t[D - 1];
      for (int d = D - 2; d >= 0; --d) id = id * g.tiles()[d] + t[d];
      if (!tile_flag_[id]) {
        tile_flag_[id] = 1;
        marked_.push_back(id);
      }
      int d = 0;
      for (; d < D; ++d) {
        if (++t[d] <= hi[d]) break;
        t[d] = lo[d];
      }
      if (d == D) break;
    }
  }
  tiles_.clear();
  const auto& occ = g.occupied();
  for (Index k = 0; k < static_cast<Index>(occ.size()); ++k)
    if (tile_flag_[occ[k]]) tiles_.push_back(k);
  for (Index id : marked_) tile_flag_[id] = 0;
  for (const Candidate& c : cand_)
    for (int f = 0; f < g.nfields(); ++f) mx_[f * g.nnodes() + c.node].setZero();
  kernels.scatter_mass_position(s, tiles_, mx_);
}

// touch_ from the particles of the tiles near candidates whose domain reaches the surface of the member that holds
// their nearest node (a particle touching a surface has its nearest node within l_n of it, a candidate).
template <int D> void MemberContact<D>::touching(const Scene<D>& s) {
  const Grid<D>& g = *s.grid;
  touch_.reset(static_cast<std::size_t>(g.nnodes()) * g.nfields());
  if (!member_contact_detects_touch(s.coupling, false)) return;
  const Particles<D>& P = s.particles;
  const FrameOf<D>& fr = *s.frame;
  const double tol = 1e-6 * g.h();
  for (Index t : tiles_)
    for (Index q = g.tile_start()[t]; q < g.tile_start()[t + 1]; ++q) {
      const Index i = g.tile_particles()[q];
      const Vec<D> xr = g.grid_coord(P.x[i]);
      IVec<D> nearest;
      for (int d = 0; d < D; ++d) nearest[d] = static_cast<int>(std::lround(xr[d]));
      const Index id = g.node_id(nearest);
      if (slot_[id] < 0) continue;
      const Candidate& c = cand_[slot_[id]];
      const CurveOf<D>& curve = curves_[c.element];
      const Projection pr = project_on_curve(curve, P.x[i]);
      double r = 0;
      Vec<D> n;
      if constexpr (D == 2) {
        const double d = std::sqrt(pr.dist2);
        r = d - fr.half_depth(c.element, pr.xi);
        n = outward_normal(curve, pr.xi, P.x[i], curve.point(pr.xi), d, g.h());
      } else {
        r = space_distance(space_surface(curve, shapes_[c.element], pr.xi, P.x[i], curve.point(pr.xi)), g.h(), n);
      }
      if (r - particle_reach<D>(P, i, -n) <= tol) touch_.add(g, s.bodies[P.body[i]].field * g.nnodes(), P.x[i], n);
    }
}

template <int D> void MemberContact<D>::apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt) {
  {
    s.frame->clear_loads();
    force_.setZero();
    loaded_.clear();
    loads_.clear();
    Grid<D>& g = *s.grid;
    if (held_flag_.size() != static_cast<std::size_t>(g.nnodes() * g.nfields())) held_flag_.assign(static_cast<std::size_t>(g.nnodes() * g.nfields()), 0);
    for (Index k : held_) held_flag_[k] = 1;  // the nodes that pressed on a member in the previous step
    find_candidates(s);
    if (!cand_.empty()) {
      mass_positions(s, kernels);
      touching(s);
      boundary_forces(s, dt);
    }
    for (Index k : held_) held_flag_[k] = 0;
    held_.clear();
    for (const Loaded& l : loaded_)
      if (l.pressed) held_.push_back(l.k);
  }
}

// A candidate node's geometry this step: its position, the member's velocity and spin at the projection (a scalar in
// 2D, a vector in 3D), the outward normal from the centre-line towards the node (3D: of the section's surface there)
// and the half-depth.
template <int D> struct NodeGeometry {
  Vec<D> x, vc, n0;
  std::conditional_t<D == 2, double, Vec3> omega;
  double hm = 0;
  [[maybe_unused]] SpaceSurface surf;
};

template <int D> NodeGeometry<D> MemberContact<D>::geometry(const Scene<D>& s, const Candidate& c) const {
  const FrameOf<D>& fr = *s.frame;
  const Grid<D>& g = *s.grid;
  NodeGeometry<D> geo;
  geo.x = g.node_pos(c.node);
  const CurveOf<D>& curve = curves_[c.element];
  geo.vc = fr.velocity_at(c.element, c.xi);
  geo.omega = fr.angular_velocity_at(c.element, c.xi);
  if constexpr (D == 2) {
    geo.hm = fr.half_depth(c.element, c.xi);
    geo.n0 = outward_normal(curve, c.xi, geo.x, c.xm, std::sqrt(c.dist2), g.h());
  } else {
    geo.surf = space_surface(curve, shapes_[c.element], c.xi, geo.x, c.xm);
    space_distance(geo.surf, g.h(), geo.n0);
  }
  return geo;
}

// Stage 1 at one node-field pair (Lin & Yang 2024 eqs. 19-25): the boundary force that gives the held material the
// member surface's velocity, weighted by q, its reaction and the held mass on the member.
template <int D> void MemberContact<D>::load_field(Scene<D>& s, const Candidate& c, const NodeGeometry<D>& geo, int f, double dt) {
  FrameOf<D>& fr = *s.frame;
  Grid<D>& g = *s.grid;
  const MemberCoupling& opt = s.coupling;
  const double ln = opt.decay_scale * g.h();
  const Index k = f * g.nnodes() + c.node;
  const double m = g.m[k];
  if (!(m > 0)) return;
  const Vec<D>& x = geo.x;
  double hm = geo.hm;
  // Orientation by the mass-weighted particle position the node sees, eqs. (24)-(25); a node inside a
  // rectangular section takes the face the material lies beyond.
  const Vec<D> xbar = mx_[k] / m;
  Vec<D> n = (xbar - c.xm).dot(geo.n0) >= 0 ? geo.n0 : Vec<D>(-geo.n0);
  if constexpr (D == 3)
    if (!geo.surf.round && c.surface < 0) n = face_towards(geo.surf, xbar, c.xm);
  // Bodies bonded to the members (a tyre buffer fixed on the dam face) stick whatever the mode, and are
  // held from the node distance: measured from x-bar the bond peeled (the held mass sagged, q fell).
  const bool bonded = std::find(opt.bonded_fields.begin(), opt.bonded_fields.end(), f) != opt.bonded_fields.end();
  const MemberContactMode mode = bonded ? MemberContactMode::stick : opt.mode;
  const bool node_distance = bonded || opt.distance == DistanceKind::node;
  // The surface point x^M + arm supporting n, the distance to its tangent plane (eq. 23) and its velocity:
  // centre-line velocity plus omega x arm, so the material is held where the reaction acts (its power then
  // matches the frame's, moment included).
  Vec<D> arm, vstar;
  double r = 0;
  if constexpr (D == 2) {
    arm = hm * n;
    r = ((node_distance ? x : xbar) - c.xm).dot(n) - hm;
    vstar = geo.vc + geo.omega * hm * Vec2(-n.y(), n.x());
  } else {
    arm = space_arm(geo.surf, n);
    r = ((node_distance ? x : xbar) - c.xm - arm).dot(n);
    hm = arm.dot(n);  // the section's extent along n, for the weight's band
    vstar = geo.vc + geo.omega.cross(arm);
  }
  double q = weight(opt.decay, r, ln, hm, held_flag_[k] != 0, mode == MemberContactMode::stick);
  // Surface detection: a node is taken only when engaged by particles touching the member, among those within
  // l_n / 2 of its surface on either side (as a rigid wall: a face between grid lines acts at the nearest node
  // row). Unilateral contact keeps it while touched; stuck material keeps it while in the release band.
  if (member_contact_detects_touch(opt, bonded)) {
    const bool taken = touch_.engaged(k) && (q > 0 || r <= 0.5 * ln * (1 + 1e-9));
    const bool kept = mode == MemberContactMode::stick && held_flag_[k] && q > 0;
    q = taken || kept ? 1.0 : 0.0;
  }
  if (q == 0) return;
  loaded_.push_back(Loaded{k, n, vstar, q, mode, false});
  Vec<D> fv = -g.f[k] + (m * vstar - g.p[k]) / dt;  // eq. (20)
  if (mode != MemberContactMode::stick) {
    const double fn = fv.dot(n);
    if (fn <= 0) return;  // separating: no force, eq. (21)
    Vec<D> ft = fv - fn * n;
    ft = mode == MemberContactMode::friction ? coulomb_projection(ft, opt.friction * fn) : Vec<D>(Vec<D>::Zero());
    fv = fn * n + ft;
  }
  const Vec<D> fbc = q * fv;  // eq. (19)
  g.f[k] += fbc;
  // Reaction on the member at the surface point: force plus the moment of the offset.
  const Vec<D> F = -fbc;
  if constexpr (D == 2) fr.add_point_load(c.element, c.xi, F, arm.x() * F.y() - arm.y() * F.x());
  else fr.add_point_load(c.element, c.xi, F, arm.cross(F));
  // The held material moves with the member: its mass joins the frame's inertia for the step
  // (all directions when stuck, the normal one when sliding).
  fr.add_point_mass(c.element, c.xi, q * m * (mode == MemberContactMode::stick ? Mat<D>(Mat<D>::Identity()) : Mat<D>(n * n.transpose())), arm);
  force_ += F;
  loaded_.back().pressed = true;
  loads_.push_back(ContactLoadOf<D>{c.element, c.xi, c.xm + arm, F});
  ++stats_.loaded;
}

// f_bc of eqs. (19)-(21) on the candidate nodes, the reactions on the frame and the held masses.
template <int D> void MemberContact<D>::boundary_forces(Scene<D>& s, double dt) {
  for (const Candidate& c : cand_) {
    const NodeGeometry<D> geo = geometry(s, c);
    for (int f : s.coupling.fields) load_field(s, c, geo, f, dt);
  }
}

template <int D> void MemberContact<D>::constrain_remap(const Scene<D>& s, std::vector<Vec<D>>& vel) const {
  const MemberCoupling& opt = s.coupling;
  for (const Loaded& l : loaded_) {
    Vec<D>& v = vel[l.k];
    if (l.mode == MemberContactMode::stick) {
      v += l.q * (l.vstar - v);
      continue;
    }
    const Vec<D> rel = v - l.vstar;
    const double vn = rel.dot(l.n);
    if (vn >= 0) continue;  // separating
    Vec<D> dv = -l.q * vn * l.n;
    if (l.mode == MemberContactMode::friction) dv -= coulomb_projection(Vec<D>(rel - vn * l.n), opt.friction * l.q * -vn);
    v += dv;
  }
}

template <int D> std::vector<std::array<Vec<D>, 2>> member_bounds(const FrameOf<D>& fr) {
  std::vector<std::array<Vec<D>, 2>> boxes(static_cast<std::size_t>(fr.nelements()));
  for (int e = 0; e < fr.nelements(); ++e) {
    Vec<D> lo, hi;
    curve_box(fr.curve(e), lo, hi);
    const double reach = section_reach<D>(shape_of(fr, e));
    boxes[e] = {(lo.array() - reach).matrix(), (hi.array() + reach).matrix()};
  }
  return boxes;
}

template class MemberContact<2>;
template class MemberContact<3>;
template std::vector<std::array<Vec<2>, 2>> member_bounds<2>(const FrameOf<2>&);
template std::vector<std::array<Vec<3>, 2>> member_bounds<3>(const FrameOf<3>&);

}  // namespace dmi
