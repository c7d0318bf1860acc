#include "engine/solid/element.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dmi::solid {

void Elastic::validate() const {
  if (!(E_Pa > 0) || !std::isfinite(E_Pa)) throw std::invalid_argument("Elastic: E_Pa must be > 0");
  if (!(nu > -1 && nu < 0.5)) throw std::invalid_argument("Elastic: nu must lie in (-1, 0.5)");
  if (!(thickness_m > 0)) throw std::invalid_argument("Elastic: thickness_m must be > 0");
  if (!(density_kg_m3 >= 0)) throw std::invalid_argument("Elastic: density_kg_m3 must be >= 0");
}

const Eigen::MatrixXd& corner_signs(int dim) {
  static const Eigen::MatrixXd s2 = (Eigen::MatrixXd(4, 2) << -1, -1, 1, -1, 1, 1, -1, 1).finished();
  static const Eigen::MatrixXd s3 = (Eigen::MatrixXd(8, 3) << -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,  //
                                     -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1).finished();
  if (dim == 2) return s2;
  if (dim == 3) return s3;
  throw std::invalid_argument("corner_signs: dim must be 2 or 3, got " + std::to_string(dim));
}

namespace {
// N and dN/dxi at xi in fixed sizes (one implementation for the public dynamic form and the element kernels below).
template <int DIM> void shape_fixed(const Eigen::Matrix<double, DIM, 1>& xi, Eigen::Matrix<double, (1 << DIM), 1>& N,
                                    Eigen::Matrix<double, (1 << DIM), DIM>& dN) {
  const Eigen::MatrixXd& s = corner_signs(DIM);
  constexpr double scale = 1.0 / (1 << DIM);
  for (int a = 0; a < (1 << DIM); ++a) {
    double f[DIM];  // 1D factors (1 + s_ad xi_d)
    for (int d = 0; d < DIM; ++d) f[d] = 1 + s(a, d) * xi(d);
    double prod = f[0];
    for (int d = 1; d < DIM; ++d) prod *= f[d];
    N(a) = scale * prod;
    for (int d = 0; d < DIM; ++d) {
      double p = scale * s(a, d);
      for (int e = 0; e < DIM; ++e)
        if (e != d) p *= f[e];
      dN(a, d) = p;
    }
  }
}

template <int DIM> void shape_dynamic(const Eigen::VectorXd& xi, Eigen::VectorXd& N, Eigen::MatrixXd& dN) {
  Eigen::Matrix<double, (1 << DIM), 1> Nf;
  Eigen::Matrix<double, (1 << DIM), DIM> dNf;
  shape_fixed<DIM>(Eigen::Matrix<double, DIM, 1>(xi), Nf, dNf);
  N = Nf, dN = dNf;
}
}  // namespace

void shape_functions(int dim, const Eigen::VectorXd& xi, Eigen::VectorXd& N, Eigen::MatrixXd& dN) {
  corner_signs(dim);  // throws unless dim is 2 or 3
  if (xi.size() != dim) throw std::invalid_argument("shape_functions: xi must have dim entries");
  if (dim == 3) shape_dynamic<3>(xi, N, dN);
  else shape_dynamic<2>(xi, N, dN);
}

Eigen::MatrixXd gauss_points(int dim) { return corner_signs(dim) / std::sqrt(3.0); }

Eigen::MatrixXd elasticity_matrix(const Elastic& mat) {
  mat.validate();
  const double E = mat.E_Pa, nu = mat.nu;
  if (mat.analysis == Analysis::solid3d) {
    const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(6, 6);
    D.topLeftCorner(3, 3).setConstant(lam);
    for (int i = 0; i < 3; ++i) D(i, i) += 2 * mu, D(i + 3, i + 3) = mu;
    return D;
  }
  Eigen::MatrixXd D(3, 3);
  if (mat.analysis == Analysis::plane_strain) {
    const double c = E / ((1 + nu) * (1 - 2 * nu));
    D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  } else {
    const double c = E / (1 - nu * nu);
    D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  }
  return D;
}

namespace {
// B at xi in fixed sizes (one implementation for the public dynamic form, the stiffness and the stress recovery).
template <int DIM> struct Fixed {
  static constexpr int nen = 1 << DIM, ndof = DIM * nen, nstr = DIM == 3 ? 6 : 3;
  using Coords = Eigen::Matrix<double, nen, DIM>;
  using Point = Eigen::Matrix<double, DIM, 1>;
  using B = Eigen::Matrix<double, nstr, ndof>;
};

template <int DIM> typename Fixed<DIM>::B b_matrix(const typename Fixed<DIM>::Coords& X, const typename Fixed<DIM>::Point& xi, double& det) {
  constexpr int nen = Fixed<DIM>::nen;
  Eigen::Matrix<double, nen, 1> N;
  Eigen::Matrix<double, nen, DIM> dN;
  shape_fixed<DIM>(xi, N, dN);
  const Eigen::Matrix<double, DIM, DIM> J = X.transpose() * dN;  // J_ij = dx_i / dxi_j
  det = J.determinant();
  if (!(std::abs(det) > 0)) throw std::invalid_argument("strain_displacement: singular element Jacobian");
  const Eigen::Matrix<double, nen, DIM> G = dN * J.inverse();  // dN_a / dx_j
  typename Fixed<DIM>::B B = Fixed<DIM>::B::Zero();
  for (int a = 0; a < nen; ++a) {
    const int c = DIM * a;
    if constexpr (DIM == 3) {
      const double gx = G(a, 0), gy = G(a, 1), gz = G(a, 2);
      B(0, c) = gx, B(1, c + 1) = gy, B(2, c + 2) = gz;
      B(3, c + 1) = gz, B(3, c + 2) = gy;
      B(4, c) = gz, B(4, c + 2) = gx;
      B(5, c) = gy, B(5, c + 1) = gx;
    } else {
      const double gx = G(a, 0), gz = G(a, 1);
      B(0, c) = gx, B(1, c + 1) = gz, B(2, c) = gz, B(2, c + 1) = gx;
    }
  }
  return B;
}

template <int DIM> Eigen::MatrixXd stiffness(const Eigen::MatrixXd& Xd, const Eigen::MatrixXd& Dd, double volume_factor) {
  using F = Fixed<DIM>;
  const typename F::Coords X = Xd;
  const Eigen::Matrix<double, F::nstr, F::nstr> D = Dd;
  const Eigen::MatrixXd gp = gauss_points(DIM);
  Eigen::Matrix<double, F::ndof, F::ndof> K = Eigen::Matrix<double, F::ndof, F::ndof>::Zero();
  for (int g = 0; g < F::nen; ++g) {
    double detJ = 0;
    const typename F::Point xi = gp.row(g).transpose();
    const typename F::B B = b_matrix<DIM>(X, xi, detJ);
    const typename F::B DB = D * B;
    K.noalias() += B.transpose() * DB * (detJ * volume_factor);
  }
  return K;
}

template <int DIM> Eigen::VectorXd stress_vector(const Eigen::MatrixXd& Xd, const Eigen::VectorXd& ue, const Eigen::VectorXd& xi, const Eigen::MatrixXd& D) {
  using F = Fixed<DIM>;
  double det = 0;
  const typename F::B B = b_matrix<DIM>(typename F::Coords(Xd), typename F::Point(xi), det);
  const Eigen::Matrix<double, F::nstr, 1> strain = B * typename Eigen::Matrix<double, F::ndof, 1>(ue);
  return D * strain;
}
}  // namespace

Eigen::MatrixXd strain_displacement(const Eigen::MatrixXd& X, const Eigen::VectorXd& xi, double* detJ) {
  const int dim = static_cast<int>(X.cols()), nen = static_cast<int>(X.rows());
  if ((dim != 2 && dim != 3) || nen != (1 << dim)) throw std::invalid_argument("strain_displacement: X must be 2^dim x dim");
  if (xi.size() != dim) throw std::invalid_argument("strain_displacement: xi must have dim entries");
  double det = 0;
  Eigen::MatrixXd B = dim == 3 ? Eigen::MatrixXd(b_matrix<3>(Fixed<3>::Coords(X), Fixed<3>::Point(xi), det))
                               : Eigen::MatrixXd(b_matrix<2>(Fixed<2>::Coords(X), Fixed<2>::Point(xi), det));
  if (detJ) *detJ = det;
  return B;
}

namespace {
void check_dims(const Eigen::MatrixXd& X, const Elastic& mat) {
  if (X.cols() != mat.dim())
    throw std::invalid_argument("element: solid3d needs hex8 (3 columns), plane analyses quad4 (2 columns)");
  if (X.rows() != (1 << mat.dim())) throw std::invalid_argument("element: X must be 2^dim x dim");
}
double volume_factor(const Elastic& mat) { return mat.dim() == 2 ? mat.thickness_m : 1.0; }
}  // namespace

Eigen::MatrixXd element_stiffness(const Eigen::MatrixXd& X, const Elastic& mat) {
  check_dims(X, mat);
  const Eigen::MatrixXd D = elasticity_matrix(mat);
  return mat.dim() == 3 ? stiffness<3>(X, D, volume_factor(mat)) : stiffness<2>(X, D, volume_factor(mat));
}

Eigen::MatrixXd element_mass(const Eigen::MatrixXd& X, const Elastic& mat) {
  check_dims(X, mat);
  mat.validate();
  const int dim = mat.dim(), nen = static_cast<int>(X.rows());
  const Eigen::MatrixXd gp = gauss_points(dim);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(dim * nen, dim * nen);
  Eigen::VectorXd N;
  Eigen::MatrixXd dN;
  for (int g = 0; g < gp.rows(); ++g) {
    shape_functions(dim, gp.row(g).transpose(), N, dN);
    const double w = mat.density_kg_m3 * (X.transpose() * dN).determinant() * volume_factor(mat);
    for (int a = 0; a < nen; ++a)
      for (int b = 0; b < nen; ++b)
        for (int d = 0; d < dim; ++d) M(dim * a + d, dim * b + d) += w * N(a) * N(b);
  }
  return M;
}

Stress6 element_stress(const Eigen::MatrixXd& X, const Eigen::VectorXd& ue, const Eigen::VectorXd& xi,
                       const Elastic& mat) {
  check_dims(X, mat);
  if (xi.size() != mat.dim() || ue.size() != X.size()) throw std::invalid_argument("element_stress: xi or ue has the wrong size");
  const Eigen::MatrixXd D = elasticity_matrix(mat);
  const Eigen::VectorXd s = mat.dim() == 3 ? stress_vector<3>(X, ue, xi, D) : stress_vector<2>(X, ue, xi, D);
  Stress6 out;
  if (mat.dim() == 3) return s;
  const double syy = mat.analysis == Analysis::plane_strain ? mat.nu * (s(0) + s(1)) : 0.0;
  out << s(0), syy, s(1), 0, s(2), 0;
  return out;
}

}  // namespace dmi::solid
