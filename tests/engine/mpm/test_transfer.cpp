// The transfer kernels give one result whichever path computes it:
// - the 2D AVX2 leaf (3-node stencils, FLIP) against the generic loops, P2G and G2P, one and two velocity fields;
// - 3D against 2D: a plane-strain particle set extruded along z in layers h/2 apart (every 1D shape function sums to
//   exactly 2 over such a lattice, and its slopes to 0) scatters twice the 2D nodal mass, momentum, force, mass
//   gradient and volume to the nodes inside the layers, with nothing along z; with z-invariant nodal velocities every
//   layer's particles gather exactly what their 2D parent gathers (v, x, L, F, APIC's C). All shapes, FLIP and APIC,
//   every G2P mode.
// Tolerances: round-off of sums of ~10^2 terms (relative 1e-12 of the field's largest value).
#include <gtest/gtest.h>

#include <random>

#include "engine/mpm/scene.hpp"
#include "engine/mpm/transfer.hpp"

namespace dmi {
namespace {

constexpr double kH = 0.1;
constexpr int kLayers = 20;  // along z, h/2 apart, over z in [1 h, 11 h]

struct Cloud2 {  // a random 2D particle set
  std::vector<Vec<2>> x, v;
  std::vector<Mat<2>> C, F, S;
  std::vector<double> m, vol;
  std::vector<int> body;
};

Cloud2 cloud(int n, int seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
  Cloud2 c;
  for (int i = 0; i < n; ++i) {
    c.x.emplace_back((2.2 + 6 * u(rng)) * kH, (2.2 + 6 * u(rng)) * kH);
    c.v.emplace_back(s(rng), s(rng));
    Mat<2> C, F, S;
    C << s(rng), s(rng), s(rng), s(rng);
    F << 1 + 0.1 * s(rng), 0.1 * s(rng), 0.1 * s(rng), 1 + 0.1 * s(rng);
    S << s(rng), 0, 0, s(rng);
    S(0, 1) = S(1, 0) = s(rng);
    c.C.push_back(10 * C), c.F.push_back(F), c.S.push_back(1e5 * S);
    c.m.push_back(1 + u(rng)), c.vol.push_back(1e-3 * (1 + u(rng)));
    c.body.push_back(i % 2);
  }
  return c;
}

template <int D> void resize(Particles<D>& P, std::size_t n) {
  P.x.resize(n), P.x0.resize(n), P.v.resize(n), P.half_size.assign(n, Vec<D>::Constant(kH / 4));
  P.reach_lo = P.reach_hi = P.half_size;
  P.F.resize(n), P.L.assign(n, Mat<D>::Zero()), P.C.resize(n), P.stress.resize(n), P.stress_zz.assign(n, 0.0);
  P.mass.resize(n), P.vol0.resize(n), P.vol.resize(n), P.body.resize(n), P.id.resize(n), P.slot.resize(n);
  for (std::size_t i = 0; i < n; ++i) P.id[i] = P.slot[i] = static_cast<Index>(i);
}

template <int D> std::unique_ptr<Scene<D>> scene(const Cloud2& c, int nfields, ShapeKind shape, TransferKind scheme) {
  auto s = std::make_unique<Scene<D>>();
  const std::size_t n2 = c.x.size(), layers = D == 2 ? 1 : kLayers;
  resize(s->particles, n2 * layers);
  auto& P = s->particles;
  for (std::size_t l = 0; l < layers; ++l)
    for (std::size_t k = 0; k < n2; ++k) {
      const std::size_t i = l * n2 + k;
      P.x[i].template head<2>() = c.x[k], P.v[i].template head<2>() = c.v[k];
      P.C[i].setZero(), P.F[i].setIdentity(), P.stress[i].setZero();
      P.C[i].template topLeftCorner<2, 2>() = c.C[k], P.F[i].template topLeftCorner<2, 2>() = c.F[k];
      P.stress[i].template topLeftCorner<2, 2>() = c.S[k];
      if constexpr (D == 3) P.x[i][2] = (1 + (l + 0.5) / 2) * kH, P.v[i][2] = 0, P.stress[i](2, 2) = 0.5 * c.S[k](0, 0);
      P.x0[i] = P.x[i], P.mass[i] = c.m[k], P.vol0[i] = P.vol[i] = c.vol[k];
      P.body[i] = nfields > 1 ? c.body[k] : 0;
    }
  for (int b = 0; b < nfields; ++b) {
    Body body;
    body.field = b;
    s->bodies.push_back(body);
  }
  s->bodies[0].begin = 0, s->bodies[0].end = static_cast<Index>(P.size());  // ranges are not read by the transfers
  s->gravity = Vec<D>::Zero(), s->gravity[1] = -9.81;
  s->options.shape = shape, s->options.transfer = scheme, s->options.flip_blend = 0.97;
  s->grid = std::make_unique<Grid<D>>(Vec<D>::Zero(), IVec<D>::Constant(12), kH, nfields);
  s->grid->bin(P.x);
  return s;
}

double max_abs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}
template <int D> double max_abs(const std::vector<Vec<D>>& a) {
  double m = 0;
  for (const auto& x : a) m = std::max(m, x.cwiseAbs().maxCoeff());
  return m;
}

// Nodal velocities for G2P, the same in both scenes: a smooth field of (x, y) plus noise, zero along z; m marks the
// nodes the 2D scatter left empty.
template <int D> void set_nodal_velocities(Grid<D>& g, const Grid<2>& g2, int seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> s(-1, 1);
  std::vector<Vec<2>> vl(g2.m.size()), v(g2.m.size());
  for (auto& x : vl) x = Vec<2>(s(rng), s(rng));
  for (auto& x : v) x = Vec<2>(s(rng), s(rng));
  for (Index id = 0; id < g.nnodes() * g.nfields(); ++id) {
    const Index node = id % g.nnodes(), fld = id / g.nnodes();
    const IVec<D> ijk = g.node_ijk(node);
    const Index id2 = fld * g2.nnodes() + g2.node_id(IVec<2>(ijk[0], ijk[1]));
    g.vL[id].setZero(), g.v[id].setZero();
    g.vL[id].template head<2>() = vl[id2], g.v[id].template head<2>() = v[id2], g.m[id] = g2.m[id2];
  }
}

void expect_near_rel(double a, double b, double scale, const char* what) {
  EXPECT_NEAR(a, b, 1e-12 * std::max(scale, 1e-300)) << what;
}

TEST(TransferPaths, AvxLeafMatchesGenericLoops2D) {
  const Cloud2 c = cloud(300, 1);
  for (ShapeKind shape : {ShapeKind::bspline2, ShapeKind::gimp})
    for (int nf : {1, 2}) {
      auto a = scene<2>(c, nf, shape, TransferKind::flip), b = scene<2>(c, nf, shape, TransferKind::flip);
      const auto fast = make_transfer_kernels<2>(shape, TransferPath::fastest), slow = make_transfer_kernels<2>(shape, TransferPath::scalar);
      fast->p2g(*a, false), slow->p2g(*b, false);
      const Grid<2>&ga = *a->grid, &gb = *b->grid;
      const double sm = max_abs(ga.m), sp = max_abs<2>(ga.p), sf = max_abs<2>(ga.f);
      for (std::size_t k = 0; k < ga.m.size(); ++k) {
        expect_near_rel(ga.m[k], gb.m[k], sm, "m");
        for (int d = 0; d < 2; ++d) expect_near_rel(ga.p[k][d], gb.p[k][d], sp, "p"), expect_near_rel(ga.f[k][d], gb.f[k][d], sf, "f");
        if (nf > 1) {
          expect_near_rel(ga.vol[k], gb.vol[k], max_abs(ga.vol), "vol");
          for (int d = 0; d < 2; ++d) expect_near_rel(ga.grad_m[k][d], gb.grad_m[k][d], max_abs<2>(ga.grad_m), "grad m");
        }
      }
      // Two gathers with different nodal velocities: the vector path's packed node records are rebuilt by each.
      for (int seed : {7, 8}) {
        set_nodal_velocities(*a->grid, *a->grid, seed), set_nodal_velocities(*b->grid, *a->grid, seed);
        ASSERT_TRUE(fast->g2p(*a, 1e-3, G2PMode::full).ok);
        ASSERT_TRUE(slow->g2p(*b, 1e-3, G2PMode::full).ok);
        for (std::size_t i = 0; i < c.x.size(); ++i) {
          const auto &Pa = a->particles, &Pb = b->particles;
          EXPECT_NEAR((Pa.v[i] - Pb.v[i]).norm(), 0, 1e-13);
          EXPECT_NEAR((Pa.x[i] - Pb.x[i]).norm(), 0, 1e-15);
          EXPECT_NEAR((Pa.L[i] - Pb.L[i]).norm(), 0, 1e-12 * Pa.L[i].norm());
          EXPECT_NEAR((Pa.F[i] - Pb.F[i]).norm(), 0, 1e-14);
        }
      }
    }
}

void extrusion_case(ShapeKind shape, TransferKind scheme, int nf) {
  const Cloud2 c = cloud(200, 2);
  auto s2 = scene<2>(c, nf, shape, scheme);
  auto s3 = scene<3>(c, nf, shape, scheme);
  const auto k2 = make_transfer_kernels<2>(shape, TransferPath::scalar);
  const auto k3 = make_transfer_kernels<3>(shape);
  k2->p2g(*s2, false), k3->p2g(*s3, false);
  const Grid<2>& g2 = *s2->grid;
  const Grid<3>& g3 = *s3->grid;
  const double sm = max_abs(g2.m), sp = max_abs<2>(g2.p), sf = max_abs<2>(g2.f);
  int checked = 0;
  for (Index id = 0; id < g3.nnodes() * g3.nfields(); ++id) {
    const IVec<3> ijk = g3.node_ijk(id % g3.nnodes());
    if (ijk[2] < 3 || ijk[2] > 9) continue;  // nodes whose support lies inside the layers
    const Index id2 = (id / g3.nnodes()) * g2.nnodes() + g2.node_id(IVec<2>(ijk[0], ijk[1]));
    expect_near_rel(g3.m[id], 2 * g2.m[id2], sm, "m");
    for (int d = 0; d < 2; ++d) {
      expect_near_rel(g3.p[id][d], 2 * g2.p[id2][d], sp, "p");
      expect_near_rel(g3.f[id][d] - 2 * g2.f[id2][d], 0, 2 * sf, "f");
    }
    expect_near_rel(g3.p[id][2], 0, sp, "p_z");
    expect_near_rel(g3.f[id][2], 0, sf, "f_z");
    if (nf > 1) {
      expect_near_rel(g3.vol[id], 2 * g2.vol[id2], max_abs(g2.vol), "vol");
      for (int d = 0; d < 2; ++d) expect_near_rel(g3.grad_m[id][d], 2 * g2.grad_m[id2][d], max_abs<2>(g2.grad_m), "grad m");
      expect_near_rel(g3.grad_m[id][2], 0, max_abs<2>(g2.grad_m), "grad m_z");
    }
    checked += g2.m[id2] > 0;
  }
  EXPECT_GT(checked, 7 * 50);
  for (G2PMode mode : {G2PMode::full, G2PMode::velocity_only, G2PMode::kinematics}) {
    auto a = scene<2>(c, nf, shape, scheme);
    auto b = scene<3>(c, nf, shape, scheme);
    k2->p2g(*a, false);
    set_nodal_velocities(*a->grid, g2), set_nodal_velocities(*b->grid, g2);
    ASSERT_TRUE(k2->g2p(*a, 1e-3, mode).ok);
    ASSERT_TRUE(k3->g2p(*b, 1e-3, mode).ok);
    const Particles<2>& P2 = a->particles;
    const Particles<3>& P3 = b->particles;
    for (std::size_t i = 0; i < P3.size(); ++i) {
      const std::size_t k = i % c.x.size();
      EXPECT_NEAR((P3.v[i].head<2>() - P2.v[k]).norm(), 0, 1e-13);
      EXPECT_NEAR(P3.v[i][2], 0, 1e-13);
      EXPECT_NEAR((P3.x[i].head<2>() - P2.x[k]).norm(), 0, 1e-15);
      const double sl = P2.L[k].norm() + 1;
      EXPECT_NEAR((P3.L[i].topLeftCorner<2, 2>() - P2.L[k]).norm(), 0, 1e-12 * sl);
      EXPECT_NEAR(P3.L[i].col(2).norm() + P3.L[i].row(2).norm(), 0, 1e-12 * sl);
      EXPECT_NEAR((P3.F[i].topLeftCorner<2, 2>() - P2.F[k]).norm(), 0, 1e-14);
      if (scheme == TransferKind::apic && mode != G2PMode::kinematics) {
        EXPECT_NEAR((P3.C[i].topLeftCorner<2, 2>() - P2.C[k]).norm(), 0, 1e-11 * (P2.C[k].norm() + 1));
      }
    }
  }
}

TEST(TransferPaths, ThreeDExtrusionReproducesPlaneStrainLinear) {
  extrusion_case(ShapeKind::linear, TransferKind::flip, 1);
  extrusion_case(ShapeKind::linear, TransferKind::flip, 2);
}
TEST(TransferPaths, ThreeDExtrusionReproducesPlaneStrainGimp) {
  extrusion_case(ShapeKind::gimp, TransferKind::flip, 2);
  extrusion_case(ShapeKind::gimp, TransferKind::apic, 1);
}
TEST(TransferPaths, ThreeDExtrusionReproducesPlaneStrainBSpline) {
  extrusion_case(ShapeKind::bspline2, TransferKind::flip, 1);
  extrusion_case(ShapeKind::bspline2, TransferKind::apic, 2);
}

}  // namespace
}  // namespace dmi
