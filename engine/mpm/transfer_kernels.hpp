// The particle <-> grid transfers, written once for 2D and 3D (the equations are stated in transfer.hpp): the stencil
// walked row by row along x (shape.hpp's Stencil), loops over D with compile-time bounds, node fields through raw
// pointers, and the AVX2 3 x 3 kernels (transfer2d_avx.hpp) as a leaf for the 2D FLIP case. Eigen's small products are
// not inlined in the hot loops, hence plain arrays. Each node still
// receives its contributions in particle order, so sums do not depend on the thread count.
#pragma once
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "engine/common/parallel.hpp"
#include "engine/mpm/scene.hpp"
#include "engine/mpm/shape.hpp"
#include "engine/mpm/transfer.hpp"
#include "engine/mpm/transfer2d_avx.hpp"

namespace dmi::detail {

// Transfer schemes (transfer.hpp): FLIP/PIC blend, or APIC's affine velocity C_p.
struct Flip {
  static constexpr bool affine = false;
};
struct Apic {
  static constexpr bool affine = true;
};
// What P2G scatters: mass, momentum and force; the same with the contact fields (grad m, volume) of multi-field
// bodies; or momentum alone (the MUSL remap).
struct ScatterForces {
  static constexpr bool force = true, contact = false;
};
struct ScatterContact {
  static constexpr bool force = true, contact = true;
};
struct ScatterMomentum {
  static constexpr bool force = false, contact = false;
};
// What G2P updates (G2PMode): velocity and kinematics from v^L (USL); velocity only (MUSL pass 1); position from v^L
// and the velocity gradient from the remapped v (MUSL pass 2).
struct GatherFull {
  static constexpr bool velocity = true, kinematics = true, gradient_of_remap = false;
};
struct GatherVelocity {
  static constexpr bool velocity = true, kinematics = false, gradient_of_remap = false;
};
struct GatherKinematics {
  static constexpr bool velocity = false, kinematics = true, gradient_of_remap = true;
};

// The grid as the kernels see it, by value: inside an OpenMP region shared variables are reached through a pointer,
// and every store through the node pointers could alias them, so the compiler would reload h, the origin, the
// strides... after each store. A by-value copy cannot alias.
template <int D> struct GridView {
  Vec<D> origin;
  double h, ih;
  Index stride[D];     // node-id step per axis (x fastest)
  Index nn;            // nodes per velocity field
  double lo[D], hi[D];  // the interior (Grid::interior) in grid coordinates

  explicit GridView(const Grid<D>& g) : origin(g.origin()), h(g.h()), ih(g.inv_h()), nn(g.nnodes()) {
    Index st = 1;
    for (int d = 0; d < D; ++d) {
      stride[d] = st, st *= g.nodes()[d];
      lo[d] = 0.5, hi[d] = g.cells()[d] - 0.5;
    }
  }
  template <class St> Index base_id(const St& st) const {
    Index id = 0;
    for (int d = 0; d < D; ++d) id += static_cast<Index>(st.base[d]) * stride[d];
    return id;
  }
  // Node-id offset of each stencil row from the base node.
  template <class St> void row_offsets(Index* off) const {
    for (int r = 0; r < St::R; ++r) {
      off[r] = 0;
      for (int d = 1; d < D; ++d) off[r] += static_cast<Index>(St::digit(r, d)) * stride[d];
    }
  }
};

// Per-node P2G record: momentum and force side by side (p_0..p_D-1, f_0..f_D-1), 32-byte aligned in 2D (Grid::pf).
template <int D> constexpr int kRecord = 2 * D;

template <int D> struct ScatterCtx {
  const Vec<D>* __restrict x;
  const Vec<D>* __restrict v;
  const Vec<D>* __restrict half;
  const Mat<D>* __restrict C;
  const Mat<D>* __restrict F;
  const Mat<D>* __restrict stress;
  const double* __restrict mass;
  const double* __restrict vol;
  const double* __restrict vol0;
  const int* __restrict body;
  const Body* bodies;
  const Index* __restrict order;
  double* __restrict gm;
  double* __restrict gp;  // momentum (MUSL remap), interleaved
  double* __restrict pf;  // records (kRecord)
  double* __restrict gg;  // grad m, interleaved
  double* __restrict gvol;
  GridView<D> g;
};

// Offsets (m) of the stencil's nodes from the particle for APIC: along x per node a, along the other axes per row r.
template <int D, class St> struct NodeDistances {
  double x[St::K], row[D - 1][St::R];
  NodeDistances(const St& st, double h, std::true_type /*affine*/) : NodeDistances(st, h) {}
  explicit NodeDistances(const St& st, double h) {
    for (int a = 0; a < St::K; ++a) x[a] = (st.base[0] + a - st.xr[0]) * h;
    for (int r = 0; r < St::R; ++r)
      for (int d = 1; d < D; ++d) row[d - 1][r] = (st.base[d] + St::digit(r, d) - st.xr[d]) * h;
  }
  template <class T> NodeDistances(const St&, double, T) {}  // FLIP: not needed
  void at(int r, int a, double* dx) const {
    dx[0] = x[a];
    for (int d = 1; d < D; ++d) dx[d] = row[d - 1][r];
  }
};

// What a particle brings to every node of its stencil: m_p, m_p v_p, m_p C_p (APIC), -V_p sigma_p (force) and its
// in-plane volume (contact).
template <int D> struct ScatterParticle {
  double mp = 0, mv[D] = {}, mC[D][D] = {}, s[D][D] = {}, vip = 0;
};

// One row of the stencil without the affine term: the weights factor as w_x(a) W(r), so the row's factors once, then
// two products a node.
template <int D, class St>
[[gnu::always_inline]] inline void scatter_row_factored(const ScatterCtx<D>& c, const St& st, int r, Index row, const ScatterParticle<D>& p) {
  constexpr int RC = kRecord<D>;
  const double W = st.W[r], mW = p.mp * W;
  double pW[D], fx[D], fo[D];
  for (int k = 0; k < D; ++k) {
    pW[k] = W * p.mv[k];
    fx[k] = W * p.s[k][0];
    fo[k] = 0;
    for (int d = 1; d < D; ++d) fo[k] += p.s[k][d] * st.dW[d - 1][r];
  }
  for (int a = 0; a < St::K; ++a) {
    const Index id = row + a;
    const double wa = st.w[0][a], da = st.dwx[a];
    c.gm[id] += wa * mW;
    double* rec = c.pf + RC * id;
    for (int k = 0; k < D; ++k) rec[k] += wa * pW[k];
    for (int k = 0; k < D; ++k) rec[D + k] += da * fx[k] + wa * fo[k];
  }
}

// One row node by node: mass, momentum (APIC: m_p C_p (x_i - x_p), its part along the axes other than x once per row),
// force, and for contact the mass gradient and volume.
template <int D, class St, class Scheme, class Fill, class Dist>
[[gnu::always_inline]] inline void scatter_row_nodes(const ScatterCtx<D>& c, const St& st, int r, Index row, const ScatterParticle<D>& p,
                                                     [[maybe_unused]] const Dist& dist) {
  constexpr int RC = kRecord<D>;
  [[maybe_unused]] double crow[D];
  if constexpr (Scheme::affine)
    for (int k = 0; k < D; ++k) {
      crow[k] = 0;
      for (int d = 1; d < D; ++d) crow[k] += p.mC[k][d] * dist.row[d - 1][r];
    }
  for (int a = 0; a < St::K; ++a) {
    const Index id = row + a;
    const double N = st.w[0][a] * st.W[r];
    double dN[D];
    dN[0] = st.dwx[a] * st.W[r];
    for (int d = 1; d < D; ++d) dN[d] = st.w[0][a] * st.dW[d - 1][r];
    double pm[D];
    for (int k = 0; k < D; ++k) pm[k] = N * p.mv[k];
    if constexpr (Scheme::affine)
      for (int k = 0; k < D; ++k) pm[k] += N * (p.mC[k][0] * dist.x[a] + crow[k]);
    if constexpr (Fill::force) {
      c.gm[id] += N * p.mp;
      double* rec = c.pf + RC * id;
      for (int k = 0; k < D; ++k) rec[k] += pm[k];
      for (int k = 0; k < D; ++k) {
        double f = 0;
        for (int j = 0; j < D; ++j) f += p.s[k][j] * dN[j];
        rec[D + k] += f;
      }
    } else {
      for (int k = 0; k < D; ++k) c.gp[D * id + k] += pm[k];
    }
    if constexpr (Fill::contact) {
      for (int k = 0; k < D; ++k) c.gg[D * id + k] += p.mp * dN[k];
      c.gvol[id] += N * p.vip;
    }
  }
}

// P2G (Lin & Yang 2024, eqs. 5-8) of the particles order[q0 .. q1): m_i += N m_p, p_i += N m_p (v_p + C_p (x_i - x_p)),
// f_i += -V_p sigma_p grad N (gravity m_i g is added when the records are unpacked); contact: grad m_i += m_p grad N,
// vol_i += N V_in-plane.
template <int D, class Shape, class Scheme, class Fill, bool SIMD>
inline void scatter_range(const ScatterCtx<D> c, Index q0, Index q1) {
  using St = Stencil<D, Shape>;
  constexpr int R = St::R, RC = kRecord<D>;
  Index rowoff[R];
  c.g.template row_offsets<St>(rowoff);
  for (Index q = q0; q < q1; ++q) {
    const Index i = c.order[q];
    St st;
    st.compute(c.x[i], c.half[i], c.g.origin, c.g.ih);
    ScatterParticle<D> p;
    p.mp = c.mass[i];
    for (int k = 0; k < D; ++k) p.mv[k] = p.mp * c.v[i][k];
    if constexpr (Scheme::affine)
      for (int k = 0; k < D; ++k)
        for (int j = 0; j < D; ++j) p.mC[k][j] = p.mp * c.C[i](k, j);
    if constexpr (Fill::force) {
      const double vol = c.vol[i];
      for (int k = 0; k < D; ++k)
        for (int j = 0; j < D; ++j) p.s[k][j] = -vol * c.stress[i](k, j);
    }
    // In-plane volume for the contact fill test: plane-stress thinning (F_zz) must not switch contact off, since the
    // cell volume it is compared with has the initial thickness.
    if constexpr (Fill::contact) p.vip = c.vol0[i] * c.F[i].determinant();
    const Index node0 = c.bodies[c.body[i]].field * c.g.nn + c.g.base_id(st);
#ifdef DMI_HAVE_AVX2_K3
    if constexpr (SIMD && D == 2 && St::K == 3 && !Scheme::affine && Fill::force) {
      scatter_k3_avx(c.pf, c.gm, node0, c.g.stride[1], st.w[0], st.dw[0], st.w[1], st.dw[1], c.g.ih, p.mp, c.v[i].data(), c.vol[i], c.stress[i].data());
      if constexpr (Fill::contact)
        scatter_grad_k3_avx(c.gg, c.gvol, node0, c.g.stride[1], st.w[0], st.dw[0], st.w[1], st.dw[1], c.g.ih, p.mp, p.vip);
      continue;
    }
#endif
    [[maybe_unused]] const NodeDistances<D, St> dist(st, c.g.h, std::bool_constant<Scheme::affine>{});
    for (int r = 0; r < R; ++r) {
      const Index row = node0 + rowoff[r];
      if constexpr (Fill::force) {
        __builtin_prefetch(c.pf + RC * (row + kNodeAhead), 1);
        __builtin_prefetch(c.gm + row + kNodeAhead, 1);
      } else {
        __builtin_prefetch(c.gp + D * (row + kNodeAhead), 1);
      }
      if constexpr (Fill::contact) {
        __builtin_prefetch(c.gg + D * (row + kNodeAhead), 1);
        __builtin_prefetch(c.gvol + row + kNodeAhead, 1);
      }
      if constexpr (!Scheme::affine && Fill::force && !Fill::contact)
        scatter_row_factored<D, St>(c, st, r, row, p);
      else
        scatter_row_nodes<D, St, Scheme, Fill>(c, st, r, row, p, dist);
    }
  }
}

template <int D, class Shape, class Scheme, class Fill, bool SIMD> void scatter(Scene<D>& s) {
  Grid<D>& g = *s.grid;
  const Particles<D>& P = s.particles;
  const ScatterCtx<D> c{P.x.data(), P.v.data(), P.half_size.data(), P.C.data(), P.F.data(), P.stress.data(), P.mass.data(), P.vol.data(),
                        P.vol0.data(), P.body.data(), s.bodies.data(), g.tile_particles().data(), g.m.data(), g.p.data()->data(), g.pf(),
                        Fill::contact ? g.grad_m.data()->data() : nullptr, Fill::contact ? g.vol.data() : nullptr, GridView<D>(g)};
  const Index* start = g.tile_start().data();
  const bool parallel = static_cast<Index>(P.size()) > kParallelMin;
  for (int col = 0; col < Grid<D>::kColors; ++col) {
    const auto* runs = g.color_runs(col).data();
    const Index nr = static_cast<Index>(g.color_runs(col).size());
    // c is passed by value into each run's scatter: a copy that no store can alias.
    parallel_for_dynamic(nr, parallel, [c, start, runs](Index k) {
      scatter_range<D, Shape, Scheme, Fill, SIMD>(c, start[runs[k].begin], start[runs[k].end]);
    });
  }
  if constexpr (Fill::force) {  // unpack the records into p, f (+ gravity m_i g, eq. 8) and zero them for the next step
    const auto& active = g.active();
    const Index na = static_cast<Index>(active.size()), nn = g.nnodes();
    const Vec<D> grav = s.gravity;
    parallel_for(0, na, [&](Index a) {
      for (int fld = 0; fld < g.nfields(); ++fld) {
        const Index k = fld * nn + active[a];
        double* rec = g.pf() + kRecord<D> * k;
        for (int d = 0; d < D; ++d) g.p[k][d] = rec[d], g.f[k][d] = rec[D + d] + g.m[k] * grav[d];
        std::fill(rec, rec + kRecord<D>, 0.0);
      }
    });
  }
}

template <int D> struct GatherCtx {
  Vec<D>* __restrict x;
  Vec<D>* __restrict v;
  const Vec<D>* __restrict half;
  Mat<D>* __restrict C;
  Mat<D>* __restrict F;
  Mat<D>* __restrict L;
  const int* __restrict body;
  const Body* bodies;
  const double* __restrict gvl;  // v^L, interleaved
  const double* __restrict gv;   // v^k (or the MUSL remap), interleaved
  const double* __restrict gm;   // nodal mass (0 on empty nodes after the grid update)
  const double* __restrict rec;  // 2D: (v^L, v^L - v) per node (Grid::vrec), packed for the AVX2 FLIP gather
  GridView<D> g;
  double blend, dt;
};

// Whether G2P takes the AVX2 gather over the packed node records (Grid::vrec): 2D, 3-node stencils, FLIP, the full
// update. gather() packs the records exactly when gather_range reads them.
template <int D, class Shape, class Scheme, class Mode, bool SIMD>
constexpr bool kVectorGather =
#ifdef DMI_HAVE_AVX2_K3
    SIMD && D == 2 && Shape::K == 3 && !Scheme::affine && Mode::velocity && Mode::kinematics;
#else
    false;
#endif

// One particle's sums over its stencil in G2P: its velocity, the FLIP increment, the velocity gradient, APIC's moments
// B and D, and the empty-node fix's interpolated velocity and slopes: references to the caller's small arrays, which
// the compiler can keep in registers one by one (not one aggregate of them all).
template <int D> struct GatherSums {
  double (&vp)[D], (&dv)[D], (&l)[D][D], (&b)[D][D], (&dd)[D][D], (&ubar)[D], (&gempty)[D];
};

// FLIP without the empty-node fix, row by row: the weights factor as w_x(a) W(r), so each row sums over its K nodes
// with the x weights alone and scales once (a third of the multiplications of the node-by-node loop). gu: the velocity
// the gradient is taken of.
template <int D, class St, class Mode>
[[gnu::always_inline]] inline void gather_rows(const GatherCtx<D>& c, const St& st, Index node0, const Index* rowoff, const double* gu,
                                               const GatherSums<D>& s) {
  constexpr int K = St::K, R = St::R;
  const bool same = gu == c.gvl;  // USL: the gradient is taken of v^L, whose row sums are already there
  for (int r = 0; r < R; ++r) {
    const Index row = node0 + rowoff[r];
    __builtin_prefetch(c.gvl + D * (row + kNodeAhead));
    __builtin_prefetch(c.gv + D * (row + kNodeAhead));
    double sv[D] = {}, sdv[D] = {}, sgx[D] = {}, su[D] = {};
    for (int a = 0; a < K; ++a) {
      const Index id = row + a;
      const double wa = st.w[0][a];
      const double* vl = c.gvl + D * id;
      for (int k = 0; k < D; ++k) sv[k] += wa * vl[k];
      if constexpr (Mode::velocity)
        for (int k = 0; k < D; ++k) sdv[k] += wa * (vl[k] - c.gv[D * id + k]);
      if constexpr (Mode::kinematics) {
        const double* u = gu + D * id;
        for (int k = 0; k < D; ++k) sgx[k] += st.dwx[a] * u[k];
        if (!same)
          for (int k = 0; k < D; ++k) su[k] += wa * u[k];
      }
    }
    const double W = st.W[r];
    for (int k = 0; k < D; ++k) s.vp[k] += W * sv[k];
    if constexpr (Mode::velocity)
      for (int k = 0; k < D; ++k) s.dv[k] += W * sdv[k];
    if constexpr (Mode::kinematics) {
      const double* sw = same ? sv : su;
      for (int k = 0; k < D; ++k) {
        s.l[k][0] += W * sgx[k];
        for (int d = 1; d < D; ++d) s.l[k][d] += st.dW[d - 1][r] * sw[k];
      }
    }
  }
}

// Node by node: APIC's moments, or FLIP's increment; the gradient, and with linear shapes the empty-node fix (see
// gather_range).
template <int D, class St, class Scheme, class Mode, bool EmptyFix, class Dist>
[[gnu::always_inline]] inline void gather_nodes(const GatherCtx<D>& c, const St& st, const Dist& dist, Index node0, const Index* rowoff,
                                                const double* gu, const GatherSums<D>& s) {
  constexpr int K = St::K, R = St::R;
  for (int r = 0; r < R; ++r) {
    const Index row = node0 + rowoff[r];
    __builtin_prefetch(c.gvl + D * (row + kNodeAhead));
    __builtin_prefetch(c.gv + D * (row + kNodeAhead));
    for (int a = 0; a < K; ++a) {
      const Index id = row + a;
      const double N = st.w[0][a] * st.W[r];
      const double* vl = c.gvl + D * id;
      if constexpr (Mode::velocity) {
        if constexpr (Scheme::affine) {
          double dx[D];
          dist.at(r, a, dx);
          for (int k = 0; k < D; ++k) {
            for (int j = 0; j < D; ++j) s.b[k][j] += N * vl[k] * dx[j];
            for (int j = k; j < D; ++j) s.dd[k][j] += N * dx[k] * dx[j];  // symmetric: upper triangle
          }
        } else {
          for (int k = 0; k < D; ++k) s.dv[k] += N * (vl[k] - c.gv[D * id + k]);
        }
      }
      for (int k = 0; k < D; ++k) s.vp[k] += N * vl[k];
      if constexpr (Mode::kinematics) {
        double dN[D];
        dN[0] = st.dwx[a] * st.W[r];
        for (int d = 1; d < D; ++d) dN[d] = st.w[0][a] * st.dW[d - 1][r];
        const double* u = gu + D * id;
        for (int k = 0; k < D; ++k)
          for (int j = 0; j < D; ++j) s.l[k][j] += u[k] * dN[j];
        if constexpr (EmptyFix) {
          for (int k = 0; k < D; ++k) s.ubar[k] += N * u[k];
          if (c.gm[id] == 0)
            for (int j = 0; j < D; ++j) s.gempty[j] += dN[j];
        }
      }
    }
  }
}

// Particle i from its sums: velocity (FLIP blend or APIC's C_p), position, L and F <- (I + dt L) F. Returns 1 if one
// became non-finite or the particle left the grid interior.
template <int D, class Scheme, class Mode>
[[gnu::always_inline]] inline int update_particle(const GatherCtx<D>& c, Index i, const GatherSums<D>& s) {
  int bad = 0;
  if constexpr (Mode::velocity) {
    if constexpr (Scheme::affine) {
      Mat<D> B, Dp;  // C_p = B_p D_p^-1; D_p > 0 for GIMP and B-splines, linear APIC is refused (Solver)
      for (int k = 0; k < D; ++k)
        for (int j = 0; j < D; ++j) B(k, j) = s.b[k][j], Dp(k, j) = j >= k ? s.dd[k][j] : s.dd[j][k];
      for (int k = 0; k < D; ++k) c.v[i][k] = s.vp[k];
      c.C[i] = B * Dp.inverse();
    } else {
      for (int k = 0; k < D; ++k) c.v[i][k] = c.blend * (c.v[i][k] + s.dv[k]) + (1 - c.blend) * s.vp[k];
    }
  }
  if constexpr (Mode::kinematics) {
    double lsum = 0;
    for (int k = 0; k < D; ++k) {
      c.x[i][k] += c.dt * s.vp[k];
      const double xr = (c.x[i][k] - c.g.origin[k]) * c.g.ih;
      if (!(xr >= c.g.lo[k] && xr < c.g.hi[k])) bad = 1;
    }
    // L and F through their column-major storage in scalars: a copy of F as a Mat goes through the stack as small
    // stores read back by one wide load, which cannot be forwarded. F <- (I + dt L) F.
    double* Lp = c.L[i].data();
    double* Fp = c.F[i].data();
    double f[D][D];
    for (int k = 0; k < D; ++k)
      for (int j = 0; j < D; ++j) Lp[j * D + k] = s.l[k][j], lsum += s.l[k][j], f[k][j] = Fp[j * D + k];
    for (int k = 0; k < D; ++k)
      for (int j = 0; j < D; ++j) {
        double lf = 0;
        for (int m = 0; m < D; ++m) lf += s.l[k][m] * f[m][j];
        Fp[j * D + k] = f[k][j] + c.dt * lf;
      }
    if (!std::isfinite(lsum)) bad = 1;
  }
  double vsum = 0;
  for (int k = 0; k < D; ++k) vsum += c.v[i][k];
  if (!std::isfinite(vsum)) bad = 1;
  return bad;
}

// G2P (Lin & Yang 2024, eqs. 13-14; APIC: Jiang et al. 2015) of particles [i0, i1). Returns 1 if one became non-finite or
// left the grid interior.
template <int D, class Shape, class Scheme, class Mode, bool SIMD> inline int gather_range(const GatherCtx<D> c, Index i0, Index i1) {
  using St = Stencil<D, Shape>;
  constexpr int R = St::R;
  Index rowoff[R];
  c.g.template row_offsets<St>(rowoff);
  int bad = 0;
  for (Index i = i0; i < i1; ++i) {
    St st;
    st.compute(c.x[i], c.half[i], c.g.origin, c.g.ih);
    const Index node0 = c.bodies[c.body[i]].field * c.g.nn + c.g.base_id(st);
    const double* gu = Mode::gradient_of_remap ? c.gv : c.gvl;  // the velocity the gradient is taken of
    double vp[D] = {}, dv[D] = {}, l[D][D] = {}, b[D][D] = {}, dd[D][D] = {}, ubar[D] = {}, gempty[D] = {};
    const GatherSums<D> s{vp, dv, l, b, dd, ubar, gempty};
    // Linear shapes: a particle exactly on a grid line has weight 0 but slope 1/h at the node beyond it; at a body's
    // leading face that node is empty (v = 0), which read as a velocity gradient -v/h (stress in a rigid translation,
    // docs/reliability.md). An empty node is given the particle's interpolated velocity instead: with sum grad N = 0,
    // L += u_bar (x) sum over empty nodes of grad N.
    constexpr bool kEmptyFix = std::is_same_v<Shape, LinearShape> && Mode::kinematics;
    constexpr bool kVector = kVectorGather<D, Shape, Scheme, Mode, SIMD>;
#ifdef DMI_HAVE_AVX2_K3
    if constexpr (kVector) {
      const GatherRecK3 gk = gather_rec_k3_avx(c.rec, node0, c.g.stride[1], st.w[0], st.dw[0], st.w[1], st.dw[1], c.g.ih);
      s.vp[0] = gk.vpx, s.vp[1] = gk.vpy, s.dv[0] = gk.dvx, s.dv[1] = gk.dvy;
      s.l[0][0] = gk.l00, s.l[0][1] = gk.l01, s.l[1][0] = gk.l10, s.l[1][1] = gk.l11;
    }
#endif
    constexpr bool kRows = !kVector && !Scheme::affine && !kEmptyFix;
    if constexpr (kRows) {
      gather_rows<D, St, Mode>(c, st, node0, rowoff, gu, s);
    } else if constexpr (!kVector) {
      const NodeDistances<D, St> dist(st, c.g.h, std::bool_constant<Scheme::affine>{});
      gather_nodes<D, St, Scheme, Mode, kEmptyFix>(c, st, dist, node0, rowoff, gu, s);
    }
    if constexpr (kEmptyFix)
      for (int k = 0; k < D; ++k)
        for (int j = 0; j < D; ++j) s.l[k][j] += s.ubar[k] * s.gempty[j];
    bad |= update_particle<D, Scheme, Mode>(c, i, s);
  }
  return bad;
}

template <int D, class Shape, class Scheme, class Mode, bool SIMD>
G2PResult gather(Scene<D>& s, double dt, const typename TransferKernels<D>::ChunkHook* after) {
  Grid<D>& g = *s.grid;
  Particles<D>& P = s.particles;
  [[maybe_unused]] double* rec = nullptr;
  if constexpr (kVectorGather<D, Shape, Scheme, Mode, SIMD>) {
    // The records the vector gather reads, at the active nodes of every field (the particles' stencils lie inside them).
    const auto& active = g.active();
    const Index nn = g.nnodes();
    rec = g.vrec();
    parallel_for(0, static_cast<Index>(active.size()), [&](Index a) {
      for (int fld = 0; fld < g.nfields(); ++fld) {
        const Index k = fld * nn + active[a];
        for (int d = 0; d < D; ++d) rec[2 * D * k + d] = g.vL[k][d], rec[2 * D * k + D + d] = g.vL[k][d] - g.v[k][d];
      }
    });
  }
  const GatherCtx<D> c{P.x.data(), P.v.data(), P.half_size.data(), P.C.data(), P.F.data(), P.L.data(), P.body.data(), s.bodies.data(),
                       g.vL.data()->data(), g.v.data()->data(), g.m.data(), rec, GridView<D>(g), s.options.flip_blend, dt};
  const Index np = static_cast<Index>(P.size());
  constexpr Index kChunk = 1024;
  const Index nchunks = (np + kChunk - 1) / kChunk;
  // A chunk's hook (after: particles kept in front of walls, the stress update) runs right after its gather, on data still in cache.
  const int bad = parallel_or(nchunks, np > kParallelMin, [c, np, after](Index k) {
    const Index i0 = k * kChunk, i1 = std::min(np, (k + 1) * kChunk);
    const int b = gather_range<D, Shape, Scheme, Mode, SIMD>(c, i0, i1);
    if (Mode::kinematics && after) (*after)(i0, i1);
    return b;
  });
  return G2PResult{bad == 0};
}

}  // namespace dmi::detail
