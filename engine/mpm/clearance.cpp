#include "engine/mpm/clearance.hpp"

#include <algorithm>
#include <limits>

#include "engine/mpm/member_contact.hpp"

namespace dmi {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <int D> struct Box {
  Vec<D> lo = Vec<D>::Constant(kInf), hi = Vec<D>::Constant(-kInf);
  bool empty() const { return !(lo[0] <= hi[0]); }
  // The separation along each axis, negative where they overlap.
  std::array<double, 3> sep(const Box& o) const {
    std::array<double, 3> s{-kInf, -kInf, -kInf};
    for (int d = 0; d < D; ++d) s[d] = std::max(o.lo[d] - hi[d], lo[d] - o.hi[d]);
    return s;
  }
};

template <int D> Box<D> particle_box(const Particles<D>& P, const Body& b) {
  Box<D> box;
  for (Index i = b.begin; i < b.end; ++i) box.lo = box.lo.cwiseMin(P.x[i]), box.hi = box.hi.cwiseMax(P.x[i]);
  return box;
}

// The distance g by which the box can grow on every axis with all its corners still on the free side of the plane:
// min over corners of n.(x - p), per unit of |n|_1 (the grown box's nearest corner moves by g |n|_1 along n).
template <int D> double plane_gap(const Box<D>& b, const Vec<D>& point, const Vec<D>& normal) {
  double g = kInf;
  for (int corner = 0; corner < (1 << D); ++corner) {
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = (corner >> d) & 1 ? b.hi[d] : b.lo[d];
    g = std::min(g, normal.dot(x - point));
  }
  return g / normal.template lpNorm<1>();
}

template <int D> Box<D> box_of(const Vec<D>& lo, const Vec<D>& hi) {
  Box<D> b;
  b.lo = lo, b.hi = hi;
  return b;
}

}  // namespace

template <int D> bool body_gaps(const Scene<D>& s, int k, const Clearance& c, std::vector<Gap>& out) {
  out.clear();
  const Particles<D>& P = s.particles;
  const Box<D> me = particle_box(P, s.bodies[k]);
  if (me.empty()) return false;
  for (std::size_t o = 0; o < s.bodies.size(); ++o) {
    if (static_cast<int>(o) == k) continue;
    const Box<D> other = particle_box(P, s.bodies[o]);
    out.push_back({other.empty() ? std::array<double, 3>{kInf, -kInf, -kInf} : me.sep(other), c.bodies, Gap::body});
  }
  for (const Wall<D>& w : s.walls)
    out.push_back({w.box ? me.sep(box_of(w.lo, w.hi)) : std::array<double, 3>{plane_gap(me, w.point, w.normal), -kInf, -kInf}, c.walls,
                   Gap::wall});
  for (const VelocityRegion<D>& r : s.regions) out.push_back({me.sep(box_of(r.lo, r.hi)), c.walls, Gap::region});
  if (s.frame)
    for (const auto& e : member_bounds<D>(*s.frame)) out.push_back({me.sep(box_of(e[0], e[1])), c.members, Gap::member});
  return true;
}

template <int D> bool body_is_clear(const Scene<D>& s, int k, const Clearance& c) {
  std::vector<Gap> gaps;
  if (!body_gaps(s, k, c, gaps)) return false;
  return std::all_of(gaps.begin(), gaps.end(), [](const Gap& g) { return g.gap() >= g.clear; });
}

template bool body_gaps(const Scene<2>&, int, const Clearance&, std::vector<Gap>&);
template bool body_gaps(const Scene<3>&, int, const Clearance&, std::vector<Gap>&);
template bool body_is_clear(const Scene<2>&, int, const Clearance&);
template bool body_is_clear(const Scene<3>&, int, const Clearance&);

}  // namespace dmi
