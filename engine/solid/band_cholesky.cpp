#include "engine/solid/band_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dmi::solid {

int BandCholesky::bandwidth(const Eigen::SparseMatrix<double>& A) {
  int b = 0;
  for (int col = 0; col < A.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it) b = std::max(b, std::abs(static_cast<int>(it.row()) - col));
  return b;
}

bool BandCholesky::compute(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols()) throw std::invalid_argument("BandCholesky: the matrix must be square");
  n_ = static_cast<int>(A.rows());
  b_ = std::max(1, bandwidth(A));
  const int nb = (n_ + b_ - 1) / b_;
  auto size = [&](int k) { return std::min(b_, n_ - k * b_); };
  diag_.assign(static_cast<std::size_t>(nb), {});
  sub_.assign(static_cast<std::size_t>(std::max(nb - 1, 0)), {});
  for (int k = 0; k < nb; ++k) diag_[k] = Eigen::MatrixXd::Zero(size(k), size(k));
  for (int k = 0; k + 1 < nb; ++k) sub_[k] = Eigen::MatrixXd::Zero(size(k + 1), size(k));
  // The lower triangle into the blocks: row r, column c <= r lies in block row r / b, block column c / b (equal or one
  // less, as r - c <= b).
  for (int col = 0; col < A.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it) {
      const int r = static_cast<int>(it.row());
      if (r < col) continue;
      const int kr = r / b_, kc = col / b_;
      if (kr == kc) diag_[kr](r - kr * b_, col - kc * b_) = it.value();
      else sub_[kc](r - kr * b_, col - kc * b_) = it.value();
    }
  double max_diag = 0;
  for (int k = 0; k < nb; ++k) max_diag = std::max(max_diag, diag_[k].diagonal().cwiseAbs().maxCoeff());
  const double floor = pivot_floor(n_, max_diag);
  auto fail = [&] { n_ = 0, diag_.clear(), sub_.clear(); return false; };
  for (int k = 0; k < nb; ++k) {
    Eigen::MatrixXd& Akk = diag_[k];
    if (k > 0) Akk.selfadjointView<Eigen::Lower>().rankUpdate(sub_[k - 1], -1.0);  // A_kk - L_k,k-1 L_k,k-1^T
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(Akk);  // in place: the lower triangle becomes L_kk
    if (llt.info() != Eigen::Success || !Akk.diagonal().allFinite()) return fail();
    const double p = Akk.diagonal().minCoeff();
    if (!(p * p > floor)) return fail();
    if (k + 1 < nb)  // L_k+1,k = A_k+1,k L_kk^-T
      Akk.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(sub_[k]);
  }
  return true;
}

Eigen::VectorXd BandCholesky::solve(const Eigen::VectorXd& rhs) const {
  if (rhs.size() != n_) throw std::invalid_argument("BandCholesky::solve: the right-hand side has the wrong length");
  Eigen::VectorXd x = rhs;
  const int nb = static_cast<int>(diag_.size());
  for (int k = 0; k < nb; ++k) {  // L y = rhs
    auto yk = x.segment(k * b_, diag_[k].rows());
    if (k > 0) yk.noalias() -= sub_[k - 1] * x.segment((k - 1) * b_, diag_[k - 1].rows());
    diag_[k].triangularView<Eigen::Lower>().solveInPlace(yk);
  }
  for (int k = nb - 1; k >= 0; --k) {  // L^T x = y
    auto xk = x.segment(k * b_, diag_[k].rows());
    if (k + 1 < nb) xk.noalias() -= sub_[k].transpose() * x.segment((k + 1) * b_, diag_[k + 1].rows());
    diag_[k].triangularView<Eigen::Lower>().transpose().solveInPlace(xk);
  }
  return x;
}

}  // namespace dmi::solid
