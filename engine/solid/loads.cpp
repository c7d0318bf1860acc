#include "engine/solid/loads.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dmi::solid {

void add_point_load(const Mesh& m, int node, const Eigen::VectorXd& force_N, Eigen::VectorXd& f) {
  if (node < 0 || node >= m.n_nodes()) throw std::invalid_argument("add_point_load: node out of range");
  if (force_N.size() != m.dim || !force_N.allFinite())
    throw std::invalid_argument("add_point_load: force must have dim finite entries");
  if (f.size() != m.n_dofs()) throw std::invalid_argument("add_point_load: f has the wrong length");
  f.segment(m.dim * node, m.dim) += force_N;
}

int nearest_face_node(const Mesh& m, Face face, double y_m, double z_m) {
  if (!m.structured()) throw std::invalid_argument("nearest_face_node: mesh is not structured");
  const int i = face == Face::upstream ? 0 : m.nx;
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= m.nz; ++k)
    for (int j = 0; j <= (m.dim == 3 ? m.ny : 0); ++j) {
      const int n = m.node_id(i, j, k);
      const double dz = m.nodes(n, m.dim - 1) - z_m, dy = m.dim == 3 ? m.nodes(n, 1) - y_m : 0.0;
      if (dy * dy + dz * dz < best_d) best_d = dy * dy + dz * dz, best = n;
    }
  return best;
}

void PatchLoad::validate() const {
  if (!std::isfinite(centre_y_m) || !std::isfinite(centre_z_m)) throw std::invalid_argument("PatchLoad: centre not set");
  if (!(width_m > 0) || !(height_m > 0)) throw std::invalid_argument("PatchLoad: width_m and height_m must be > 0");
  if (!std::isfinite(total_force_N) || total_force_N == 0) throw std::invalid_argument("PatchLoad: total_force_N must be finite, non-zero");
  if (!direction.allFinite() || !(direction.norm() > 0)) throw std::invalid_argument("PatchLoad: direction must be non-zero");
  if (gauss_per_direction < 1 || gauss_per_direction > 6) throw std::invalid_argument("PatchLoad: gauss_per_direction must be 1..6");
}

namespace {
// Gauss-Legendre points and weights on [-1, 1]: Newton on P_n, w = 2 / ((1 - x^2) P_n'(x)^2) (A&S 25.4.29).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n), w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = 0;
      for (int k = 1; k <= n; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2 * k - 1) * z * p1 - (k - 1) * p2) / k;
      }
      dp = n * (z * p0 - p1) / (z * z - 1);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-15) break;
    }
    x[i] = z, w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}
}  // namespace

PatchLoadReport add_patch_load(const Mesh& m, const PatchLoad& p, Eigen::VectorXd& f) {
  p.validate();
  if (m.dim != 3 || !m.structured()) throw std::invalid_argument("add_patch_load: needs a structured hex8 mesh");
  if (f.size() != m.n_dofs()) throw std::invalid_argument("add_patch_load: f has the wrong length");
  const Eigen::Vector3d d = p.direction.normalized();
  const double area = p.width_m * p.height_m;
  PatchLoadReport rep;
  rep.nominal_peak_pressure_Pa = (p.shape == PatchShape::pyramid ? 3.0 : 1.0) * p.total_force_N / area;
  auto q = [&](double y, double z) {
    const double u = std::abs(y - p.centre_y_m) / (0.5 * p.width_m), v = std::abs(z - p.centre_z_m) / (0.5 * p.height_m);
    if (u > 1 || v > 1) return 0.0;
    return rep.nominal_peak_pressure_Pa * (p.shape == PatchShape::pyramid ? 1 - std::max(u, v) : 1.0);
  };
  std::vector<double> gx, gw;
  gauss_legendre(p.gauss_per_direction, gx, gw);
  const int i = p.face == Face::upstream ? 0 : m.nx;
  Eigen::VectorXd mag = Eigen::VectorXd::Zero(m.n_nodes());  // sum_a N_a q |J| w per node
  for (int k = 0; k < m.nz; ++k)
    for (int j = 0; j < m.ny; ++j) {
      const int ids[4] = {m.node_id(i, j, k), m.node_id(i, j + 1, k), m.node_id(i, j + 1, k + 1), m.node_id(i, j, k + 1)};
      Eigen::Matrix<double, 4, 3> X;
      for (int a = 0; a < 4; ++a) X.row(a) = m.nodes.row(ids[a]);
      for (int gs = 0; gs < p.gauss_per_direction; ++gs)
        for (int gt = 0; gt < p.gauss_per_direction; ++gt) {
          const double s = gx[gs], t = gx[gt];
          const Eigen::Vector4d N(0.25 * (1 - s) * (1 - t), 0.25 * (1 + s) * (1 - t), 0.25 * (1 + s) * (1 + t),
                                  0.25 * (1 - s) * (1 + t));
          const Eigen::Vector4d Ns(-0.25 * (1 - t), 0.25 * (1 - t), 0.25 * (1 + t), -0.25 * (1 + t));
          const Eigen::Vector4d Nt(-0.25 * (1 - s), -0.25 * (1 + s), 0.25 * (1 + s), 0.25 * (1 - s));
          const Eigen::Vector3d x = X.transpose() * N;
          const double qv = q(x(1), x(2));
          if (qv == 0) continue;
          // Area of the face's projection on the y-z plane: |(x_,s x x_,t) . e_x|.
          const double dA = std::abs((X.transpose() * Ns).cross(X.transpose() * Nt)(0)) * gw[gs] * gw[gt];
          for (int a = 0; a < 4; ++a) mag(ids[a]) += N(a) * qv * dA;
        }
    }
  rep.integrated_force_N = mag.sum();
  if (!(std::abs(rep.integrated_force_N) > 0))
    throw std::invalid_argument("add_patch_load: the patch covers no Gauss point of the face (refine or move it)");
  rep.scale = p.total_force_N / rep.integrated_force_N;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (mag(n) != 0) {
      f.segment<3>(3 * n) += rep.scale * mag(n) * d;
      ++rep.loaded_nodes;
    }
  return rep;
}

}  // namespace dmi::solid
