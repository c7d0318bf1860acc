// The band Cholesky factorisation (engine/solid/band_cholesky.hpp) against a dense factorisation and against the
// sparse LDL^T it replaces: the same solution to round-off (the factor is unique), the bandwidth of a structured mesh
// as numbered, and refusal of matrices that are not positive definite.
#include <gtest/gtest.h>

#include <random>

#include "engine/solid/band_cholesky.hpp"
#include "engine/solid/mesh.hpp"
#include "engine/solid/static_solver.hpp"

namespace dmi::solid {
namespace {

// A random symmetric positive definite matrix of bandwidth b: B B^T + n I with B random and lower-banded (width b/2).
Eigen::SparseMatrix<double> random_band(int n, int b, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - b / 2); j <= i; ++j) B(i, j) = u(rng);
  Eigen::MatrixXd A = B * B.transpose();
  A.diagonal().array() += 0.1;
  return A.sparseView();
}

TEST(BandCholesky, SolvesAsTheDenseFactorisationWhateverTheLastBlock) {
  for (const auto& [n, b] : {std::pair{200, 17}, std::pair{201, 20}, std::pair{64, 63}, std::pair{50, 1}}) {
    const Eigen::SparseMatrix<double> A = random_band(n, 2 * (b / 2), 7u + static_cast<unsigned>(n));
    BandCholesky f;
    ASSERT_TRUE(f.compute(A)) << n << " " << b;
    EXPECT_LE(BandCholesky::bandwidth(A), b);
    Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(n, -1, 2);
    const Eigen::VectorXd x = f.solve(rhs), ref = Eigen::MatrixXd(A).llt().solve(rhs);
    EXPECT_LE((x - ref).norm(), 1e-10 * ref.norm()) << n << " " << b;
    EXPECT_LE((A * x - rhs).norm(), 1e-11 * rhs.norm()) << n << " " << b;
  }
}

TEST(BandCholesky, RefusesWhatIsNotPositiveDefinite) {
  Eigen::SparseMatrix<double> A = random_band(40, 6, 3u);
  A.coeffRef(25, 25) = -1;
  BandCholesky f;
  EXPECT_FALSE(f.compute(A));
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(10, 10);
  EXPECT_FALSE(f.compute(Z.sparseView()));
}

TEST(BandCholesky, StructuredHex8BlockHasTheLayerBandAndMatchesTheSparseFactorisation) {
  TaperedBlock b;
  b.nx = 3, b.ny = 2, b.nz = 5, b.sloped = SlopedFace::downstream;
  const Mesh m = hex8_tapered_block(b);
  Elastic mat;
  mat.E_Pa = 25e9, mat.nu = 0.2;
  const Eigen::SparseMatrix<double> K = assemble_stiffness(m, mat);
  EXPECT_EQ(BandCholesky::bandwidth(K), 3 * ((b.nx + 1) * (b.ny + 1) + b.nx + 3) - 1);
  const std::vector<int> fixed = node_dofs(m, nodes_at_height(m, 0.0));
  // K_ff by removing the base's rows and columns (the base is the first layer: a shift of the numbering).
  const int nf = static_cast<int>(fixed.size()), n = m.n_dofs() - nf;
  const Eigen::SparseMatrix<double> Kff = K.bottomRightCorner(n, n);
  BandCholesky band;
  ASSERT_TRUE(band.compute(Kff));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Kff);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; i += 3) f(i) = 1e5;  // a horizontal load on every node
  const Eigen::VectorXd a = band.solve(f), r = ldlt.solve(f);
  EXPECT_LE((a - r).norm(), 1e-11 * r.norm());
  // And through the solver, with its reactions: they balance the load.
  const StaticSolver solver(K, fixed);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(m.n_dofs());
  F.tail(n) = f;
  const StaticSolution s = solver.solve(F);
  EXPECT_LE((s.u.tail(n) - r).norm(), 1e-11 * r.norm());
  EXPECT_NEAR(total_reaction(m, s.reaction, nodes_at_height(m, 0.0))(0), -f.sum(), 1e-9 * f.sum());
}

// A block held along one edge only keeps a rigid rotation about it: K_ff is singular, its last pivot round-off of
// either sign; the solver refuses it (a sign test alone let it through about half the time).
TEST(BandCholesky, StructureFreeToRotateAboutAHeldEdgeIsRefused) {
  TaperedBlock b;
  b.nx = 2, b.ny = 3, b.nz = 2;
  const Mesh m = hex8_tapered_block(b);
  Elastic mat;
  mat.E_Pa = 25e9, mat.nu = 0.2;
  std::vector<int> edge;
  for (int j = 0; j <= b.ny; ++j) edge.push_back(m.node_id(0, j, 0));
  EXPECT_THROW(StaticSolver(assemble_stiffness(m, mat), node_dofs(m, edge)), std::invalid_argument);
  // Held on the whole base it is stiff.
  EXPECT_NO_THROW(StaticSolver(assemble_stiffness(m, mat), node_dofs(m, nodes_at_height(m, 0.0))));
}

}  // namespace
}  // namespace dmi::solid
