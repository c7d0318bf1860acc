#include "engine/mpm/transfer.hpp"

#include "engine/common/parallel.hpp"

#include <Eigen/LU>
#include <cmath>
#include <type_traits>

#include "engine/mpm/shape.hpp"
#include "engine/mpm/transfer2d.hpp"

namespace dmi {
namespace {

template <int D, class Shape> class Kernels final : public TransferKernels<D> {
  using St = Stencil<D, Shape>;

 public:
  void p2g(Scene<D>& s, bool momentum_only) const override {
    // The options are fixed per call: dispatch once to a kernel without run-time branches inside.
    const bool apic = s.options.transfer == TransferKind::apic;
    const bool grad = s.grid->nfields() > 1;
    if (momentum_only) {
      apic ? scatter<true, false, true>(s) : scatter<false, false, true>(s);
    } else if (grad) {
      apic ? scatter<true, true, false>(s) : scatter<false, true, false>(s);
    } else {
      apic ? scatter<true, false, false>(s) : scatter<false, false, false>(s);
    }
  }

  // APIC: affine momentum; GRAD: mass gradient and volume per field (contact); MOMENTUM: MUSL remap only.
  template <bool APIC, bool GRAD, bool MOMENTUM> void scatter(Scene<D>& s) const {
    if constexpr (D == 2) {
      detail::scatter2d<Shape, APIC, GRAD, MOMENTUM>(s);
      return;
    }
    Grid<D>& g = *s.grid;
    const Particles<D>& P = s.particles;
    const double h = g.h();
    const Index nn = g.nnodes();
    const auto& start = g.tile_start();
    const auto& order = g.tile_particles();
    const bool parallel = static_cast<Index>(P.size()) > kParallelMin;
    for (int c = 0; c < Grid<D>::kColors; ++c) {
      const auto& runs = g.color_runs(c);
      const Index nr = static_cast<Index>(runs.size());
      parallel_for_dynamic(nr, parallel, [&](Index k) {
        St st;
        for (Index q = start[runs[k].begin]; q < start[runs[k].end]; ++q) {
          const Index i = order[q];
          const Vec<D> xr = g.grid_coord(P.x[i]);
          st.compute(xr, P.half_size[i] * g.inv_h(), g.inv_h());
          const double mp = P.mass[i];
          const Vec<D> mv = mp * P.v[i];
          const Index off = s.bodies[P.body[i]].field * nn;
          [[maybe_unused]] Mat<D> mC, vs;
          if constexpr (APIC) mC = mp * P.C[i];
          // In-plane volume for the contact fill test: plane-stress thinning (F_zz) must not switch
          // contact off, since the cell volume it is compared with has the initial thickness.
          [[maybe_unused]] double vol_in_plane = 0;
          if constexpr (GRAD) vol_in_plane = P.vol0[i] * P.F[i].determinant();
          if constexpr (!MOMENTUM) vs = -P.vol[i] * P.stress[i];
          for (int n = 0; n < St::NN; ++n) {
            const IVec<D> ijk = st.base + st.offset[n];
            const Index id = off + g.node_id(ijk);
            const double N = st.N[n];
            if constexpr (APIC) {
              const Vec<D> dx = (ijk.template cast<double>() - xr) * h;
              g.p[id] += N * (mv + mC * dx);
            } else {
              g.p[id] += N * mv;
            }
            if constexpr (!MOMENTUM) {
              g.m[id] += N * mp;
              g.f[id] += vs * st.dN[n];  // gravity m_i g is added per node below
            }
            if constexpr (GRAD) {
              g.grad_m[id] += mp * st.dN[n];
              g.vol[id] += N * vol_in_plane;
            }
          }
        }
      });
    }
    // Gravity on the grid: sum_p N_ip m_p g = m_i g (eq. 8's body force), one multiply per node instead of one per
    // particle-node pair.
    if constexpr (!MOMENTUM) {
      const Vec<D> grav = s.gravity;
      const auto& active = g.active();
      parallel_for(0, static_cast<Index>(active.size()), [&](Index a) {
        for (int fld = 0; fld < g.nfields(); ++fld) g.f[fld * nn + active[a]] += g.m[fld * nn + active[a]] * grav;
      });
    }
  }

  int stencils(const Scene<D>& s, Index begin, Index end, std::vector<Index>& node, std::vector<Vec<D>>& grad) const override {
    const Grid<D>& g = *s.grid;
    const Particles<D>& P = s.particles;
    node.resize(static_cast<std::size_t>(end - begin) * St::NN);
    grad.resize(node.size());
    parallel_for(begin, end, [&](Index i) {
      St st;
      st.compute(g.grid_coord(P.x[i]), P.half_size[i] * g.inv_h(), g.inv_h());
      const std::size_t k0 = static_cast<std::size_t>(i - begin) * St::NN;
      for (int n = 0; n < St::NN; ++n) node[k0 + n] = g.node_id(st.base + st.offset[n]), grad[k0 + n] = st.dN[n];
    });
    return St::NN;
  }

  void scatter_mass_position(const Scene<D>& s, const std::vector<Index>& tiles, std::vector<Vec<D>>& mx) const override {
    const Grid<D>& g = *s.grid;
    const Particles<D>& P = s.particles;
    const Index nn = g.nnodes();
    St st;
    for (Index t : tiles) {
      for (Index q = g.tile_start()[t]; q < g.tile_start()[t + 1]; ++q) {
        const Index i = g.tile_particles()[q];
        st.compute(g.grid_coord(P.x[i]), P.half_size[i] * g.inv_h(), g.inv_h());
        const Vec<D> mxp = P.mass[i] * P.x[i];
        const Index off = s.bodies[P.body[i]].field * nn;
        for (int n = 0; n < St::NN; ++n) mx[off + g.node_id(st.base + st.offset[n])] += st.N[n] * mxp;
      }
    }
  }

  G2PResult g2p(Scene<D>& s, double dt, G2PMode mode, const typename TransferKernels<D>::ChunkHook* after_chunk) const override {
    if constexpr (D == 2) return detail::g2p2d<Shape>(s, dt, mode, after_chunk);
    Grid<D>& g = *s.grid;
    Particles<D>& P = s.particles;
    const bool apic = s.options.transfer == TransferKind::apic;
    const double blend = s.options.flip_blend;
    const double h = g.h();
    const Index nn = g.nnodes();
    const Index np = static_cast<Index>(P.size());
    const int bad = parallel_or(np, np > kParallelMin, [&](Index i) {
      int b = 0;
      St st;
      const Vec<D> xr = g.grid_coord(P.x[i]);
      st.compute(xr, P.half_size[i] * g.inv_h(), g.inv_h());
      const Index off = s.bodies[P.body[i]].field * nn;
      Vec<D> vpic = Vec<D>::Zero(), dv = Vec<D>::Zero();
      Mat<D> L = Mat<D>::Zero(), B = Mat<D>::Zero(), Dp = Mat<D>::Zero();
      // Linear shapes: an empty node takes the particle's interpolated velocity in the gradient (as in 2D,
      // transfer2d.hpp: a particle on a grid plane has slope 1/h at the empty node beyond a leading face).
      constexpr bool kEmptyFix = std::is_same_v<Shape, LinearShape>;
      Vec<D> ubar = Vec<D>::Zero(), gempty = Vec<D>::Zero();
      for (int n = 0; n < St::NN; ++n) {
        const IVec<D> ijk = st.base + st.offset[n];
        const Index id = off + g.node_id(ijk);
        const double N = st.N[n];
        const Vec<D>& vl = g.vL[id];
        if (mode != G2PMode::kinematics) {
          if (apic) {
            const Vec<D> dx = (ijk.template cast<double>() - xr) * h;
            B += N * vl * dx.transpose();
            Dp += N * dx * dx.transpose();
          } else {
            dv += N * (vl - g.v[id]);
          }
        }
        vpic += N * vl;
        const Vec<D>& u = mode == G2PMode::kinematics ? g.v[id] : vl;
        L += u * st.dN[n].transpose();
        if constexpr (kEmptyFix) {
          ubar += N * u;
          if (g.m[id] == 0) gempty += st.dN[n];
        }
      }
      if constexpr (kEmptyFix) L += ubar * gempty.transpose();
      if (mode != G2PMode::kinematics) {
        if (apic) {
          P.v[i] = vpic;
          P.C[i] = B * Dp.inverse();  // D_p > 0 for GIMP and B-splines; linear APIC is refused (Solver)
        } else {
          P.v[i] = blend * (P.v[i] + dv) + (1 - blend) * vpic;
        }
      }
      if (mode != G2PMode::velocity_only) {
        P.x[i] += dt * vpic;
        P.L[i] = L;
        P.F[i] = (Mat<D>::Identity() + dt * L) * P.F[i];
        if (!g.interior(P.x[i]) || !L.allFinite()) b = 1;
      }
      if (!P.v[i].allFinite()) b = 1;
      return b;
    });
    if (after_chunk && mode != G2PMode::velocity_only) (*after_chunk)(0, np);
    return G2PResult{bad == 0};
  }
};

}  // namespace

template <int D> std::unique_ptr<TransferKernels<D>> make_transfer_kernels(ShapeKind shape) {
  switch (shape) {
    case ShapeKind::linear: return std::make_unique<Kernels<D, LinearShape>>();
    case ShapeKind::gimp: return std::make_unique<Kernels<D, GimpShape>>();
    case ShapeKind::bspline2: return std::make_unique<Kernels<D, BSpline2Shape>>();
  }
  return nullptr;
}

template std::unique_ptr<TransferKernels<2>> make_transfer_kernels<2>(ShapeKind);
template std::unique_ptr<TransferKernels<3>> make_transfer_kernels<3>(ShapeKind);

}  // namespace dmi
