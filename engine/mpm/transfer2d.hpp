// 2D transfer kernels written out in scalars (the same equations as transfer.hpp states): separable weights
// per axis, the stencil walked row by row (x fastest, as the node ids run), node fields through raw pointers.
// Eigen's small products were not inlined in the hot loops (perf: 8 % in one outer product alone). Each node
// still receives its contributions in particle order, so sums do not depend on the thread count.
#pragma once
#include <cmath>

#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"

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
  double* __restrict gf;
  double* __restrict gg;
  double* __restrict gvol;
  double h, ih, ox, oy, gx, gy;
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
    [[maybe_unused]] double c00 = 0, c01 = 0, c10 = 0, c11 = 0, s00 = 0, s01 = 0, s10 = 0, s11 = 0, mgx = 0, mgy = 0, vip = 0;
    if constexpr (APIC) c00 = mp * c.C[i](0, 0), c01 = mp * c.C[i](0, 1), c10 = mp * c.C[i](1, 0), c11 = mp * c.C[i](1, 1);
    if constexpr (!MOMENTUM) {
      const double vol = c.vol[i];
      const Mat<2>& S = c.stress[i];
      s00 = -vol * S(0, 0), s01 = -vol * S(0, 1), s10 = -vol * S(1, 0), s11 = -vol * S(1, 1);
      mgx = mp * c.gx, mgy = mp * c.gy;
    }
    // In-plane volume for the contact fill test (plane-stress thinning must not switch contact off).
    if constexpr (GRAD) vip = c.vol0[i] * c.F[i].determinant();
    const Index off = c.bodies[c.body[i]].field * c.nn;
    for (int b = 0; b < K; ++b) {
      const Index row = off + static_cast<Index>(by + b) * c.nx + bx;
      const double Wy = wy[b], dWy = dwy[b] * c.ih;
      [[maybe_unused]] const double dy = (by + b - yr) * c.h;
      for (int a = 0; a < K; ++a) {
        const Index id = row + a;
        const double N = wx[a] * Wy, dNx = dwx[a] * c.ih * Wy, dNy = wx[a] * dWy;
        if constexpr (APIC) {
          const double dx = (bx + a - xr) * c.h;
          c.gp[2 * id] += N * (mvx + c00 * dx + c01 * dy);
          c.gp[2 * id + 1] += N * (mvy + c10 * dx + c11 * dy);
        } else {
          c.gp[2 * id] += N * mvx;
          c.gp[2 * id + 1] += N * mvy;
        }
        if constexpr (!MOMENTUM) {
          c.gm[id] += N * mp;
          c.gf[2 * id] += s00 * dNx + s01 * dNy + N * mgx;
          c.gf[2 * id + 1] += s10 * dNx + s11 * dNy + N * mgy;
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
               P.vol0.data(), P.body.data(), s.bodies.data(), g.tile_particles().data(), g.m.data(), g.p.data()->data(), g.f.data()->data(),
               GRAD ? g.grad_m.data()->data() : nullptr, GRAD ? g.vol.data() : nullptr, g.h(), g.inv_h(), g.origin()[0], g.origin()[1],
               s.gravity[0], s.gravity[1], g.nodes()[0], g.nnodes()};
  const Index* start = g.tile_start().data();
  const bool parallel = static_cast<Index>(P.size()) > kParallelMin;
  for (int col = 0; col < 4; ++col) {
    const Index* tiles = g.color_tiles(col).data();
    const Index nt = static_cast<Index>(g.color_tiles(col).size());
#pragma omp parallel for schedule(dynamic, 1) firstprivate(c) if (parallel)
    for (Index k = 0; k < nt; ++k) scatter_range<Shape, APIC, GRAD, MOMENTUM>(c, start[tiles[k]], start[tiles[k] + 1]);
  }
}

template <class Shape> G2PResult g2p2d(Scene<2>& s, double dt, G2PMode mode) {
  constexpr int K = Shape::K;
  Grid<2>& g = *s.grid;
  Particles<2>& P = s.particles;
  const bool apic = s.options.transfer == TransferKind::apic;
  const double blend = s.options.flip_blend;
  const double h = g.h(), ih = g.inv_h(), ox = g.origin()[0], oy = g.origin()[1];
  const Index nx = g.nodes()[0], nn = g.nnodes();
  const double* gvl = g.vL.data()->data();
  const double* gv = g.v.data()->data();
  const double* gu = mode == G2PMode::kinematics ? gv : gvl;  // the velocity the gradient is taken of
  const Index np = static_cast<Index>(P.size());
  int bad = 0;
#pragma omp parallel for schedule(static) reduction(| : bad) if (np > kParallelMin)
  for (Index i = 0; i < np; ++i) {
    const double xr = (P.x[i][0] - ox) * ih, yr = (P.x[i][1] - oy) * ih;
    int bx, by;
    double wx[K], dwx[K], wy[K], dwy[K];
    Shape::eval(xr, P.half_size[i][0] * ih, bx, wx, dwx);
    Shape::eval(yr, P.half_size[i][1] * ih, by, wy, dwy);
    const Index off = s.bodies[P.body[i]].field * nn;
    double vpx = 0, vpy = 0, dvx = 0, dvy = 0, l00 = 0, l01 = 0, l10 = 0, l11 = 0;
    double b00 = 0, b01 = 0, b10 = 0, b11 = 0, d00 = 0, d01 = 0, d11 = 0;
    for (int b = 0; b < K; ++b) {
      const Index row = off + static_cast<Index>(by + b) * nx + bx;
      const double Wy = wy[b], dWy = dwy[b] * ih, dy = (by + b - yr) * h;
      for (int a = 0; a < K; ++a) {
        const Index id = row + a;
        const double N = wx[a] * Wy, dNx = dwx[a] * ih * Wy, dNy = wx[a] * dWy;
        const double vlx = gvl[2 * id], vly = gvl[2 * id + 1];
        if (mode != G2PMode::kinematics) {
          if (apic) {
            const double dx = (bx + a - xr) * h;
            b00 += N * vlx * dx, b01 += N * vlx * dy, b10 += N * vly * dx, b11 += N * vly * dy;
            d00 += N * dx * dx, d01 += N * dx * dy, d11 += N * dy * dy;
          } else {
            dvx += N * (vlx - gv[2 * id]), dvy += N * (vly - gv[2 * id + 1]);
          }
        }
        vpx += N * vlx, vpy += N * vly;
        const double ux = gu[2 * id], uy = gu[2 * id + 1];
        l00 += ux * dNx, l01 += ux * dNy, l10 += uy * dNx, l11 += uy * dNy;
      }
    }
    if (mode != G2PMode::kinematics) {
      if (apic) {
        P.v[i] = Vec<2>(vpx, vpy);
        const double det = d00 * d11 - d01 * d01;  // D_p > 0 for GIMP and B-splines; linear APIC is refused (Solver)
        const double i00 = d11 / det, i01 = -d01 / det, i11 = d00 / det;
        P.C[i] << b00 * i00 + b01 * i01, b00 * i01 + b01 * i11, b10 * i00 + b11 * i01, b10 * i01 + b11 * i11;
      } else {
        P.v[i] = Vec<2>(blend * (P.v[i][0] + dvx) + (1 - blend) * vpx, blend * (P.v[i][1] + dvy) + (1 - blend) * vpy);
      }
    }
    if (mode != G2PMode::velocity_only) {
      P.x[i] += dt * Vec<2>(vpx, vpy);
      Mat<2> L;
      L << l00, l01, l10, l11;
      P.L[i] = L;
      P.F[i] = (Mat<2>::Identity() + dt * L) * P.F[i];
      if (!g.interior(P.x[i]) || !std::isfinite(l00 + l01 + l10 + l11)) bad = 1;
    }
    if (!std::isfinite(P.v[i][0] + P.v[i][1])) bad = 1;
  }
  return G2PResult{bad == 0};
}

}  // namespace dmi::detail
