#include "engine/mpm/clearance.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "engine/contact/member_contact.hpp"

namespace dmi {
namespace {

template <int D> struct Box {
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity()), hi = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(lo[0] <= hi[0]); }
  // Separated by at least gap along some axis (nodes are shared per axis: a box test in the max norm).
  bool apart(const Box& o, double gap) const {
    for (int d = 0; d < D; ++d)
      if (o.lo[d] - hi[d] >= gap || lo[d] - o.hi[d] >= gap) return true;
    return false;
  }
};

template <int D> Box<D> particle_box(const Particles<D>& P, const Body& b) {
  Box<D> box;
  for (Index i = b.begin; i < b.end; ++i) box.lo = box.lo.cwiseMin(P.x[i]), box.hi = box.hi.cwiseMax(P.x[i]);
  return box;
}

// Every corner of the box grown by gap lies strictly on the free side of the plane.
template <int D> bool in_front(const Box<D>& b, const Vec<D>& point, const Vec<D>& normal, double gap) {
  for (int corner = 0; corner < (1 << D); ++corner) {
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = (corner >> d) & 1 ? b.hi[d] + gap : b.lo[d] - gap;
    if (!(normal.dot(x - point) > 0)) return false;
  }
  return true;
}

}  // namespace

template <int D> bool body_is_clear(const Scene<D>& s, int k, const Clearance& c) {
  const Particles<D>& P = s.particles;
  const Box<D> me = particle_box(P, s.bodies[k]);
  if (me.empty()) return false;
  for (std::size_t o = 0; o < s.bodies.size(); ++o) {
    if (static_cast<int>(o) == k) continue;
    const Box<D> other = particle_box(P, s.bodies[o]);
    if (!other.empty() && !me.apart(other, c.bodies)) return false;
  }
  for (const Wall<D>& w : s.walls) {
    if (w.box) {
      Box<D> wb;
      wb.lo = w.lo, wb.hi = w.hi;
      if (!me.apart(wb, c.walls)) return false;
    } else if (!in_front(me, w.point, w.normal, c.walls)) {
      return false;
    }
  }
  for (const VelocityRegion<D>& r : s.regions) {
    Box<D> rb;
    rb.lo = r.lo, rb.hi = r.hi;
    if (!me.apart(rb, c.walls)) return false;
  }
  if (s.frame)
    for (const auto& e : member_bounds<D>(*s.frame)) {
      Box<D> eb;
      eb.lo = e[0], eb.hi = e[1];
      if (!me.apart(eb, c.members)) return false;
    }
  return true;
}

template bool body_is_clear(const Scene<2>&, int, const Clearance&);
template bool body_is_clear(const Scene<3>&, int, const Clearance&);

}  // namespace dmi
