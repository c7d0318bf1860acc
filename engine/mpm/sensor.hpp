// Pressure sensors: the normal traction a face receives, averaged over a patch as a transducer reads it. The face's
// reaction arrives as nodal forces (the grid nodes a wall or member holds, spaced h); each is spread over its
// tributary square of side h centred at the node's projection on the face (a segment in 2D), and the patch receives
// the part of it that falls inside: p = sum_i (f_i . n_in) |T_i n S| / (|T_i| |S|), with |S| the patch area (its
// length times the thickness in 2D). A patch much larger than h reads force over area; one smaller than h the
// traction of the node whose square holds it.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "engine/common/types.hpp"

namespace dmi {

template <int D> struct PressurePatch {
  std::string name;
  Vec<D> centre = Vec<D>::Zero();
  Vec<D> normal = Vec<D>::Zero();  // outward: from the face into the material
  Vec<D> t1 = Vec<D>::Zero(), t2 = Vec<D>::Zero();  // axes of the square in the face (t2 unused in 2D)
  double size = 0;                 // side of the square (m)
  double area = 0;                 // m^2
  double force = 0;                // compressive normal force on the patch in the last step (N)
  // Other walls meeting the face (point, normal into the material): a node's tributary square is cut where it
  // passes behind one (the half behind a floor of the node in the corner holds no material), so a sensor in a
  // corner reads the traction of the material, not half of it.
  std::vector<std::pair<Vec<D>, Vec<D>>> clips;
};

// A patch of side size centred at c with outward normal n; t1: the first in-face axis (3D; zero: chosen); thickness:
// the 2D analysis thickness (ignored in 3D).
template <int D> PressurePatch<D> make_patch(const std::string& name, const Vec<D>& c, const Vec<D>& n, double size, double thickness,
                                             Vec<D> t1 = Vec<D>::Zero()) {
  PressurePatch<D> p;
  p.name = name, p.centre = c, p.normal = n.normalized(), p.size = size;
  if constexpr (D == 2) {
    p.t1 = Vec<D>(-p.normal.y(), p.normal.x());
    p.area = size * thickness;
  } else {
    if (!(t1.norm() > 0)) {  // the axis least aligned with n, made orthogonal to it
      int k = 0;
      for (int d = 1; d < 3; ++d) if (std::abs(p.normal[d]) < std::abs(p.normal[k])) k = d;
      t1 = Vec<D>::Unit(k);
    }
    p.t1 = (t1 - t1.dot(p.normal) * p.normal).normalized();
    p.t2 = p.normal.cross(p.t1);
    p.area = size * size;
  }
  return p;
}

// The part [lo, hi] (offsets along axis t from the node at x) of a node's tributary in front of the clipping walls
// that cross t (|t . m| > 1/2), intersected with the patch [-s/2, s/2] about u, as a fraction of that part.
template <int D> double clipped_overlap(const PressurePatch<D>& p, const Vec<D>& x, const Vec<D>& t, double u, double h) {
  double lo = -0.5 * h, hi = 0.5 * h;
  for (const auto& [q, m] : p.clips) {
    const double tm = t.dot(m);
    if (std::abs(tm) <= 0.5) continue;
    const double s0 = -(x - q).dot(m) / tm;  // (x + s t - q) . m >= 0
    if (tm > 0) lo = std::max(lo, s0);
    else hi = std::min(hi, s0);
  }
  if (!(hi > lo)) return 0.0;
  return std::max(0.0, std::min(u + hi, 0.5 * p.size) - std::max(u + lo, -0.5 * p.size)) / (hi - lo);
}

// Fraction of a node's force at x (spacing h) the patch receives: 0 unless the node lies between a cell in front of
// the face and two behind it (a wall holds the nodes its material's stencils reach, up to 1.5 h behind its plane;
// the patch's centre lies on the face).
template <int D> double patch_weight(const PressurePatch<D>& p, const Vec<D>& x, double h) {
  const Vec<D> r = x - p.centre;
  if (const double depth = r.dot(p.normal); depth > h * (1 + 1e-9) || depth < -2 * h) return 0.0;
  double w = clipped_overlap(p, x, p.t1, r.dot(p.t1), h);
  if constexpr (D == 3) w *= clipped_overlap(p, x, p.t2, r.dot(p.t2), h);
  return w;
}

// Adds a nodal force f (of the material on the face, N) at x to the patch.
template <int D> void patch_add(PressurePatch<D>& p, const Vec<D>& x, const Vec<D>& f, double h) {
  if (const double w = patch_weight(p, x, h); w > 0) p.force -= w * f.dot(p.normal);
}

inline double patch_pressure(double force, double area) { return area > 0 ? force / area : 0.0; }

}  // namespace dmi
