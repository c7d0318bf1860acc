// Cholesky factorisation of a sparse symmetric positive definite matrix within its band, by dense blocks.
// With bandwidth b (|i - j| <= b for every non-zero) and the rows cut into blocks of b, the matrix is block
// tridiagonal and so is its factor's band: per block k (Golub & Van Loan 2013, sec. 4.5.1, block tridiagonal LU, in
// the symmetric case)
//   L_kk L_kk^T = A_kk - L_k,k-1 L_k,k-1^T,   L_k+1,k = A_k+1,k L_kk^-T,
// about n b^2 flops in dense kernels (Eigen's blocked LLT, triangular solves and rank updates), where a simplicial
// sparse factorisation walks the same fill column by column. The structured solid meshes numbered layer by layer have
// b = dim ((nx + 1)(ny + 1) + nx + 3) - 1: for the dam body's 8 x 10 x 20 hex8 mesh (6 237 unknowns, b = 329) it
// factorises several times faster than Eigen's SimplicialLDLT with AMD ordering (docs/performance.md).
#pragma once
#include <algorithm>
#include <limits>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace dmi::solid {

class BandCholesky {
 public:
  // max |i - j| over the stored entries of A (0 for a diagonal or empty matrix).
  static int bandwidth(const Eigen::SparseMatrix<double>& A);
  // Storage of the factor's blocks for an n x n matrix of bandwidth b (two b x b blocks per b rows), bytes.
  static double bytes(int n, int b) { return 16.0 * n * std::max(b, 1); }
  // The smallest pivot d (of L D L^T; L_ii^2 here) taken as positive definite for an n x n matrix: a pivot at round-off
  // level of the largest diagonal entry is a null vector whose sign rounding decided (a structure with too few
  // supports), not a stiffness. Used by the band and the sparse factorisation alike.
  static double pivot_floor(int n, double max_diag) { return n * std::numeric_limits<double>::epsilon() * max_diag; }
  // Factorises A (its lower triangle is read; A must be square). False, and nothing factorised, when a pivot is not
  // above pivot_floor (not positive definite to working precision).
  bool compute(const Eigen::SparseMatrix<double>& A);
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  int rows() const { return n_; }

 private:
  int n_ = 0, b_ = 1;
  std::vector<Eigen::MatrixXd> diag_;  // L_kk, lower triangular
  std::vector<Eigen::MatrixXd> sub_;   // L_k+1,k
};

}  // namespace dmi::solid
