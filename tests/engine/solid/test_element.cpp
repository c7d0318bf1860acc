// Hex8 / quad4 elements (engine/solid/element.hpp) against identities: rigid-body modes carry no energy,
// stiffness symmetry, consistent mass sums to rho V, and the patch test — a linear displacement field
// prescribed on the boundary of a distorted mesh is reproduced exactly inside, with constant stress D eps.
#include <gtest/gtest.h>

#include <stdexcept>

#include "engine/solid/static_solver.hpp"
#include "engine/solid/stress.hpp"

namespace dmi::solid {
namespace {

Elastic steel(Analysis a = Analysis::solid3d) {
  Elastic m;
  m.E_Pa = 200e9, m.nu = 0.3, m.analysis = a, m.thickness_m = 0.05, m.density_kg_m3 = 7850;
  return m;
}

// A unit box/square of 2^dim elements with the shared interior node moved off-centre.
Mesh distorted_patch(int dim) {
  TaperedBlock b;
  b.height_m = 1, b.width_m = 1, b.base_thickness_m = 1, b.crest_thickness_m = 1, b.nx = b.ny = b.nz = 2;
  Mesh m = dim == 3 ? hex8_tapered_block(b) : quad4_tapered_section(b);
  const int c = m.node_id(1, 1, 1);
  if (dim == 3) m.nodes.row(c) << 0.62, 0.41, 0.57;
  else m.nodes.row(c) << 0.62, 0.43;
  m.validate();
  return m;
}

void patch_test(int dim, Analysis a) {
  const Mesh m = distorted_patch(dim);
  const Elastic mat = steel(a);
  Eigen::MatrixXd A(dim, dim);  // u = A x + c
  if (dim == 3) A << 1e-3, 2e-4, -3e-4, 5e-4, -7e-4, 1e-4, -2e-4, 3e-4, 4e-4;
  else A << 1e-3, 2e-4, -5e-4, -7e-4;
  const Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(dim, 1e-4, 3e-4);
  Eigen::VectorXd exact(m.n_dofs());
  std::vector<int> boundary;
  for (int n = 0; n < m.n_nodes(); ++n) {
    exact.segment(dim * n, dim) = A * m.nodes.row(n).transpose() + c;
    if (n != m.node_id(1, 1, 1)) boundary.push_back(n);
  }
  const StaticSolver solver(assemble_stiffness(m, mat), node_dofs(m, boundary));
  ASSERT_EQ(solver.n_free(), dim);
  const StaticSolution s = solver.solve(Eigen::VectorXd::Zero(m.n_dofs()), exact);
  EXPECT_LE((s.u - exact).cwiseAbs().maxCoeff(), 1e-14);
  // Constant stress D eps everywhere.
  const Eigen::MatrixXd eps = 0.5 * (A + A.transpose());
  Eigen::VectorXd v = dim == 3 ? Eigen::VectorXd(6) : Eigen::VectorXd(3);
  if (dim == 3) v << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(1, 2), 2 * eps(0, 2), 2 * eps(0, 1);
  else v << eps(0, 0), eps(1, 1), 2 * eps(0, 1);
  const Eigen::VectorXd sig = elasticity_matrix(mat) * v;
  const StressField f = recover_stress(m, mat, s.u);
  for (Location l : {Location::gauss, Location::centroid, Location::node})
    for (const Stress6& st : f.at(l)) {
      EXPECT_NEAR(st(0), sig(0), 1e-6 * sig.norm());
      EXPECT_NEAR(st(2), dim == 3 ? sig(2) : sig(1), 1e-6 * sig.norm());
      EXPECT_NEAR(st(4), dim == 3 ? sig(4) : sig(2), 1e-6 * sig.norm());
    }
  // Reactions of a self-equilibrated state sum to zero.
  EXPECT_LE(total_reaction(m, s.reaction, boundary).norm(), 1e-6 * s.reaction.cwiseAbs().maxCoeff());
}

TEST(Hex8, PatchTestDistortedMeshIsExact) { patch_test(3, Analysis::solid3d); }
TEST(Quad4, PatchTestDistortedMeshPlaneStrainIsExact) { patch_test(2, Analysis::plane_strain); }
TEST(Quad4, PatchTestDistortedMeshPlaneStressIsExact) { patch_test(2, Analysis::plane_stress); }

TEST(Hex8, RigidBodyModesCarryNoEnergyAndStiffnessIsSymmetric) {
  const Mesh m = distorted_patch(3);
  const Eigen::MatrixXd X = m.element_coordinates(7);
  const Eigen::MatrixXd K = element_stiffness(X, steel());
  EXPECT_LE((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-6 * K.cwiseAbs().maxCoeff());
  for (int mode = 0; mode < 6; ++mode) {
    Eigen::VectorXd u(24);
    for (int a = 0; a < 8; ++a) {
      const Eigen::Vector3d x = X.row(a).transpose();
      Eigen::Vector3d w = Eigen::Vector3d::Zero();
      w(mode % 3) = 1;
      u.segment<3>(3 * a) = mode < 3 ? w : Eigen::Vector3d(w.cross(x));
    }
    EXPECT_LE((K * u).norm(), 1e-6 * K.norm() * u.norm()) << "mode " << mode;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
  EXPECT_GT(es.eigenvalues()(6), 1e-6 * es.eigenvalues()(23));  // exactly 6 zero modes
}

TEST(Hex8, ConsistentMassSumsToRhoTimesVolume) {
  const Mesh m = distorted_patch(3);
  const Elastic mat = steel();
  const Eigen::SparseMatrix<double> M = assemble_mass(m, mat);
  // Unit translation in x: u^T M u = rho V (V = 1 m^3: the distortion keeps the outer box).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.n_dofs());
  for (int n = 0; n < m.n_nodes(); ++n) u(3 * n) = 1;
  EXPECT_NEAR(u.dot(M * u), mat.density_kg_m3, 1e-9 * mat.density_kg_m3);
}

TEST(Quad4, ConsistentMassIncludesThickness) {
  const Mesh m = distorted_patch(2);
  const Elastic mat = steel(Analysis::plane_stress);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.n_dofs());
  for (int n = 0; n < m.n_nodes(); ++n) u(2 * n + 1) = 1;
  EXPECT_NEAR(u.dot(assemble_mass(m, mat) * u), mat.density_kg_m3 * mat.thickness_m, 1e-9 * mat.density_kg_m3);
}

TEST(SolidInput, BadInputThrows) {
  Elastic bad = steel();
  bad.nu = 0.5;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
  const Mesh m3 = distorted_patch(3);
  EXPECT_THROW(assemble_stiffness(m3, steel(Analysis::plane_stress)), std::invalid_argument);
  Mesh inverted = m3;
  inverted.nodes.col(0) *= -1;  // mirrored: negative Jacobians
  EXPECT_THROW(inverted.validate(), std::invalid_argument);
  EXPECT_THROW(parse_sloped_face("left"), std::invalid_argument);
  TaperedBlock b;
  b.nz = 0;
  EXPECT_THROW(hex8_tapered_block(b), std::invalid_argument);
  const Eigen::SparseMatrix<double> K = assemble_stiffness(m3, steel());
  EXPECT_THROW(StaticSolver(K, {}), std::invalid_argument);              // nothing fixed
  EXPECT_THROW(StaticSolver(K, {0, 1, 2}), std::invalid_argument);       // one node fixed: still singular
}

TEST(SolidStress, MeasuresOfKnownTensors) {
  Stress6 s;
  s << 100, 0, 0, 0, 0, 0;  // uniaxial
  EXPECT_NEAR(measure(s, Measure::von_mises), 100, 1e-12);
  EXPECT_NEAR(measure(s, Measure::max_shear), 50, 1e-12);
  s << 0, 0, 0, 0, 0, 40;  // pure shear sxy
  EXPECT_NEAR(measure(s, Measure::max_principal), 40, 1e-12);
  EXPECT_NEAR(measure(s, Measure::min_principal), -40, 1e-12);
  EXPECT_NEAR(measure(s, Measure::von_mises), 40 * std::sqrt(3.0), 1e-12);
  s << 10, 20, 30, 4, 5, 6;
  const Eigen::Vector3d p = principal_stresses(s);
  EXPECT_NEAR(p.sum(), 60, 1e-12);  // trace invariant
  EXPECT_GE(p(0), p(1));
  EXPECT_GE(p(1), p(2));
}

}  // namespace
}  // namespace dmi::solid
