// 2D transfer kernels written out in scalars (the same equations as transfer.hpp states): separable weights
// per axis, the stencil walked row by row (x fastest, as the node ids run), node fields through raw pointers.
// Eigen's small products were not inlined in the hot loops (perf: 8 % in one outer product alone). Each node
// still receives its contributions in particle order, so sums do not depend on the thread count.
#pragma once
#include <type_traits>
#include <algorithm>
#include <cmath>

#include "engine/common/parallel.hpp"
#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"
#include "engine/mpm/transfer2d_avx.hpp"

namespace dmi::detail {

// Everything one tile's scatter needs, by value: inside an OpenMP region shared variables are reached through a
// pointer, and every store through the node pointers could alias them, so the compiler reloaded h, the origin,
// the stride... after each store (perf: stack reloads in the hottest lines). A by-value copy cannot alias.
struct ScatterCtx {
  const Vec<2>* __restrict x;
  const Vec<2>* __restrict v;
  const Vec<2>* __restrict half;
  const Mat<2>* __restrict C;
  const Mat<2>* __restrict F;
  const Mat<2>* __restrict stress;
  const double* __restrict mass;
  const double* __restrict vol;
  const double* __restrict vol0;
  const int* __restrict body;
  const Body* bodies;
  const Index* __restrict order;
  double* __restrict gm;
  double* __restrict gp;
  double* __restrict pf;  // interleaved (px, py, fx, fy) records, 32-byte aligned (Grid::pf)
  double* __restrict gg;
  double* __restrict gvol;
  double h, ih, ox, oy;
  Index nx, nn;
};

template <class Shape, bool APIC, bool GRAD, bool MOMENTUM> inline void scatter_range(const ScatterCtx c, Index q0, Index q1) {
  constexpr int K = Shape::K;
  for (Index q = q0; q < q1; ++q) {
    const Index i = c.order[q];
    const double xr = (c.x[i][0] - c.ox) * c.ih, yr = (c.x[i][1] - c.oy) * c.ih;
    int bx, by;
    double wx[K], dwx[K], wy[K], dwy[K];
    Shape::eval(xr, c.half[i][0] * c.ih, bx, wx, dwx);
    Shape::eval(yr, c.half[i][1] * c.ih, by, wy, dwy);
    const double mp = c.mass[i], mvx = mp * c.v[i][0], mvy = mp * c.v[i][1];
    [[maybe_unused]] double c00 = 0, c01 = 0, c10 = 0, c11 = 0, s00 = 0, s01 = 0, s10 = 0, s11 = 0, vip = 0;
    if constexpr (APIC) c00 = mp * c.C[i](0, 0), c01 = mp * c.C[i](0, 1), c10 = mp * c.C[i](1, 0), c11 = mp * c.C[i](1, 1);
    if constexpr (!MOMENTUM) {
      const double vol = c.vol[i];
      const Mat<2>& S = c.stress[i];
      s00 = -vol * S(0, 0), s01 = -vol * S(0, 1), s10 = -vol * S(1, 0), s11 = -vol * S(1, 1);
    }
    // In-plane volume for the contact fill test (plane-stress thinning must not switch contact off).
    if constexpr (GRAD) vip = c.vol0[i] * c.F[i].determinant();
    const Index off = c.bodies[c.body[i]].field * c.nn;
#ifdef DMI_HAVE_AVX2_K3
    if constexpr (K == 3 && !APIC && !MOMENTUM) {
      const Index node0 = off + static_cast<Index>(by) * c.nx + bx;
      scatter_k3_avx(c.pf, c.gm, node0, c.nx, wx, dwx, wy, dwy, c.ih, mp, mvx, mvy, s00, s01, s10, s11);
      if constexpr (GRAD) scatter_grad_k3_avx(c.gg, c.gvol, node0, c.nx, wx, dwx, wy, dwy, c.ih, mp, vip);
      continue;
    }
#endif
    for (int b = 0; b < K; ++b) {
      const Index row = off + static_cast<Index>(by + b) * c.nx + bx;
      if constexpr (MOMENTUM) {
        __builtin_prefetch(c.gp + 2 * (row + kNodeAhead), 1);
      } else {
        __builtin_prefetch(c.pf + 4 * (row + kNodeAhead), 1);
        __builtin_prefetch(c.gm + row + kNodeAhead, 1);
      }
      if constexpr (GRAD) {
        __builtin_prefetch(c.gg + 2 * (row + kNodeAhead), 1);
        __builtin_prefetch(c.gvol + row + kNodeAhead, 1);
      }
      const double Wy = wy[b], dWy = dwy[b] * c.ih;
      [[maybe_unused]] const double dy = (by + b - yr) * c.h;
      for (int a = 0; a < K; ++a) {
        const Index id = row + a;
        const double N = wx[a] * Wy, dNx = dwx[a] * c.ih * Wy, dNy = wx[a] * dWy;
        double px = N * mvx, py = N * mvy;
        if constexpr (APIC) {
          const double dx = (bx + a - xr) * c.h;
          px += N * (c00 * dx + c01 * dy), py += N * (c10 * dx + c11 * dy);
        }
        if constexpr (MOMENTUM) {
          c.gp[2 * id] += px;
          c.gp[2 * id + 1] += py;
        } else {
          c.gm[id] += N * mp;
          double* r = c.pf + 4 * id;
          r[0] += px;
          r[1] += py;
          r[2] += s00 * dNx + s01 * dNy;  // gravity: m_i g when the records are unpacked
          r[3] += s10 * dNx + s11 * dNy;
        }
        if constexpr (GRAD) {
          c.gg[2 * id] += mp * dNx;
          c.gg[2 * id + 1] += mp * dNy;
          c.gvol[id] += N * vip;
        }
      }
    }
  }
}

template <class Shape, bool APIC, bool GRAD, bool MOMENTUM> void scatter2d(Scene<2>& s) {
  Grid<2>& g = *s.grid;
  const Particles<2>& P = s.particles;
  ScatterCtx c{P.x.data(), P.v.data(), P.half_size.data(), P.C.data(), P.F.data(), P.stress.data(), P.mass.data(), P.vol.data(),
               P.vol0.data(), P.body.data(), s.bodies.data(), g.tile_particles().data(), g.m.data(), g.p.data()->data(),
               g.pf(),
               GRAD ? g.grad_m.data()->data() : nullptr, GRAD ? g.vol.data() : nullptr, g.h(), g.inv_h(), g.origin()[0], g.origin()[1],
               g.nodes()[0], g.nnodes()};
  const Index* start = g.tile_start().data();
  const bool parallel = static_cast<Index>(P.size()) > kParallelMin;
  for (int col = 0; col < Grid<2>::kColors; ++col) {
    const auto* runs = g.color_runs(col).data();
    const Index nr = static_cast<Index>(g.color_runs(col).size());
    // c is passed by value into each run's scatter: a copy that no store can alias.
    parallel_for_dynamic(nr, parallel, [c, start, runs](Index k) { scatter_range<Shape, APIC, GRAD, MOMENTUM>(c, start[runs[k].begin], start[runs[k].end]); });
  }
  if constexpr (!MOMENTUM) {  // unpack the records into p, f (+ gravity m_i g, eq. 8) and zero them for the next step
    const auto& active = g.active();
    const Index na = static_cast<Index>(active.size()), nn = g.nnodes();
    const Vec<2> grav = s.gravity;
    parallel_for(0, na, [&](Index a) {
      for (int fld = 0; fld < g.nfields(); ++fld) {
        const Index k = fld * nn + active[a];
        double* r = g.pf() + 4 * k;
        g.p[k] = Vec<2>(r[0], r[1]);
        g.f[k] = Vec<2>(r[2], r[3]) + g.m[k] * grav;
        r[0] = r[1] = r[2] = r[3] = 0.0;
      }
    });
  }
}

// G2P context, by value for the same reason as ScatterCtx.
struct GatherCtx {
  Vec<2>* __restrict x;
  Vec<2>* __restrict v;
  const Vec<2>* __restrict half;
  Mat<2>* __restrict C;
  Mat<2>* __restrict F;
  Mat<2>* __restrict L;
  const int* __restrict body;
  const Body* bodies;
  const double* __restrict gvl;
  const double* __restrict gv;
  const double* __restrict gm;  // nodal mass, field layout (0 on empty nodes after the grid update)
  double h, ih, ox, oy, blend, dt, lo_x, hi_x, lo_y, hi_y;  // lo/hi: the grid interior in grid coordinates
  Index nx, nn;
};

// MODE: 0 full (USL), 1 velocity only (MUSL pass 1), 2 kinematics (MUSL pass 2). Returns 1 for a bad particle.
template <class Shape, bool APIC, int MODE> inline int gather_range(const GatherCtx c, Index i0, Index i1) {
  constexpr int K = Shape::K;
  int bad = 0;
  for (Index i = i0; i < i1; ++i) {
    const double xr = (c.x[i][0] - c.ox) * c.ih, yr = (c.x[i][1] - c.oy) * c.ih;
    int bx, by;
    double wx[K], dwx[K], wy[K], dwy[K];
    Shape::eval(xr, c.half[i][0] * c.ih, bx, wx, dwx);
    Shape::eval(yr, c.half[i][1] * c.ih, by, wy, dwy);
    const Index off = c.bodies[c.body[i]].field * c.nn;
    const double* gu = MODE == 2 ? c.gv : c.gvl;  // the velocity the gradient is taken of
    double vpx = 0, vpy = 0, dvx = 0, dvy = 0, l00 = 0, l01 = 0, l10 = 0, l11 = 0;
    double b00 = 0, b01 = 0, b10 = 0, b11 = 0, d00 = 0, d01 = 0, d11 = 0;
#ifdef DMI_HAVE_AVX2_K3
    constexpr bool kVector = K == 3 && !APIC && MODE == 0;
    if constexpr (kVector) {
      const GatherK3 gk = gather_k3_avx(c.gvl, c.gv, off + static_cast<Index>(by) * c.nx + bx, c.nx, wx, dwx, wy, dwy, c.ih);
      vpx = gk.vpx, vpy = gk.vpy, dvx = gk.vpx - gk.nvx, dvy = gk.vpy - gk.nvy;
      l00 = gk.l00, l01 = gk.l01, l10 = gk.l10, l11 = gk.l11;
    }
#else
    constexpr bool kVector = false;
#endif
    // Linear shapes: a particle exactly on a grid line has weight 0 but slope 1/h at the node beyond it; at a body's
    // leading face that node is empty (v = 0), which read as a velocity gradient -v/h (stress in a rigid translation,
    // docs/reliability.md). An empty node is given the particle's interpolated velocity instead: with sum grad N = 0,
    // L += u_bar (x) sum over empty nodes of grad N.
    constexpr bool kEmptyFix = std::is_same_v<Shape, LinearShape> && MODE != 1;
    double ubx = 0, uby = 0, gex = 0, gey = 0;
    for (int b = 0; b < (kVector ? 0 : K); ++b) {
      const Index row = off + static_cast<Index>(by + b) * c.nx + bx;
      __builtin_prefetch(c.gvl + 2 * (row + kNodeAhead));
      __builtin_prefetch(c.gv + 2 * (row + kNodeAhead));
      const double Wy = wy[b], dWy = dwy[b] * c.ih, dy = (by + b - yr) * c.h;
      for (int a = 0; a < K; ++a) {
        const Index id = row + a;
        const double N = wx[a] * Wy, dNx = dwx[a] * c.ih * Wy, dNy = wx[a] * dWy;
        const double vlx = c.gvl[2 * id], vly = c.gvl[2 * id + 1];
        if constexpr (MODE != 2) {
          if constexpr (APIC) {
            const double dx = (bx + a - xr) * c.h;
            b00 += N * vlx * dx, b01 += N * vlx * dy, b10 += N * vly * dx, b11 += N * vly * dy;
            d00 += N * dx * dx, d01 += N * dx * dy, d11 += N * dy * dy;
          } else {
            dvx += N * (vlx - c.gv[2 * id]), dvy += N * (vly - c.gv[2 * id + 1]);
          }
        }
        vpx += N * vlx, vpy += N * vly;
        if constexpr (MODE != 1) {
          const double ux = gu[2 * id], uy = gu[2 * id + 1];
          l00 += ux * dNx, l01 += ux * dNy, l10 += uy * dNx, l11 += uy * dNy;
          if constexpr (kEmptyFix) {
            ubx += N * ux, uby += N * uy;
            if (c.gm[id] == 0) gex += dNx, gey += dNy;
          }
        }
      }
    }
    if constexpr (kEmptyFix) l00 += ubx * gex, l01 += ubx * gey, l10 += uby * gex, l11 += uby * gey;
    if constexpr (MODE != 2) {
      if constexpr (APIC) {
        c.v[i] = Vec<2>(vpx, vpy);
        const double det = d00 * d11 - d01 * d01;  // D_p > 0 for GIMP and B-splines; linear APIC is refused (Solver)
        const double i00 = d11 / det, i01 = -d01 / det, i11 = d00 / det;
        c.C[i] << b00 * i00 + b01 * i01, b00 * i01 + b01 * i11, b10 * i00 + b11 * i01, b10 * i01 + b11 * i11;
      } else {
        c.v[i] = Vec<2>(c.blend * (c.v[i][0] + dvx) + (1 - c.blend) * vpx, c.blend * (c.v[i][1] + dvy) + (1 - c.blend) * vpy);
      }
    }
    if constexpr (MODE != 1) {
      const double x = c.x[i][0] + c.dt * vpx, y = c.x[i][1] + c.dt * vpy;
      c.x[i] = Vec<2>(x, y);
      // L and F through their column-major storage in scalars: a copy of F as a Mat<2> went through the stack as two
      // 16-byte stores read back by one 32-byte load, which cannot be forwarded (perf: 22 % of G2P's samples on the
      // next instruction). Gone from the profile now; the step's time did not change measurably (the wait overlapped).
      double* l = c.L[i].data();
      l[0] = l00, l[1] = l10, l[2] = l01, l[3] = l11;
      double* f = c.F[i].data();
      const double f00 = f[0], f10 = f[1], f01 = f[2], f11 = f[3];
      f[0] = f00 + c.dt * (l00 * f00 + l01 * f10), f[2] = f01 + c.dt * (l00 * f01 + l01 * f11);
      f[1] = f10 + c.dt * (l10 * f00 + l11 * f10), f[3] = f11 + c.dt * (l10 * f01 + l11 * f11);
      const double gxr = (x - c.ox) * c.ih, gyr = (y - c.oy) * c.ih;  // Grid::interior
      if (!(gxr >= c.lo_x && gxr < c.hi_x && gyr >= c.lo_y && gyr < c.hi_y) || !std::isfinite(l00 + l01 + l10 + l11)) bad = 1;
    }
    if (!std::isfinite(c.v[i][0] + c.v[i][1])) bad = 1;
  }
  return bad;
}

template <class Shape, bool APIC, int MODE> G2PResult gather2d(Scene<2>& s, double dt, const TransferKernels<2>::ChunkHook* after) {
  Grid<2>& g = *s.grid;
  Particles<2>& P = s.particles;
  const GatherCtx c{P.x.data(), P.v.data(), P.half_size.data(), P.C.data(), P.F.data(), P.L.data(), P.body.data(), s.bodies.data(),
                    g.vL.data()->data(), g.v.data()->data(), g.m.data(), g.h(), g.inv_h(), g.origin()[0], g.origin()[1], s.options.flip_blend, dt,
                    0.5, g.cells()[0] - 0.5, 0.5, g.cells()[1] - 0.5, g.nodes()[0], g.nnodes()};
  const Index np = static_cast<Index>(P.size());
  constexpr Index kChunk = 1024;
  const Index nchunks = (np + kChunk - 1) / kChunk;
  // A chunk's stress update (after) runs right after its gather, on data still in cache.
  const int bad = parallel_or(nchunks, np > kParallelMin, [c, np, after](Index k) {
    const Index i0 = k * kChunk, i1 = std::min(np, (k + 1) * kChunk);
    const int b = gather_range<Shape, APIC, MODE>(c, i0, i1);
    if (MODE != 1 && after) (*after)(i0, i1);
    return b;
  });
  return G2PResult{bad == 0};
}

template <class Shape> G2PResult g2p2d(Scene<2>& s, double dt, G2PMode mode, const TransferKernels<2>::ChunkHook* a) {
  const bool apic = s.options.transfer == TransferKind::apic;
  const int m = mode == G2PMode::full ? 0 : mode == G2PMode::velocity_only ? 1 : 2;
  if (apic) return m == 0 ? gather2d<Shape, true, 0>(s, dt, a) : m == 1 ? gather2d<Shape, true, 1>(s, dt, a) : gather2d<Shape, true, 2>(s, dt, a);
  return m == 0 ? gather2d<Shape, false, 0>(s, dt, a) : m == 1 ? gather2d<Shape, false, 1>(s, dt, a) : gather2d<Shape, false, 2>(s, dt, a);
}

}  // namespace dmi::detail
