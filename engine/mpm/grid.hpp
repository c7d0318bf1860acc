// Background grid: uniform cells of size h, dense node storage (allocated once, zeroed lazily)
// and an active-node list rebuilt each step from the occupied tiles, so per-step cost follows
// the occupied cells, not the box. Several velocity fields (one per contact body) share a node
// layout: array index = field * nnodes + node.
// Particles are binned into tiles of T^D cells. A binning stays valid while every particle lies within kMargin cells
// of its tile (outgrown() says when not), so most steps only zero P2G's sums (clear_sums()) and keep the tile order,
// the scatter's runs and the active nodes (docs/performance.md). A tile's
// particles therefore reach the nodes [T t - 1 - kMargin, T t + T + 1 + kMargin] (tile_nodes).
// The scatter's work items are runs of occupied tiles in one colour: a run's particles are contiguous in the tile
// order, and same-colour runs are 3 T cells apart, wider than any reach (3 T - 1 - kMargin > T + 1 + kMargin), so a
// colour's runs scatter in parallel without locks, and the summation order per node (colour, run, particle order)
// does not depend on the thread count. Runs are whole tile rows along x (colour: the other tile coordinates modulo
// 3, 3^(D-1) colours), which stream the particle arrays; with too few rows to share among threads, single tiles
// coloured by all their coordinates modulo 3 (3^D colours).
#pragma once
#include <array>
#include <vector>

#include "engine/common/types.hpp"

namespace dmi {

// Calls f(ijk) for the node indices of the box [lo, hi] (inclusive), x fastest, until f returns true; returns
// whether one did.
template <int D, class F> bool any_node_in_box(const IVec<D>& lo, const IVec<D>& hi, F&& f) {
  IVec<D> ijk = lo;
  while (true) {
    if (f(static_cast<const IVec<D>&>(ijk))) return true;
    int d = 0;
    for (; d < D; ++d) {
      if (++ijk[d] <= hi[d]) break;
      ijk[d] = lo[d];
    }
    if (d == D) return false;
  }
}

template <int D> class Grid {
 public:
  static constexpr int T = 4;  // tile width in cells

  Grid(const Vec<D>& origin, const IVec<D>& cells, double h, int nfields);
  // Not copyable: pf() and vrec() point into the grid's own storage.
  Grid(const Grid&) = delete;
  Grid& operator=(const Grid&) = delete;

  Index node_id(const IVec<D>& ijk) const {
    Index id = ijk[D - 1];
    for (int d = D - 2; d >= 0; --d) id = id * nodes_[d] + ijk[d];
    return id;
  }
  IVec<D> node_ijk(Index id) const {
    IVec<D> ijk;
    for (int d = 0; d < D; ++d) {
      ijk[d] = static_cast<int>(id % nodes_[d]);
      id /= nodes_[d];
    }
    return ijk;
  }
  Vec<D> node_pos(Index id) const { return origin_ + h_ * node_ijk(id).template cast<double>(); }
  Vec<D> grid_coord(const Vec<D>& x) const { return (x - origin_) * inv_h_; }
  // True when every shape function's stencil around x lies on the grid: 1/2 <= xr < cells - 1/2.
  bool interior(const Vec<D>& x) const {
    const Vec<D> xr = grid_coord(x);
    for (int d = 0; d < D; ++d)
      if (!(xr[d] >= 0.5 && xr[d] < cells_[d] - 0.5)) return false;
    return true;
  }

  // Bins particle positions into the occupied tiles (stable counting sort) and rebuilds the
  // active-node list. Every field is zero at every node when it returns (the previous step's
  // active nodes are cleared), so nodes outside the active set never hold stale values.
  void bin(const std::vector<Vec<D>>& x);
  // The step's clear while the binning holds: zeroes the sums P2G accumulates into (m; grad m and vol with several
  // fields) at the active nodes. The rest is written whole at every active node each step (p, f by P2G's unpacking,
  // v, v^L by the solver's grid update, zero where a node is empty).
  void clear_sums();
  // True when the binning no longer holds the particles at x: their number changed, or one lies more than kMargin
  // cells outside its tile (its stencil may then reach nodes outside the active set, or a same-colour run's).
  bool outgrown(const std::vector<Vec<D>>& x) const;
  static constexpr int kMargin = 1;  // cells a particle may move out of its tile before a rebinning
  // Checkpoint restart: each particle's tile at the last binning, and the binning rebuilt from them (the same tile
  // order, runs and active nodes, hence the same summation order as the run that wrote them).
  const std::vector<Index>& particle_tiles() const { return tile_of_; }
  void restore_binning(std::vector<Index> tiles);

  double h() const { return h_; }
  double inv_h() const { return inv_h_; }
  const Vec<D>& origin() const { return origin_; }
  const IVec<D>& cells() const { return cells_; }
  const IVec<D>& nodes() const { return nodes_; }
  Index nnodes() const { return nnodes_; }
  int nfields() const { return nfields_; }
  const std::vector<Index>& active() const { return active_; }
  // Work items of colour c: occupied-tile index ranges [begin, end), each scattered by one thread in order.
  struct TileRun {
    Index begin, end;
  };
  const std::vector<TileRun>& color_runs(int c) const { return color_runs_[c]; }
  static constexpr int kColors = D == 2 ? 9 : 27;  // 3^D
  // Fewest tile rows for row runs when the particles are many enough to scatter in parallel.
  static constexpr Index kMinRows = 16;
  // Occupied tiles (tile ids, ascending); index k into this list is the "occupied-tile index".
  const std::vector<Index>& occupied() const { return occupied_; }
  const IVec<D>& tiles() const { return tiles_; }  // tile counts per axis
  Index ntiles() const { return ntiles_; }
  // Tile coordinates of tile id t: cells [T t, T t + T - 1] along each axis.
  IVec<D> tile_coord(Index t) const {
    IVec<D> ti;
    for (int d = 0; d < D; ++d) {
      ti[d] = static_cast<int>(t % tiles_[d]);
      t /= tiles_[d];
    }
    return ti;
  }
  // Nodes a particle of tile t can touch while the binning holds (cells [T t - kMargin, T t + T - 1 + kMargin] -> nodes
  // [T t - 1 - kMargin, T t + T + 1 + kMargin]), clamped to the grid: lo and hi inclusive along each axis.
  void tile_nodes(Index t, IVec<D>& lo, IVec<D>& hi) const {
    const IVec<D> ti = tile_coord(t);
    for (int d = 0; d < D; ++d) {
      lo[d] = std::max(0, reach_lo(ti[d]));
      hi[d] = std::min(nodes_[d] - 1, reach_hi(ti[d]));
    }
  }
  // Unclamped along one axis: the first and last node a particle of tile coordinate t can touch.
  static constexpr int reach_lo(int t) { return t * T - 1 - kMargin; }
  static constexpr int reach_hi(int t) { return t * T + T + 1 + kMargin; }
  // The tiles whose particles can touch node n while the binning holds (the inverse of tile_nodes: T t - 1 - kMargin <=
  // n <= T t + T + 1 + kMargin), clamped to the grid: lo and hi inclusive along each axis.
  void tiles_reaching(const IVec<D>& n, IVec<D>& lo, IVec<D>& hi) const {
    for (int d = 0; d < D; ++d) {
      const int a = n[d] - reach_hi(0);  // lo = ceil(a / T), at least 0
      lo[d] = a <= 0 ? 0 : (a + T - 1) / T;
      hi[d] = std::min(tiles_[d] - 1, (n[d] - reach_lo(0)) / T);
    }
  }
  // Nodes within the quadratic B-spline support (1.5 cells) of a point at grid coordinates xr, clamped to the grid.
  void support_nodes(const Vec<D>& xr, IVec<D>& lo, IVec<D>& hi) const {
    for (int d = 0; d < D; ++d) {
      lo[d] = std::max(0, static_cast<int>(std::ceil(xr[d] - 1.5)));
      hi[d] = std::min(nodes_[d] - 1, static_cast<int>(std::floor(xr[d] + 1.5)));
    }
  }
  // Particles of occupied tile k: tile_particles()[tile_start()[k] .. tile_start()[k+1]).
  const std::vector<Index>& tile_start() const { return tile_start_; }
  const std::vector<Index>& tile_particles() const { return tile_particles_; }

  // Nodal fields, size nfields * nnodes.
  std::vector<double> m;        // mass (kg)
  std::vector<Vec<D>> p;        // momentum (kg m/s)
  std::vector<Vec<D>> f;        // total force (N)
  std::vector<Vec<D>> v;        // velocity at the start of the step v^k (m/s)
  std::vector<Vec<D>> vL;       // updated velocity v^L (m/s)
  std::vector<double> vol;      // sum_p V_p N_ip, for the contact overlap test (m^3)
  std::vector<Vec<D>> grad_m;   // sum_p m_p grad N_i(x_p): outward from a body, for contact normals (kg/m)
  // P2G scratch: momentum and force of a node side by side (p_0..p_D-1, f_0..f_D-1) in one record (32-byte aligned in
  // 2D), so the scatter touches one record per node instead of two arrays (in 2D it adds it as one 4-wide vector);
  // unpacked into p, f (and zeroed) right after the scatter. The mass goes straight into m.
  double* pf() { return pf_; }
  // G2P scratch: v^L and the FLIP increment v^L - v^k of a node side by side (v^L_0..v^L_D-1, dv_0..dv_D-1), 32-byte
  // aligned, packed from vL and v at the active nodes right before the vector gather, which alone reads it (its values
  // are valid only inside that G2P; elsewhere they are stale). Allocated on the first call (serial code only), so
  // scenes whose G2P does not take that path do not carry it.
  double* vrec();

 private:
  std::vector<double> pf_storage_, vrec_storage_;
  double* pf_ = nullptr;
  double* vrec_ = nullptr;
  Vec<D> origin_;
  IVec<D> cells_, nodes_, tiles_;
  double h_, inv_h_;
  Index nnodes_, ntiles_;
  int nfields_;
  void active_nodes_2d();
  void clear();  // every field zeroed at the active nodes
  Index tile_of(const Vec<D>& x, IVec<D>& cell) const;  // tile id of a position and its cell (clamped to the grid)
  void count_sort_tiles(const std::vector<Vec<D>>* x);  // tile_of_ from x, or as it is (x null)
  void build_runs_and_nodes(Index np);
  void color_runs_build(Index np);  // rows_ and color_runs_ from occupied_
  std::vector<TileRun> rows_;        // occupied tiles by tile row (equal y [and z] tile coordinates), ascending
  std::vector<std::vector<Index>> chunk_count_, chunk_occupied_;  // per-thread tile counts (chunk 0 uses tile_count_)
  std::vector<Index> active_;
  std::vector<unsigned char> flag_;  // 3D active-node collection only
  std::vector<IVec<D>> home_;        // each particle's tile coordinates at the last binning
  void zero_node(Index id);
  std::vector<Index> tile_of_, tile_start_, tile_particles_, tile_count_, occupied_;
  std::array<std::vector<TileRun>, kColors> color_runs_;
};

}  // namespace dmi
