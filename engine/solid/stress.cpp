#include "engine/solid/stress.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dmi::solid {

const char* to_string(Measure m) {
  switch (m) {
    case Measure::von_mises: return "von Mises";
    case Measure::max_principal: return "max principal";
    case Measure::min_principal: return "min principal";
    case Measure::max_shear: return "max shear";
    case Measure::sxx: return "sxx";
    case Measure::syy: return "syy";
    case Measure::szz: return "szz";
    case Measure::syz: return "syz";
    case Measure::sxz: return "sxz";
    case Measure::sxy: return "sxy";
  }
  return "?";
}

const char* to_string(Location l) {
  switch (l) {
    case Location::gauss: return "Gauss points";
    case Location::centroid: return "centroids";
    case Location::node: return "nodes";
  }
  return "?";
}

Eigen::Vector3d principal_stresses(const Stress6& s) {
  Eigen::Matrix3d T;
  T << s(0), s(5), s(4), s(5), s(1), s(3), s(4), s(3), s(2);
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(T, Eigen::EigenvaluesOnly).eigenvalues();
  return {ev(2), ev(1), ev(0)};
}

namespace {
bool from_principal(Measure m) { return m == Measure::max_principal || m == Measure::min_principal || m == Measure::max_shear; }
// A principal-stress measure from the principal stresses p (descending).
double principal_measure(const Eigen::Vector3d& p, Measure m) {
  return m == Measure::max_principal ? p(0) : m == Measure::min_principal ? p(2) : 0.5 * (p(0) - p(2));
}
}  // namespace

double measure(const Stress6& s, Measure m) {
  switch (m) {
    case Measure::von_mises: {
      const double a = s(0) - s(1), b = s(1) - s(2), c = s(2) - s(0);
      return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
    }
    case Measure::max_principal:
    case Measure::min_principal:
    case Measure::max_shear: return principal_measure(principal_stresses(s), m);
    case Measure::sxx: return s(0);
    case Measure::syy: return s(1);
    case Measure::szz: return s(2);
    case Measure::syz: return s(3);
    case Measure::sxz: return s(4);
    case Measure::sxy: return s(5);
  }
  throw std::invalid_argument("measure: unknown measure");
}

const std::vector<Stress6>& StressField::at(Location l) const {
  switch (l) {
    case Location::gauss: return gauss;
    case Location::centroid: return centroid;
    case Location::node: return nodal;
  }
  throw std::invalid_argument("StressField::at: unknown location");
}

StressField recover_stress(const Mesh& m, const Elastic& mat, const Eigen::VectorXd& u) {
  if (m.dim != mat.dim()) throw std::invalid_argument("recover_stress: mesh dim does not match the analysis type");
  if (u.size() != m.n_dofs() || !u.allFinite()) throw std::invalid_argument("recover_stress: u must be finite, n_dofs long");
  const int dim = m.dim, nen = m.nodes_per_element();
  const Eigen::MatrixXd gp = gauss_points(dim), corners = corner_signs(dim);
  // E(a, g) = N_g(sqrt 3 s_a): Gauss-point values -> corner values.
  Eigen::MatrixXd extrap(nen, nen);
  Eigen::VectorXd N;
  Eigen::MatrixXd dN;
  for (int a = 0; a < nen; ++a) {
    shape_functions(dim, std::sqrt(3.0) * corners.row(a).transpose(), N, dN);
    extrap.row(a) = N.transpose();
  }
  StressField out;
  out.gauss.resize(static_cast<std::size_t>(m.n_elements()) * nen);
  out.centroid.resize(m.n_elements());
  out.nodal.assign(m.n_nodes(), Stress6::Zero());
  std::vector<int> count(m.n_nodes(), 0);
  Eigen::VectorXd ue(dim * nen);
  for (int e = 0; e < m.n_elements(); ++e) {
    const Eigen::MatrixXd X = m.element_coordinates(e);
    for (int a = 0; a < nen; ++a) ue.segment(dim * a, dim) = u.segment(dim * m.elements(e, a), dim);
    Eigen::Matrix<double, 6, Eigen::Dynamic> sg(6, nen);
    for (int g = 0; g < nen; ++g) {
      sg.col(g) = element_stress(X, ue, gp.row(g).transpose(), mat);
      out.gauss[static_cast<std::size_t>(e) * nen + g] = sg.col(g);
    }
    out.centroid[e] = element_stress(X, ue, Eigen::VectorXd::Zero(dim), mat);
    const Eigen::MatrixXd sn = sg * extrap.transpose();  // 6 x nen corner values
    for (int a = 0; a < nen; ++a) {
      out.nodal[m.elements(e, a)] += sn.col(a);
      ++count[m.elements(e, a)];
    }
  }
  for (int n = 0; n < m.n_nodes(); ++n)
    if (count[n]) out.nodal[n] /= count[n];
  return out;
}

Eigen::VectorXd point_coordinates(const Mesh& m, Location l, int index) {
  const int nen = m.nodes_per_element();
  if (l == Location::node) return m.nodes.row(index).transpose();
  const int e = l == Location::centroid ? index : index / nen;
  Eigen::VectorXd xi = Eigen::VectorXd::Zero(m.dim), N;
  if (l == Location::gauss) xi = gauss_points(m.dim).row(index % nen).transpose();
  Eigen::MatrixXd dN;
  shape_functions(m.dim, xi, N, dN);
  return m.element_coordinates(e).transpose() * N;
}

std::vector<Peak> peaks(const StressField& s, const std::vector<Measure>& ms, Location l) {
  const std::vector<Stress6>& pts = s.at(l);
  if (pts.empty()) throw std::invalid_argument("peak: empty stress field");
  const bool any_principal = std::any_of(ms.begin(), ms.end(), from_principal);
  std::vector<Peak> out(ms.size());
  for (Peak& p : out) p.value = -INFINITY;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d ps = any_principal ? principal_stresses(pts[i]) : Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < ms.size(); ++k) {
      const Measure m = ms[k];
      const double v = from_principal(m) ? principal_measure(ps, m) : measure(pts[i], m);
      const double key = m == Measure::max_principal ? v : std::abs(v);
      if (key > out[k].value) out[k].value = key, out[k].index = static_cast<int>(i);
    }
  }
  return out;
}

Peak peak(const StressField& s, Measure m, Location l) { return peaks(s, {m}, l).front(); }

}  // namespace dmi::solid
