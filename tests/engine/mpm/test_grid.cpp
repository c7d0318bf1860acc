// Grid binning invariants (engine/mpm/grid.cpp): the active-node list and the particle order by tile, which the
// kernels and their determinism rely on. The fast paths (ordered active list without a sort, counting sort split
// over threads) are compared with the plain definitions.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "engine/mpm/grid.hpp"

namespace dmi {
namespace {

// Clusters of particles, some on the grid's edges and some tiles apart, on a 61 x 37-cell grid (tiles of 4 cells
// do not divide it).
std::vector<Vec<2>> scattered_particles() {
  std::mt19937 rng(7);
  std::vector<Vec<2>> x;
  const Vec<2> centres[] = {{0.3, 0.3}, {6.0, 3.6}, {2.2, 1.0}, {5.9, 0.2}, {0.2, 3.5}, {4.0, 2.0}};
  std::uniform_real_distribution<double> u(-0.45, 0.45);
  for (const Vec<2>& c : centres)
    for (int k = 0; k < 3000; ++k) {
      Vec<2> p = c + Vec<2>(u(rng), u(rng));
      p = p.cwiseMax(Vec<2>(0.05, 0.05)).cwiseMin(Vec<2>(6.05, 3.65));
      x.push_back(p);
    }
  return x;
}

// Plain definition: every node a particle of an occupied tile can touch, sorted and unique.
std::vector<Index> reachable_nodes(const Grid<2>& g) {
  std::vector<Index> ids;
  for (Index t : g.occupied()) {
    IVec<2> lo, hi;
    g.tile_nodes(t, lo, hi);
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) ids.push_back(g.node_id(IVec<2>(i, j)));
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

TEST(Grid, ActiveNodesAreTheReachableOnesInAscendingOrder) {
  Grid<2> g(Vec<2>(0, 0), IVec<2>(61, 37), 0.1, 1);
  const std::vector<Vec<2>> x = scattered_particles();
  g.bin(x);
  EXPECT_EQ(g.active(), reachable_nodes(g));
  // Again after the particles moved (the previous active set is cleared, not merged).
  std::vector<Vec<2>> y = x;
  for (auto& p : y) p = (p + Vec<2>(1.3, -0.7)).cwiseMax(Vec<2>(0.05, 0.05)).cwiseMin(Vec<2>(6.05, 3.65));
  g.bin(y);
  EXPECT_EQ(g.active(), reachable_nodes(g));
}

TEST(Grid, ParticleOrderByTileIsStableAndThreadIndependent) {
  const std::vector<Vec<2>> x = scattered_particles();
  std::vector<std::vector<Index>> orders;
  const int threads = omp_get_max_threads();
  for (int nt : {1, 2, 3}) {
    omp_set_num_threads(nt);
    Grid<2> g(Vec<2>(0, 0), IVec<2>(61, 37), 0.1, 1);
    g.bin(x);
    orders.push_back(g.tile_particles());
    // Stable counting sort: by tile (in the order of occupied()), then by particle index.
    const auto& start = g.tile_start();
    for (std::size_t k = 0; k + 1 < start.size(); ++k)
      for (Index q = start[k]; q < start[k + 1]; ++q) {
        const Vec<2> p = x[g.tile_particles()[q]];
        const Index t = static_cast<Index>(std::min(36, int(p[1] / 0.1)) / Grid<2>::T) * g.tiles()[0] +
                        std::min(60, int(p[0] / 0.1)) / Grid<2>::T;
        ASSERT_EQ(t, g.occupied()[k]);
        if (q > start[k]) ASSERT_LT(g.tile_particles()[q - 1], g.tile_particles()[q]);
      }
  }
  omp_set_num_threads(threads);
  EXPECT_EQ(orders[0], orders[1]);
  EXPECT_EQ(orders[0], orders[2]);
}

// The scatter's work items: every occupied tile in exactly one run, runs of consecutive occupied tiles, and no node
// reached by two runs of one colour (the lock-free scatter's condition, with each tile's reach widened by the margin
// its particles may move before a rebinning). Many particles on few tile rows fall back to single tiles in 3^D
// colours; otherwise runs are whole tile rows in 3^(D-1) colours.
void check_runs(const Grid<2>& g, bool expect_rows) {
  std::vector<int> seen(g.occupied().size(), 0);
  bool rows = true;
  for (int c = 0; c < Grid<2>::kColors; ++c) {
    std::vector<int> reach(static_cast<std::size_t>(g.nnodes()), 0);
    for (const auto& r : g.color_runs(c)) {
      ASSERT_LT(r.begin, r.end);
      const Index row = g.occupied()[r.begin] / g.tiles()[0];
      for (Index k = r.begin; k < r.end; ++k) {
        ++seen[k];
        ASSERT_EQ(g.occupied()[k] / g.tiles()[0], row);  // one tile row
        IVec<2> lo, hi;
        g.tile_nodes(g.occupied()[k], lo, hi);
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int i = lo[0]; i <= hi[0]; ++i) {
            int& n = reach[g.node_id(IVec<2>(i, j))];
            ASSERT_TRUE(n == 0 || n == 1 + (&r - g.color_runs(c).data())) << "node reached by two runs of colour " << c;
            n = 1 + static_cast<int>(&r - g.color_runs(c).data());
          }
      }
      rows = rows && (r.end == static_cast<Index>(g.occupied().size()) || g.occupied()[r.end] / g.tiles()[0] != row);
    }
  }
  for (int n : seen) ASSERT_EQ(n, 1);
  EXPECT_EQ(rows, expect_rows);
  if (expect_rows)
    for (int c = 3; c < Grid<2>::kColors; ++c) EXPECT_TRUE(g.color_runs(c).empty());
}

TEST(Grid, ScatterRunsCoverTheTilesAndSameColourRunsDoNotShareNodes) {
  // 18,000 particles on 10 tile rows (< kMinRows): single tiles.
  Grid<2> g(Vec<2>(0, 0), IVec<2>(61, 37), 0.1, 1);
  g.bin(scattered_particles());
  check_runs(g, false);
  // The same particles on a grid of 0.05 m cells span 19 tile rows: whole rows.
  Grid<2> fine(Vec<2>(0, 0), IVec<2>(122, 74), 0.05, 1);
  fine.bin(scattered_particles());
  check_runs(fine, true);
  // Few particles (a serial scatter): rows, whatever their number.
  std::vector<Vec<2>> few = scattered_particles();
  few.resize(2000);
  Grid<2> small(Vec<2>(0, 0), IVec<2>(61, 37), 0.1, 1);
  small.bin(few);
  check_runs(small, true);
}

// The binning is kept between steps while every particle stays within kMargin cells of its tile: a move of less than
// a cell keeps it, a move of two cells (some particle then sits two cells beyond its tile) does not, and neither does
// a change in the number of particles.
TEST(Grid, BinningHoldsWhileParticlesStayWithinTheMargin) {
  ASSERT_EQ(Grid<2>::kMargin, 1);
  Grid<2> g(Vec<2>(0, 0), IVec<2>(122, 74), 0.05, 1);
  const std::vector<Vec<2>> x = scattered_particles();
  g.bin(x);
  EXPECT_FALSE(g.outgrown(x));
  for (const Vec<2>& d : {Vec<2>(0.99 * 0.05, 0), Vec<2>(0, -0.99 * 0.05), Vec<2>(0.7 * 0.05, 0.7 * 0.05)}) {
    std::vector<Vec<2>> y = x;
    for (auto& p : y) p += d;
    EXPECT_FALSE(g.outgrown(y)) << d.transpose();
  }
  for (const Vec<2>& d : {Vec<2>(2.0 * 0.05, 0), Vec<2>(0, -2.0 * 0.05)}) {
    std::vector<Vec<2>> y = x;
    for (auto& p : y) p += d;
    EXPECT_TRUE(g.outgrown(y)) << d.transpose();
  }
  std::vector<Vec<2>> one = x;
  one[123] += Vec<2>(0, 9 * 0.05);  // a single particle far out
  EXPECT_TRUE(g.outgrown(one));
  std::vector<Vec<2>> more = x;
  more.push_back(x[0]);
  EXPECT_TRUE(g.outgrown(more));
}

// While the binning holds, every node of a moved particle's stencil (the widest: nodes floor(xr) - 1 .. floor(xr) + 2
// along each axis) is active, and the particle's tile is among those Grid::tiles_reaching gives for each of those
// nodes (member contact gathers the mass-weighted positions there from those tiles' particles). Every particle moves
// by up to a cell in each direction, so many sit a cell outside their tile.
TEST(Grid, StencilsOfMovedParticlesStayInsideTheBinning) {
  const double h = 0.05;
  Grid<2> g(Vec<2>(0, 0), IVec<2>(122, 74), h, 1);
  const std::vector<Vec<2>> x = scattered_particles();
  g.bin(x);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.999 * h, 0.999 * h);
  std::vector<Vec<2>> y = x;
  for (auto& p : y) p += Vec<2>(u(rng), u(rng));
  ASSERT_FALSE(g.outgrown(y));
  const auto& active = g.active();
  long outside = 0;
  for (std::size_t k = 0; k < g.occupied().size(); ++k) {
    const IVec<2> tile = g.tile_coord(g.occupied()[k]);
    for (Index q = g.tile_start()[k]; q < g.tile_start()[k + 1]; ++q) {
      const Vec<2> xr = y[g.tile_particles()[q]] / h;
      const IVec<2> c(static_cast<int>(std::floor(xr[0])), static_cast<int>(std::floor(xr[1])));
      outside += c[0] < tile[0] * Grid<2>::T || c[0] >= (tile[0] + 1) * Grid<2>::T || c[1] < tile[1] * Grid<2>::T ||
                 c[1] >= (tile[1] + 1) * Grid<2>::T;
      for (int j = std::max(0, c[1] - 1); j <= std::min(74, c[1] + 2); ++j)
        for (int i = std::max(0, c[0] - 1); i <= std::min(122, c[0] + 2); ++i) {
          ASSERT_TRUE(std::binary_search(active.begin(), active.end(), g.node_id(IVec<2>(i, j)))) << "node " << i << ", " << j;
          IVec<2> lo, hi;
          g.tiles_reaching(IVec<2>(i, j), lo, hi);
          ASSERT_TRUE(tile[0] >= lo[0] && tile[0] <= hi[0] && tile[1] >= lo[1] && tile[1] <= hi[1]) << "node " << i << ", " << j;
        }
    }
  }
  EXPECT_GT(outside, 1000);  // the margin was used
  // The inverse relation is exact: node n lies in tile_nodes(t) exactly when t lies in tiles_reaching(n).
  for (Index t = 0; t < g.ntiles(); ++t) {
    IVec<2> nlo, nhi;
    g.tile_nodes(t, nlo, nhi);
    const IVec<2> tc = g.tile_coord(t);
    for (int j = 0; j < 75; ++j)
      for (int i = 0; i < 123; ++i) {
        IVec<2> lo, hi;
        g.tiles_reaching(IVec<2>(i, j), lo, hi);
        const bool in_nodes = i >= nlo[0] && i <= nhi[0] && j >= nlo[1] && j <= nhi[1];
        const bool in_tiles = tc[0] >= lo[0] && tc[0] <= hi[0] && tc[1] >= lo[1] && tc[1] <= hi[1];
        ASSERT_EQ(in_nodes, in_tiles) << "tile " << t << ", node " << i << ", " << j;
      }
  }
}

// A checkpoint keeps each particle's tile; the binning rebuilt from them is the one the run had (order, runs, nodes).
TEST(Grid, BinningRestoredFromTheParticlesTilesIsTheSame) {
  const std::vector<Vec<2>> x = scattered_particles();
  Grid<2> g(Vec<2>(0, 0), IVec<2>(122, 74), 0.05, 1), r(Vec<2>(0, 0), IVec<2>(122, 74), 0.05, 1);
  g.bin(x);
  std::vector<Vec<2>> y = x;
  for (auto& p : y) p += Vec<2>(0.03, -0.02);  // moved since the binning: the restored one must not re-bin them
  ASSERT_FALSE(g.outgrown(y));
  r.restore_binning(g.particle_tiles());
  EXPECT_EQ(r.tile_particles(), g.tile_particles());
  EXPECT_EQ(r.tile_start(), g.tile_start());
  EXPECT_EQ(r.occupied(), g.occupied());
  EXPECT_EQ(r.active(), g.active());
  for (int c = 0; c < Grid<2>::kColors; ++c) {
    ASSERT_EQ(r.color_runs(c).size(), g.color_runs(c).size());
    for (std::size_t k = 0; k < g.color_runs(c).size(); ++k)
      EXPECT_TRUE(r.color_runs(c)[k].begin == g.color_runs(c)[k].begin && r.color_runs(c)[k].end == g.color_runs(c)[k].end);
  }
  EXPECT_FALSE(r.outgrown(y));
}

}  // namespace
}  // namespace dmi
