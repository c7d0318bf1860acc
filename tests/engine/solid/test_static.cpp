// Linear statics (engine/solid/static_solver.hpp, loads.hpp) against closed forms: a bar under end
// pressure (sigma = p, u = p L / E, lateral contraction nu p / E, exactly), a cantilever under a tip load
// converging to Timoshenko's P L^3 / (3 E I) + P L / (kappa G A) (kappa = 5/6) with refinement, equilibrium
// of reactions (forces and moments), and the pyramid patch load's resultant and scaling.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/solid/loads.hpp"
#include "engine/solid/static_solver.hpp"
#include "engine/solid/stress.hpp"

namespace dmi::solid {
namespace {

constexpr double E = 30e9, nu = 0.25;

Elastic concrete(Analysis a = Analysis::solid3d, double t = 1.0) {
  Elastic m;
  m.E_Pa = E, m.nu = nu, m.analysis = a, m.thickness_m = t;
  return m;
}

TEST(SolidStatic, UniaxialBarUnderEndPressureIsExact) {
  // Bar along x: L = 2 m, 0.3 x 0.5 m section; symmetry supports (x at x = 0, y at y = 0, z at z = 0).
  TaperedBlock b;
  b.base_thickness_m = b.crest_thickness_m = 2.0, b.width_m = 0.3, b.height_m = 0.5, b.nx = 5, b.ny = 2, b.nz = 3;
  const Mesh m = hex8_tapered_block(b);
  std::vector<int> fixed;
  for (int n = 0; n < m.n_nodes(); ++n)
    for (int d = 0; d < 3; ++d)
      if (std::abs(m.nodes(n, d)) < 1e-12) fixed.push_back(3 * n + d);
  const double p = 2e6, F = p * 0.3 * 0.5;
  PatchLoad pl;
  pl.face = Face::downstream, pl.shape = PatchShape::uniform;
  pl.centre_y_m = 0.15, pl.centre_z_m = 0.25, pl.width_m = 0.3, pl.height_m = 0.5, pl.total_force_N = F;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
  const PatchLoadReport rep = add_patch_load(m, pl, f);
  EXPECT_NEAR(rep.scale, 1.0, 1e-13);  // a uniform patch matching the face is integrated exactly
  EXPECT_EQ(rep.loaded_nodes, 12);
  const StaticSolution s = StaticSolver(assemble_stiffness(m, concrete()), fixed).solve(f);
  for (int n = 0; n < m.n_nodes(); ++n) {
    const Eigen::Vector3d x = m.nodes.row(n).transpose(), u = s.u.segment<3>(3 * n);
    EXPECT_NEAR(u(0), p * x(0) / E, 1e-12);
    EXPECT_NEAR(u(1), -nu * p * x(1) / E, 1e-12);
    EXPECT_NEAR(u(2), -nu * p * x(2) / E, 1e-12);
  }
  EXPECT_NEAR(s.u(3 * m.node_id(5, 0, 0)), p * 2.0 / E, 1e-12);
  const StressField st = recover_stress(m, concrete(), s.u);
  for (Location l : {Location::gauss, Location::centroid, Location::node})
    for (const Stress6& sg : st.at(l)) {
      EXPECT_NEAR(sg(0), p, 1e-6 * p);
      EXPECT_NEAR(sg.tail<5>().cwiseAbs().maxCoeff(), 0, 1e-6 * p);
    }
  Eigen::Vector3d R = Eigen::Vector3d::Zero();
  for (int n = 0; n < m.n_nodes(); ++n) R += s.reaction.segment<3>(3 * n);
  EXPECT_NEAR(R(0), -F, 1e-9 * F);
  EXPECT_NEAR(R.tail<2>().norm(), 0, 1e-9 * F);
}

// Vertical cantilever (base z = 0 clamped), depth d along x, width w along y, tip shear P in +x shared
// over the crest nodes by their tributary widths; returns the mean crest u_x.
struct Cantilever {
  double L = 2.0, d = 0.2, w = 0.1, P = 1e4;
  double beam() const {  // Timoshenko, kappa = 5/6
    const double I = w * d * d * d / 12, A = w * d, G = E / (2 * (1 + nu));
    return P * L * L * L / (3 * E * I) + P * L / (5.0 / 6 * G * A);
  }
};

double cantilever_hex8(const Cantilever& c, int nx, int nz, Eigen::Vector3d* moment_residual = nullptr) {
  TaperedBlock b;
  b.height_m = c.L, b.width_m = c.w, b.base_thickness_m = b.crest_thickness_m = c.d, b.nx = nx, b.ny = 1, b.nz = nz;
  const Mesh m = hex8_tapered_block(b);
  const std::vector<int> base = nodes_at_height(m, 0.0), top = nodes_at_height(m, c.L);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= 1; ++j)
      add_point_load(m, m.node_id(i, j, nz), Eigen::Vector3d(c.P * (i == 0 || i == nx ? 0.5 : 1.0) / nx / 2, 0, 0), f);
  const StaticSolution s = StaticSolver(assemble_stiffness(m, concrete()), node_dofs(m, base)).solve(f);
  if (moment_residual) {  // sum of x (f + r) x over all nodes must vanish
    Eigen::Vector3d M = Eigen::Vector3d::Zero();
    for (int n = 0; n < m.n_nodes(); ++n)
      M += Eigen::Vector3d(m.nodes.row(n).transpose()).cross(Eigen::Vector3d(f.segment<3>(3 * n) + s.reaction.segment<3>(3 * n)));
    *moment_residual = M;
  }
  double sum = 0;
  for (int n : top) sum += s.u(3 * n);
  return sum / static_cast<double>(top.size());
}

TEST(SolidStatic, Hex8CantileverConvergesToBeamTheory) {
  const Cantilever c;
  const double exact = c.beam();
  const double coarse = cantilever_hex8(c, 1, 10), mid = cantilever_hex8(c, 2, 20);
  Eigen::Vector3d Mres;
  const double fine = cantilever_hex8(c, 4, 40, &Mres);
  const double e1 = std::abs(coarse / exact - 1), e2 = std::abs(mid / exact - 1), e3 = std::abs(fine / exact - 1);
  // Full integration locks: the coarse mesh is far too stiff, refinement removes most of it.
  EXPECT_LT(coarse, exact);
  EXPECT_LT(e2, 0.6 * e1);
  EXPECT_LT(e3, 0.6 * e2);
  EXPECT_LT(e3, 0.05) << "fine " << fine << " beam " << exact;
  EXPECT_LT(Mres.norm(), 1e-8 * c.P * c.L);  // moment equilibrium of loads and reactions
}

TEST(SolidStatic, Quad4PlaneStressCantileverConvergesToBeamTheory) {
  const Cantilever c;
  auto run = [&](int nx, int nz) {
    TaperedBlock b;
    b.height_m = c.L, b.base_thickness_m = b.crest_thickness_m = c.d, b.nx = nx, b.nz = nz;
    const Mesh m = quad4_tapered_section(b);
    const Elastic mat = concrete(Analysis::plane_stress, c.w);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
    for (int i = 0; i <= nx; ++i)
      add_point_load(m, m.node_id(i, 0, nz), Eigen::Vector2d(c.P * (i == 0 || i == nx ? 0.5 : 1.0) / nx, 0), f);
    const std::vector<int> base = nodes_at_height(m, 0.0);
    const StaticSolution s = StaticSolver(assemble_stiffness(m, mat), node_dofs(m, base)).solve(f);
    EXPECT_NEAR(total_reaction(m, s.reaction, base)(0), -c.P, 1e-9 * c.P);
    return s.u(2 * m.node_id(nx / 2, 0, nz));
  };
  const double exact = c.beam();
  const double e1 = std::abs(run(2, 10) / exact - 1), e2 = std::abs(run(4, 40) / exact - 1), e3 = std::abs(run(8, 80) / exact - 1);
  EXPECT_LT(e2, 0.6 * e1);
  EXPECT_LT(e3, e2);
  EXPECT_LT(e3, 0.03);
}

TEST(SolidLoads, PyramidPatchResultantIsExactAndScaleNearOne) {
  TaperedBlock b;  // 0.05 m face quads, so a 0.4 x 0.4 patch spans 8 x 8 quads
  b.height_m = 1.0, b.width_m = 1.0, b.nx = 1, b.ny = 20, b.nz = 20;
  const Mesh m = hex8_tapered_block(b);
  PatchLoad p;
  p.centre_y_m = 0.5, p.centre_z_m = 0.5, p.width_m = 0.4, p.height_m = 0.4, p.total_force_N = 980e3;
  p.direction = Eigen::Vector3d(2, 0, 0);  // normalised internally
  for (int g : {2, 6}) {
    p.gauss_per_direction = g;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
    const PatchLoadReport r = add_patch_load(m, p, f);
    Eigen::Vector3d R = Eigen::Vector3d::Zero();
    for (int n = 0; n < m.n_nodes(); ++n) R += f.segment<3>(3 * n);
    EXPECT_NEAR(R(0), 980e3, 1e-9 * 980e3);
    EXPECT_NEAR(R.tail<2>().norm(), 0, 1e-9);
    EXPECT_NEAR(r.nominal_peak_pressure_Pa, 3 * 980e3 / 0.16, 1e-6);
    EXPECT_NEAR(r.scale, 1.0, g == 2 ? 0.02 : 0.002);
    // The centre node takes the largest share (pyramid).
    const int centre = m.node_id(0, 10, 10);
    EXPECT_DOUBLE_EQ(f.cwiseAbs().maxCoeff(), f(3 * centre));
  }
  p.centre_z_m = 5.0;  // off the face
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
  EXPECT_THROW(add_patch_load(m, p, f), std::invalid_argument);
}

}  // namespace
}  // namespace dmi::solid
