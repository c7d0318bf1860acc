#include "engine/mpm/transfer.hpp"

#include "engine/common/parallel.hpp"
#include "engine/mpm/shape.hpp"
#include "engine/mpm/transfer_kernels.hpp"

namespace dmi {
namespace {

using namespace detail;

// One instance per (dimension, shape, AVX2 leaf allowed); the scheme, the scatter content and the G2P mode are fixed
// per call and dispatched once here to kernels without run-time branches inside (transfer_kernels.hpp).
template <int D, class Shape, bool SIMD> class Kernels final : public TransferKernels<D> {
  using St = Stencil<D, Shape>;

 public:
  void p2g(Scene<D>& s, bool momentum_only) const override {
    if (s.options.transfer == TransferKind::apic) {
      p2g_fill<Apic>(s, momentum_only);
    } else {
      p2g_fill<Flip>(s, momentum_only);
    }
  }

  G2PResult g2p(Scene<D>& s, double dt, G2PMode mode, const typename TransferKernels<D>::ChunkHook* after) const override {
    if (s.options.transfer == TransferKind::apic) return g2p_mode<Apic>(s, dt, mode, after);
    return g2p_mode<Flip>(s, dt, mode, after);
  }

  int stencils(const Scene<D>& s, Index begin, Index end, std::vector<Index>& node, std::vector<double>& weight,
               std::vector<Vec<D>>& grad, std::vector<Mat<D>>* H) const override {
    const Grid<D>& g = *s.grid;
    const Particles<D>& P = s.particles;
    node.resize(static_cast<std::size_t>(end - begin) * St::NN);
    weight.resize(node.size()), grad.resize(node.size());
    if (H) H->resize(static_cast<std::size_t>(end - begin));
    parallel_for(begin, end, [&](Index i) {
      St st;
      st.compute(P.x[i], P.half_size[i], g.origin(), g.inv_h());
      std::size_t k = static_cast<std::size_t>(i - begin) * St::NN;
      for (int r = 0; r < St::R; ++r)
        for (int a = 0; a < St::K; ++a, ++k) node[k] = g.node_id(st.node(r, a)), weight[k] = st.N(r, a), grad[k] = st.grad(r, a);
      if (H) (*H)[static_cast<std::size_t>(i - begin)] = st.inverse_weighted_slopes(g.inv_h());
    });
    return St::NN;
  }

  void scatter_mass_position(const Scene<D>& s, const std::vector<Index>& tiles, std::vector<Vec<D>>& mx) const override {
    const Grid<D>& g = *s.grid;
    const Particles<D>& P = s.particles;
    const Index nn = g.nnodes();
    St st;
    for (Index t : tiles) {
      for (Index q = g.tile_start()[t]; q < g.tile_start()[t + 1]; ++q) {
        const Index i = g.tile_particles()[q];
        st.compute(P.x[i], P.half_size[i], g.origin(), g.inv_h());
        const Vec<D> mxp = P.mass[i] * P.x[i];
        const Index off = s.bodies[P.body[i]].field * nn;
        for (int r = 0; r < St::R; ++r)
          for (int a = 0; a < St::K; ++a) mx[off + g.node_id(st.node(r, a))] += st.N(r, a) * mxp;
      }
    }
  }

 private:
  template <class Scheme> void p2g_fill(Scene<D>& s, bool momentum_only) const {
    if (momentum_only) {
      scatter<D, Shape, Scheme, ScatterMomentum, SIMD>(s);
    } else if (s.grid->nfields() > 1) {
      scatter<D, Shape, Scheme, ScatterContact, SIMD>(s);
    } else {
      scatter<D, Shape, Scheme, ScatterForces, SIMD>(s);
    }
  }
  template <class Scheme> G2PResult g2p_mode(Scene<D>& s, double dt, G2PMode mode, const typename TransferKernels<D>::ChunkHook* a) const {
    switch (mode) {
      case G2PMode::full: return gather<D, Shape, Scheme, GatherFull, SIMD>(s, dt, a);
      case G2PMode::velocity_only: return gather<D, Shape, Scheme, GatherVelocity, SIMD>(s, dt, a);
      case G2PMode::kinematics: return gather<D, Shape, Scheme, GatherKinematics, SIMD>(s, dt, a);
    }
    return G2PResult{false};
  }
};

template <int D, bool SIMD> std::unique_ptr<TransferKernels<D>> make_kernels(ShapeKind shape) {
  switch (shape) {
    case ShapeKind::linear: return std::make_unique<Kernels<D, LinearShape, SIMD>>();
    case ShapeKind::gimp: return std::make_unique<Kernels<D, GimpShape, SIMD>>();
    case ShapeKind::bspline2: return std::make_unique<Kernels<D, BSpline2Shape, SIMD>>();
  }
  return nullptr;
}

}  // namespace

template <int D> std::unique_ptr<TransferKernels<D>> make_transfer_kernels(ShapeKind shape, TransferPath path) {
  return path == TransferPath::scalar ? make_kernels<D, false>(shape) : make_kernels<D, true>(shape);
}

template std::unique_ptr<TransferKernels<2>> make_transfer_kernels<2>(ShapeKind, TransferPath);
template std::unique_ptr<TransferKernels<3>> make_transfer_kernels<3>(ShapeKind, TransferPath);

}  // namespace dmi
