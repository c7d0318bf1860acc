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

// Breakpoints in [-1, 1] of a straight edge's parameter (c0 at -1, c1 at +1): the ends plus the breaks
// strictly inside, sorted.
std::vector<double> split_interval(double c0, double c1, const std::vector<double>& breaks) {
  std::vector<double> t{-1.0, 1.0};
  for (double b : breaks) {
    const double r = 2 * (b - c0) / (c1 - c0) - 1;
    if (r > -1 + 1e-12 && r < 1 - 1e-12) t.push_back(r);
  }
  std::sort(t.begin(), t.end());
  return t;
}
}  // namespace

Eigen::VectorXd face_load_magnitudes(const Mesh& m, Face face, const FaceTractionFn& q, int gauss_per_direction,
                                     double thickness_m, const std::vector<double>& y_breaks,
                                     const std::vector<double>& z_breaks) {
  if (!m.structured()) throw std::invalid_argument("face_load_magnitudes: mesh is not structured");
  if (gauss_per_direction < 1 || gauss_per_direction > 6) throw std::invalid_argument("face_load_magnitudes: gauss_per_direction must be 1..6");
  if (!q) throw std::invalid_argument("face_load_magnitudes: no traction function");
  if (!(thickness_m > 0)) throw std::invalid_argument("face_load_magnitudes: thickness_m must be > 0");
  std::vector<double> gx, gw;
  gauss_legendre(gauss_per_direction, gx, gw);
  const int i = face == Face::upstream ? 0 : m.nx, ng = gauss_per_direction;
  Eigen::VectorXd mag = Eigen::VectorXd::Zero(m.n_nodes());  // sum_a N_a q |J| w per node
  if (m.dim == 2) {
    for (int k = 0; k < m.nz; ++k) {
      const int ids[2] = {m.node_id(i, 0, k), m.node_id(i, 0, k + 1)};
      const double z0 = m.nodes(ids[0], 1), z1 = m.nodes(ids[1], 1);
      const std::vector<double> tb = split_interval(z0, z1, z_breaks);
      for (std::size_t b = 0; b + 1 < tb.size(); ++b) {
        const double tc = 0.5 * (tb[b] + tb[b + 1]), th = 0.5 * (tb[b + 1] - tb[b]);
        for (int g = 0; g < ng; ++g) {
          const double t = tc + th * gx[g], N0 = 0.5 * (1 - t), N1 = 0.5 * (1 + t);
          const double qv = q(0.0, N0 * z0 + N1 * z1);
          if (qv == 0) continue;
          const double dA = std::abs(0.5 * (z1 - z0)) * (gw[g] * th) * thickness_m;  // projection on z
          mag(ids[0]) += N0 * qv * dA, mag(ids[1]) += N1 * qv * dA;
        }
      }
    }
    return mag;
  }
  for (int k = 0; k < m.nz; ++k)
    for (int j = 0; j < m.ny; ++j) {
      const int ids[4] = {m.node_id(i, j, k), m.node_id(i, j + 1, k), m.node_id(i, j + 1, k + 1), m.node_id(i, j, k + 1)};
      Eigen::Matrix<double, 4, 3> X;
      for (int a = 0; a < 4; ++a) X.row(a) = m.nodes.row(ids[a]);
      const std::vector<double> sb = split_interval(X(0, 1), X(1, 1), y_breaks), tb = split_interval(X(0, 2), X(3, 2), z_breaks);
      for (std::size_t bs = 0; bs + 1 < sb.size(); ++bs)
        for (std::size_t bt = 0; bt + 1 < tb.size(); ++bt) {
          const double sc = 0.5 * (sb[bs] + sb[bs + 1]), sh = 0.5 * (sb[bs + 1] - sb[bs]);
          const double tc = 0.5 * (tb[bt] + tb[bt + 1]), th = 0.5 * (tb[bt + 1] - tb[bt]);
          for (int gs = 0; gs < ng; ++gs)
            for (int gt = 0; gt < ng; ++gt) {
              const double s = sc + sh * gx[gs], t = tc + th * gx[gt];
              const Eigen::Vector4d N(0.25 * (1 - s) * (1 - t), 0.25 * (1 + s) * (1 - t), 0.25 * (1 + s) * (1 + t),
                                      0.25 * (1 - s) * (1 + t));
              const Eigen::Vector4d Ns(-0.25 * (1 - t), 0.25 * (1 - t), 0.25 * (1 + t), -0.25 * (1 + t));
              const Eigen::Vector4d Nt(-0.25 * (1 - s), -0.25 * (1 + s), 0.25 * (1 + s), 0.25 * (1 - s));
              const Eigen::Vector3d x = X.transpose() * N;
              const double qv = q(x(1), x(2));
              if (qv == 0) continue;
              // Area of the face's projection on the y-z plane: |(x_,s x x_,t) . e_x|.
              const double dA = std::abs((X.transpose() * Ns).cross(X.transpose() * Nt)(0)) * (gw[gs] * sh) * (gw[gt] * th);
              for (int a = 0; a < 4; ++a) mag(ids[a]) += N(a) * qv * dA;
            }
        }
    }
  return mag;
}

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
  const Eigen::VectorXd mag = face_load_magnitudes(m, p.face, q, p.gauss_per_direction, 1.0);
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

void FaceTraction::validate() const {
  if (!q_Pa) throw std::invalid_argument("FaceTraction: q_Pa not set");
  if (!direction.allFinite() || !(direction.norm() > 0)) throw std::invalid_argument("FaceTraction: direction must be non-zero");
  if (gauss_per_direction < 1 || gauss_per_direction > 6) throw std::invalid_argument("FaceTraction: gauss_per_direction must be 1..6");
  for (double b : y_breaks) if (!std::isfinite(b)) throw std::invalid_argument("FaceTraction: non-finite y break");
  for (double b : z_breaks) if (!std::isfinite(b)) throw std::invalid_argument("FaceTraction: non-finite z break");
}

FaceLoadReport add_face_traction(const Mesh& m, const Elastic& mat, const FaceTraction& t, Eigen::VectorXd& f) {
  t.validate();
  mat.validate();
  if (m.dim != mat.dim()) throw std::invalid_argument("add_face_traction: mesh dim does not match the analysis type");
  if (f.size() != m.n_dofs()) throw std::invalid_argument("add_face_traction: f has the wrong length");
  const Eigen::Vector3d d = t.direction.normalized();
  if (m.dim == 2 && std::abs(d(1)) > 1e-12) throw std::invalid_argument("add_face_traction: 2D direction must have d_y = 0");
  const Eigen::VectorXd mag = face_load_magnitudes(m, t.face, t.q_Pa, t.gauss_per_direction,
                                                   m.dim == 2 ? mat.thickness_m : 1.0, t.y_breaks, t.z_breaks);
  FaceLoadReport rep;
  rep.resultant_N = mag.sum();
  for (int n = 0; n < m.n_nodes(); ++n)
    if (mag(n) != 0) {
      if (m.dim == 3) f.segment<3>(3 * n) += mag(n) * d;
      else f(2 * n) += mag(n) * d(0), f(2 * n + 1) += mag(n) * d(2);
      ++rep.loaded_nodes;
    }
  return rep;
}

double piecewise_linear(const std::vector<double>& z_m, const std::vector<double>& q_Pa, double z) {
  if (z < z_m.front() || z > z_m.back()) return 0.0;
  const std::size_t i = std::min<std::size_t>(std::upper_bound(z_m.begin(), z_m.end(), z) - z_m.begin(), z_m.size() - 1);
  const double r = (z - z_m[i - 1]) / (z_m[i] - z_m[i - 1]);
  return q_Pa[i - 1] + r * (q_Pa[i] - q_Pa[i - 1]);
}

FaceLoadReport add_pressure_profile(const Mesh& m, const Elastic& mat, Face face, const std::vector<double>& z_m,
                                    const std::vector<double>& q_Pa, Eigen::VectorXd& f, const Eigen::Vector3d& direction) {
  if (z_m.size() < 2 || z_m.size() != q_Pa.size()) throw std::invalid_argument("add_pressure_profile: need >= 2 (z, q) samples");
  for (std::size_t i = 0; i < z_m.size(); ++i) {
    if (!std::isfinite(z_m[i]) || !std::isfinite(q_Pa[i])) throw std::invalid_argument("add_pressure_profile: non-finite sample");
    if (i > 0 && !(z_m[i] > z_m[i - 1])) throw std::invalid_argument("add_pressure_profile: z_m must increase strictly");
  }
  FaceTraction t;
  t.face = face, t.direction = direction, t.z_breaks = z_m;
  t.q_Pa = [&](double, double z) { return piecewise_linear(z_m, q_Pa, z); };
  return add_face_traction(m, mat, t, f);
}

}  // namespace dmi::solid
