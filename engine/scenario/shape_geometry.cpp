#include "engine/scenario/shape_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace dmi {

void shape_bounds(const ShapeConfig& s, int dim, DVec& lo, DVec& hi) {
  lo.assign(dim, 0.0);
  hi.assign(dim, 0.0);
  if (s.type == "polygon") {
    for (int d = 0; d < dim; ++d) {
      lo[d] = hi[d] = s.vertices.front()[d];
      for (const auto& p : s.vertices) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
    }
    return;
  }
  for (int d = 0; d < dim; ++d) {
    lo[d] = s.type == "box" ? s.min[d] : s.center[d] - s.radius;
    hi[d] = s.type == "box" ? s.max[d] : s.center[d] + s.radius;
  }
}

bool shape_contains(const ShapeConfig& s, const double* x, int dim) {
  if (s.type == "ball") {
    double r2 = 0;
    for (int d = 0; d < dim; ++d) r2 += (x[d] - s.center[d]) * (x[d] - s.center[d]);
    return r2 <= s.radius * s.radius && r2 >= s.inner_radius * s.inner_radius;
  }
  if (s.type == "polygon") {  // even-odd crossing test along +x (O'Rourke, Computational Geometry in C, 7.4)
    bool in = false;
    const auto& v = s.vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      const double yi = v[i][1], yj = v[j][1];
      if ((yi > x[1]) != (yj > x[1]) && x[0] < v[j][0] + (x[1] - yj) * (v[i][0] - v[j][0]) / (yi - yj)) in = !in;
    }
    return in;
  }
  for (int d = 0; d < dim; ++d)
    if (x[d] < s.min[d] || x[d] > s.max[d]) return false;
  return true;
}

double polygon_area(const std::vector<DVec>& v) {
  double a = 0;  // shoelace formula
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) a += v[j][0] * v[i][1] - v[i][0] * v[j][1];
  return 0.5 * a;
}

bool polygon_self_intersects(const std::vector<DVec>& v) {
  const std::size_t n = v.size();
  auto orient = [](const DVec& a, const DVec& b, const DVec& c) {
    const double o = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return (o > 0) - (o < 0);
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbouring edges share a vertex
      const DVec &a = v[i], &b = v[(i + 1) % n], &c = v[j], &d = v[(j + 1) % n];
      if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) return true;
    }
  return false;
}

}  // namespace dmi
