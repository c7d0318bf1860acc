#include "engine/mpm/fluid_volume.hpp"

#include <algorithm>
#include <cmath>

namespace dmi {

namespace {

// The nodal shape function along one axis at r = (x - x_i) / h: the quadratic B-spline, or the hat of linear shape
// functions and of uGIMP (whose particle weights are the hat convolved with the particle's extent, so that particles
// tiling a space give sum_p N_ip V_p = the hat's integral over it).
double nodal(ShapeKind k, double r) {
  r = std::abs(r);
  if (k == ShapeKind::bspline2) return r < 0.5 ? 0.75 - r * r : r < 1.5 ? 0.5 * (1.5 - r) * (1.5 - r) : 0.0;
  return r < 1 ? 1 - r : 0.0;
}

template <int D> bool free_space(const Scene<D>& s, const Vec<D>& x) {
  for (const Wall<D>& w : s.walls) {
    if (w.box) {
      if (((x - w.lo).array() > 0).all() && ((w.hi - x).array() > 0).all()) return false;
    } else if ((x - w.point).dot(w.normal) < 0) {
      return false;
    }
  }
  return true;
}

}  // namespace

template <int D> bool FluidVolumes<D>::needed(const Scene<D>& s) {
  for (const Body& b : s.bodies)
    if (!b.rigid && s.materials[b.material]->volume_relaxation() > 0) return true;
  return false;
}

template <int D> std::vector<double> FluidVolumes<D>::node_volumes(const Scene<D>& s) {
  const Grid<D>& g = *s.grid;
  const double h = g.h(), full = std::pow(h, D);
  const double reach = s.options.shape == ShapeKind::bspline2 ? 1.5 : 1.0;  // support half-width (cells)
  const int per_cell = D == 2 ? 8 : 4, n = static_cast<int>(2 * reach) * per_cell;  // quadrature points per axis
  const double dq = 2 * reach / n;                                                    // their spacing (cells)
  std::vector<double> vol(static_cast<std::size_t>(g.nnodes()), full);
  for (Index id = 0; id < g.nnodes(); ++id) {
    const Vec<D> x = g.node_pos(id);
    bool cut = false;  // a wall passes within the support (its box grown by the support)
    for (const Wall<D>& w : s.walls) {
      if (w.box) cut = cut || (((x - w.lo).array() > -reach * h).all() && ((w.hi - x).array() > -reach * h).all());
      else cut = cut || std::abs((x - w.point).dot(w.normal)) < reach * h * std::sqrt(static_cast<double>(D));
    }
    if (!cut) {
      if (!free_space(s, x)) vol[static_cast<std::size_t>(id)] = 0;  // deep behind a wall
      continue;
    }
    double v = 0;
    Index total = 1;
    for (int d = 0; d < D; ++d) total *= n;
    for (Index q = 0; q < total; ++q) {
      Index rest = q;
      Vec<D> r;
      double wq = 1;
      for (int d = 0; d < D; ++d) {
        r[d] = -reach + dq * (static_cast<double>(rest % n) + 0.5);
        rest /= n;
        wq *= nodal(s.options.shape, r[d]) * dq * h;
      }
      if (wq > 0 && free_space(s, Vec<D>(x + h * r))) v += wq;
    }
    vol[static_cast<std::size_t>(id)] = v;
  }
  return vol;
}

template <int D> void FluidVolumes<D>::apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt) {
  const Grid<D>& g = *s.grid;
  Particles<D>& P = s.particles;
  if (vol_.size() != static_cast<std::size_t>(g.nnodes())) vol_ = node_volumes(s);
  for (int f = 0; f < g.nfields(); ++f) {
    bool any = false;
    for (const Body& b : s.bodies) any = any || (b.field == f && !b.rigid && b.end > b.begin && s.materials[b.material]->volume_relaxation() > 0);
    if (!any) continue;
    ref_.assign(vol_.size(), 0.0);  // sum_q N_iq V0_q over every body of the field
    const Body* last = nullptr;       // the body whose stencils node_ and w_ hold
    int ne = 0;
    for (const Body& b : s.bodies) {
      if (b.field != f || b.end == b.begin) continue;
      ne = kernels.stencils(s, b.begin, b.end, node_, w_, grad_), last = &b;
      for (Index i = b.begin; i < b.end; ++i)
        for (int e = 0; e < ne; ++e) {
          const std::size_t k = static_cast<std::size_t>(i - b.begin) * ne + e;
          ref_[static_cast<std::size_t>(node_[k])] += w_[k] * P.vol0[i];
        }
    }
    for (const Body& b : s.bodies) {
      const Material<D>& mat = *s.materials[b.material];
      const double n = mat.volume_relaxation();
      if (b.field != f || b.rigid || b.end == b.begin || !(n > 0)) continue;
      const double kappa = std::min(1.0, dt * mat.wave_speed() / (n * g.h()));
      const double before = mat.strain_energy(P, b.begin, b.end);
      if (last != &b) ne = kernels.stencils(s, b.begin, b.end, node_, w_, grad_), last = &b;
      for (Index i = b.begin; i < b.end; ++i) {
        double space = 0, present = 0;
        for (int e = 0; e < ne; ++e) {
          const std::size_t k = static_cast<std::size_t>(i - b.begin) * ne + e;
          space += w_[k] * vol_[static_cast<std::size_t>(node_[k])];
          present += w_[k] * ref_[static_cast<std::size_t>(node_[k])];
        }
        const double J = P.F[i].determinant();
        if (!(present > 0 && space > 0 && J > 0)) continue;
        const double Jn = J * std::exp(kappa * std::log(space / (present * J)));
        P.F[i] = (D == 2 ? std::sqrt(Jn) : std::cbrt(Jn)) * Mat<D>::Identity();
        P.vol[i] = P.vol0[i] * Jn;
      }
      added_ += mat.strain_energy(P, b.begin, b.end) - before;
    }
  }
}

template class FluidVolumes<2>;
template class FluidVolumes<3>;

}  // namespace dmi
