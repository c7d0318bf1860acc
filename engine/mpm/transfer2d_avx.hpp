// AVX2 forms of the 2D FLIP scatter and gather for 3-node stencils (quadratic B-splines, uGIMP): the same equations
// as the generic loops of transfer_kernels.hpp (Lin & Yang 2024, eqs. 5-8 and 13-14) with 4-wide vectors: a node's (px, py, fx, fy)
// record is one aligned vector in the scatter, and (v^L, v^L - v) of a node one aligned record in the gather (the
// scalar loops spill their operands to the stack). Sums are the same terms
// in the same node order; rounding differs from the scalar loops by FMA contraction and by FLIP's increment summed as
// sum N (v^L - v) rather than sum N v^L - sum N v. No access reaches past a row's third node
// (prefetches may: they never fault).
#pragma once
#include "engine/common/types.hpp"

namespace dmi::detail {
// Software prefetch distance of the 2D transfers, in nodes along a stencil row: particles run along a row of tiles in
// x, so the nodes kNodeAhead to the right of the current stencil are the ones the next particles of the row will
// touch. Measured with bench/kernels (1 M particles, quadratic B-splines, 1 thread, 3 rounds): P2G 37 ms without,
// 23.6-26 ms 4 nodes ahead, 20.4-24.3 ms 8 ahead, 20.3-23.4 ms 12 ahead, 20.6-22.6 ms 16 ahead; G2P 27.5-29.1 ms
// without, 23.5-26.0 ms 8 ahead, 25.7-27.4 ms 32 ahead. Hardware prefetch does not cover them: each particle's
// three stencil rows are three separate streams nx nodes apart.
constexpr Index kNodeAhead = 8;
}  // namespace dmi::detail

#if defined(__AVX2__) && defined(__FMA__)
#define DMI_HAVE_AVX2_K3 1
#include <immintrin.h>

namespace dmi::detail {

// Scatter of one particle with weights wx, dwx, wy, dwy (grid units) to the 3 x 3 nodes from node0 (rows nx apart):
// record (px, py, fx, fy) of node (a, b) += Wy_b P_a + dWy_b Q_a, and m += Wy_b wx_a m_p, where
//   P_a = (wx_a m vx, wx_a m vy, dwx_a/h s00, dwx_a/h s10),  Q_a = wx_a (0, 0, s01, s11),  s = -V sigma,
// i.e. N m v and -V sigma grad N with N = wx_a Wy_b, grad N = (dwx_a Wy_b / h, wx_a dWy_b). v: the particle's velocity,
// sigma: its in-plane stress column-major (s00, s10, s01, s11), both read as vectors: (m v, s col 0) and (0, s col 1)
// are one product and one lane move each (built from scalars they were a dozen shuffles).
[[gnu::always_inline]] inline void scatter_k3_avx(double* pf, double* gm, Index node0, Index nx, const double* wx, const double* dwx,
                                                  const double* wy, const double* dwy, double ih, double mp, const double* v, double vol,
                                                  const double* sigma) {
  const __m256d S = _mm256_mul_pd(_mm256_loadu_pd(sigma), _mm256_set1_pd(-vol));
  const __m128d mv = _mm_mul_pd(_mm_set1_pd(mp), _mm_loadu_pd(v));
  const __m256d V1 = _mm256_insertf128_pd(_mm256_castpd128_pd256(mv), _mm256_castpd256_pd128(S), 1);  // (m v, s col 0)
  const __m256d V2 = _mm256_permute2f128_pd(S, S, 0x18);                                              // (0, 0, s col 1)
  __m256d P[3], Q[3];
  for (int a = 0; a < 3; ++a) {
    const __m256d w = _mm256_set1_pd(wx[a]), d = _mm256_set1_pd(dwx[a] * ih);
    P[a] = _mm256_mul_pd(_mm256_blend_pd(w, d, 0b1100), V1);
    Q[a] = _mm256_mul_pd(w, V2);
  }
  for (int b = 0; b < 3; ++b) {
    const Index id = node0 + b * nx;
    double* r = pf + 4 * id;
    __builtin_prefetch(r + 4 * kNodeAhead, 1);
    __builtin_prefetch(gm + id + kNodeAhead, 1);
    const __m256d W = _mm256_set1_pd(wy[b]), dW = _mm256_set1_pd(dwy[b] * ih);
    for (int a = 0; a < 3; ++a)
      _mm256_store_pd(r + 4 * a, _mm256_add_pd(_mm256_load_pd(r + 4 * a), _mm256_fmadd_pd(W, P[a], _mm256_mul_pd(dW, Q[a]))));
    const double wm = wy[b] * mp;
    gm[id] += wx[0] * wm;
    gm[id + 1] += wx[1] * wm;
    gm[id + 2] += wx[2] * wm;
  }
}

// The contact fields of the same particle (multi-field bodies): grad m += m_p grad N (interleaved x, y) and
// vol += N V_in-plane. A stencil row of grad m is 6 adjacent doubles: Wy G1 + dWy G2 with
// G1 = m_p / h (dwx_0, 0, dwx_1, 0, dwx_2, 0) and G2 = m_p (0, wx_0, 0, wx_1, 0, wx_2).
[[gnu::always_inline]] inline void scatter_grad_k3_avx(double* gg, double* gvol, Index node0, Index nx, const double* wx, const double* dwx,
                                                       const double* wy, const double* dwy, double ih, double mp, double vip) {
  const double mh = mp * ih;
  const __m256d G1 = _mm256_set_pd(0.0, mh * dwx[1], 0.0, mh * dwx[0]), G2 = _mm256_set_pd(mp * wx[1], 0.0, mp * wx[0], 0.0);
  const __m128d H1 = _mm_set_pd(0.0, mh * dwx[2]), H2 = _mm_set_pd(mp * wx[2], 0.0);
  for (int b = 0; b < 3; ++b) {
    const Index id = node0 + b * nx;
    double* g = gg + 2 * id;
    __builtin_prefetch(g + 2 * kNodeAhead, 1);
    __builtin_prefetch(gvol + id + kNodeAhead, 1);
    const __m256d W = _mm256_set1_pd(wy[b]), dW = _mm256_set1_pd(dwy[b] * ih);
    _mm256_storeu_pd(g, _mm256_add_pd(_mm256_loadu_pd(g), _mm256_fmadd_pd(W, G1, _mm256_mul_pd(dW, G2))));
    const __m128d W1 = _mm256_castpd256_pd128(W), dW1 = _mm256_castpd256_pd128(dW);
    _mm_storeu_pd(g + 4, _mm_add_pd(_mm_loadu_pd(g + 4), _mm_fmadd_pd(W1, H1, _mm_mul_pd(dW1, H2))));
    const double wv = wy[b] * vip;
    gvol[id] += wx[0] * wv;
    gvol[id + 1] += wx[1] * wv;
    gvol[id + 2] += wx[2] * wv;
  }
}

// Gather of one particle from the packed records of Grid::vrec, (vLx, vLy, dvx, dvy) per node with dv = v^L - v^k (the
// FLIP increment), rows starting at node offset row0, nx apart: a row's three records are three aligned 4-wide loads,
// and sum_a w_a r_a gives (sum N v^L, sum N dv) in one vector (no horizontal sums); the slopes' lanes 0-1 give the
// gradient of v^L. Returns (vpx, vpy, dvx, dvy, l00, l01, l10, l11). Against two interleaved arrays (v^L, v) read
// 6 + 6 doubles a row: docs/performance.md, "The kernel at 20 M updates/s per core".
struct GatherRecK3 {
  double vpx, vpy, dvx, dvy, l00, l01, l10, l11;
};
[[gnu::always_inline]] inline GatherRecK3 gather_rec_k3_avx(const double* rec, Index row0, Index nx, const double* wx, const double* dwx,
                                                          const double* wy, const double* dwy, double ih) {
  const __m256d W0 = _mm256_set1_pd(wx[0]), W1 = _mm256_set1_pd(wx[1]), W2 = _mm256_set1_pd(wx[2]);
  const __m256d D0 = _mm256_set1_pd(dwx[0] * ih), D1 = _mm256_set1_pd(dwx[1] * ih), D2 = _mm256_set1_pd(dwx[2] * ih);
  __m256d aN = _mm256_setzero_pd(), aDx = aN, aDy = aN;
  for (int b = 0; b < 3; ++b) {
    const double* r = rec + 4 * (row0 + b * nx);
    __builtin_prefetch(r + 4 * kNodeAhead);
    const __m256d R0 = _mm256_load_pd(r), R1 = _mm256_load_pd(r + 4), R2 = _mm256_load_pd(r + 8);
    const __m256d s = _mm256_fmadd_pd(W2, R2, _mm256_fmadd_pd(W1, R1, _mm256_mul_pd(W0, R0)));
    const __m256d g = _mm256_fmadd_pd(D2, R2, _mm256_fmadd_pd(D1, R1, _mm256_mul_pd(D0, R0)));
    const __m256d W = _mm256_set1_pd(wy[b]);
    aN = _mm256_fmadd_pd(W, s, aN);
    aDx = _mm256_fmadd_pd(W, g, aDx);
    aDy = _mm256_fmadd_pd(_mm256_set1_pd(dwy[b] * ih), s, aDy);
  }
  alignas(32) double n[4], dx[4], dy[4];
  _mm256_store_pd(n, aN);
  _mm256_store_pd(dx, aDx);
  _mm256_store_pd(dy, aDy);
  return GatherRecK3{n[0], n[1], n[2], n[3], dx[0], dy[0], dx[1], dy[1]};
}

}  // namespace dmi::detail
#endif
