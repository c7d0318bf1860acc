#include "engine/common/parallel.hpp"
#include "engine/mpm/grid.hpp"

#include <cstdint>
#include <omp.h>

#include <algorithm>
#include <cmath>

namespace dmi {

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
  pf_storage_.assign(2 * D * n + 4, 0.0);  // + slack to start on a 32-byte boundary
  const auto addr = reinterpret_cast<std::uintptr_t>(pf_storage_.data());
  pf_ = pf_storage_.data() + ((32 - addr % 32) % 32) / sizeof(double);
  if (D == 3) flag_.assign(static_cast<std::size_t>(nnodes_), 0);
  tile_count_.assign(static_cast<std::size_t>(ntiles_), 0);
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
  // Zero the nodes of the previous step, so every node outside the active set is zero.
  const Index nold = static_cast<Index>(active_.size());
  parallel_for(0, nold, [&](Index a) { zero_node(active_[a]); });

  const Index np = static_cast<Index>(x.size());
  tile_of_.resize(x.size());
  tile_particles_.resize(x.size());
  occupied_.clear();
  count_sort_tiles(x);
  const Index nocc = static_cast<Index>(occupied_.size());

  color_runs_build(np);
  active_.clear();
  if constexpr (D == 2) {  // the active nodes in ascending order without a sort
    active_nodes_2d();
    return;
  }
  for (Index k = 0; k < nocc; ++k) {
    IVec<D> lo, hi;
    tile_nodes(occupied_[k], lo, hi);
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
// by the parity of ty (and tz); rows two apart are 2 T cells apart. Measured against single tiles in 2^D colours
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
      for (int d = by_rows ? 1 : 0; d < D; ++d) color |= (ti[d] & 1) << (by_rows ? d - 1 : d);
      color_runs_[color].push_back(by_rows ? r : TileRun{k, k + 1});
    }
}

template <int D> Index Grid<D>::tile_of(const Vec<D>& x) const {
  const Vec<D> xr = grid_coord(x);
  Index t = 0;
  for (int d = D - 1; d >= 0; --d) {
    const int c = std::clamp(static_cast<int>(std::floor(xr[d])), 0, cells_[d] - 1);
    t = t * tiles_[d] + c / T;
  }
  return t;
}

// Stable counting sort of the particles by tile (tile_particles_, tile_start_, occupied_ ascending). Large sets are
// split into one contiguous chunk per thread: each counts its chunk into its own array, the chunks' offsets within a
// tile follow in chunk order, and each fills its own chunk, so the order is exactly the serial one (particles by
// tile, then by index). Serially these two passes over the particles limited two threads (docs/performance.md). The
// counting pass also finds each particle's tile (a pass of its own before: 4.3 of 11.6 ms binning 1 M particles).
template <int D> void Grid<D>::count_sort_tiles(const std::vector<Vec<D>>& x) {
  const Index np = static_cast<Index>(x.size());
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
      const Index t = tile_of(x[i]);
      tile_of_[i] = t;
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

// The nodes the occupied tiles' particles can touch (tile (tx, ty): node columns [tx T - 1, tx T + T + 1], rows
// [ty T - 1, ty T + T + 1]), in ascending node id, in O(active nodes + occupied tiles): occupied_ is sorted by tile
// id, so each tile row's tiles are a contiguous run ordered by tx; a node row j is reached by at most two tile rows,
// whose column intervals are merged in order. Replaces collecting in tile order and sorting (std::sort was 3-4 % of
// a 1 M-particle step, serial).
template <int D> void Grid<D>::active_nodes_2d() {
  if constexpr (D == 2) {
    auto ty_of = [&](const TileRun& r) { return static_cast<int>(occupied_[r.begin] / tiles_[0]); };  // rows_: one tile row each
    auto row_lo = [](int ty) { return ty * T - 1; };
    auto row_hi = [](int ty) { return ty * T + T + 1; };
    int next_row = 0;  // rows below it are done
    for (std::size_t g = 0; g < rows_.size(); ++g) {
      for (int j = std::max({next_row, row_lo(ty_of(rows_[g])), 0}); j <= std::min(row_hi(ty_of(rows_[g])), nodes_[1] - 1); ++j) {
        // Tile rows reaching row j among rows g and g + 1 (ascending in ty; g - 1 ended below j).
        const TileRun* a = &rows_[g];
        const TileRun* b = g + 1 < rows_.size() && row_lo(ty_of(rows_[g + 1])) <= j ? &rows_[g + 1] : nullptr;
        Index ia = a->begin, ib = b ? b->begin : 0;
        int last = -1;  // last column emitted in this row
        while (ia < a->end || (b && ib < b->end)) {
          const bool take_a = !b || ib >= b->end || (ia < a->end && occupied_[ia] % tiles_[0] <= occupied_[ib] % tiles_[0]);
          const Index t = take_a ? occupied_[ia++] : occupied_[ib++];
          const int tx = static_cast<int>(t % tiles_[0]);
          const int c0 = std::max({last + 1, tx * T - 1, 0}), c1 = std::min(tx * T + T + 1, nodes_[0] - 1);
          for (int c = c0; c <= c1; ++c) active_.push_back(static_cast<Index>(j) * nodes_[0] + c);
          last = std::max(last, c1);
        }
        next_row = j + 1;
      }
    }
  }
}

template class Grid<2>;
template class Grid<3>;

}  // namespace dmi
