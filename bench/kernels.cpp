// Google Benchmark of the 2D MPM step, phase by phase, on `damimpact bench kernel`'s falling block (quadratic
// B-splines, FLIP, linear elastic), and two floors measured on the same machine:
//   build/bench/kernels [--benchmark_filter=...] [--benchmark_format=json]
//   DMI_KERNEL_PARTICLES=N (default 1,000,000), OMP_NUM_THREADS=1 for one core.
// items_per_second is particles per second through the phase (the whole step for Step). Figures only, nothing is
// asserted; docs/performance.md ("What limits one core") reads them.
//   ScatterFloor: the production scatter (scatter_k3_avx, transfer2d_avx.hpp) over a minimal particle stream (10
//                 doubles each, in tile-row order), with no indirection, no body lookup and no other pass: what
//                 the scatter's nodal read-modify-writes cost alone.
//   GatherFloor:  the production gather (gather_rec_k3_avx) over a minimal particle stream (8 doubles each), with the
//                 FLIP velocity, position and F updates: what G2P's arithmetic and nodal loads cost alone.
//   CopyFloor:    every particle array read once and written once (the bytes of Particles<2>): the memory-traffic
//                 time of one pass over all particle data.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "engine/mpm/shape.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/mpm/transfer2d_avx.hpp"
#include "engine/scenario/config.hpp"
#include "engine/sim/build_scene.hpp"
#include "verify/bench.hpp"

using namespace dmi;

namespace {

long particles() {
  const char* e = std::getenv("DMI_KERNEL_PARTICLES");
  return e ? std::atol(e) : 1000000;
}

// One solver, built on first use and stepped 3 times (binned, sorted once, stresses non-zero).
struct Block {
  std::unique_ptr<Solver<2>> solver;
  std::unique_ptr<TransferKernels<2>> kernels;
  double dt = 0;
  Block() {
    solver = std::make_unique<Solver<2>>(build_scene<2>(block_scenario(particles(), "bspline2", "flip")));
    kernels = make_transfer_kernels<2>(ShapeKind::bspline2);
    dt = solver->stable_time_step(1e-3);
    for (int k = 0; k < 3; ++k) solver->step(dt);
  }
  Scene<2>& scene() { return solver->scene(); }
  long n() { return static_cast<long>(scene().particles.size()); }
};

Block& block() {
  static Block b;
  return b;
}

void Step(benchmark::State& st) {
  Block& b = block();
  const long s0 = b.solver->steps(), r0 = b.solver->rebins();
  for (auto _ : st) b.solver->step(b.dt);
  st.SetItemsProcessed(st.iterations() * b.n());
  const double steps = static_cast<double>(b.solver->steps() - s0);
  st.counters["rebin_share"] = static_cast<double>(b.solver->rebins() - r0) / steps;  // binnings forced by particles moving out
}

// Tiles of every particle, counting sort by tile, scatter runs, active nodes, the previous step's nodes zeroed.
void Bin(benchmark::State& st) {
  Block& b = block();
  for (auto _ : st) b.scene().grid->bin(b.scene().particles.x);
  st.SetItemsProcessed(st.iterations() * b.n());
}

// What a step costs instead while the binning holds: the check that it does, and the fields zeroed.
void KeepBinning(benchmark::State& st) {
  Block& b = block();
  b.scene().grid->bin(b.scene().particles.x);
  for (auto _ : st) {
    benchmark::DoNotOptimize(b.scene().grid->outgrown(b.scene().particles.x));
    b.scene().grid->clear_sums();
  }
  st.SetItemsProcessed(st.iterations() * b.n());
}

// Mass, momentum and force scatter (nodal masses accumulate over the iterations: the same work each time).
void P2G(benchmark::State& st) {
  Block& b = block();
  b.scene().grid->bin(b.scene().particles.x);
  for (auto _ : st) b.kernels->p2g(b.scene(), false);
  st.SetItemsProcessed(st.iterations() * b.n());
}

// Velocity, position (dt = 0: the particles stay put), velocity gradient and F, without the stress update.
void G2P(benchmark::State& st) {
  Block& b = block();
  for (auto _ : st) benchmark::DoNotOptimize(b.kernels->g2p(b.scene(), 0.0, G2PMode::full));
  st.SetItemsProcessed(st.iterations() * b.n());
}

// The linear-elastic stress update of every particle as a pass of its own.
void Stress(benchmark::State& st) {
  Block& b = block();
  Scene<2>& s = b.scene();
  for (auto _ : st) s.materials[0]->update(s.particles, 0, b.n(), b.dt);
  st.SetItemsProcessed(st.iterations() * b.n());
}

// The floors' particles: about particles() of them on a side x side lattice, 2 per cell of a unit grid starting a cell
// in, in the order the solver sorts them: tiles of 4 x 4 cells (8 x 8 particles) along tile rows, row by row inside.
int lattice_side() { return static_cast<int>(std::sqrt(static_cast<double>(particles()))); }
template <class P, class Make> std::vector<P> tile_ordered(int side, Make make) {
  std::vector<P> p;
  p.reserve(static_cast<std::size_t>(side) * side);
  for (int ty = 0; ty < side; ty += 8)
    for (int tx = 0; tx < side; tx += 8)
      for (int j = ty; j < std::min(side, ty + 8); ++j)
        for (int i = tx; i < std::min(side, tx + 8); ++i) p.push_back(make(1.25 + 0.5 * i, 1.25 + 0.5 * j));
  return p;
}

void ScatterFloor(benchmark::State& st) {
  struct P {
    double x, y, vx, vy, m, vol, s[4];  // s: stress column-major
  };
  const int side = lattice_side();
  const Index nx = side / 2 + 4;
  const std::vector<P> p = tile_ordered<P>(side, [](double x, double y) { return P{x, y, 0.1, 0.2, 1.0, 1e-3, {1, 2, 2, 3}}; });
  std::vector<double> storage(4 * static_cast<std::size_t>(nx * nx) + 4), gm(static_cast<std::size_t>(nx * nx));
  double* pf = storage.data() + ((32 - reinterpret_cast<std::uintptr_t>(storage.data()) % 32) % 32) / sizeof(double);
  for (auto _ : st) {
    for (const P& a : p) {
      int bx, by;
      double wx[3], dwx[3], wy[3], dwy[3];
      BSpline2Shape::eval(a.x, 0, bx, wx, dwx);
      BSpline2Shape::eval(a.y, 0, by, wy, dwy);
      detail::scatter_k3_avx(pf, gm.data(), static_cast<Index>(by) * nx + bx, nx, wx, dwx, wy, dwy, 1.0, a.m, &a.vx, a.vol, a.s);
    }
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(p.size()));
}

// The production gather (gather_rec_k3_avx) over a minimal particle stream: weights, the 3 x 3 nodes' records, then
// FLIP velocity, position and F updated in place (dt = 0: the particles stay put).
void GatherFloor(benchmark::State& st) {
  struct P {
    double x, y, vx, vy, F[4];
  };
  const int side = lattice_side();
  const Index nx = side / 2 + 4;
  std::vector<P> p = tile_ordered<P>(side, [](double x, double y) { return P{x, y, 0.1, 0.2, {1, 0, 0, 1}}; });
  std::vector<double> store(4 * static_cast<std::size_t>(nx * nx) + 4, 0.1);  // (v^L, v^L - v) per node, 32-byte aligned
  const double* rec = store.data() + (32 - reinterpret_cast<std::uintptr_t>(store.data()) % 32) % 32 / sizeof(double);
  const double dt = 0;
  for (auto _ : st) {
    for (P& a : p) {
      int bx, by;
      double wx[3], dwx[3], wy[3], dwy[3];
      BSpline2Shape::eval(a.x, 0, bx, wx, dwx);
      BSpline2Shape::eval(a.y, 0, by, wy, dwy);
      const detail::GatherRecK3 g = detail::gather_rec_k3_avx(rec, static_cast<Index>(by) * nx + bx, nx, wx, dwx, wy, dwy, 1.0);
      a.vx += g.dvx, a.vy += g.dvy;
      a.x += dt * g.vpx, a.y += dt * g.vpy;
      const double f0 = a.F[0], f1 = a.F[1], f2 = a.F[2], f3 = a.F[3];
      a.F[0] = f0 + dt * (g.l00 * f0 + g.l01 * f2), a.F[1] = f1 + dt * (g.l00 * f1 + g.l01 * f3);
      a.F[2] = f2 + dt * (g.l10 * f0 + g.l11 * f2), a.F[3] = f3 + dt * (g.l10 * f1 + g.l11 * f3);
    }
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(p.size()));
}

void CopyFloor(benchmark::State& st) {
  const long n = particles();
  const std::size_t bytes = Particles<2>::kBytesPerParticle;
  std::vector<char> a(bytes * static_cast<std::size_t>(n), 1), b(a.size(), 0);
  for (auto _ : st) {
    std::memcpy(b.data(), a.data(), a.size());
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(st.iterations() * n);
  st.counters["bytes_per_particle"] = static_cast<double>(bytes);
}

}  // namespace

BENCHMARK(Bin)->Unit(benchmark::kMillisecond);
BENCHMARK(KeepBinning)->Unit(benchmark::kMillisecond);
BENCHMARK(P2G)->Unit(benchmark::kMillisecond);
BENCHMARK(G2P)->Unit(benchmark::kMillisecond);
BENCHMARK(Stress)->Unit(benchmark::kMillisecond);
BENCHMARK(Step)->Unit(benchmark::kMillisecond);
BENCHMARK(ScatterFloor)->Unit(benchmark::kMillisecond);
BENCHMARK(GatherFloor)->Unit(benchmark::kMillisecond);
BENCHMARK(CopyFloor)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
