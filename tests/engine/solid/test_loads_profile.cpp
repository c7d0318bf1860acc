// General face tractions (engine/solid/loads.hpp): the consistent nodal forces of a pressure q(y, z) on an
// x-face carry the exact resultant  int q dA  and base moment  int q z dA  (the isoparametric N_a reproduce
// z, so sum_a f_a z_a = int q z dA) for uniform, hydrostatic (cut off between nodes) and piecewise-linear
// profiles, on 2D sections (times the thickness) and 3D blocks, vertical or sloped faces. A uniform profile
// gives the same nodal forces as the full-face uniform patch load, and static equilibrium closes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/solid/loads.hpp"
#include "engine/solid/static_solver.hpp"

namespace dmi::solid {
namespace {

constexpr double H = 4.0, W = 2.0, T2d = 0.7;  // height, 3D face width, 2D thickness

Elastic material(int dim) {
  Elastic m;
  m.E_Pa = 25e9, m.nu = 0.3, m.analysis = dim == 3 ? Analysis::solid3d : Analysis::plane_strain;
  m.thickness_m = T2d;
  return m;
}

Mesh block(int dim, SlopedFace sloped = SlopedFace::upstream) {
  TaperedBlock b;  // Lin, Cheng & Tuan's 4 m column: 1.6 m base, 1.0 m crest
  b.sloped = sloped, b.nx = 2, b.ny = 5, b.nz = 20;
  return dim == 3 ? hex8_tapered_block(b) : quad4_tapered_section(b);
}

// Resultant along x and moment of the x-forces about the base (sum f_x z) and about the y = 0 edge (3D).
struct Sums { double Fx = 0, Fother = 0, Mz = 0, My = 0; };
Sums sums(const Mesh& m, const Eigen::VectorXd& f) {
  Sums s;
  for (int n = 0; n < m.n_nodes(); ++n) {
    const double fx = f(m.dim * n);
    s.Fx += fx, s.Mz += fx * m.nodes(n, m.dim - 1);
    if (m.dim == 3) s.My += fx * m.nodes(n, 1);
    for (int d = 1; d < m.dim; ++d) s.Fother += std::abs(f(m.dim * n + d));
  }
  return s;
}

// Closed forms of a piecewise-linear profile: int q dz and int q z dz (exact per linear segment).
void closed_form(const std::vector<double>& z, const std::vector<double>& q, double& F, double& M) {
  F = M = 0;
  for (std::size_t i = 0; i + 1 < z.size(); ++i) {
    const double l = z[i + 1] - z[i];
    F += 0.5 * l * (q[i] + q[i + 1]);
    M += l / 6 * (q[i] * (2 * z[i] + z[i + 1]) + q[i + 1] * (z[i] + 2 * z[i + 1]));
  }
}

TEST(SolidLoadsProfile, ResultantAndBaseMomentAreExact) {
  const double g = 9.81, rho_w = 1000, h = 3.37;  // water depth, not at a node (0.2 m spacing)
  const std::vector<std::vector<double>> zs = {{0, H}, {0, h}, {0.13, 1.05, 2.5, 3.71}};
  const std::vector<std::vector<double>> qs = {{2e5, 2e5}, {rho_w * g * h, 0}, {1e5, 4e5, -5e4, 2e5}};
  for (int dim : {2, 3})
    for (Face face : {Face::upstream, Face::downstream})
      for (std::size_t c = 0; c < zs.size(); ++c) {
        const Mesh m = block(dim);
        Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
        const FaceLoadReport r = add_pressure_profile(m, material(dim), face, zs[c], qs[c], f);
        double F, M;
        closed_form(zs[c], qs[c], F, M);
        const double b = dim == 3 ? W : T2d;
        const Sums s = sums(m, f);
        EXPECT_NEAR(s.Fx, F * b, 1e-12 * std::abs(F * b)) << dim << "D case " << c;
        EXPECT_NEAR(r.resultant_N, F * b, 1e-12 * std::abs(F * b));
        EXPECT_NEAR(s.Mz, M * b, 1e-12 * std::abs(M * b)) << dim << "D case " << c;
        EXPECT_EQ(s.Fother, 0.0);
        if (dim == 3) {
          EXPECT_NEAR(s.My, 0.5 * W * F * b, 1e-12 * std::abs(F * b));  // uniform across the width
        }
      }
  // Hydrostatic closed forms: rho g h^2 / 2 per unit width, base moment rho g h^3 / 6.
  const Mesh m = block(3);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
  add_pressure_profile(m, material(3), Face::upstream, {0, h}, {rho_w * g * h, 0}, f);
  EXPECT_NEAR(sums(m, f).Fx, rho_w * g * h * h / 2 * W, 1e-9);
  EXPECT_NEAR(sums(m, f).Mz, rho_w * g * h * h * h / 6 * W, 1e-9);
}

TEST(SolidLoadsProfile, GeneralTractionVaryingAcrossTheWidth) {
  // q = q0 (1 + y / W) z / H on a sloped 3D face: F = q0 (3 W / 2)(H / 2), M_base = q0 (3 W / 2)(H^2 / 3),
  // moment about y = 0: q0 (W^2 / 2 + W^2 / 3)(H / 2). Bilinear in (y, z): 2 x 2 Gauss is exact.
  const double q0 = 3e5;
  const Mesh m = block(3, SlopedFace::both);
  FaceTraction t;
  t.q_Pa = [&](double y, double z) { return q0 * (1 + y / W) * z / H; };
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
  add_face_traction(m, material(3), t, f);
  const Sums s = sums(m, f);
  EXPECT_NEAR(s.Fx, q0 * 1.5 * W * H / 2, 1e-9 * q0);
  EXPECT_NEAR(s.Mz, q0 * 1.5 * W * H * H / 3, 1e-9 * q0);
  EXPECT_NEAR(s.My, q0 * (W * W / 2 + W * W / 3) * H / 2, 1e-9 * q0);
  // Inclined direction in 2D: the forces follow d, the magnitude is unchanged.
  const Mesh m2 = block(2);
  FaceTraction t2;
  t2.q_Pa = [](double, double) { return 1e5; };
  t2.direction = Eigen::Vector3d(3, 0, -4);
  Eigen::VectorXd f2 = Eigen::VectorXd::Zero(m2.n_dofs());
  const FaceLoadReport r2 = add_face_traction(m2, material(2), t2, f2);
  EXPECT_NEAR(r2.resultant_N, 1e5 * H * T2d, 1e-6);
  EXPECT_NEAR(f2(Eigen::seq(0, Eigen::last, 2)).sum(), 0.6 * 1e5 * H * T2d, 1e-6);
  EXPECT_NEAR(f2(Eigen::seq(1, Eigen::last, 2)).sum(), -0.8 * 1e5 * H * T2d, 1e-6);
  EXPECT_EQ(r2.loaded_nodes, m2.nz + 1);
  t2.direction = Eigen::Vector3d(1, 1, 0);
  EXPECT_THROW(add_face_traction(m2, material(2), t2, f2), std::invalid_argument);
}

TEST(SolidLoadsProfile, BreaksMakeKinkedProfilesExact) {
  // A kink between nodes: plain Gauss misses the resultant, splitting the segment at the kink recovers it.
  const Mesh m = block(2);
  FaceTraction t;
  t.q_Pa = [](double, double z) { return z < 1.33 ? 1e5 * (1.33 - z) : 0.0; };
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.n_dofs());
  const double exact = 1e5 * 1.33 * 1.33 / 2 * T2d;
  const double plain = add_face_traction(m, material(2), t, f).resultant_N;
  t.z_breaks = {1.33};
  const double split = add_face_traction(m, material(2), t, f).resultant_N;
  EXPECT_GT(std::abs(plain / exact - 1), 1e-5);
  EXPECT_NEAR(split / exact, 1.0, 1e-13);
}

TEST(SolidLoadsProfile, UniformProfileMatchesFullFaceUniformPatchAndEquilibrates) {
  const Mesh m = block(3);
  const double q = 2.5e5;
  Eigen::VectorXd fp = Eigen::VectorXd::Zero(m.n_dofs()), fq = fp;
  PatchLoad p;
  p.shape = PatchShape::uniform, p.centre_y_m = W / 2, p.centre_z_m = H / 2, p.width_m = W, p.height_m = H;
  p.total_force_N = q * W * H;
  EXPECT_NEAR(add_patch_load(m, p, fp).scale, 1.0, 1e-13);
  add_pressure_profile(m, material(3), Face::upstream, {0, H}, {q, q}, fq);
  EXPECT_LT((fp - fq).cwiseAbs().maxCoeff(), 1e-9 * q);
  // Static equilibrium of the loaded block: base reactions balance the resultant and the base moment.
  const std::vector<int> base = nodes_at_height(m, 0.0);
  const StaticSolution s = StaticSolver(assemble_stiffness(m, material(3)), node_dofs(m, base)).solve(fq);
  const Eigen::VectorXd R = total_reaction(m, s.reaction, base);
  EXPECT_NEAR(R(0), -q * W * H, 1e-8 * q * W * H);
  // Moment about the y axis, sum (z F_x - x F_z) = 0: the base (z = 0) reactions give sum x r_z = q W H^2 / 2.
  double M_react = 0;
  for (int n : base) M_react += s.reaction(3 * n + 2) * m.nodes(n, 0);
  EXPECT_NEAR(M_react, q * W * H * H / 2, 1e-7 * q * W * H * H);
}

}  // namespace
}  // namespace dmi::solid
