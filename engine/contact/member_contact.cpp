#include "engine/contact/member_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/contact/projection.hpp"

namespace dmi {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Weight q of the boundary force at signed distance r from a member surface of half depth hm (eq. 16).
// Sharp: a node is held fully (q = 1) once r <= r_on and, if it was held in the previous step, while
// r <= r_on + l_n / 2; else it is free. r_on = max(0, (l_n - 2 hm) / 2): nodes on or inside the member surface, as a
// rigid wall holds the nodes on or behind its plane, widened for members thinner than l_n so that the held band
// (2 hm + 2 r_on >= l_n) always contains a grid node. The release band keeps a member that vibrates across the
// threshold from switching a loaded node on and off every step: each switch is a plastic impact of the node, and
// a hard impact lost 54-79 % of its energy without it. Linear 1 - r / l_n and cosine (1 + cos(pi r / l_n)) / 2 hold
// nodes partly; a partly held node is braked by q of its approach velocity every step, a dashpot of impedance
// ~ q (1 - q) rho c per unit area that absorbs a hard elastic impact (docs/verification.md, member contact).
double weight(DecayKind k, double r, double ln, double hm, bool held_before) {
  if (k == DecayKind::sharp) {
    const double on = std::max(0.0, 0.5 * ln - hm) + 1e-9 * ln;  // a node on the surface is held (round-off)
    return r <= on || (held_before && r <= on + 0.5 * ln) ? 1.0 : 0.0;
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
void curve_box(const ElementCurve& c, Vec2& lo, Vec2& hi) {
  const Vec2 p0 = c.point(0), p3 = c.point(1);
  const Vec2 p1 = p0 + c.d1(0) / 3, p2 = p3 - c.d1(1) / 3;
  lo = p0.cwiseMin(p1).cwiseMin(p2).cwiseMin(p3);
  hi = p0.cwiseMax(p1).cwiseMax(p2).cwiseMax(p3);
}

}  // namespace

template <int D> MemberContact<D>::MemberContact(const Grid<D>& g) {
  slot_.assign(static_cast<std::size_t>(g.nnodes()), -1);
  mx_.assign(static_cast<std::size_t>(g.nnodes() * g.nfields()), Vec<D>::Zero());
}

// Every active node within reach (half depth + decay layer) of an element, with its nearest element.
template <int D> void MemberContact<D>::find_candidates(const Scene<D>& s) {
  if constexpr (D == 2) {
    const Grid<2>& g = *s.grid;
    const Frame& fr = *s.frame;
    // With the material distance, x-bar may lie up to a stencil half-width (1.5 h) nearer the member.
    const double ln = s.coupling.decay_scale * g.h() + (s.coupling.distance == DistanceKind::material ? 1.5 * g.h() : 0.0);
    for (const Candidate& c : cand_) slot_[c.node] = -1;
    cand_.clear();
    // Nodes that can hold mass: the box of the occupied tiles' reach.
    IVec<2> occ_lo(g.nodes()[0], g.nodes()[1]), occ_hi(-1, -1);
    for (Index t : g.occupied()) {
      IVec<2> lo, hi;
      g.tile_nodes(t, lo, hi);
      occ_lo = occ_lo.cwiseMin(lo), occ_hi = occ_hi.cwiseMax(hi);
    }
    curves_.resize(static_cast<std::size_t>(fr.nelements()));
    for (int e = 0; e < fr.nelements(); ++e) {
      curves_[e] = fr.curve(e);
      const ElementCurve& c = curves_[e];
      Vec2 lo, hi;
      curve_box(c, lo, hi);
      const double hd_max = std::max(fr.half_depth(e, 0), fr.half_depth(e, 1));  // depth tapers linearly
      const double reach = hd_max + ln + 1e-9 * g.h();
      // Lower bound on a node's distance to the curve without projecting: the curve lies in the hull of its Bezier
      // points P0..P3, and every hull point is within dev = max(dist(P1, chord), dist(P2, chord)) of the chord
      // segment P0P3 (distance to a convex set is convex), so |x - curve| >= |x - chord| - dev.
      const Vec2 q0 = c.point(0), q3 = c.point(1), q1 = q0 + c.d1(0) / 3, q2 = q3 - c.d1(1) / 3;
      const Vec2 ch = q3 - q0;
      const double ch2 = ch.squaredNorm();
      auto seg_dist = [&](const Vec2& x) {
        const double t = ch2 > 0 ? std::clamp((x - q0).dot(ch) / ch2, 0.0, 1.0) : 0.0;
        return (x - q0 - t * ch).norm();
      };
      const double dev = std::max(seg_dist(q1), seg_dist(q2));
      IVec<2> a, b;
      for (int d = 0; d < 2; ++d) {
        a[d] = std::max({0, occ_lo[d], static_cast<int>(std::ceil((lo[d] - reach - g.origin()[d]) * g.inv_h()))});
        b[d] = std::min({g.nodes()[d] - 1, occ_hi[d], static_cast<int>(std::floor((hi[d] + reach - g.origin()[d]) * g.inv_h()))});
      }
      for (int j = a[1]; j <= b[1]; ++j)
        for (int i = a[0]; i <= b[0]; ++i) {
          const Index id = g.node_id(IVec<2>(i, j));
          bool has_mass = false;
          for (int f : s.coupling.fields) has_mass = has_mass || g.m[f * g.nnodes() + id] > 0;
          if (!has_mass) continue;
          const Vec2 x = g.node_pos(id);
          int& k = slot_[id];
          // Exact skips: r >= ln (free zone), or no nearer than the surface this node already has.
          const double r_low = seg_dist(x) - dev - hd_max;
          if (r_low >= ln || (k >= 0 && r_low >= cand_[k].surface)) continue;
          const Projection pr = project_on_curve(c, x);
          ++stats_.candidates;
          stats_.projection_iterations += pr.iterations;
          stats_.max_projection_iterations = std::max(stats_.max_projection_iterations, pr.iterations);
          const double r = std::sqrt(pr.dist2) - fr.half_depth(e, pr.xi);
          if (r >= ln) continue;  // free zone whichever side the material is on (node distance)
          if (k < 0) {
            k = static_cast<int>(cand_.size());
            cand_.push_back(Candidate{id, e, pr.xi, pr.dist2, r, c.point(pr.xi)});
          } else if (r < cand_[k].surface) {  // nearest surface, not centre-line (joints of unequal depth)
            cand_[k] = Candidate{id, e, pr.xi, pr.dist2, r, c.point(pr.xi)};
          }
        }
    }
  }
}

// mx_i = sum_p m_p N_ip x_p at the candidate nodes, from the particles of the tiles that reach them.
// mx_i = sum_p m_p N_ip x_p at the candidate nodes, from the particles of the occupied tiles that
// reach them: tile t's particles touch nodes [T t - 1, T t + T + 1], so node n is reached by tiles
// ceil((n - T - 1) / T) .. floor((n + 1) / T) along each axis.
template <int D> void MemberContact<D>::mass_positions(const Scene<D>& s, const TransferKernels<D>& kernels) {
  const Grid<D>& g = *s.grid;
  constexpr int T = Grid<D>::T;
  if (tile_flag_.size() != static_cast<std::size_t>(g.ntiles())) tile_flag_.assign(static_cast<std::size_t>(g.ntiles()), 0);
  marked_.clear();
  for (const Candidate& c : cand_) {
    const IVec<D> n = g.node_ijk(c.node);
    IVec<D> lo, hi;
    for (int d = 0; d < D; ++d) {
      lo[d] = std::max(0, (n[d] - 1 + T - 1) / T - 1);  // ceil((n - T - 1) / T), n >= 0
      hi[d] = std::min(g.tiles()[d] - 1, (n[d] + 1) / T);
    }
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
  if (s.coupling.decay != DecayKind::sharp || s.coupling.detection != DetectionKind::surface) return;
  if constexpr (D == 2) {
    const Particles<2>& P = s.particles;
    const Frame& fr = *s.frame;
    const double tol = 1e-6 * g.h();
    for (Index t : tiles_)
      for (Index q = g.tile_start()[t]; q < g.tile_start()[t + 1]; ++q) {
        const Index i = g.tile_particles()[q];
        const Vec2 xr = g.grid_coord(P.x[i]);
        const Index id = g.node_id(IVec<2>(static_cast<int>(std::lround(xr[0])), static_cast<int>(std::lround(xr[1]))));
        if (slot_[id] < 0) continue;
        const Candidate& c = cand_[slot_[id]];
        const ElementCurve& curve = curves_[c.element];
        const Projection pr = project_on_curve(curve, P.x[i]);
        const double d = std::sqrt(pr.dist2), hm = fr.half_depth(c.element, pr.xi);
        const Vec2 n = outward_normal(curve, pr.xi, P.x[i], curve.point(pr.xi), d, g.h());
        if (d - hm - particle_reach<2>(P, i, -n) <= tol) touch_.add(g, s.bodies[P.body[i]].field * g.nnodes(), P.x[i], n);
      }
  }
}

template <int D> void MemberContact<D>::apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt) {
  if constexpr (D != 2) {
    throw std::logic_error("beam-column members are 2D only");
  } else {
    Frame& fr = *s.frame;
    fr.clear_loads();
    force_.setZero();
    loaded_.clear();
    loads_.clear();
    Grid<2>& g = *s.grid;
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

// f_bc of eqs. (19)-(21) on the candidate nodes, the reactions on the frame and the held masses.
template <int D> void MemberContact<D>::boundary_forces(Scene<D>& s, double dt) {
  if constexpr (D == 2) {
    Frame& fr = *s.frame;
    Grid<2>& g = *s.grid;
    const MemberCoupling& opt = s.coupling;
    const double ln = opt.decay_scale * g.h();
    const Index nn = g.nnodes();
    for (const Candidate& c : cand_) {
      const Vec2 x = g.node_pos(c.node);
      const ElementCurve& curve = curves_[c.element];
      const double hm = fr.half_depth(c.element, c.xi);
      const Vec2 vc = fr.velocity_at(c.element, c.xi);
      const double omega = fr.angular_velocity_at(c.element, c.xi);
      const double dist = std::sqrt(c.dist2);
      const Vec2 n0 = outward_normal(curve, c.xi, x, c.xm, dist, g.h());  // from the centre-line towards the node
      for (int f : opt.fields) {
        const Index k = f * nn + c.node;
        const double m = g.m[k];
        if (!(m > 0)) continue;
        // Orientation by the mass-weighted particle position the node sees, eqs. (24)-(25).
        const Vec2 xbar = mx_[k] / m;
        const Vec2 n = (xbar - c.xm).dot(n0) >= 0 ? n0 : Vec2(-n0);
        // Bodies bonded to the members (a tyre buffer fixed on the dam face) stick whatever the mode, and are
        // held from the node distance: measured from x-bar the bond peeled (the held mass sagged, q fell).
        const bool bonded = std::find(opt.bonded_fields.begin(), opt.bonded_fields.end(), f) != opt.bonded_fields.end();
        const MemberContactMode mode = bonded ? MemberContactMode::stick : opt.mode;
        const bool node_distance = bonded || opt.distance == DistanceKind::node;
        const double r = ((node_distance ? x : xbar) - c.xm).dot(n) - hm;  // eq. (23)
        // Velocity of the member's surface point x^M + c n: centre-line velocity plus omega x (c n), so the
        // material is held where the reaction acts (its power then matches the frame's, moment included).
        const Vec2 vstar = vc + omega * hm * Vec2(-n.y(), n.x());
        double q = weight(opt.decay, r, ln, hm, held_flag_[k] != 0);
        // Surface detection: only nodes engaged by particles touching the member, among those within l_n / 2 of
        // its surface on either side (as a rigid wall: a face between grid lines acts at the nearest node row).
        if (mode != MemberContactMode::stick && opt.decay == DecayKind::sharp && opt.detection == DetectionKind::surface)
          q = touch_.engaged(k) && (q > 0 || r <= 0.5 * ln * (1 + 1e-9)) ? 1.0 : 0.0;
        if (q == 0) continue;
        loaded_.push_back(Loaded{k, n, vstar, q, mode, false});
        Vec2 fv = -g.f[k] + (m * vstar - g.p[k]) / dt;  // eq. (20)
        if (mode != MemberContactMode::stick) {
          const double fn = fv.dot(n);
          if (fn <= 0) continue;  // separating: no force, eq. (21)
          Vec2 ft = fv - fn * n;
          if (mode == MemberContactMode::friction) {
            const double lim = opt.friction * fn, t = ft.norm();
            if (t > lim) ft *= lim / t;
          } else {
            ft.setZero();
          }
          fv = fn * n + ft;
        }
        const Vec2 fbc = q * fv;  // eq. (19)
        g.f[k] += fbc;
        // Reaction on the member at the surface point x^M + c n: force plus the moment of the offset.
        const Vec2 arm = hm * n, F = -fbc;
        fr.add_point_load(c.element, c.xi, F, arm.x() * F.y() - arm.y() * F.x());
        // The held material moves with the member: its mass joins the frame's inertia for the step
        // (all directions when stuck, the normal one when sliding).
        fr.add_point_mass(c.element, c.xi, q * m * (mode == MemberContactMode::stick ? Mat<2>(Mat<2>::Identity()) : Mat<2>(n * n.transpose())));
        force_ += F;
        loaded_.back().pressed = true;
        loads_.push_back(ContactLoad{c.element, c.xi, c.xm + hm * n, F});
        ++stats_.loaded;
      }
    }
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
    if (l.mode == MemberContactMode::friction) {
      const Vec<D> vt = rel - vn * l.n;
      const double t = vt.norm(), cut = std::min(t, opt.friction * l.q * -vn);
      if (t > 0) dv -= cut / t * vt;
    }
    v += dv;
  }
}

template class MemberContact<2>;
template class MemberContact<3>;

}  // namespace dmi
