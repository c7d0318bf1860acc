#include "engine/solid/mesh.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/solid/element.hpp"

namespace dmi::solid {

SlopedFace parse_sloped_face(std::string_view name) {
  if (name == "upstream") return SlopedFace::upstream;
  if (name == "downstream") return SlopedFace::downstream;
  if (name == "both") return SlopedFace::both;
  throw std::invalid_argument("sloped face '" + std::string(name) + "': expected upstream, downstream or both");
}

const char* to_string(SlopedFace s) {
  switch (s) {
    case SlopedFace::upstream: return "upstream";
    case SlopedFace::downstream: return "downstream";
    case SlopedFace::both: return "both";
  }
  return "?";
}

int Mesh::node_id(int i, int j, int k) const {
  if (!structured()) throw std::invalid_argument("Mesh::node_id: mesh is not structured");
  if (i < 0 || i > nx || k < 0 || k > nz || (dim == 3 && (j < 0 || j > ny)))
    throw std::invalid_argument("Mesh::node_id: (" + std::to_string(i) + "," + std::to_string(j) + "," +
                                std::to_string(k) + ") outside the structured grid");
  return dim == 3 ? i + (nx + 1) * (j + (ny + 1) * k) : i + (nx + 1) * k;
}

Eigen::MatrixXd Mesh::element_coordinates(int e) const {
  const int nen = nodes_per_element();
  Eigen::MatrixXd X(nen, dim);
  for (int a = 0; a < nen; ++a) X.row(a) = nodes.row(elements(e, a));
  return X;
}

void Mesh::validate() const {
  if (dim != 2 && dim != 3) throw std::invalid_argument("Mesh: dim must be 2 or 3, got " + std::to_string(dim));
  if (nodes.cols() != dim || elements.cols() != nodes_per_element() || n_nodes() == 0 || n_elements() == 0)
    throw std::invalid_argument("Mesh: nodes must be n x dim and elements n x 2^dim, both non-empty");
  if (!nodes.allFinite()) throw std::invalid_argument("Mesh: non-finite node coordinate");
  if (elements.minCoeff() < 0 || elements.maxCoeff() >= n_nodes())
    throw std::invalid_argument("Mesh: element refers to a node id out of range");
  const Eigen::VectorXd centre = Eigen::VectorXd::Zero(dim);
  for (int e = 0; e < n_elements(); ++e) {
    double detJ = 0;
    strain_displacement(element_coordinates(e), centre, &detJ);
    if (!(detJ > 0)) throw std::invalid_argument("Mesh: element " + std::to_string(e) + " has Jacobian " +
                                                 std::to_string(detJ) + " <= 0 at its centroid");
  }
}

double TaperedBlock::thickness(double z) const {
  return base_thickness_m + (crest_thickness_m - base_thickness_m) * z / height_m;
}
double TaperedBlock::x_upstream(double z) const {
  switch (sloped) {
    case SlopedFace::upstream: return base_thickness_m - thickness(z);
    case SlopedFace::downstream: return 0.0;
    case SlopedFace::both: return 0.5 * (base_thickness_m - thickness(z));
  }
  return NAN;
}

void TaperedBlock::validate(int dim) const {
  auto positive = [](double v, const char* what) {
    if (!(v > 0) || !std::isfinite(v)) throw std::invalid_argument(std::string("TaperedBlock: ") + what + " must be > 0");
  };
  positive(height_m, "height_m");
  positive(base_thickness_m, "base_thickness_m");
  positive(crest_thickness_m, "crest_thickness_m");
  if (dim == 3) positive(width_m, "width_m");
  if (nx < 1 || nz < 1 || (dim == 3 && ny < 1))
    throw std::invalid_argument("TaperedBlock: element counts nx, ny, nz must be >= 1");
}

Mesh hex8_tapered_block(const TaperedBlock& b) {
  b.validate(3);
  Mesh m;
  m.dim = 3;
  m.nx = b.nx, m.ny = b.ny, m.nz = b.nz;
  m.nodes.resize((b.nx + 1) * (b.ny + 1) * (b.nz + 1), 3);
  for (int k = 0; k <= b.nz; ++k) {
    const double z = b.height_m * k / b.nz;
    for (int j = 0; j <= b.ny; ++j)
      for (int i = 0; i <= b.nx; ++i)
        m.nodes.row(m.node_id(i, j, k)) << b.x_upstream(z) + b.thickness(z) * i / b.nx, b.width_m * j / b.ny, z;
  }
  m.elements.resize(b.nx * b.ny * b.nz, 8);
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j)
      for (int i = 0; i < b.nx; ++i) {
        const int e = i + b.nx * (j + b.ny * k);
        for (int c = 0; c < 2; ++c)
          m.elements.block(e, 4 * c, 1, 4) << m.node_id(i, j, k + c), m.node_id(i + 1, j, k + c),
              m.node_id(i + 1, j + 1, k + c), m.node_id(i, j + 1, k + c);
      }
  m.validate();
  return m;
}

Mesh quad4_tapered_section(const TaperedBlock& b) {
  b.validate(2);
  Mesh m;
  m.dim = 2;
  m.nx = b.nx, m.ny = 0, m.nz = b.nz;
  m.nodes.resize((b.nx + 1) * (b.nz + 1), 2);
  for (int k = 0; k <= b.nz; ++k) {
    const double z = b.height_m * k / b.nz;
    for (int i = 0; i <= b.nx; ++i) m.nodes.row(m.node_id(i, 0, k)) << b.x_upstream(z) + b.thickness(z) * i / b.nx, z;
  }
  m.elements.resize(b.nx * b.nz, 4);
  for (int k = 0; k < b.nz; ++k)
    for (int i = 0; i < b.nx; ++i)
      m.elements.row(i + b.nx * k) << m.node_id(i, 0, k), m.node_id(i + 1, 0, k), m.node_id(i + 1, 0, k + 1),
          m.node_id(i, 0, k + 1);
  m.validate();
  return m;
}

std::vector<int> nodes_at_height(const Mesh& m, double z0, double tol) {
  std::vector<int> out;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (std::abs(m.nodes(n, m.dim - 1) - z0) <= tol) out.push_back(n);
  return out;
}

}  // namespace dmi::solid
