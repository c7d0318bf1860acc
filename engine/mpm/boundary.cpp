#include "engine/common/coulomb.hpp"
#include "engine/common/parallel.hpp"
#include "engine/mpm/boundary.hpp"
#include "engine/mpm/rigid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dmi {
namespace {

// Outward normal (into the free side) of the wall at a node, or zero when the node is free.
template <int D> bool wall_normal(const Wall<D>& w, const Vec<D>& x, double tol, Vec<D>& n) {
  if (!w.box) {
    n = w.normal;
    return (x - w.point).dot(w.normal) <= tol;
  }
  double best = std::numeric_limits<double>::infinity();
  n.setZero();
  for (int d = 0; d < D; ++d) {
    if (x[d] < w.lo[d] - tol || x[d] > w.hi[d] + tol) return false;
  }
  for (int d = 0; d < D; ++d) {
    const double to_lo = x[d] - w.lo[d], to_hi = w.hi[d] - x[d];
    if (to_lo < best) { best = to_lo; n = -Vec<D>::Unit(d); }
    if (to_hi < best) { best = to_hi; n = Vec<D>::Unit(d); }
  }
  return true;
}

template <int D> Vec<D> constrain(const Vec<D>& v, const Vec<D>& n, WallCondition c, double mu) {
  const double vn = v.dot(n);
  switch (c) {
    case WallCondition::stick: return Vec<D>::Zero();
    case WallCondition::roller: return v - vn * n;
    case WallCondition::slip: return vn < 0 ? Vec<D>(v - vn * n) : v;
    case WallCondition::friction: {
      if (vn >= 0) return v;
      const Vec<D> vt = v - vn * n;  // the wall removes the approach and as much of the slip as mu (-vn) allows
      return Vec<D>(vt - coulomb_projection(vt, mu * (-vn)));
    }
  }
  return v;
}

bool unilateral(const WallCondition c) { return c == WallCondition::slip || c == WallCondition::friction; }

}  // namespace

template <int D> bool wall_mirror(const Grid<D>& g, const Wall<D>& w, Index id, Index& image, Mat<D>& S) {
  const bool bilateral = w.condition == WallCondition::stick || w.condition == WallCondition::roller;
  if (!bilateral || w.box || w.mirror_axis < 0) return false;
  Vec<D> n;
  if (!wall_normal(w, g.node_pos(id), 1e-9 * g.h(), n)) return false;
  IVec<D> ijk = g.node_ijk(id);
  const int a = w.mirror_axis;
  if (ijk[a] == w.mirror_index) return false;
  ijk[a] = 2 * w.mirror_index - ijk[a];
  if (ijk[a] < 0 || ijk[a] >= g.nodes()[a]) return false;
  image = g.node_id(ijk);
  S = w.condition == WallCondition::stick ? Mat<D>(-Mat<D>::Identity()) : Mat<D>(Mat<D>::Identity() - 2 * n * n.transpose());
  return true;
}

namespace {

// Signed distance from the wall to a particle's centre x (the largest outward distance over a box's faces): surface_gap
// is at least this less the particle's reach.
template <int D> double centre_gap(const Wall<D>& w, const Vec<D>& x) {
  if (!w.box) return (x - w.point).dot(w.normal);
  double gap = -std::numeric_limits<double>::infinity();
  for (int d = 0; d < D; ++d) gap = std::max({gap, w.lo[d] - x[d], x[d] - w.hi[d]});
  return gap;
}

// Signed distance from the wall to the nearest point of particle i's domain (negative: it overlaps the wall), and
// the wall's outward normal there.
template <int D> double surface_gap(const Wall<D>& w, const Particles<D>& P, Index i, Vec<D>& n) {
  if (!w.box) {
    n = w.normal;
    return (P.x[i] - w.point).dot(w.normal) - particle_reach<D>(P, i, -w.normal);  // reach towards the wall
  }
  double gap = -std::numeric_limits<double>::infinity();
  for (int d = 0; d < D; ++d)
    for (int side = 0; side < 2; ++side) {
      const double out = side ? P.x[i][d] - w.hi[d] : w.lo[d] - P.x[i][d];
      const double g = out - particle_reach<D>(P, i, (side ? -1.0 : 1.0) * Vec<D>::Unit(d));
      if (g > gap) gap = g, n = side ? Vec<D>(Vec<D>::Unit(d)) : Vec<D>(-Vec<D>::Unit(d));
    }
  return gap;
}

}  // namespace

template <int D> void wall_touch(Scene<D>& s) {
  const Grid<D>& g = *s.grid;
  const Particles<D>& P = s.particles;
  const Index np = static_cast<Index>(P.size());
  const double tol = 1e-6 * g.h();
  std::vector<unsigned char> flag;
  std::vector<double> bound;  // per particle: particle_reach_bound, so that the exact gap is computed only near a wall
  for (auto& w : s.walls) {
    if (!w.surface_detection || !unilateral(w.condition)) continue;
    w.touch.reset(static_cast<std::size_t>(g.nnodes()) * g.nfields());
    if (bound.empty()) {
      bound.resize(P.size());
      parallel_for(0, np, [&](Index i) { bound[i] = particle_reach_bound(P, i); });
    }
    flag.assign(P.size(), 0);
    parallel_for(0, np, [&](Index i) {
      if (centre_gap(w, P.x[i]) - bound[i] > tol) return;  // the gap is at least this
      Vec<D> n;
      flag[i] = surface_gap(w, P, i, n) <= tol;
    });
    for (Index i = 0; i < np; ++i) {
      if (!flag[i]) continue;
      Vec<D> n;
      surface_gap(w, P, i, n);
      w.touch.add(g, s.bodies[P.body[i]].field * g.nnodes(), P.x[i], n);
    }
  }
}

template <int D> void keep_in_front_of_walls(Scene<D>& s, Index i0, Index i1) {
  Particles<D>& P = s.particles;
  for (const Body& b : s.bodies) {
    if (b.rigid) continue;
    for (const auto& w : s.walls) {
      if (w.box) continue;
      for (Index i = std::max(b.begin, i0); i < std::min(b.end, i1); ++i)
        if (const double gap = (P.x[i] - w.point).dot(w.normal); gap < 0) P.x[i] -= gap * w.normal;
    }
  }
}

template <int D>
double apply_boundaries(Scene<D>& s, std::vector<Vec<D>>& vel, double dt, double time, bool record, bool reset, const std::vector<Index>* nodes) {
  Grid<D>& g = *s.grid;
  if (record && reset) {
    for (auto& w : s.walls) {
      w.force = w.carried, w.carried.setZero();
      for (auto& ps : w.sensors) ps.force = 0;
    }
    for (auto& r : s.regions) r.force.setZero();
    for (auto& in : s.inflows) in.force.setZero();
  }
  if (s.walls.empty() && s.regions.empty() && s.inflows.empty()) return 0.0;
  const double tol = 1e-9 * g.h();
  const Index nn = g.nnodes();
  double work = 0.0;
  const std::vector<char> hull = hull_fields(s);  // plane unilateral walls meet these fields at the rigid hull
  for (Index id : nodes ? *nodes : g.active()) {
    const Vec<D> x = g.node_pos(id);
    for (int fld = 0; fld < g.nfields(); ++fld) {
      const Index k = fld * nn + id;
      const double m = g.m[k];
      if (m <= 0) continue;
      for (auto& w : s.walls) {
        if (hull[fld] && !w.box && unilateral(w.condition)) continue;  // RigidBodies::wall_contact
        // Surface detection: only nodes engaged by particles touching the wall, so the held patch is the contact
        // patch to within a node spacing (not the stencil's reach), among the nodes within h/2 of the plane on
        // either side: a plane between grid lines acts at the nearest node row, not at the row behind it.
        const bool surface = w.surface_detection && unilateral(w.condition);
        Vec<D> n;
        if (!wall_normal(w, x, surface ? 0.5 * g.h() : tol, n)) continue;
        if (surface && !w.touch.engaged(k)) continue;
        const Vec<D> before = vel[k];
        vel[k] = constrain(before, n, w.condition, w.friction);
        bool mirrored = false;
        Index image;
        Mat<D> S;
        if (wall_mirror(g, w, id, image, S) && g.m[fld * nn + image] > 0) {  // the image's velocity, reflected
          vel[k] = S * vel[fld * nn + image];
          mirrored = true;
        }
        if (record) {
          const Vec<D> dp = m * (vel[k] - before);
          w.force -= dp / dt;
          for (auto& ps : w.sensors)
            if (n.dot(ps.normal) > 0.5) patch_add(ps, x, Vec<D>(-dp / dt), g.h());
          // A fixed wall does no work; a mirrored node's velocity is an image, not wall motion.
          if (!mirrored) work += dp.dot(vel[k]);
        }
      }
      for (auto& r : s.regions) {
        if (time < r.start || time >= r.end) continue;
        if (((x - r.lo).array() < -tol).any() || ((r.hi - x).array() < -tol).any()) continue;
        const Vec<D> before = vel[k];
        vel[k] = r.velocity;
        if (record) {
          const Vec<D> dp = m * (vel[k] - before);
          r.force -= dp / dt;
          work += dp.dot(vel[k]);
        }
      }
      for (auto& in : s.inflows) {  // the driven zone of an inflow (engine/mpm/inflow.hpp), on its body's field
        if (fld != s.bodies[static_cast<std::size_t>(in.body)].field || !in.driving(time) || !in.in_zone(x, tol)) continue;
        const Vec<D> before = vel[k];
        vel[k] = in.velocity(time);
        if (record) {
          const Vec<D> dp = m * (vel[k] - before);
          in.force -= dp / dt;
          work += dp.dot(vel[k]);
        }
      }
    }
  }
  return work;
}

// Bodies touch at a node when their particle volumes there, sum_b sum_p V_p N_ip, fill its support:
// without a gap the sum is the full cell volume (partition of unity) wherever the interface lies.
constexpr double kContactFill = 0.99;

// Surface detection between bodies. At a node where two fields (the two with most volume there) have mass, each
// field's front is how far its material reaches beyond the node along an axis, over its particles in the node's
// column (within h/2 across the axis): max_p (x_p - x_i) . e + reach_p(e) (particle_reach, engine/mpm/touch.hpp).
// The bodies touch when their fronts along opposite directions meet (overlap f_a + f_b >= 0), as a particle
// touches a wall. The axis is the one of three candidates along which they overlap least (the separating-axis
// rule): the bisector of the two unit mass gradients, and each field's own. A corner over a face then presses
// along the face's normal (a block's corner normal, tilted by its front face, braked it on a slab), two equal
// curved bodies along their bisector (the own normals of each, tilted by x/R, show more overlap).
template <int D> void body_fronts(Scene<D>& s) {
  const Grid<D>& g = *s.grid;
  const Particles<D>& P = s.particles;
  const Index nn = g.nnodes();
  const int nf = g.nfields();
  s.body_pair.assign(static_cast<std::size_t>(nn), {-1, -1});
  s.body_axes.resize(static_cast<std::size_t>(nn));
  s.body_front.resize(static_cast<std::size_t>(nn));
  const auto& active = g.active();
  parallel_for(0, static_cast<Index>(active.size()), [&](Index a) {
    const Index id = active[a];
    int first = -1, second = -1;
    for (int b = 0; b < nf; ++b) {
      const Index k = b * nn + id;
      if (g.m[k] <= 0 || !(g.grad_m[k].norm() > 0)) continue;
      if (first < 0 || g.vol[k] > g.vol[first * nn + id]) {
        second = first;
        first = b;
      } else if (second < 0 || g.vol[k] > g.vol[second * nn + id]) {
        second = b;
      }
    }
    if (second < 0) return;
    const int lo = std::min(first, second), hi = std::max(first, second);
    const Vec<D> ga = g.grad_m[lo * nn + id].normalized(), gb = g.grad_m[hi * nn + id].normalized();
    Vec<D> bis = ga - gb;  // outward of lo, towards hi
    if (!(bis.norm() > 1e-12)) bis = ga;
    s.body_pair[id] = {lo, hi};
    s.body_axes[id] = {bis.normalized(), ga, Vec<D>(-gb)};
    s.body_front[id].fill(-std::numeric_limits<double>::infinity());
  });
  const double h = g.h(), tol = 0.5 + 1e-9;
  // Only the particles of tiles whose node box holds a shared node can reach one.
  const auto& occupied = g.occupied();
  for (Index k = 0; k < static_cast<Index>(occupied.size()); ++k) {
    IVec<D> blo, bhi;
    g.tile_nodes(occupied[k], blo, bhi);
    if (!any_node_in_box<D>(blo, bhi, [&](const IVec<D>& c) { return s.body_pair[g.node_id(c)][0] >= 0; })) continue;
    for (Index q = g.tile_start()[k]; q < g.tile_start()[k + 1]; ++q) {
      const Index i = g.tile_particles()[q];
      const int f = s.bodies[P.body[i]].field;
      const Vec<D> xr = g.grid_coord(P.x[i]);
      IVec<D> lo, hi;
      g.support_nodes(xr, lo, hi);
      any_node_in_box<D>(lo, hi, [&](const IVec<D>& ijk) {
        const Index id = g.node_id(ijk);
        const auto& pair = s.body_pair[id];
        if (pair[0] == f || pair[1] == f) {
          const int side = pair[0] == f ? 0 : 1;
          const Vec<D> r = xr - ijk.template cast<double>();  // particle minus node, grid units
          for (int j = 0; j < 3; ++j) {
            const Vec<D> e = (side ? -1.0 : 1.0) * s.body_axes[id][j];
            const double rn = r.dot(e);
            if ((r - rn * e).cwiseAbs().maxCoeff() > tol) continue;
            double& front = s.body_front[id][2 * j + side];
            front = std::max(front, rn * h + particle_reach(P, i, e));
          }
        }
        return false;
      });
    }
  }
}

template <int D> bool pair_normal(const Scene<D>& s, Index id, double tol, Vec<D>& n) {
  const auto& front = s.body_front[id];
  // The least overlap over the three axes; none unless every axis's column holds both fields (a node beyond a
  // body's edge sees it only along a tilted axis).
  int best = -1;
  double overlap = std::numeric_limits<double>::infinity();
  for (int j = 0; j < 3; ++j) {
    const double o = front[2 * j] + front[2 * j + 1];
    if (!std::isfinite(o)) return false;
    if (o < overlap) overlap = o, best = j;
  }
  if (overlap < -tol) return false;  // separated along some axis
  n = s.body_axes[id][best];
  return true;
}

bool pair_masses_count(double ma, double mb) {
  // A field with under 1e-6 of the node's mass takes no force worth applying, and its correction P / m only
  // amplifies round-off (total momentum drifted by 1e-12 in the colliding-disk test, 1e-15 without).
  return !(std::min(ma, mb) < 1e-6 * (ma + mb));
}

// The pair's correction at a node in surface detection: momentum-conserving, along the least-overlap axis.
template <int D> void pair_contact(Scene<D>& s, std::vector<Vec<D>>& vel, Index id, double tol) {
  const Grid<D>& g = *s.grid;
  const auto& pair = s.body_pair[id];
  Vec<D> n;
  if (!pair_normal(s, id, tol, n)) return;
  const Index nn = g.nnodes(), ka = pair[0] * nn + id, kb = pair[1] * nn + id;
  const double ma = g.m[ka], mb = g.m[kb];
  if (!pair_masses_count(ma, mb)) return;
  // Relative velocity of a to the pair's centre of mass, m_b (v_a - v_b) / (m_a + m_b); b's is -m_a/m_b of it, so
  // one impulse P applied as +P/m_a and -P/m_b makes the two corrections equal and opposite to round-off.
  const Vec<D> rel = mb * (vel[ka] - vel[kb]) / (ma + mb);
  const double vn = rel.dot(n);
  if (vn <= 0) return;  // separating
  const Vec<D> rt = rel - vn * n;
  const double mu = s.options.contact_friction;
  const Vec<D> dva = -vn * n - coulomb_projection(rt, mu * vn);  // stick: -rel, to the centre of mass
  const Vec<D> P = ma * dva;  // stick: dva = -rel takes a to the centre of mass, and P takes b there too
  vel[ka] += P / ma;
  vel[kb] -= P / mb;
}

template <int D>
void body_contact(Scene<D>& s, std::vector<Vec<D>>& vel, bool fronts, const std::vector<Index>* nodes, const std::vector<char>* skip) {
  Grid<D>& g = *s.grid;
  const int nf = g.nfields();
  if (nf < 2) return;
  const Index nn = g.nnodes();
  const auto& active = nodes ? *nodes : g.active();
  const Index na = static_cast<Index>(active.size());
  if (s.options.contact_detection == BodyDetection::surface) {
    if (fronts || s.body_pair.size() != static_cast<std::size_t>(nn)) body_fronts(s);
    const double tol = 1e-6 * g.h();
    parallel_for(0, na, [&](Index a) {
      const auto& pair = s.body_pair[active[a]];
      if (pair[0] >= 0 && !(skip && ((*skip)[pair[0]] != 0) != ((*skip)[pair[1]] != 0))) pair_contact(s, vel, active[a], tol);
    });
    return;
  }
  const double mu = s.options.contact_friction;
  const double fill = kContactFill * s.options.cell_volume;
  parallel_for(0, na, [&](Index a) {
    const Index id = active[a];
    int present = 0;
    double mt = 0, vt = 0;
    Vec<D> pt = Vec<D>::Zero(), gt = Vec<D>::Zero();
    for (int b = 0; b < nf; ++b) {
      const Index k = b * nn + id;
      if (g.m[k] <= 0) continue;
      ++present;
      mt += g.m[k];
      vt += g.vol[k];
      pt += g.m[k] * vel[k];
      gt += g.grad_m[k];
    }
    if (present < 2 || vt < fill) return;  // supports overlap, the bodies do not touch
    const Vec<D> vcm = pt / mt;
    for (int b = 0; b < nf; ++b) {
      const Index k = b * nn + id;
      if (g.m[k] <= 0) continue;
      Vec<D> n = 2.0 * g.grad_m[k] - gt;  // g_b - sum_{c != b} g_c
      const double len = n.norm();
      if (!(len > 0)) continue;
      n /= len;
      const Vec<D> rel = vel[k] - vcm;
      const double vn = rel.dot(n);
      if (vn <= 0) continue;  // separating or sliding apart: no correction
      const Vec<D> rt = rel - vn * n;
      vel[k] -= vn * n + coulomb_projection(rt, mu * vn);  // stick: to vcm
    }
  });
}

template bool wall_mirror<2>(const Grid<2>&, const Wall<2>&, Index, Index&, Mat<2>&);
template bool wall_mirror<3>(const Grid<3>&, const Wall<3>&, Index, Index&, Mat<3>&);
template void wall_touch<2>(Scene<2>&);
template void wall_touch<3>(Scene<3>&);
template void keep_in_front_of_walls<2>(Scene<2>&, Index, Index);
template void keep_in_front_of_walls<3>(Scene<3>&, Index, Index);
template double apply_boundaries<2>(Scene<2>&, std::vector<Vec<2>>&, double, double, bool, bool, const std::vector<Index>*);
template double apply_boundaries<3>(Scene<3>&, std::vector<Vec<3>>&, double, double, bool, bool, const std::vector<Index>*);
template void body_contact<2>(Scene<2>&, std::vector<Vec<2>>&, bool, const std::vector<Index>*, const std::vector<char>*);
template void body_contact<3>(Scene<3>&, std::vector<Vec<3>>&, bool, const std::vector<Index>*, const std::vector<char>*);
template bool pair_normal<2>(const Scene<2>&, Index, double, Vec<2>&);
template bool pair_normal<3>(const Scene<3>&, Index, double, Vec<3>&);

}  // namespace dmi
