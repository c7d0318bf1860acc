// Particle <-> grid transfer kernels, one instance per (dimension, shape function), chosen once
// when the solver is built; the transfer scheme (FLIP/PIC blend or APIC) is read per call. One implementation for
// 2D and 3D (transfer_kernels.hpp).
//   P2G (Lin & Yang 2024 eqs. 5-8): m_i = sum_p N_ip m_p,  p_i = sum_p N_ip m_p (v_p + C_p (x_i - x_p)),
//        f_i = -sum_p V_p sigma_p grad N_ip + sum_p N_ip m_p g.   (C_p = 0 unless APIC)
//   G2P (eqs. 13-14): FLIP v_p += sum N_ip (v^L_i - v^k_i), PIC v_p = sum N_ip v^L_i, blended;
//        x_p += dt sum N_ip v^L_i;  L_p = sum v_i (x) grad N_ip;  F_p <- (I + dt L_p) F_p.
//   APIC (Jiang et al. 2015): v_p = sum N v^L, C_p = B_p D_p^-1 with B_p = sum N v^L (x_i-x_p)^T,
//        D_p = sum N (x_i-x_p)(x_i-x_p)^T (h^2/4 I for quadratic B-splines, computed generally).
#pragma once
#include <functional>
#include <memory>

#include "engine/mpm/scene.hpp"

namespace dmi {

enum class G2PMode {
  full,           // USL: velocity, position, velocity gradient from v^L
  velocity_only,  // MUSL pass 1: particle velocity (and APIC C) only
  kinematics      // MUSL pass 2: position from v^L, velocity gradient from the remapped v
};

struct G2PResult {
  bool ok = true;  // false: a particle became non-finite or left the grid interior
};

template <int D> class TransferKernels {
 public:
  virtual ~TransferKernels() = default;
  // Scatter mass, momentum and (unless momentum_only) force with gravity m_i g, and mass gradient. Grid was binned.
  virtual void p2g(Scene<D>& s, bool momentum_only) const = 0;
  // after_chunk (modes full and kinematics): called on particle ranges [begin, end) once their kinematics are done,
  // possibly concurrently for disjoint ranges (the fused pointwise stress update, Solver::grid_to_particles).
  using ChunkHook = std::function<void(Index, Index)>;
  virtual G2PResult g2p(Scene<D>& s, double dt, G2PMode mode, const ChunkHook* after_chunk = nullptr) const = 0;
  // mx_i += sum_p m_p N_ip x_p over the particles of the given occupied tiles (indices into
  // Grid::occupied()), serially: the mass-weighted particle position a node sees (Lin & Yang 2024
  // eq. 25) where members need it. mx has the grid's field layout.
  // The stencils of particles [begin, end) for operators built outside the transfer (the implicit viscosity,
  // engine/mpm/viscous.hpp): NN = K^D entries per particle, node[k NN + n] the node's index in its field,
  // weight[k NN + n] its N and grad[k NN + n] its grad N (1/m), k = particle - begin. Entry n is the node base + (n's
  // digits base K, axis 0 least significant). With H, also per particle sum_n grad N grad N^T / N (1/m^2; from the 1D
  // factors, Stencil::inverse_weighted_slopes). Returns NN.
  virtual int stencils(const Scene<D>& s, Index begin, Index end, std::vector<Index>& node, std::vector<double>& weight,
                       std::vector<Vec<D>>& grad, std::vector<Mat<D>>* H = nullptr) const = 0;
  virtual void scatter_mass_position(const Scene<D>& s, const std::vector<Index>& tiles, std::vector<Vec<D>>& mx) const = 0;
};

// fastest: the AVX2 leaf where it applies (2D, 3-node stencils, FLIP; when built for AVX2); scalar: the generic loops
// everywhere (the cross-check of the leaf).
enum class TransferPath { fastest, scalar };
template <int D> std::unique_ptr<TransferKernels<D>> make_transfer_kernels(ShapeKind shape, TransferPath path = TransferPath::fastest);

}  // namespace dmi
