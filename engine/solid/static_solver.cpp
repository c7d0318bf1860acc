#include "engine/solid/static_solver.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dmi::solid {

namespace {
// The band's dense blocks up to 1 GiB: measured on the dam body (downstream slope, E 25 GPa), the band factorised
// 8 x 10 x 20 hex8 cells (5 940 unknowns, b = 329) in 0.17 s against 0.58 s by SimplicialLDLT, 8 x 20 x 10 (b = 599) in
// 0.30 against 0.47 s, 16 x 20 x 40 (42 840 unknowns, b = 1 127, 0.77 GB) in 5.4 against 94 s.
constexpr double kBandBytes = 1024.0 * 1024 * 1024;
// Straight into compressed columns on the pattern of the node adjacency (nodes sharing an element): each entry sums
// its elements' terms in element order, as setFromTriplets did (the same matrix to the bit), without the ~1 M
// triplets it sorted (90 of 96 ms of the dam body's assembly).
template <class ElementMatrix>
Eigen::SparseMatrix<double> assemble(const Mesh& m, const Elastic& mat, ElementMatrix&& element_matrix) {
  m.validate();
  mat.validate();
  if (m.dim != mat.dim()) throw std::invalid_argument("assemble: mesh dim does not match the analysis type");
  const int dim = m.dim, nen = m.nodes_per_element(), nn = m.n_nodes();
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(nn));
  for (int e = 0; e < m.n_elements(); ++e)
    for (int a = 0; a < nen; ++a)
      for (int b = 0; b < nen; ++b) adj[m.elements(e, b)].push_back(m.elements(e, a));
  for (auto& l : adj) std::sort(l.begin(), l.end()), l.erase(std::unique(l.begin(), l.end()), l.end());
  Eigen::SparseMatrix<double> K(m.n_dofs(), m.n_dofs());
  long nnz = 0;
  for (const auto& l : adj) nnz += static_cast<long>(dim) * dim * static_cast<long>(l.size());
  K.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  double* val = K.valuePtr();
  std::fill(val, val + nnz, 0.0);
  outer[0] = 0;
  for (int nb = 0; nb < nn; ++nb)
    for (int db = 0; db < dim; ++db) {
      const int col = dim * nb + db;
      int q = outer[col];
      for (int na : adj[nb])
        for (int da = 0; da < dim; ++da) inner[q++] = dim * na + da;
      outer[col + 1] = q;
    }
  for (int e = 0; e < m.n_elements(); ++e) {
    const Eigen::MatrixXd Ke = element_matrix(m.element_coordinates(e), mat);
    for (int b = 0; b < nen; ++b) {
      const int nb = m.elements(e, b);
      const std::vector<int>& l = adj[nb];
      for (int a = 0; a < nen; ++a) {
        const int na = m.elements(e, a);
        const int at = dim * static_cast<int>(std::lower_bound(l.begin(), l.end(), na) - l.begin());
        for (int db = 0; db < dim; ++db)
          for (int da = 0; da < dim; ++da) val[outer[dim * nb + db] + at + da] += Ke(dim * a + da, dim * b + db);
      }
    }
  }
  return K;
}
}  // namespace

Eigen::SparseMatrix<double> assemble_stiffness(const Mesh& m, const Elastic& mat) {
  return assemble(m, mat, element_stiffness);
}

Eigen::SparseMatrix<double> assemble_mass(const Mesh& m, const Elastic& mat) {
  if (!(mat.density_kg_m3 > 0)) throw std::invalid_argument("assemble_mass: density_kg_m3 must be > 0");
  return assemble(m, mat, element_mass);
}

std::vector<int> node_dofs(const Mesh& m, const std::vector<int>& nodes) {
  std::vector<int> dofs;
  for (int n : nodes) {
    if (n < 0 || n >= m.n_nodes()) throw std::invalid_argument("node_dofs: node " + std::to_string(n) + " out of range");
    for (int d = 0; d < m.dim; ++d) dofs.push_back(m.dim * n + d);
  }
  return dofs;
}

StaticSolver::StaticSolver(const Eigen::SparseMatrix<double>& K, std::vector<int> fixed_dofs) : K_(K) {
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n) throw std::invalid_argument("StaticSolver: K must be square");
  std::sort(fixed_dofs.begin(), fixed_dofs.end());
  fixed_dofs.erase(std::unique(fixed_dofs.begin(), fixed_dofs.end()), fixed_dofs.end());
  if (fixed_dofs.empty()) throw std::invalid_argument("StaticSolver: no DOF is fixed (rigid-body modes)");
  if (fixed_dofs.front() < 0 || fixed_dofs.back() >= n) throw std::invalid_argument("StaticSolver: fixed DOF out of range");
  fixed_ = std::move(fixed_dofs);
  std::vector<int> map(n, -1);  // free index, or -(1 + constrained index)
  for (std::size_t c = 0; c < fixed_.size(); ++c) map[fixed_[c]] = -1 - static_cast<int>(c);
  for (int i = 0; i < n; ++i)
    if (map[i] == -1 && !std::binary_search(fixed_.begin(), fixed_.end(), i)) {
      map[i] = static_cast<int>(free_.size());
      free_.push_back(i);
    }
  std::vector<Eigen::Triplet<double>> ff, fc;
  for (int col = 0; col < K.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
      const int r = map[it.row()], c = map[it.col()];
      if (r >= 0 && c >= 0) ff.emplace_back(r, c, it.value());
      else if (r >= 0) fc.emplace_back(r, -1 - c, it.value());
    }
  Eigen::SparseMatrix<double> Kff(n_free(), n_free());
  Kff.setFromTriplets(ff.begin(), ff.end());
  K_fc_.resize(n_free(), static_cast<int>(fixed_.size()));
  K_fc_.setFromTriplets(fc.begin(), fc.end());
  const char* singular = "StaticSolver: K_ff is singular or not positive definite (insufficient supports?)";
  banded_ = BandCholesky::bytes(n_free(), BandCholesky::bandwidth(Kff)) <= kBandBytes;
  if (banded_) {
    if (!band_.compute(Kff)) throw std::invalid_argument(singular);
    return;
  }
  ldlt_.compute(Kff);
  const double floor = BandCholesky::pivot_floor(n_free(), Kff.diagonal().cwiseAbs().maxCoeff());
  if (ldlt_.info() != Eigen::Success || !(ldlt_.vectorD().array() > floor).all()) throw std::invalid_argument(singular);
}

StaticSolution StaticSolver::solve(const Eigen::VectorXd& f, const Eigen::VectorXd& u_prescribed) const {
  const int n = static_cast<int>(K_.rows());
  if (f.size() != n) throw std::invalid_argument("StaticSolver::solve: f has the wrong length");
  if (u_prescribed.size() != 0 && u_prescribed.size() != n)
    throw std::invalid_argument("StaticSolver::solve: u_prescribed must be empty or full length");
  if (!f.allFinite()) throw std::invalid_argument("StaticSolver::solve: non-finite load");
  Eigen::VectorXd uc = Eigen::VectorXd::Zero(static_cast<int>(fixed_.size()));
  if (u_prescribed.size())
    for (std::size_t c = 0; c < fixed_.size(); ++c) uc(c) = u_prescribed(fixed_[c]);
  Eigen::VectorXd rhs(n_free());
  for (int i = 0; i < n_free(); ++i) rhs(i) = f(free_[i]);
  rhs -= K_fc_ * uc;
  const Eigen::VectorXd uf = banded_ ? band_.solve(rhs) : Eigen::VectorXd(ldlt_.solve(rhs));
  StaticSolution s;
  s.u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n_free(); ++i) s.u(free_[i]) = uf(i);
  for (std::size_t c = 0; c < fixed_.size(); ++c) s.u(fixed_[c]) = uc(c);
  const Eigen::VectorXd r = K_ * s.u - f;
  s.reaction = Eigen::VectorXd::Zero(n);
  for (int i : fixed_) s.reaction(i) = r(i);
  if (!s.u.allFinite()) throw std::invalid_argument("StaticSolver::solve: solution is not finite");
  return s;
}

Eigen::VectorXd total_reaction(const Mesh& m, const Eigen::VectorXd& reaction, const std::vector<int>& nodes) {
  if (reaction.size() != m.n_dofs()) throw std::invalid_argument("total_reaction: reaction has the wrong length");
  Eigen::VectorXd R = Eigen::VectorXd::Zero(m.dim);
  for (int n : nodes) R += reaction.segment(m.dim * n, m.dim);
  return R;
}

}  // namespace dmi::solid
