#include "engine/common/parallel.hpp"
#include "engine/mpm/boundary.hpp"

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
      const Vec<D> vt = v - vn * n;
      const double t = vt.norm(), slip = mu * (-vn);
      return t > slip ? Vec<D>(vt * (1 - slip / t)) : Vec<D>::Zero();
    }
  }
  return v;
}

bool unilateral(const WallCondition c) { return c == WallCondition::slip || c == WallCondition::friction; }

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
  for (auto& w : s.walls) {
    if (!w.surface_detection || !unilateral(w.condition)) continue;
    w.touch.reset(static_cast<std::size_t>(g.nnodes()) * g.nfields());
    flag.assign(P.size(), 0);
    parallel_for(0, np, [&](Index i) {
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

template <int D> double apply_boundaries(Scene<D>& s, std::vector<Vec<D>>& vel, double dt, double time, bool record) {
  Grid<D>& g = *s.grid;
  if (record) {
    for (auto& w : s.walls) w.force.setZero();
    for (auto& r : s.regions) r.force.setZero();
  }
  if (s.walls.empty() && s.regions.empty()) return 0.0;
  const double tol = 1e-9 * g.h();
  const Index nn = g.nnodes();
  double work = 0.0;
  for (Index id : g.active()) {
    const Vec<D> x = g.node_pos(id);
    for (int fld = 0; fld < g.nfields(); ++fld) {
      const Index k = fld * nn + id;
      const double m = g.m[k];
      if (m <= 0) continue;
      for (auto& w : s.walls) {
        // Surface detection: only nodes engaged by particles touching the wall, so the held patch is the contact
        // patch to within a node spacing (not the stencil's reach), among the nodes within h/2 of the plane on
        // either side: a plane between grid lines acts at the nearest node row, not at the row behind it.
        const bool surface = w.surface_detection && unilateral(w.condition);
        Vec<D> n;
        if (!wall_normal(w, x, surface ? 0.5 * g.h() : tol, n)) continue;
        if (surface && !w.touch.engaged(k)) continue;
        const Vec<D> before = vel[k];
        vel[k] = constrain(before, n, w.condition, w.friction);
        const bool bilateral = w.condition == WallCondition::stick || w.condition == WallCondition::roller;
        bool mirrored = false;
        if (bilateral && w.mirror_axis >= 0) {
          IVec<D> ijk = g.node_ijk(id);
          const int a = w.mirror_axis;
          if (ijk[a] != w.mirror_index) {
            ijk[a] = 2 * w.mirror_index - ijk[a];
            if (ijk[a] >= 0 && ijk[a] < g.nodes()[a]) {
              const Index km = fld * nn + g.node_id(ijk);
              if (g.m[km] > 0) {  // odd reflection of the free node's velocity (normal part only for a roller)
                const Vec<D> vm = vel[km];
                vel[k] = w.condition == WallCondition::stick ? Vec<D>(-vm) : Vec<D>(vm - 2 * vm.dot(n) * n);
                mirrored = true;
              }
            }
          }
        }
        if (record) {
          const Vec<D> dp = m * (vel[k] - before);
          w.force -= dp / dt;
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
    }
  }
  return work;
}

// Bodies touch at a node when their particle volumes there, sum_b sum_p V_p N_ip, fill its support:
// without a gap the sum is the full cell volume (partition of unity) wherever the interface lies.
constexpr double kContactFill = 0.99;

template <int D> void body_contact(Scene<D>& s, std::vector<Vec<D>>& vel) {
  Grid<D>& g = *s.grid;
  const int nf = g.nfields();
  if (nf < 2) return;
  const Index nn = g.nnodes();
  const double mu = s.options.contact_friction;
  const double fill = kContactFill * s.options.cell_volume;
  const auto& active = g.active();
  const Index na = static_cast<Index>(active.size());
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
      const double t = rt.norm();
      if (t <= mu * vn) {
        vel[k] = vcm;  // stick
      } else {
        vel[k] -= vn * n + (t > 0 ? Vec<D>(mu * vn * rt / t) : Vec<D>::Zero());
      }
    }
  });
}

template void wall_touch<2>(Scene<2>&);
template void wall_touch<3>(Scene<3>&);
template double apply_boundaries<2>(Scene<2>&, std::vector<Vec<2>>&, double, double, bool);
template double apply_boundaries<3>(Scene<3>&, std::vector<Vec<3>>&, double, double, bool);
template void body_contact<2>(Scene<2>&, std::vector<Vec<2>>&);
template void body_contact<3>(Scene<3>&, std::vector<Vec<3>>&);

}  // namespace dmi
