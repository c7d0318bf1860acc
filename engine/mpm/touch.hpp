// Surface contact detection shared by rigid walls and beam-column members. A unilateral boundary holds a grid node
// only where the body's surface touches it: a particle touches when its domain reaches the boundary, and it engages
// the boundary's nodes of its stencil that lie within half a cell of it along the boundary (its tributary node
// column). Holding every node on or behind a boundary instead (node detection) holds the whole stencil reach of
// the body's surface, 1.5 h for quadratic B-splines, before the body arrives: a curved body then meets the
// boundary on a patch ~sqrt(3 R h) wide at first touch, and a hard elastic impact's peak force depended several-fold
// on the cell size and on where the face lay between grid lines (docs/verification.md, "Hard impact"). A share of
// the node's mass as the criterion failed on curved bodies: the few touching particles at the bottom of a cylinder
// carry a third of the mass of the nodes under them (their neighbours along the wall are higher), so no node on
// the plane engaged and the contact went through the nearly empty nodes behind it.
#pragma once
#include <algorithm>
#include <vector>

#include "engine/common/types.hpp"
#include "engine/mpm/grid.hpp"
#include "engine/common/particles.hpp"

namespace dmi {

// Reach of particle i's material from its centre along the unit direction n: the box [-reach_lo, reach_hi] (the
// particle's domain, extended to the seeded shape's surface for particles next to it) mapped by F reaches
// sum_j |a_j| r_j, a = F^T n, r_j = reach_hi_j if a_j > 0 else reach_lo_j. The lattice of particle domains is a
// staircase: the bottom layer of a ball seeded at h/2 spacing is flat over a disc of radius ~sqrt(R h), wider than
// the Hertz contact patch at design cells, so contact decided on the domains alone met a flat punch. A particle
// pressed against a boundary shortens with its centre moving towards it, so its deformed reach stays on the
// boundary and a contact decided on it alone switches on and off; the undeformed reach (F = I) keeps it until the
// particle has moved away by its own compression. The larger of the two.
template <int D> double particle_reach(const Particles<D>& P, Index i, const Vec<D>& n) {
  auto along = [&](const Vec<D>& a) {
    double r = 0;
    for (int j = 0; j < D; ++j) r += std::abs(a[j]) * (a[j] > 0 ? P.reach_hi[i][j] : P.reach_lo[i][j]);
    return r;
  };
  return std::max(along(P.F[i].transpose() * n), along(n));
}

// An upper bound of particle_reach over every direction: sum_j |a_j| r_j <= |a| |r| <= |F|_F |r| (a = F^T n, |n| = 1,
// r_j the larger of reach_lo_j and reach_hi_j), and |r| for the undeformed reach.
template <int D> double particle_reach_bound(const Particles<D>& P, Index i) {
  return std::max(1.0, P.F[i].norm()) * P.reach_lo[i].cwiseMax(P.reach_hi[i]).norm();
}

// Node-fields engaged by touching particles (grid field layout), reset entry by entry.
class TouchSet {
 public:
  void reset(std::size_t size) {
    if (flag_.size() != size) {
      flag_.assign(size, 0);
    } else {
      for (Index k : set_) flag_[k] = 0;
    }
    set_.clear();
  }
  bool engaged(Index k) const { return flag_[k] != 0; }
  // A particle at x of the field starting at field_offset touches a boundary whose normal there is n (unit):
  // engages the nodes within the quadratic B-spline support (1.5 h) along n and within h/2 of x across it.
  template <int D> void add(const Grid<D>& g, Index field_offset, const Vec<D>& x, const Vec<D>& n) {
    const Vec<D> xr = g.grid_coord(x);
    IVec<D> lo, hi;
    g.support_nodes(xr, lo, hi);
    const double tol = 0.5 + 1e-9;
    any_node_in_box<D>(lo, hi, [&](const IVec<D>& ijk) {
      const Vec<D> r = ijk.template cast<double>() - xr;  // node minus particle, grid units
      const double rn = r.dot(n);
      if (std::abs(rn) <= 1.5 && (r - rn * n).cwiseAbs().maxCoeff() <= tol) {
        const Index k = field_offset + g.node_id(ijk);
        if (!flag_[k]) flag_[k] = 1, set_.push_back(k);
      }
      return false;
    });
  }

 private:
  std::vector<unsigned char> flag_;
  std::vector<Index> set_;
};

}  // namespace dmi
