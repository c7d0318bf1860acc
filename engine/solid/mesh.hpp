// Structured meshes for the linear solid model (Lin, Cheng & Tuan, Table 1): hex8 blocks and quad4 sections.
//   Coordinates: x through the thickness (upstream face -> downstream face), y across the face width
//   (3D only), z up the height; metres. A 2D mesh stores (x, z) in its two columns.
//   Corner order (VTK): quad4 (-1,-1),(1,-1),(1,1),(-1,1); hex8 the same at zeta = -1, then at zeta = +1,
//   with xi along x (i), eta along y (j), zeta along z (k).
//   Structured node id: i + (nx+1)(j + (ny+1)k) in 3D, i + (nx+1)k in 2D; element id likewise with nx, ny.
#pragma once
#include <Eigen/Dense>
#include <string_view>
#include <vector>

namespace dmi::solid {

// Which face of the tapered block is inclined; "both" tapers symmetrically about the base mid-plane.
enum class SlopedFace { upstream, downstream, both };
SlopedFace parse_sloped_face(std::string_view name);  // "upstream" | "downstream" | "both", else throws
const char* to_string(SlopedFace s);

// The two faces normal to x that loads are applied to.
enum class Face { upstream, downstream };

struct Mesh {
  int dim = 3;                 // 2 (quad4 in the x-z plane) or 3 (hex8)
  Eigen::MatrixXd nodes;       // n_nodes x dim
  Eigen::MatrixXi elements;    // n_elements x 2^dim, corner order above
  int nx = -1, ny = -1, nz = -1;  // structured counts; -1 when unstructured (ny = 0 in 2D)

  int nodes_per_element() const { return dim == 3 ? 8 : 4; }
  int n_nodes() const { return static_cast<int>(nodes.rows()); }
  int n_elements() const { return static_cast<int>(elements.rows()); }
  int n_dofs() const { return dim * n_nodes(); }
  bool structured() const { return nx > 0; }
  // Structured node id (throws when unstructured or out of range); j is ignored in 2D.
  int node_id(int i, int j, int k) const;
  // Element corner coordinates, nodes_per_element x dim.
  Eigen::MatrixXd element_coordinates(int e) const;
  // Checks sizes, node ids in range and a positive Jacobian at every element centroid; throws.
  void validate() const;
};

// Tapered block: thickness t(z) = t_b + (t_c - t_b) z / H along x.
struct TaperedBlock {
  double height_m = 4.0;
  double width_m = 2.0;            // along y (3D only)
  double base_thickness_m = 1.6;   // t_b at z = 0
  double crest_thickness_m = 1.0;  // t_c at z = H
  SlopedFace sloped = SlopedFace::upstream;
  int nx = 8, ny = 10, nz = 20;    // elements through thickness, across width, up the height

  // Thickness and x of the upstream face at height z (the downstream face is at x_upstream + thickness). The vertical
  // face (if any) stays on its side of the base: downstream face at x = t_b when the upstream face slopes, upstream at
  // x = 0 otherwise.
  double thickness(double z) const;
  double x_upstream(double z) const;
  void validate(int dim) const;
};

Mesh hex8_tapered_block(const TaperedBlock& b);
// The same section in the x-z plane as quad4 (b.ny and b.width_m are ignored).
Mesh quad4_tapered_section(const TaperedBlock& b);

// Nodes with |z - z0| <= tol (z is the last coordinate column).
std::vector<int> nodes_at_height(const Mesh& m, double z0, double tol = 1e-9);

}  // namespace dmi::solid
