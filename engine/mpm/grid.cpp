#include "engine/common/parallel.hpp"
#include "engine/mpm/grid.hpp"

#include <cstdint>
#include <omp.h>

#include <algorithm>
#include <cmath>

namespace dmi {

namespace {
// n zeroed doubles in storage, returned from the first 32-byte boundary (the 4-wide AVX2 records' aligned loads).
double* aligned32(std::vector<double>& storage, std::size_t n) {
  storage.assign(n + 4, 0.0);  // + slack to reach the boundary
  const auto addr = reinterpret_cast<std::uintptr_t>(storage.data());
  return storage.data() + ((32 - addr % 32) % 32) / sizeof(double);
}
}  // namespace

template <int D>
Grid<D>::Grid(const Vec<D>& origin, const IVec<D>& cells, double h, int nfields)
    : origin_(origin), cells_(cells), h_(h), inv_h_(1.0 / h), nfields_(nfields) {
  nnodes_ = 1;
  ntiles_ = 1;
  for (int d = 0; d < D; ++d) {
    nodes_[d] = cells[d] + 1;
    tiles_[d] = (cells[d] + T - 1) / T;
    nnodes_ *= nodes_[d];
    ntiles_ *= tiles_[d];
  }
  const auto n = static_cast<std::size_t>(nnodes_ * nfields);
  m.assign(n, 0.0);
  p.assign(n, Vec<D>::Zero());
  f.assign(n, Vec<D>::Zero());
  v.assign(n, Vec<D>::Zero());
  vL.assign(n, Vec<D>::Zero());
  if (nfields > 1) {
    grad_m.assign(n, Vec<D>::Zero());
    vol.assign(n, 0.0);
  }
  pf_ = aligned32(pf_storage_, 2 * D * n);
  tile_count_.assign(static_cast<std::size_t>(ntiles_), 0);
}

template <int D> double* Grid<D>::vrec() {
  if (!vrec_) vrec_ = aligned32(vrec_storage_, 2 * D * static_cast<std::size_t>(nnodes_ * nfields_));
  return vrec_;
}

template <int D> void Grid<D>::zero_node(Index id) {
  for (int fld = 0; fld < nfields_; ++fld) {
    const Index k = fld * nnodes_ + id;
    m[k] = 0;
    p[k].setZero();
    f[k].setZero();
    v[k].setZero();
    vL[k].setZero();
    if (nfields_ > 1) {
      grad_m[k].setZero();
      vol[k] = 0;
    }
  }
}

// Cost O(particles + occupied tiles), never O(box): tiles are counted in a persistent array that
// is reset only where it was touched.
template <int D> void Grid<D>::bin(const std::vector<Vec<D>>& x) {
  clear();  // the nodes of the previous binning, so every node outside the new active set is zero
  tile_of_.resize(x.size());
  home_.resize(x.size());
  count_sort_tiles(&x);
  build_runs_and_nodes(static_cast<Index>(x.size()));
}

template <int D> void Grid<D>::clear() {
  const Index na = static_cast<Index>(active_.size());
  parallel_for(0, na, [&](Index a) { zero_node(active_[a]); });
}

// Only what P2G accumulates: p and f are written whole by its unpacking, v and v^L by the grid update, at every active
// node (zeroing all nine fields cost 2/3 of a binning, 1 M particles).
template <int D> void Grid<D>::clear_sums() {
  const Index na = static_cast<Index>(active_.size());
  parallel_for(0, na, [&](Index a) {
    for (int fld = 0; fld < nfields_; ++fld) {
      const Index k = fld * nnodes_ + active_[a];
      m[k] = 0;
      if (nfields_ > 1) grad_m[k].setZero(), vol[k] = 0;
    }
  });
}

template <int D> bool Grid<D>::outgrown(const std::vector<Vec<D>>& x) const {
  if (x.size() != home_.size()) return true;
  const Index np = static_cast<Index>(x.size());
  constexpr Index kChunk = 4096;
  return parallel_or((np + kChunk - 1) / kChunk, np > kParallelMin, [&](Index k) {
    // In grid coordinates, particle i is held while T home - kMargin <= xr < T home + T + kMargin along each axis (the
    // cell test on floor(xr), without the floor: branch-free, vectorisable; NaN counts as out).
    bool out = false;
    for (Index i = k * kChunk; i < std::min(np, (k + 1) * kChunk); ++i)
      for (int d = 0; d < D; ++d) {
        const double xr = (x[i][d] - origin_[d]) * inv_h_, lo = home_[i][d] * T - kMargin;
        out |= !(xr >= lo && xr < lo + (T + 2 * kMargin));
      }
    return static_cast<int>(out);
  }) != 0;
}

template <int D> void Grid<D>::restore_binning(std::vector<Index> tiles) {
  clear();
  tile_of_ = std::move(tiles);
  home_.resize(tile_of_.size());
  for (std::size_t i = 0; i < tile_of_.size(); ++i) home_[i] = tile_coord(tile_of_[i]);
  count_sort_tiles(nullptr);
  build_runs_and_nodes(static_cast<Index>(tile_of_.size()));
}

template <int D> void Grid<D>::build_runs_and_nodes(Index np) {
  color_runs_build(np);
  active_.clear();
  if constexpr (D == 2) {  // the active nodes in ascending order without a sort
    active_nodes_2d();
    return;
  }
  if (flag_.size() != static_cast<std::size_t>(nnodes_)) flag_.assign(static_cast<std::size_t>(nnodes_), 0);
  for (Index t : occupied_) {
    IVec<D> lo, hi;
    tile_nodes(t, lo, hi);
    any_node_in_box<D>(lo, hi, [&](const IVec<D>& ijk) {
      const Index id = node_id(ijk);
      if (!flag_[id]) {
        flag_[id] = 1;
        active_.push_back(id);
      }
      return false;
    });
  }
  // Ascending node ids: grid loops then stream memory row by row (in tile order a 10x wider grid cost 1.9x per step).
  std::sort(active_.begin(), active_.end());
  for (Index id : active_) flag_[id] = 0;
}

// Row runs: a maximal run of occupied tiles with equal (ty[, tz]) (occupied_ ascends in tile id = x fastest), coloured
// by ty (and tz) modulo 3; rows three apart are 3 T cells apart. Measured against single tiles in 2^D colours
// (1 M particles, quadratic B-splines, docs/performance.md): a colour's tiles were every other tile of every other
// row, so each pass read the particle arrays in 1/4 slices, and the scatter took 1.7x as long out of cache.
template <int D> void Grid<D>::color_runs_build(Index np) {
  rows_.clear();  // maximal runs of occupied tiles in one tile row
  for (Index k = 0; k < static_cast<Index>(occupied_.size()); ++k) {
    if (rows_.empty() || occupied_[k] / tiles_[0] != occupied_[rows_.back().begin] / tiles_[0]) rows_.push_back(TileRun{k, k});
    rows_.back().end = k + 1;
  }
  for (auto& c : color_runs_) c.clear();
  const bool by_rows = np <= kParallelMin || static_cast<Index>(rows_.size()) >= kMinRows;
  for (const TileRun& r : rows_)
    for (Index k = r.begin; k < r.end; k = by_rows ? r.end : k + 1) {
      const IVec<D> ti = tile_coord(occupied_[k]);
      int color = 0;
      for (int d = D - 1; d >= (by_rows ? 1 : 0); --d) color = 3 * color + ti[d] % 3;
      color_runs_[color].push_back(by_rows ? r : TileRun{k, k + 1});
    }
}

template <int D> Index Grid<D>::tile_of(const Vec<D>& x, IVec<D>& cell) const {
  const Vec<D> xr = grid_coord(x);
  Index t = 0;
  for (int d = D - 1; d >= 0; --d) {
    cell[d] = std::clamp(static_cast<int>(std::floor(xr[d])), 0, cells_[d] - 1);
    t = t * tiles_[d] + cell[d] / T;
  }
  return t;
}

// Stable counting sort of the particles by tile (tile_particles_, tile_start_, occupied_ ascending). Large sets are
// split into one contiguous chunk per thread: each counts its chunk into its own array, the chunks' offsets within a
// tile follow in chunk order, and each fills its own chunk, so the order is exactly the serial one (particles by
// tile, then by index). Serially these two passes over the particles limited two threads (docs/performance.md). The
// counting pass also finds each particle's tile (a pass of its own before: 4.3 of 11.6 ms binning 1 M particles).
template <int D> void Grid<D>::count_sort_tiles(const std::vector<Vec<D>>* x) {
  const Index np = static_cast<Index>(tile_of_.size());
  tile_particles_.resize(tile_of_.size());
  occupied_.clear();
  const int nt = np > kParallelMin ? std::max(1, omp_get_max_threads()) : 1;
  if (static_cast<int>(chunk_count_.size()) < nt) chunk_count_.resize(static_cast<std::size_t>(nt));
  chunk_occupied_.resize(static_cast<std::size_t>(nt));
  auto chunk = [np, nt](int c) { return np * c / nt; };
  auto counts = [&](int c) -> std::vector<Index>& { return c == 0 ? tile_count_ : chunk_count_[c]; };
  auto count = [&](int c) {
    std::vector<Index>& cnt = counts(c);
    if (cnt.size() != static_cast<std::size_t>(ntiles_)) cnt.assign(static_cast<std::size_t>(ntiles_), 0);
    std::vector<Index>& occ = chunk_occupied_[c];
    occ.clear();
    for (Index i = chunk(c); i < chunk(c + 1); ++i) {  // the tile of each particle, counted as it is found
      Index t = tile_of_[i];
      if (x) {
        IVec<D> cell;
        t = tile_of_[i] = tile_of((*x)[i], cell);
        for (int d = 0; d < D; ++d) home_[i][d] = cell[d] / T;
      }
      if (cnt[t]++ == 0) occ.push_back(t);
    }
  };
  auto fill = [&](int c) {
    std::vector<Index>& cnt = counts(c);
    for (Index i = chunk(c); i < chunk(c + 1); ++i) tile_particles_[cnt[tile_of_[i]]++] = i;
  };
  if (nt > 1) {
#pragma omp parallel for schedule(static, 1) num_threads(nt)
    for (int c = 0; c < nt; ++c) count(c);
  } else {
    count(0);
  }
  occupied_.clear();
  for (int c = 0; c < nt; ++c) occupied_.insert(occupied_.end(), chunk_occupied_[c].begin(), chunk_occupied_[c].end());
  std::sort(occupied_.begin(), occupied_.end());
  occupied_.erase(std::unique(occupied_.begin(), occupied_.end()), occupied_.end());
  const Index nocc = static_cast<Index>(occupied_.size());
  tile_start_.resize(static_cast<std::size_t>(nocc + 1));
  tile_start_[0] = 0;
  for (Index k = 0; k < nocc; ++k) {
    const Index t = occupied_[k];
    Index pos = tile_start_[k];
    for (int c = 0; c < nt; ++c) {  // counts become the fill positions of each chunk in tile t
      std::vector<Index>& cnt = counts(c);
      const Index n = cnt[t];
      cnt[t] = pos;
      pos += n;
    }
    tile_start_[k + 1] = pos;
  }
  if (nt > 1) {
#pragma omp parallel for schedule(static, 1) num_threads(nt)
    for (int c = 0; c < nt; ++c) fill(c);
  } else {
    fill(0);
  }
  for (int c = 0; c < nt; ++c)  // reset only the occupied tiles (every chunk's entry there holds a fill position)
    for (Index t : occupied_) counts(c)[t] = 0;
}

// The nodes the occupied tiles' particles can touch (tile_nodes), in ascending node id, in O(active nodes + occupied
// tiles): occupied_ is sorted by tile id, so each tile row's tiles are a contiguous run ordered by tx; the tile rows
// reaching node row j are a window of consecutive rows_ (at most kWindow), whose column intervals are merged in
// order, without collecting in tile order and sorting (a serial sort of every active node).
template <int D> void Grid<D>::active_nodes_2d() {
  if constexpr (D == 2) {
    constexpr int kReach = reach_hi(0) - reach_lo(0) + 1, kWindow = (kReach + T - 1) / T + 1;  // node rows a tile row reaches
    const std::size_t nr = rows_.size();
    auto ty_of = [&](std::size_t g) { return static_cast<int>(occupied_[rows_[g].begin] / tiles_[0]); };  // rows_: one tile row each
    std::size_t a = 0, b = 0;  // window [a, b): the tile rows reaching node row j
    for (int j = 0; j < nodes_[1];) {
      while (a < nr && reach_hi(ty_of(a)) < j) ++a;
      if (b < a) b = a;
      while (b < nr && reach_lo(ty_of(b)) <= j) ++b;
      if (a == b) {  // no tile row reaches j: on to the next one that reaches anything
        if (a == nr) break;
        j = std::max(j + 1, reach_lo(ty_of(a)));
        continue;
      }
      Index at[kWindow], end[kWindow];
      const int w = static_cast<int>(b - a);
      for (int k = 0; k < w; ++k) at[k] = rows_[a + k].begin, end[k] = rows_[a + k].end;
      int last = -1;  // last column emitted in this row
      while (true) {
        int pick = -1, tx = 0;
        for (int k = 0; k < w; ++k)
          if (at[k] < end[k]) {
            const int t = static_cast<int>(occupied_[at[k]] % tiles_[0]);
            if (pick < 0 || t < tx) pick = k, tx = t;
          }
        if (pick < 0) break;
        ++at[pick];
        const int c0 = std::max({last + 1, reach_lo(tx), 0}), c1 = std::min(reach_hi(tx), nodes_[0] - 1);
        for (int c = c0; c <= c1; ++c) active_.push_back(static_cast<Index>(j) * nodes_[0] + c);
        last = std::max(last, c1);
      }
      ++j;
    }
  }
}

template class Grid<2>;
template class Grid<3>;

}  // namespace dmi
